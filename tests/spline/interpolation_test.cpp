// tests/spline/interpolation_test.cpp — common/spline/interpolation.{h,cpp}.
//
// Expected values come from the worked examples of ch. 1 §1.6 (each test
// names the example) or from properties: the interpolating polynomial is
// unique (Theorem 1), so Vandermonde, Lagrange and Newton must agree.
#include "spline_test_support.h"
#include "spline/interpolation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace gllab::spline {
namespace {

// ---- tolerances ---------------------------------------------------------------
// Relative to the size of the data (max(1, max |f_i|)) unless a test says otherwise.
constexpr double kExact = 1e-12;  // a few thousand round-offs: "the same number"
// The Vandermonde solve loses accuracy with the matrix's condition number. On
// the spread nodes below (gaps >= 1/(2n)) the deviation from the Lagrange form
// grows about 8x per degree: 6e-14 at n = 3, 4e-12 at n = 5, 3e-10 at n = 7
// (2000 random cases). The Vandermonde leg therefore stops at n = 5 and allows
// 25x the worst deviation seen there. This is the lecture's point about
// conditioning, not slack in the code.
constexpr double kVandermonde = 1e-10;
constexpr int kMaxVandermondeDegree = 5;
// Gaussian elimination with partial pivoting is backward stable: whatever the
// condition number, the residual of a condition p^(j)(t_i) = f_i^(j) stays a
// few round-offs of the terms it sums, sum_k |k!/(k-j)! c_k t_i^(k-j)|
// (measured: 2e-14 of that sum for up to 12 conditions).
constexpr double kBackward = 1e-12;

// Braces alone cannot tell a double node from a Vec3 node: name the type.
using ScalarNodes = std::vector<HermiteNode<double>>;
using PointNodes = std::vector<HermiteNode<Vec3>>;

constexpr int kRandomCases = 200;  // random inputs per property test
constexpr int kSamples = 101;      // parameters per curve comparison

// ---- helpers --------------------------------------------------------------------

using testing::error_of;
using testing::expect_contains;
using testing::expect_near_vec;

/// Nodes spread over [0, 1] with gaps of at least 1 / (2n): a grid, jittered.
std::vector<double> spread_nodes(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> jitter(0.0, 0.5);
  std::vector<double> t;
  for (int i = 0; i <= n; ++i) t.push_back(n == 0 ? jitter(rng) : (i + jitter(rng)) / (n + 0.5));
  return t;
}

std::vector<double> random_values(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> value(-5.0, 5.0);
  std::vector<double> f;
  for (int i = 0; i < count; ++i) f.push_back(value(rng));
  return f;
}

std::vector<Vec3> random_points(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> value(-5.0, 5.0);
  std::vector<Vec3> f;
  for (int i = 0; i < count; ++i) f.push_back({value(rng), value(rng), value(rng)});
  return f;
}

double scale_of(const std::vector<double>& f) {
  double s = 1;
  for (double v : f) s = std::max(s, std::fabs(v));
  return s;
}

/// The j-th derivative of sum c_k t^k at t, written out independently of the library.
double monomial_derivative(const std::vector<double>& c, int j, double t) {
  double sum = 0;
  for (int k = j; k < static_cast<int>(c.size()); ++k) {
    double falling = 1;
    for (int q = 0; q < j; ++q) falling *= k - q;
    sum += c[static_cast<std::size_t>(k)] * falling * std::pow(t, k - j);
  }
  return sum;
}

/// sum_k |k!/(k-j)! c_k t^(k-j)|: the size of the terms monomial_derivative adds.
double monomial_derivative_terms(const std::vector<double>& c, int j, double t) {
  double sum = 0;
  for (int k = j; k < static_cast<int>(c.size()); ++k) {
    double falling = 1;
    for (int q = 0; q < j; ++q) falling *= k - q;
    sum += std::fabs(c[static_cast<std::size_t>(k)] * falling * std::pow(t, k - j));
  }
  return sum;
}

// ---- Vandermonde / monomial form ------------------------------------------------

TEST(Vandermonde, LectureLagrangeExampleGivesPoint1XSquaredMinusPoint6XPlus1) {
  // ch. 1 §1.6, Lagrange example 2: (0, 1), (1, 0.5), (2, 0.2) -> 0.1 x^2 - 0.6 x + 1.
  const std::vector<double> c = vandermonde_coefficients({0, 1, 2}, {1, 0.5, 0.2});
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0], 1.0, kExact);
  EXPECT_NEAR(c[1], -0.6, kExact);
  EXPECT_NEAR(c[2], 0.1, kExact);
}

TEST(Vandermonde, MatrixRowsArePowersOfTheNodes) {
  // ch. 1 §1.6, Theorem 1: A[i][j] = t_i^j.
  const auto A = vandermonde_matrix({2, -1, 0.5});
  const std::vector<std::vector<double>> expected = {{1, 2, 4}, {1, -1, 1}, {1, 0.5, 0.25}};
  EXPECT_EQ(A, expected);
}

TEST(Vandermonde, RecoversAPolynomialOfLowerDegree) {
  // ch. 1 §1.6 "Beware": n + 1 nodes give degree AT MOST n. Data from
  // p(t) = 2 - t + 3 t^2 at 6 nodes: the higher coefficients come out 0.
  const std::vector<double> nodes = {-1, -0.3, 0.2, 0.9, 1.5, 2};
  std::vector<double> f;
  for (double t : nodes) f.push_back(2 - t + 3 * t * t);
  const std::vector<double> c = vandermonde_coefficients(nodes, f);
  const std::vector<double> expected = {2, -1, 3, 0, 0, 0};
  ASSERT_EQ(c.size(), expected.size());
  for (std::size_t j = 0; j < c.size(); ++j) EXPECT_NEAR(c[j], expected[j], kVandermonde * scale_of(f)) << j;
}

TEST(Vandermonde, PointValuesSolveThreeSystemsWithOneMatrix) {
  // ch. 1 §1.6 "Note": a 3D curve is one system per coordinate; each
  // coordinate must equal the scalar solve of that coordinate.
  std::mt19937 rng(11);
  for (int n = 0; n <= 6; ++n) {
    const std::vector<double> nodes = spread_nodes(rng, n);
    const std::vector<Vec3> f = random_points(rng, n + 1);
    std::vector<double> fx, fy, fz;
    for (const Vec3& p : f) {
      fx.push_back(p.x);
      fy.push_back(p.y);
      fz.push_back(p.z);
    }
    const auto c = vandermonde_coefficients(nodes, f);
    const auto cx = vandermonde_coefficients(nodes, fx), cy = vandermonde_coefficients(nodes, fy),
               cz = vandermonde_coefficients(nodes, fz);
    for (std::size_t j = 0; j < c.size(); ++j) {
      EXPECT_EQ(c[j].x, cx[j]);
      EXPECT_EQ(c[j].y, cy[j]);
      EXPECT_EQ(c[j].z, cz[j]);
    }
  }
}

TEST(MonomialValue, HornerEvaluatesAscendingCoefficients) {
  // 1 + 2 t + 3 t^2 at t = 2: 1 + 4 + 12 = 17 (by hand).
  EXPECT_EQ(monomial_value(std::vector<double>{1, 2, 3}, 2.0), 17.0);
  EXPECT_EQ(monomial_value(std::vector<double>{}, 2.0), 0.0);  // the zero polynomial
}

TEST(GaussSolve, PivotsPastAZeroDiagonal) {
  // A[0][0] = 0 needs a row swap; x = (1, 2) by hand: 0*1 + 1*2 = 2, 1*1 + 1*2 = 3.
  const std::vector<double> x = gauss_solve({{0, 1}, {1, 1}}, {2, 3});
  EXPECT_NEAR(x[0], 1.0, kExact);
  EXPECT_NEAR(x[1], 2.0, kExact);
}

TEST(GaussSolve, SingularMatrixIsRejected) {
  expect_contains(error_of([] { gauss_solve({{1, 2}, {2, 4}}, {1, 2}); }), "singular");
  expect_contains(error_of([] { gauss_solve({{1, 2}, {2}}, {1, 2}); }), "row 1 has 1 entries, expected 2");
  expect_contains(error_of([] { gauss_solve({{1, 0}, {0, 1}}, std::vector<double>{1}); }), "2 rows but the right-hand side has 1");
  expect_contains(error_of([] { gauss_solve({{1, NAN}, {0, 1}}, {1, 2}); }), "A[0][1]=nan is not finite");
}

// ---- Lagrange ----------------------------------------------------------------------

TEST(Lagrange, LectureExampleQuadraticBasisAndPolynomial) {
  // ch. 1 §1.6, Lagrange example 2 with nodes 0, 1, 2:
  // L0 = (x^2 - 3x + 2)/2, L1 = -x^2 + 2x, L2 = (x^2 - x)/2, P = 0.1 x^2 - 0.6 x + 1.
  const std::vector<double> nodes = {0, 1, 2}, f = {1, 0.5, 0.2};
  for (int k = 0; k < kSamples; ++k) {
    const double x = -1 + 4.0 * k / (kSamples - 1);  // also outside [0, 2]
    EXPECT_NEAR(lagrange_basis(nodes, 0, x), (x * x - 3 * x + 2) / 2, kExact);
    EXPECT_NEAR(lagrange_basis(nodes, 1, x), -x * x + 2 * x, kExact);
    EXPECT_NEAR(lagrange_basis(nodes, 2, x), (x * x - x) / 2, kExact);
    EXPECT_NEAR(lagrange_value(nodes, f, x), 0.1 * x * x - 0.6 * x + 1, kExact);
  }
}

TEST(Lagrange, LectureLinearExampleIsTheLineThroughTwoPoints) {
  // ch. 1 §1.6, Lagrange example 1: P(x) = (y0 (x - x1) + y1 (x0 - x)) / (x0 - x1).
  const double x0 = 1, x1 = 3, y0 = 2, y1 = -4;
  for (int k = 0; k < kSamples; ++k) {
    const double x = x0 + (x1 - x0) * k / (kSamples - 1);
    EXPECT_NEAR(lagrange_value({x0, x1}, {y0, y1}, x), (y0 * (x - x1) + y1 * (x0 - x)) / (x0 - x1), kExact);
  }
}

// ch. 1 §1.6, "cubic Lagrange polynomials with uniform nodes t_i = i/3".
// The lecture prints L1 = -27/2 t^3 + 45/2 t^2 - 9t; that has the wrong sign
// (it is -1 at t_1 = 1/3, see the next test). Multiplying out the lecture's own
// product t (t - 2/3)(t - 1) / ((1/3)(-1/3)(-2/3)) = (27/2) t (t - 2/3)(t - 1) gives
// L1 = 27/2 t^3 - 45/2 t^2 + 9t, which also makes L0 + L1 + L2 + L3 = 1 and
// L2(t) = L1(1 - t) = -27/2 t^3 + 18 t^2 - 9/2 t as the lecture states.
double lecture_L0(double t) { return -4.5 * t * t * t + 9 * t * t - 5.5 * t + 1; }
double lecture_L1_sign_corrected(double t) { return 13.5 * t * t * t - 22.5 * t * t + 9 * t; }
double lecture_L2(double t) { return -13.5 * t * t * t + 18 * t * t - 4.5 * t; }
double lecture_L3(double t) { return 4.5 * t * t * t - 4.5 * t * t + t; }

TEST(Lagrange, LectureCubicBasisOnThirdsWithL1SignCorrected) {
  const std::vector<double> nodes = {0, 1.0 / 3, 2.0 / 3, 1};
  for (int k = 0; k < kSamples; ++k) {
    const double t = static_cast<double>(k) / (kSamples - 1);
    const std::vector<double> L = lagrange_basis_all(nodes, t);
    EXPECT_NEAR(L[0], lecture_L0(t), kExact) << t;
    EXPECT_NEAR(L[1], lecture_L1_sign_corrected(t), kExact) << t;
    EXPECT_NEAR(L[2], lecture_L2(t), kExact) << t;
    EXPECT_NEAR(L[3], lecture_L3(t), kExact) << t;
    // The lecture's symmetry: L2(t) = L1(1 - t), L3(t) = L0(1 - t).
    EXPECT_NEAR(L[2], lagrange_basis(nodes, 1, 1 - t), kExact);
    EXPECT_NEAR(L[3], lagrange_basis(nodes, 0, 1 - t), kExact);
  }
  // Monomial coefficients of L_i = the polynomial through the unit vector e_i.
  const std::vector<std::vector<double>> lecture_coefficients = {
      {1, -5.5, 9, -4.5}, {0, 9, -22.5, 13.5}, {0, -4.5, 18, -13.5}, {0, 1, -4.5, 4.5}};
  for (int i = 0; i < 4; ++i) {
    std::vector<double> e(4, 0.0);
    e[static_cast<std::size_t>(i)] = 1;
    const std::vector<double> c = vandermonde_coefficients(nodes, e);
    for (std::size_t j = 0; j < 4; ++j) EXPECT_NEAR(c[j], lecture_coefficients[static_cast<std::size_t>(i)][j], kExact) << i << "," << j;
  }
}

TEST(Lagrange, LecturePrintedL1OnThirdsHasTheWrongSign) {
  // The lecture's printed L1 at its own node t_1 = 1/3: -27/2/27 + 45/2/9 - 9/3 = -1,
  // where Theorem 2 demands L1(t_1) = 1.
  const double t1 = 1.0 / 3;
  const double lecture_printed_L1 = -13.5 * t1 * t1 * t1 + 22.5 * t1 * t1 - 9 * t1;
  EXPECT_NEAR(lecture_printed_L1, -1.0, kExact);
  EXPECT_NEAR(lagrange_basis({0, 1.0 / 3, 2.0 / 3, 1}, 1, t1), 1.0, kExact);
}

TEST(Lagrange, BasisIsKroneckerDeltaAtNodesAndSumsToOne) {
  // ch. 1 §1.6, Theorem 2: L_i(t_j) = delta_ij; and sum L_i = 1 (it
  // interpolates the constant 1).
  std::mt19937 rng(21);
  for (int c = 0; c < kRandomCases; ++c) {
    const int n = c % 9;
    const std::vector<double> nodes = spread_nodes(rng, n);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        EXPECT_NEAR(lagrange_basis(nodes, i, nodes[static_cast<std::size_t>(j)]), i == j ? 1.0 : 0.0, kExact);
    std::uniform_real_distribution<double> u(nodes.front(), nodes.back());
    const std::vector<double> L = lagrange_basis_all(nodes, u(rng));
    double sum = 0, size = 0;
    for (double v : L) {
      sum += v;
      size = std::max(size, std::fabs(v));
    }
    EXPECT_NEAR(sum, 1.0, kExact * std::max(1.0, size));
  }
}

// ---- Newton ----------------------------------------------------------------------

TEST(Newton, LectureExampleGivesOnePlusX) {
  // ch. 1 §1.6: (0, 1), (2, 3), (4, 5) -> table 1 | 3 1 | 5 1 0, p(x) = 1 + x.
  NewtonInterpolant<double> p;
  p.add_node(0, 1);
  p.add_node(2, 3);
  p.add_node(4, 5);
  const std::vector<std::vector<double>> table = {{1, 3, 5}, {1, 1}, {0}};
  EXPECT_EQ(p.table(), table);  // small integers: exact
  EXPECT_EQ(p.coefficients(), (std::vector<double>{1, 1, 0}));
  for (int k = 0; k < kSamples; ++k) {
    const double x = -2 + 8.0 * k / (kSamples - 1);
    EXPECT_NEAR(p(x), 1 + x, kExact);
  }
  EXPECT_EQ(p.size(), 3);
  EXPECT_EQ(p.nodes(), (std::vector<double>{0, 2, 4}));
}

TEST(Newton, BasisVanishesAtEarlierNodes) {
  // ch. 1 §1.6: N_i(t_j) = 0 for i > j, N_i(t_i) != 0.
  const std::vector<double> nodes = {0, 0.5, 1.25, 2};
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      const double v = newton_basis(nodes, i, nodes[static_cast<std::size_t>(j)]);
      if (i > j) {
        EXPECT_EQ(v, 0.0);
      } else if (i == j) {
        EXPECT_NE(v, 0.0);
      }
    }
  EXPECT_EQ(newton_basis(nodes, 0, 7.0), 1.0);  // N_0 = 1
}

TEST(Newton, IncrementalTableEqualsBatchTable) {
  // add_node extends the table diagonal by diagonal; divided_difference_table
  // fills it column by column. Each entry is the same expression of the same
  // two operands, so the doubles are identical (exact ==), for every prefix.
  std::mt19937 rng(31);
  for (int c = 0; c < kRandomCases; ++c) {
    const int n = c % 10;
    const std::vector<double> nodes = spread_nodes(rng, n);
    const std::vector<double> f = random_values(rng, n + 1);
    const std::vector<Vec3> F = random_points(rng, n + 1);
    NewtonInterpolant<double> p;
    NewtonInterpolant<Vec3> P;
    for (int k = 0; k <= n; ++k) {
      p.add_node(nodes[static_cast<std::size_t>(k)], f[static_cast<std::size_t>(k)]);
      P.add_node(nodes[static_cast<std::size_t>(k)], F[static_cast<std::size_t>(k)]);
      const std::vector<double> prefix(nodes.begin(), nodes.begin() + k + 1);
      EXPECT_EQ(p.table(), divided_difference_table(prefix, std::vector<double>(f.begin(), f.begin() + k + 1)));
      const auto batch = divided_difference_table(prefix, std::vector<Vec3>(F.begin(), F.begin() + k + 1));
      ASSERT_EQ(P.table().size(), batch.size());
      for (std::size_t col = 0; col < batch.size(); ++col) {
        ASSERT_EQ(P.table()[col].size(), batch[col].size());
        for (std::size_t j = 0; j < batch[col].size(); ++j) EXPECT_EQ(P.table()[col][j], batch[col][j]);
      }
    }
  }
}

TEST(Newton, AddingANodeKeepsTheOldTableAndInterpolatesTheNewPoint) {
  // ch. 1 §1.6: "additional nodes can be added without having to re-compute".
  NewtonInterpolant<double> p;
  p.add_node(0, 1);
  p.add_node(2, 3);
  p.add_node(4, 5);
  const auto before = p.table();
  p.add_node(1, 7);  // breaks the line 1 + x: the new point forces a cubic
  for (std::size_t k = 0; k < before.size(); ++k)
    for (std::size_t j = 0; j < before[k].size(); ++j) EXPECT_EQ(p.table()[k][j], before[k][j]);
  for (double t : {0.0, 2.0, 4.0}) EXPECT_NEAR(p(t), 1 + t, kExact);
  EXPECT_NEAR(p(1.0), 7.0, kExact);
}

TEST(Newton, NodeOrderDoesNotChangeThePolynomial) {
  // ch. 1 §1.6 "Note: the order of the nodes does not change the result".
  std::mt19937 rng(41);
  for (int c = 0; c < kRandomCases; ++c) {
    const int n = 1 + c % 7;
    std::vector<double> nodes = spread_nodes(rng, n);
    std::vector<double> f = random_values(rng, n + 1);
    NewtonInterpolant<double> forward, shuffled;
    for (int i = 0; i <= n; ++i) forward.add_node(nodes[static_cast<std::size_t>(i)], f[static_cast<std::size_t>(i)]);
    std::vector<int> order(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) order[static_cast<std::size_t>(i)] = i;
    std::shuffle(order.begin(), order.end(), rng);
    for (int i : order) shuffled.add_node(nodes[static_cast<std::size_t>(i)], f[static_cast<std::size_t>(i)]);
    for (int k = 0; k < kSamples; ++k) {
      const double t = nodes.front() + (nodes.back() - nodes.front()) * k / (kSamples - 1);
      EXPECT_NEAR(forward(t), shuffled(t), kExact * scale_of(f));
    }
  }
}

TEST(Interpolation, NewtonLagrangeAndVandermondeAgree) {
  // ch. 1 §1.6, Theorem 1: the interpolating polynomial is unique, so the
  // three constructions must give the same values (scalars and points).
  // Newton and Lagrange up to n = 7; Vandermonde up to kMaxVandermondeDegree.
  std::mt19937 rng(51);
  for (int c = 0; c < kRandomCases; ++c) {
    const int n = c % 8;
    const std::vector<double> nodes = spread_nodes(rng, n);
    const std::vector<double> f = random_values(rng, n + 1);
    const std::vector<Vec3> F = random_points(rng, n + 1);
    NewtonInterpolant<double> newton;
    NewtonInterpolant<Vec3> newton3;
    for (int i = 0; i <= n; ++i) {
      newton.add_node(nodes[static_cast<std::size_t>(i)], f[static_cast<std::size_t>(i)]);
      newton3.add_node(nodes[static_cast<std::size_t>(i)], F[static_cast<std::size_t>(i)]);
    }
    const std::vector<double> c1 = vandermonde_coefficients(nodes, f);
    const std::vector<Vec3> c3 = vandermonde_coefficients(nodes, F);  // checked for n <= 5 only
    const double scale = 5;  // |f_i| <= 5
    for (int k = 0; k < kSamples; ++k) {
      const double t = nodes.front() + (nodes.back() - nodes.front()) * k / (kSamples - 1);
      const double lagrange = lagrange_value(nodes, f, t);
      EXPECT_NEAR(newton(t), lagrange, kExact * scale);
      const Vec3 lagrange3 = lagrange_value(nodes, F, t);
      expect_near_vec(newton3(t), lagrange3, kExact * scale);
      if (n > kMaxVandermondeDegree) continue;
      EXPECT_NEAR(monomial_value(c1, t), lagrange, kVandermonde * scale);
      expect_near_vec(monomial_value(c3, t), lagrange3, kVandermonde * scale);
    }
    // ... and each interpolates its data.
    for (int i = 0; i <= n; ++i) {
      const double ti = nodes[static_cast<std::size_t>(i)];
      EXPECT_NEAR(newton(ti), f[static_cast<std::size_t>(i)], kExact * scale);
      EXPECT_NEAR(lagrange_value(nodes, f, ti), f[static_cast<std::size_t>(i)], kExact * scale);
      if (n <= kMaxVandermondeDegree) {
        EXPECT_NEAR(monomial_value(c1, ti), f[static_cast<std::size_t>(i)], kVandermonde * scale);
      }
    }
  }
}

TEST(Interpolation, OneNodeGivesTheConstant) {
  // n = 0: p(t) = f_0 everywhere.
  NewtonInterpolant<Vec3> p;
  p.add_node(0.5, {1, 2, 3});
  EXPECT_EQ(p(-10.0), (Vec3{1, 2, 3}));
  EXPECT_EQ(lagrange_value({0.5}, std::vector<double>{4.0}, 9.0), 4.0);
  EXPECT_EQ(vandermonde_coefficients({0.5}, std::vector<double>{4.0}), (std::vector<double>{4.0}));
  EXPECT_EQ(lagrange_basis({0.5}, 0, 3.0), 1.0);
}

// ---- Hermite ----------------------------------------------------------------------

TEST(Hermite, LectureBasisPolynomials) {
  // ch. 1 §1.6: H0 = 2t^3 - 3t^2 + 1, H0bar = t^3 - 2t^2 + t,
  // H1 = -2t^3 + 3t^2, H1bar = t^3 - t^2.
  for (int k = 0; k < kSamples; ++k) {
    const double t = static_cast<double>(k) / (kSamples - 1);
    const HermiteBasis H = cubic_hermite_basis(t);
    EXPECT_NEAR(H.H0, 2 * t * t * t - 3 * t * t + 1, kExact);
    EXPECT_NEAR(H.H0bar, t * t * t - 2 * t * t + t, kExact);
    EXPECT_NEAR(H.H1, -2 * t * t * t + 3 * t * t, kExact);
    EXPECT_NEAR(H.H1bar, t * t * t - t * t, kExact);
  }
}

TEST(Hermite, LectureBasisPropertiesAtTheEnds) {
  // ch. 1 §1.6: H_i(j) = delta_ij, H_i'(j) = 0, Hbar_i(j) = 0, Hbar_i'(j) = delta_ij.
  // At t = 0 and 1 the polynomials take small integers: exact.
  const HermiteBasis H0 = cubic_hermite_basis(0), H1 = cubic_hermite_basis(1);
  const HermiteBasis D0 = cubic_hermite_basis_derivative(0), D1 = cubic_hermite_basis_derivative(1);
  EXPECT_EQ(H0.H0, 1.0);
  EXPECT_EQ(H0.H1, 0.0);
  EXPECT_EQ(H1.H0, 0.0);
  EXPECT_EQ(H1.H1, 1.0);
  EXPECT_EQ(H0.H0bar, 0.0);
  EXPECT_EQ(H0.H1bar, 0.0);
  EXPECT_EQ(H1.H0bar, 0.0);
  EXPECT_EQ(H1.H1bar, 0.0);
  EXPECT_EQ(D0.H0, 0.0);
  EXPECT_EQ(D0.H1, 0.0);
  EXPECT_EQ(D1.H0, 0.0);
  EXPECT_EQ(D1.H1, 0.0);
  EXPECT_EQ(D0.H0bar, 1.0);
  EXPECT_EQ(D0.H1bar, 0.0);
  EXPECT_EQ(D1.H0bar, 0.0);
  EXPECT_EQ(D1.H1bar, 1.0);
}

TEST(Hermite, LectureMatrixAndItInvertsTheSystemMatrix) {
  // ch. 1 §1.6: the matrix, and "determined by inverting the matrix"
  // [[1,0,0,0], [0,1,0,0], [1,1,1,1], [0,1,2,3]].
  const std::array<std::array<double, 4>, 4> printed = {
      {{{1, 0, 0, 0}}, {{0, 1, 0, 0}}, {{-3, -2, 3, -1}}, {{2, 1, -2, 1}}}};
  EXPECT_EQ(hermite_matrix(), printed);
  const double S[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {1, 1, 1, 1}, {0, 1, 2, 3}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += hermite_matrix()[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] * S[k][j];
      EXPECT_EQ(sum, i == j ? 1.0 : 0.0) << i << "," << j;
    }
}

TEST(Hermite, GeneralSolveOnZeroOneReproducesTheLectureMatrix) {
  // Theorem 3's system for f(0), f'(0), f(1), f'(1) solved with unit data:
  // the coefficients of H0, H0bar, H1, H1bar = the columns of the lecture's matrix.
  for (int col = 0; col < 4; ++col) {
    std::vector<double> e(4, 0.0);
    e[static_cast<std::size_t>(col)] = 1;
    const std::vector<double> c = hermite_coefficients(ScalarNodes{{0, {e[0], e[1]}}, {1, {e[2], e[3]}}});
    ASSERT_EQ(c.size(), 4u);
    for (int row = 0; row < 4; ++row)
      EXPECT_NEAR(c[static_cast<std::size_t>(row)], hermite_matrix()[static_cast<std::size_t>(row)][static_cast<std::size_t>(col)], kExact);
  }
}

TEST(Hermite, SegmentMatchesEndPointsAndTangents) {
  const Vec3 p0{0, 0, 0}, m0{1, 2, 0}, p1{3, 1, 1}, m1{-1, 0, 2};
  EXPECT_EQ(hermite_point(p0, m0, p1, m1, 0.0), p0);
  EXPECT_EQ(hermite_point(p0, m0, p1, m1, 1.0), p1);
  EXPECT_EQ(hermite_derivative(p0, m0, p1, m1, 0.0), m0);
  EXPECT_EQ(hermite_derivative(p0, m0, p1, m1, 1.0), m1);
  EXPECT_EQ(hermite_value(2, -1, 5, 3, 1.0), 5.0);
}

TEST(Hermite, IntervalSegmentEqualsTheGeneralSolveOnThatInterval) {
  // Independent routes: basis with the chain-rule factor h versus Theorem 3's
  // system written at the nodes a and b.
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> u(-3, 3), len(0.2, 4);
  for (int c = 0; c < kRandomCases; ++c) {
    const double a = u(rng), b = a + len(rng);
    const std::vector<Vec3> d = random_points(rng, 4);  // p0, m0, p1, m1
    const std::vector<Vec3> coeff = hermite_coefficients(PointNodes{{a, {d[0], d[1]}}, {b, {d[2], d[3]}}});
    for (int k = 0; k < kSamples; ++k) {
      const double t = a + (b - a) * k / (kSamples - 1);
      // The monomial form is only as good as the terms it sums: sum |c_j| |t|^j.
      double terms = 0;
      for (std::size_t j = 0; j < coeff.size(); ++j) terms += norm(coeff[j]) * std::pow(std::fabs(t), static_cast<int>(j));
      expect_near_vec(hermite_point(d[0], d[1], d[2], d[3], t, a, b), monomial_value(coeff, t), kExact * terms);
    }
  }
  // On [0, 1] both forms are the lecture's segment.
  const Vec3 p0{1, 0, 0}, m0{0, 1, 0}, p1{0, 1, 0}, m1{-1, 0, 0};
  for (int k = 0; k < kSamples; ++k) {
    const double t = static_cast<double>(k) / (kSamples - 1);
    EXPECT_EQ(hermite_point(p0, m0, p1, m1, t, 0, 1), hermite_point(p0, m0, p1, m1, t));
  }
}

TEST(Hermite, GeneralSolveMeetsEveryCondition) {
  // ch. 1 §1.6, Theorem 3: p^(j)(t_i) = f_i^(j) for all given j < n_i.
  std::mt19937 rng(71);
  std::uniform_int_distribution<int> nodes_count(1, 4), conditions(1, 3);
  for (int c = 0; c < kRandomCases; ++c) {
    const std::vector<double> t = spread_nodes(rng, nodes_count(rng) - 1);
    std::vector<HermiteNode<double>> data;
    for (double ti : t) data.push_back({ti, random_values(rng, conditions(rng))});
    const std::vector<double> coeff = hermite_coefficients(data);
    std::size_t m1 = 0;
    for (const auto& node : data) m1 += node.derivatives.size();
    ASSERT_EQ(coeff.size(), m1);  // degree <= m = sum n_i - 1
    for (const auto& node : data)
      for (std::size_t j = 0; j < node.derivatives.size(); ++j) {
        const int jj = static_cast<int>(j);
        EXPECT_NEAR(monomial_derivative(coeff, jj, node.t), node.derivatives[j],
                    kBackward * monomial_derivative_terms(coeff, jj, node.t))
            << "t=" << node.t << " j=" << j;
      }
  }
}

TEST(Hermite, GeneralSolveRecoversAPolynomial) {
  // Data taken from p(t) = 1 - 2t + t^3 - 0.5 t^4 (values and derivatives by
  // hand): 2 conditions at -1, 3 at 0.5, 1 at 2 -> 6 conditions, degree <= 5.
  auto p = [](double t) { return 1 - 2 * t + t * t * t - 0.5 * t * t * t * t; };
  auto dp = [](double t) { return -2 + 3 * t * t - 2 * t * t * t; };
  auto ddp = [](double t) { return 6 * t - 6 * t * t; };
  const std::vector<double> c =
      hermite_coefficients(ScalarNodes{{-1, {p(-1), dp(-1)}}, {0.5, {p(0.5), dp(0.5), ddp(0.5)}}, {2, {p(2)}}});
  const std::vector<double> expected = {1, -2, 0, 1, -0.5, 0};
  ASSERT_EQ(c.size(), expected.size());
  for (std::size_t j = 0; j < c.size(); ++j) EXPECT_NEAR(c[j], expected[j], kExact) << j;
}

// ---- errors name the values ---------------------------------------------------

TEST(InterpolationErrors, EmptyNodes) {
  expect_contains(error_of([] { vandermonde_coefficients({}, std::vector<double>{}); }), "no nodes");
  expect_contains(error_of([] { lagrange_basis_all({}, 0.5); }), "no nodes");
  expect_contains(error_of([] { divided_difference_table({}, std::vector<double>{}); }), "no nodes");
  expect_contains(error_of([] { hermite_coefficients(ScalarNodes{}); }), "no nodes");
  expect_contains(error_of([] { NewtonInterpolant<double>{}(0.5); }), "no nodes yet");
}

TEST(InterpolationErrors, RepeatedNodesNameBoth) {
  expect_contains(error_of([] { lagrange_value({0, 0.5, 1, 0.5}, {1.0, 2.0, 3.0, 4.0}, 0.2); }),
                  "nodes t[1]=0.5 and t[3]=0.5 coincide");
  expect_contains(error_of([] { vandermonde_coefficients({2, 2}, {1.0, 2.0}); }), "t[0]=2 and t[1]=2 coincide");
  expect_contains(error_of([] {
                    NewtonInterpolant<double> p;
                    p.add_node(0.25, 1);
                    p.add_node(0.25, 2);
                  }),
                  "t=0.25 equals node t[0]");
  expect_contains(error_of([] { hermite_coefficients(ScalarNodes{{1, {0.0}}, {1, {2.0}}}); }), "t[0]=1 and t[1]=1 coincide");
}

TEST(InterpolationErrors, NotFiniteValuesAreNamed) {
  expect_contains(error_of([] { lagrange_value({0, NAN}, {1.0, 2.0}, 0.2); }), "t[1]=nan is not finite");
  expect_contains(error_of([] { lagrange_value({0, 1}, {1.0, INFINITY}, 0.2); }), "f[1]=inf is not finite");
  expect_contains(error_of([] { lagrange_value({0, 1}, {1.0, 2.0}, NAN); }), "t=nan is not finite");
  expect_contains(error_of([] { NewtonInterpolant<Vec3>{}.add_node(0, {1, NAN, 0}); }), "value=(1, nan, 0) is not finite");
  expect_contains(error_of([] { hermite_coefficients(ScalarNodes{{0, {1.0, NAN}}}); }), "f0^(1)=nan is not finite");
}

TEST(InterpolationErrors, SizesAndIndices) {
  expect_contains(error_of([] { vandermonde_coefficients({0, 1, 2}, {1.0, 2.0}); }), "3 nodes but 2 values");
  expect_contains(error_of([] { lagrange_basis({0, 1}, 2, 0.5); }), "i=2 is outside 0..1");
  expect_contains(error_of([] { newton_basis({0, 1}, 3, 0.5); }), "i=3 is outside 0..2");
  expect_contains(error_of([] { hermite_coefficients(ScalarNodes{{0, {}}}); }), "node 0 (t=0) has no conditions");
}

TEST(InterpolationErrors, HermiteParameterOutsideTheSegmentSaysWhichEnd) {
  const Vec3 z{};
  expect_contains(error_of([&] { hermite_point(z, z, z, z, 1.5); }), "t=1.5 is outside [0, 1] (above 1)");
  expect_contains(error_of([&] { hermite_point(z, z, z, z, -0.25); }), "t=-0.25 is outside [0, 1] (below 0)");
  expect_contains(error_of([&] { hermite_point(z, z, z, z, 0.5, 2, 1); }), "[a, b] = [2, 1] is empty");
  expect_contains(error_of([&] { hermite_point(z, {NAN, 0, 0}, z, z, 0.5); }), "m0=(nan, 0, 0) is not finite");
  expect_contains(error_of([] { hermite_value(0, 0, 0, 0, NAN); }), "t=nan is not finite");
}

}  // namespace
}  // namespace gllab::spline
