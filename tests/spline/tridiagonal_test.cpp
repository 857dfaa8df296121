// tests/spline/tridiagonal_test.cpp — the O(n) tridiagonal and cyclic
// tridiagonal solvers (common/spline/tridiagonal.h).
//
// References: dense Gaussian elimination with partial pivoting (written here,
// independent of the code under test) on random diagonally dominant systems,
// and two 3 x 3 systems worked by hand.
#include "spline/tridiagonal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace gllab::spline {
namespace {

/// Agreement with dense elimination, relative to the size of the solution:
/// a few hundred rounding errors for n <= 50 well-conditioned rows.
constexpr double kSolveTolerance = 1e-12;
/// Hand-worked solutions are small integers; only rounding separates them.
constexpr double kHandTolerance = 1e-14;

using Dense = std::vector<std::vector<double>>;

/// Gaussian elimination with partial pivoting on a dense copy (the reference).
std::vector<double> dense_solve(Dense A, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::abs(A[i][k]) > std::abs(A[pivot][k])) pivot = i;
    std::swap(A[k], A[pivot]);
    std::swap(b[k], b[pivot]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const double m = A[i][k] / A[k][k];
      for (std::size_t j = k; j < n; ++j) A[i][j] -= m * A[k][j];
      b[i] -= m * b[k];
    }
  }
  std::vector<double> x(n);
  for (std::size_t i = n; i-- > 0;) {
    double sum = b[i];
    for (std::size_t j = i + 1; j < n; ++j) sum -= A[i][j] * x[j];
    x[i] = sum / A[i][i];
  }
  return x;
}

/// The dense matrix of (lower, diag, upper); cyclic adds the corner entries
/// (for n <= 2 they fall on entries that already exist and add to them).
Dense dense_matrix(const std::vector<double>& lower, const std::vector<double>& diag,
                   const std::vector<double>& upper, bool cyclic) {
  const std::size_t n = diag.size();
  Dense A(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    A[i][i] += diag[i];
    if (i > 0) A[i][i - 1] += lower[i];
    if (i + 1 < n) A[i][i + 1] += upper[i];
  }
  if (cyclic) {
    A[0][n - 1] += lower[0];
    A[n - 1][0] += upper[n - 1];
  }
  return A;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

struct System {
  std::vector<double> lower, diag, upper, rhs;
};

/// A random strictly diagonally dominant system of n rows: off-diagonal
/// entries in [-1, 1], |diag| = |lower| + |upper| + [0.5, 2], random sign.
System random_system(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> off(-1, 1), margin(0.5, 2), value(-10, 10);
  System s;
  for (std::size_t i = 0; i < n; ++i) {
    const double l = off(rng), u = off(rng);
    const double sign = off(rng) < 0 ? -1 : 1;
    s.lower.push_back(l);
    s.upper.push_back(u);
    s.diag.push_back(sign * (std::abs(l) + std::abs(u) + margin(rng)));
    s.rhs.push_back(value(rng));
  }
  return s;
}

/// Runs f and expects std::invalid_argument whose message contains `part`.
void expect_error(const std::function<void()>& f, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one containing \"" << part << "\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << "message: " << e.what();
  }
}

// --- hand-worked cases ------------------------------------------------------------

// [2 1 0; 1 2 1; 0 1 2] x = (4, 8, 8), built from x = (1, 2, 3).
// By hand, Thomas: row 0: upper_0 = 1/2, rhs_0 = 4/2 = 2.
// Row 1: pivot 2 - 1 * 1/2 = 3/2, upper_1 = 1 / (3/2) = 2/3, rhs_1 = (8 - 2) / (3/2) = 4.
// Row 2: pivot 2 - 1 * 2/3 = 4/3, rhs_2 = (8 - 4) / (4/3) = 3.
// Back: x2 = 3, x1 = 4 - 2/3 * 3 = 2, x0 = 2 - 1/2 * 2 = 1.
TEST(SolveTridiagonal, HandWorked3x3GivesOneTwoThree) {
  const std::vector<double> x = solve_tridiagonal({0, 1, 1}, {2, 2, 2}, {1, 1, 0}, {4, 8, 8});
  ASSERT_EQ(x.size(), 3u);
  EXPECT_NEAR(x[0], 1, kHandTolerance);
  EXPECT_NEAR(x[1], 2, kHandTolerance);
  EXPECT_NEAR(x[2], 3, kHandTolerance);
}

// The entries outside the matrix (lower[0], upper[N-1]) are ignored.
TEST(SolveTridiagonal, IgnoresEntriesOutsideTheMatrix) {
  const std::vector<double> x = solve_tridiagonal({99, 1, 1}, {2, 2, 2}, {1, 1, -99}, {4, 8, 8});
  EXPECT_NEAR(x[0], 1, kHandTolerance);
  EXPECT_NEAR(x[1], 2, kHandTolerance);
  EXPECT_NEAR(x[2], 3, kHandTolerance);
}

// Cyclic [4 1 1; 1 4 1; 1 1 4] x = (9, 12, 15), built from x = (1, 2, 3).
// By hand: adding the three rows, 6 (x0 + x1 + x2) = 36, so the sum is 6; each
// row reads 3 x_i + (x0 + x1 + x2) = rhs_i, so x = (9-6, 12-6, 15-6) / 3 = (1, 2, 3).
TEST(SolveCyclicTridiagonal, HandWorked3x3GivesOneTwoThree) {
  const std::vector<double> x = solve_cyclic_tridiagonal({1, 1, 1}, {4, 4, 4}, {1, 1, 1}, {9, 12, 15});
  ASSERT_EQ(x.size(), 3u);
  EXPECT_NEAR(x[0], 1, kHandTolerance);
  EXPECT_NEAR(x[1], 2, kHandTolerance);
  EXPECT_NEAR(x[2], 3, kHandTolerance);
}

// One unknown: (lower + diag + upper) x = rhs, here (1 + 4 + 1) x = 12 -> 2.
TEST(SolveCyclicTridiagonal, OneUnknownAddsAllThreeEntries) {
  const std::vector<double> x = solve_cyclic_tridiagonal({1}, {4}, {1}, std::vector<double>{12});
  ASSERT_EQ(x.size(), 1u);
  EXPECT_NEAR(x[0], 2, kHandTolerance);
}

// Two unknowns: both off-diagonal entries of a row hit the other unknown.
// [4 (1+2); (3+1) 5] x = (4 + 3*2, 4 + 5*2) = (10, 14) from x = (1, 2).
TEST(SolveCyclicTridiagonal, TwoUnknownsAddBothOffDiagonals) {
  const std::vector<double> x = solve_cyclic_tridiagonal({1, 3}, {4, 5}, {2, 1}, {10, 14});
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0], 1, kHandTolerance);
  EXPECT_NEAR(x[1], 2, kHandTolerance);
}

TEST(SolveTridiagonal, EmptySystemHasEmptySolution) {
  EXPECT_TRUE(solve_tridiagonal({}, {}, {}, std::vector<double>{}).empty());
  EXPECT_TRUE(solve_cyclic_tridiagonal({}, {}, {}, std::vector<double>{}).empty());
}

// --- against dense elimination ------------------------------------------------------

TEST(SolveTridiagonal, MatchesDenseEliminationOnRandomDominantSystems) {
  std::mt19937 rng(20240611);  // fixed seed: the same systems every run
  for (std::size_t n = 1; n <= 50; ++n) {
    const System s = random_system(n, rng);
    const std::vector<double> x = solve_tridiagonal(s.lower, s.diag, s.upper, s.rhs);
    const std::vector<double> ref = dense_solve(dense_matrix(s.lower, s.diag, s.upper, false), s.rhs);
    const double scale = std::max(1.0, max_abs(ref));
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(x[i], ref[i], kSolveTolerance * scale) << "n=" << n << " i=" << i;
  }
}

TEST(SolveCyclicTridiagonal, MatchesDenseEliminationOnRandomDominantSystems) {
  std::mt19937 rng(7);  // fixed seed
  for (std::size_t n = 1; n <= 50; ++n) {
    const System s = random_system(n, rng);
    const std::vector<double> x = solve_cyclic_tridiagonal(s.lower, s.diag, s.upper, s.rhs);
    const std::vector<double> ref = dense_solve(dense_matrix(s.lower, s.diag, s.upper, true), s.rhs);
    const double scale = std::max(1.0, max_abs(ref));
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(x[i], ref[i], kSolveTolerance * scale) << "n=" << n << " i=" << i;
  }
}

// A Vec3 right-hand side is three scalar systems with one matrix: each
// component must match the dense solution of that component.
TEST(SolveTridiagonal, Vec3RightHandSideSolvesEachComponent) {
  std::mt19937 rng(99);  // fixed seed
  std::uniform_real_distribution<double> value(-10, 10);
  for (bool cyclic : {false, true}) {
    for (std::size_t n = 1; n <= 50; ++n) {
      const System s = random_system(n, rng);
      std::vector<Vec3> rhs(n);
      std::vector<double> rx(n), ry(n), rz(n);
      for (std::size_t i = 0; i < n; ++i) {
        rhs[i] = {value(rng), value(rng), value(rng)};
        rx[i] = rhs[i].x;
        ry[i] = rhs[i].y;
        rz[i] = rhs[i].z;
      }
      const std::vector<Vec3> x = cyclic ? solve_cyclic_tridiagonal(s.lower, s.diag, s.upper, rhs)
                                         : solve_tridiagonal(s.lower, s.diag, s.upper, rhs);
      const Dense A = dense_matrix(s.lower, s.diag, s.upper, cyclic);
      const std::vector<double> ex = dense_solve(A, rx), ey = dense_solve(A, ry), ez = dense_solve(A, rz);
      const double scale = std::max({1.0, max_abs(ex), max_abs(ey), max_abs(ez)});
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_NEAR(x[i].x, ex[i], kSolveTolerance * scale) << "cyclic=" << cyclic << " n=" << n;
        EXPECT_NEAR(x[i].y, ey[i], kSolveTolerance * scale) << "cyclic=" << cyclic << " n=" << n;
        EXPECT_NEAR(x[i].z, ez[i], kSolveTolerance * scale) << "cyclic=" << cyclic << " n=" << n;
      }
    }
  }
}

// The spline matrices (ch. 1 §1.6): D_{i-1}, 2 (D_{i-1} + D_i), D_i. Large
// systems stay accurate: the residual A x - rhs is at rounding level.
TEST(SolveCyclicTridiagonal, SplineMatrixOfThousandRowsHasTinyResidual) {
  std::mt19937 rng(3);  // fixed seed
  std::uniform_real_distribution<double> step(0.01, 3), value(-1, 1);
  const std::size_t n = 1000;
  std::vector<double> D(n), lower(n), diag(n), upper(n), rhs(n);
  for (double& d : D) d = step(rng);
  for (std::size_t i = 0; i < n; ++i) {
    const double before = D[(i + n - 1) % n];
    lower[i] = before;
    diag[i] = 2 * (before + D[i]);
    upper[i] = D[i];
    rhs[i] = value(rng);
  }
  const std::vector<double> x = solve_cyclic_tridiagonal(lower, diag, upper, rhs);
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = lower[i] * x[(i + n - 1) % n] + diag[i] * x[i] + upper[i] * x[(i + 1) % n];
    EXPECT_NEAR(ax, rhs[i], kSolveTolerance) << "row " << i;
  }
}

// --- errors -----------------------------------------------------------------------------

// [0 1; 1 0] is regular but needs a row swap: the first pivot is 0.
TEST(SolveTridiagonal, ZeroPivotNamesTheRow) {
  expect_error([] { solve_tridiagonal({0, 1}, {0, 0}, {1, 0}, {1, 1}); }, "zero pivot 0 in row 0");
}

// [1 1; 1 1] is singular: the second pivot is 1 - 1 * 1 = 0.
TEST(SolveTridiagonal, SingularMatrixNamesTheSecondRow) {
  expect_error([] { solve_tridiagonal({0, 1}, {1, 1}, {1, 0}, {1, 2}); }, "in row 1");
}

TEST(SolveTridiagonal, SizeMismatchNamesTheSizes) {
  expect_error([] { solve_tridiagonal({0, 1}, {2, 2, 2}, {1, 1, 0}, {1, 2, 3}); },
               "lower has 2, diag 3, upper 3, rhs 3");
  expect_error([] { solve_cyclic_tridiagonal({1, 1, 1}, {4, 4, 4}, {1, 1, 1}, std::vector<Vec3>(2)); },
               "rhs 2");
}

TEST(SolveTridiagonal, NanIsRejectedWithItsIndex) {
  const double nan = std::nan("");
  expect_error([&] { solve_tridiagonal({0, 1}, {2, 2}, {1, 0}, {1, nan}); }, "rhs[1]=nan is not finite");
  expect_error([&] { solve_cyclic_tridiagonal({1, 1, 1}, {4, nan, 4}, {1, 1, 1}, {1, 2, 3}); },
               "diag[1]=nan is not finite");
}

// [1 1 1; 1 1 1; 1 1 1] (cyclic, all entries 1) is singular.
TEST(SolveCyclicTridiagonal, SingularMatrixIsRejected) {
  expect_error([] { solve_cyclic_tridiagonal({1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 2, 3}); },
               "solve_cyclic_tridiagonal");
  // Two unknowns: row 0 has 1 on the diagonal and 1 + 1 off it, row 1 has
  // 1 + 1 and 4: [1 2; 2 4], determinant 4 - 4 = 0.
  expect_error([] { solve_cyclic_tridiagonal({1, 1}, {1, 4}, {1, 1}, {1, 2}); }, "zero pivot");
}

}  // namespace
}  // namespace gllab::spline
