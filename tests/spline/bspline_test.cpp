// tests/spline/bspline_test.cpp — B-spline core (common/spline/bspline.cpp).
//
// Every expected value names its origin: The NURBS Book (Piegl & Tiller, 2nd
// ed.) page, a worked example of the lecture notes, a hand computation shown in
// the comment, or a property checked over many random curves (fixed seeds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline_test_support.h"

namespace gllab::spline {
namespace {

using testing::error_of;
using testing::kRounding;
using testing::kSameCurve;

// ---- tolerances (named, never loosened to pass) -----------------------------

// kRounding and kSameCurve: spline_test_support.h.
/// Fourth-order central differences (Richardson: error O(h^4)) with h = 1e-3
/// of the knot span, relative to the largest derivative of that order seen on
/// the curve. (The plain 2-point difference has O(h^2) truncation error that
/// reached 1e-6 on rational curves; measured, it is not the code.)
constexpr double kFiniteDifference = 1e-6;
/// A jump in a derivative at a knot counts as zero below this (relative to the
/// derivative's size); a real jump (cases B–D) is larger than kJump.
constexpr double kContinuity = 1e-12;
constexpr double kJump = 1e-3;

constexpr int kSamples = 101;       // parameters per curve (>= 101, so a curve is seen at every 1 %)
constexpr int kRandomCurves = 300;  // curves per property test

// ---- helpers ------------------------------------------------------------------

double dist(Vec3 a, Vec3 b) { return norm(a - b); }

/// The size of a curve's control polygon, for relative tolerances.
double scale_of(const BsplineCurve& c) {
  double s = 1.0;
  for (const Vec3& q : c.P) s = std::max({s, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  return s;
}

/// kSamples evenly spaced parameters over the domain, both ends included.
std::vector<double> samples(const BsplineCurve& c, int count = kSamples) { return uniform_params(c, count); }

/// Random curves with fixed seeds: degree 1..5, 2..9 segments, random knot
/// spacing and interior multiplicities up to max_mult, clamped or not,
/// polynomial or rational (weights in [0.2, 5]).
struct CurveMaker {
  std::mt19937 rng;
  explicit CurveMaker(unsigned seed) : rng(seed) {}
  double real(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }

  BsplineCurve make(bool rational, bool clamped, int max_mult_over_p = 0) {
    for (;;) {
      BsplineCurve c;
      c.p = integer(1, 5);
      const int n = c.p + integer(0, 8);
      const int m = n + c.p + 1;
      const int max_mult = std::min(c.p + max_mult_over_p, c.p + 1);
      double v = real(-3, 3);
      if (clamped) {
        c.U.assign(c.p + 1, v);
        while (static_cast<int>(c.U.size()) < m + 1 - (c.p + 1)) {
          v += real(0.1, 2.0);
          const int mult = std::min(integer(1, max_mult), m + 1 - (c.p + 1) - static_cast<int>(c.U.size()));
          c.U.insert(c.U.end(), mult, v);
        }
        v += real(0.1, 2.0);
        c.U.insert(c.U.end(), c.p + 1, v);
      } else {
        while (static_cast<int>(c.U.size()) < m + 1) {
          const int mult = std::min(integer(1, max_mult), m + 1 - static_cast<int>(c.U.size()));
          c.U.insert(c.U.end(), mult, v);
          v += real(0.1, 2.0);
        }
      }
      if (!(c.U[c.p] < c.U[n + 1])) continue;  // empty domain: draw again
      for (int i = 0; i <= n; ++i) c.P.push_back({real(-10, 10), real(-10, 10), real(-10, 10)});
      if (rational)
        for (int i = 0; i <= n; ++i) c.w.push_back(real(0.2, 5.0));
      validate(c);
      return c;
    }
  }
  BsplineCurve any() { return make(integer(0, 1) == 1, integer(0, 1) == 1); }
};

/// Expects two curves to agree at the given parameters, relative to the size
/// of the first one's control polygon.
void expect_same_curve(const BsplineCurve& a, const BsplineCurve& b, const std::vector<double>& us,
                       const std::string& what) {
  const double tol = kSameCurve * scale_of(a);
  for (double u : us) {
    const Vec3 pa = curve_point(a, u);
    const Vec3 pb = curve_point(b, u);
    ASSERT_LE(dist(pa, pb), tol) << what << " at u=" << u << ": " << num(pa) << " vs " << num(pb);
  }
}

/// de Casteljau on a Bézier curve over [a, b]: an evaluator independent of the
/// B-spline code (notes "Higher Order Surfaces", "Rendering Bezier curves").
Vec3 de_casteljau(const BezierCurve& bz, double u) {
  const double t = (u - bz.a) / (bz.b - bz.a);
  std::vector<Vec3> q = bz.P;
  for (std::size_t r = 1; r < q.size(); ++r)
    for (std::size_t i = 0; i + r < q.size(); ++i) q[i] = (1 - t) * q[i] + t * q[i + 1];
  return q[0];
}

/// f'(u) ~ (8 (f(u+h) - f(u-h)) - (f(u+2h) - f(u-2h))) / (12 h), error O(h^4).
template <class F>
Vec3 richardson(F f, double u, double h) {
  return (8.0 * (f(u + h) - f(u - h)) - (f(u + 2 * h) - f(u - 2 * h))) / (12 * h);
}

// The NURBS Book p. 68 knot vector: p = 2, m = 10, n = 7.
const std::vector<double> kBookU = {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
constexpr int kBookP = 2;
constexpr int kBookN = 7;

// ---- find_span ---------------------------------------------------------------------

TEST(FindSpan, NurbsBookP68ReturnsSpan4) {
  // The NURBS Book p. 68: u = 5/2 lies in [U[4], U[5]) = [2, 3).
  EXPECT_EQ(find_span(kBookN, kBookP, 2.5, kBookU), 4);
}

TEST(FindSpan, DomainEndsUseFirstAndLastSpan) {
  // A2.1's special case: u == U[n+1] = 5 returns n = 7; u == U[p] = 0 returns p.
  EXPECT_EQ(find_span(kBookN, kBookP, 5.0, kBookU), 7);
  EXPECT_EQ(find_span(kBookN, kBookP, 0.0, kBookU), 2);
  // At an interior knot the span starts there: u = 4 (double knot U[6..7]) -> 7.
  EXPECT_EQ(find_span(kBookN, kBookP, 4.0, kBookU), 7);
}

TEST(FindSpan, LeftSpanEndsAtTheKnot) {
  // U[i] < u <= U[i+1]: u = 2 -> i = 3 ([1, 2]); u = 4 -> i = 5 ([3, 4]).
  EXPECT_EQ(find_span_left(kBookN, kBookP, 2.0, kBookU), 3);
  EXPECT_EQ(find_span_left(kBookN, kBookP, 4.0, kBookU), 5);
  EXPECT_EQ(find_span_left(kBookN, kBookP, 2.5, kBookU), 4);
  EXPECT_EQ(find_span_left(kBookN, kBookP, 0.0, kBookU), 2);  // nothing lies left of U[p]
}

TEST(FindSpan, RepeatedEndKnotOfUnclampedCurveUsesLastNonEmptySpan) {
  // p = 2, n = 4, U = {0,1,2,3,4,4,5,6}: domain [U[2], U[5]] = [2, 4] and
  // U[4] == U[5], so the span [U[4], U[5]) is empty; u = 4 is evaluated in [3, 4).
  const std::vector<double> U = {0, 1, 2, 3, 4, 4, 5, 6};
  EXPECT_EQ(find_span(4, 2, 4.0, U), 3);
}

TEST(FindSpan, OutsideTheDomainThrowsNamingUAndDomain) {
  EXPECT_ERROR_HAS(find_span(kBookN, kBookP, 5.5, kBookU), "u=5.5 is outside the domain [0, 5]");
  EXPECT_ERROR_HAS(find_span(kBookN, kBookP, -0.25, kBookU), "u=-0.25 is outside the domain [0, 5]");
  EXPECT_ERROR_HAS(find_span(kBookN, kBookP, std::nan(""), kBookU), "u=nan is not finite");
  EXPECT_ERROR_HAS(find_span(kBookN, kBookP, 1.0, std::vector<double>(10, 0.0)), "has 10 knots, needs n + p + 2 = 11");
}

// ---- basis functions -----------------------------------------------------------------

TEST(BasisFuns, NurbsBookP69AtFiveHalves) {
  // The NURBS Book p. 68–69: N_{2,2}(5/2) = 1/8, N_{3,2} = 6/8, N_{4,2} = 1/8.
  const std::vector<double> N = basis_funs(4, 2.5, kBookP, kBookU);
  ASSERT_EQ(N.size(), 3u);
  EXPECT_NEAR(N[0], 1.0 / 8, kRounding);
  EXPECT_NEAR(N[1], 6.0 / 8, kRounding);
  EXPECT_NEAR(N[2], 1.0 / 8, kRounding);
}

TEST(BasisFuns, OneBasisFunAndCoxDeBoorAgreeOnTheBookExample) {
  // The same three values one function at a time (A2.4) and by the recursion.
  const double expected[3] = {1.0 / 8, 6.0 / 8, 1.0 / 8};
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(one_basis_fun(2 + j, 2.5, kBookP, kBookU), expected[j], kRounding);
    EXPECT_NEAR(cox_de_boor(2 + j, 2.5, kBookP, kBookU), expected[j], kRounding);
  }
  // Outside the support [U[i], U[i+p+1]) the function is 0: N_{0,2}(5/2).
  EXPECT_EQ(one_basis_fun(0, 2.5, kBookP, kBookU), 0.0);
  EXPECT_EQ(cox_de_boor(0, 2.5, kBookP, kBookU), 0.0);
}

TEST(DersBasisFuns, BookKnotVectorAtFiveHalves) {
  // By hand from the Cox–de Boor recursion on [2, 3) of the p. 68 knot vector:
  // N_{2,2} = (3-u)^2/2, N_{3,2} = (u-1)(3-u)/2 + (4-u)(u-2)/2, N_{4,2} = (u-2)^2/2,
  // so at u = 5/2: N' = (-1/2, 0, 1/2) and N'' = (1, -2, 1).
  const auto ders = ders_basis_funs(4, 2.5, kBookP, 3, kBookU);
  ASSERT_EQ(ders.size(), 4u);
  const double d0[3] = {1.0 / 8, 6.0 / 8, 1.0 / 8};
  const double d1[3] = {-0.5, 0.0, 0.5};
  const double d2[3] = {1.0, -2.0, 1.0};
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(ders[0][j], d0[j], kRounding);
    EXPECT_NEAR(ders[1][j], d1[j], kRounding);
    EXPECT_NEAR(ders[2][j], d2[j], kRounding);
    EXPECT_EQ(ders[3][j], 0.0);  // order 3 > p vanishes
  }
}

TEST(BasisFuns, PartitionOfUnityAndNonNegativityOnRandomKnotVectors) {
  // Ch. 1 §1.6 comment 6 / notes "Higher Order Surfaces", "convex hull property": sum N = 1, N >= 0,
  // at uniform parameters, at every knot in the domain and at both ends.
  CurveMaker make(101);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(false, trial % 2 == 0, 1);
    std::vector<double> us = samples(c);
    for (double k : c.U)
      if (k >= c.U[c.p] && k <= c.U[c.n() + 1]) us.push_back(k);
    for (double u : us) {
      const int span = find_span(c.n(), c.p, u, c.U);
      const std::vector<double> N = basis_funs(span, u, c.p, c.U);
      double sum = 0;
      for (double v : N) {
        EXPECT_GE(v, 0.0);
        sum += v;
      }
      EXPECT_NEAR(sum, 1.0, 8 * kRounding) << "u=" << u;
      const std::vector<double> all = all_basis_funs(u, c.p, c.U);
      double all_sum = 0;
      for (double v : all) all_sum += v;
      EXPECT_NEAR(all_sum, 1.0, 8 * kRounding) << "u=" << u;
    }
  }
}

TEST(BasisFuns, AllFourFormsAgreeOnRandomKnotVectors) {
  // basis_funs (A2.2), one_basis_fun (A2.4), cox_de_boor (the lecture's recursion)
  // and all_basis_funs (the table) compute the same functions.
  CurveMaker make(102);
  for (int trial = 0; trial < kRandomCurves / 3; ++trial) {
    const BsplineCurve c = make.make(false, trial % 2 == 0, 1);
    std::vector<double> us = samples(c, 23);
    for (double k : c.U)
      if (k >= c.U[c.p] && k <= c.U[c.n() + 1]) us.push_back(k);
    for (double u : us) {
      const int span = find_span(c.n(), c.p, u, c.U);
      const std::vector<double> N = basis_funs(span, u, c.p, c.U);
      const std::vector<double> all = all_basis_funs(u, c.p, c.U);
      for (int i = 0; i <= c.n(); ++i) {
        const double expected = (i >= span - c.p && i <= span) ? N[i - (span - c.p)] : 0.0;
        EXPECT_NEAR(one_basis_fun(i, u, c.p, c.U), expected, 16 * kRounding) << "i=" << i << " u=" << u;
        EXPECT_NEAR(cox_de_boor(i, u, c.p, c.U), expected, 16 * kRounding) << "i=" << i << " u=" << u;
        EXPECT_NEAR(all[i], expected, 16 * kRounding) << "i=" << i << " u=" << u;
      }
    }
  }
}

TEST(DersBasisFuns, DerivativesSumToZeroAndMatchTheValues) {
  // d^k/du^k of sum N = d^k/du^k 1 = 0 for k >= 1; row 0 equals basis_funs.
  CurveMaker make(103);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(false, trial % 2 == 0);
    for (double u : samples(c, 31)) {
      const int span = find_span(c.n(), c.p, u, c.U);
      const auto ders = ders_basis_funs(span, u, c.p, c.p + 1, c.U);
      const std::vector<double> N = basis_funs(span, u, c.p, c.U);
      for (int j = 0; j <= c.p; ++j) EXPECT_NEAR(ders[0][j], N[j], 8 * kRounding);
      for (int k = 1; k <= c.p + 1; ++k) {
        double sum = 0;
        double size = 1;
        for (double v : ders[k]) {
          sum += v;
          size = std::max(size, std::abs(v));
        }
        EXPECT_LE(std::abs(sum), 64 * kRounding * size) << "k=" << k << " u=" << u;
      }
    }
  }
}

// ---- evaluation -------------------------------------------------------------------------

TEST(CurvePoint, ClampedCurveInterpolatesItsEndPoints) {
  // Notes "Higher Order Surfaces" "Nonperiodic knot vectors": Q(t_{k-1}) = p_0, Q(t_{n+1}) = p_n,
  // checked at u == U[p] and u == U[n+1] exactly.
  CurveMaker make(201);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, true);
    const double tol = kSameCurve * scale_of(c);
    EXPECT_LE(dist(curve_point(c, c.U[c.p]), c.P.front()), tol);
    EXPECT_LE(dist(curve_point(c, c.U[c.n() + 1]), c.P.back()), tol);
  }
}

TEST(CurvePoint, StrongConvexHull) {
  // Strong convex hull (The NURBS Book ch. 3; ch. 1 §1.6 comment 6): C(u) lies in the hull
  // of P[span-p..span]; checked through its bounding box (a consequence).
  CurveMaker make(202);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    const double tol = kSameCurve * scale_of(c);
    for (double u : samples(c)) {
      const int span = find_span(c.n(), c.p, u, c.U);
      Vec3 lo = c.P[span], hi = c.P[span];
      for (int i = span - c.p; i <= span; ++i) {
        lo = {std::min(lo.x, c.P[i].x), std::min(lo.y, c.P[i].y), std::min(lo.z, c.P[i].z)};
        hi = {std::max(hi.x, c.P[i].x), std::max(hi.y, c.P[i].y), std::max(hi.z, c.P[i].z)};
      }
      const Vec3 q = curve_point(c, u);
      EXPECT_TRUE(q.x >= lo.x - tol && q.y >= lo.y - tol && q.z >= lo.z - tol && q.x <= hi.x + tol &&
                  q.y <= hi.y + tol && q.z <= hi.z + tol)
          << "u=" << u << " C=" << num(q);
    }
  }
}

TEST(CurvePoint, AffineInvariance) {
  // Notes "Higher Order Surfaces" "Affine invariance": Phi(sum P_i N_i) = sum Phi(P_i) N_i, for a
  // random matrix and translation (rational curves too: weights unchanged).
  CurveMaker make(203);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    double A[3][3];
    for (auto& row : A)
      for (double& e : row) e = make.real(-2, 2);
    const Vec3 t{make.real(-5, 5), make.real(-5, 5), make.real(-5, 5)};
    auto phi = [&](Vec3 q) {
      return Vec3{A[0][0] * q.x + A[0][1] * q.y + A[0][2] * q.z, A[1][0] * q.x + A[1][1] * q.y + A[1][2] * q.z,
                  A[2][0] * q.x + A[2][1] * q.y + A[2][2] * q.z} +
             t;
    };
    BsplineCurve mapped = c;
    for (Vec3& q : mapped.P) q = phi(q);
    const double tol = kSameCurve * scale_of(mapped);
    for (double u : samples(c)) EXPECT_LE(dist(curve_point(mapped, u), phi(curve_point(c, u))), tol) << "u=" << u;
  }
}

TEST(CurvePoint, ReversalSymmetry) {
  // Property: with P reversed and U'[i] = a + b - U[m-i] on the domain [a, b],
  // the reversed curve R satisfies R(a + b - u) = C(u).
  CurveMaker make(204);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    const BsplineCurve r = reversed(c);
    const ParamInterval d = domain(c);
    const ParamInterval dr = domain(r);
    EXPECT_EQ(dr.a, d.a);
    EXPECT_EQ(dr.b, d.b);
    const double tol = kSameCurve * scale_of(c);
    for (double u : samples(c)) {
      const double ur = std::min(std::max(d.a + d.b - u, d.a), d.b);
      EXPECT_LE(dist(curve_point(r, ur), curve_point(c, u)), tol) << "u=" << u;
    }
  }
}

TEST(CurvePoint, PolynomialCurveWithUnitWeightsIsTheSame) {
  // Ch. 1 §1.6 NURBS comment 1: "For w_i = 1 we get a regular B-spline".
  CurveMaker make(205);
  for (int trial = 0; trial < kRandomCurves / 3; ++trial) {
    const BsplineCurve c = make.make(false, trial % 2 == 0);
    BsplineCurve r = c;
    r.w.assign(c.P.size(), 1.0);
    expect_same_curve(c, r, samples(c), "unit weights");
  }
}

TEST(DeBoor, ConstructionEndsAtTheCurvePoint) {
  CurveMaker make(206);
  for (int trial = 0; trial < kRandomCurves / 3; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    for (double u : samples(c, 17)) {
      const DeBoorConstruction d = de_boor(c, u);
      ASSERT_EQ(static_cast<int>(d.levels.size()), c.p + 1);
      ASSERT_EQ(static_cast<int>(d.alphas.size()), c.p);
      for (int r = 0; r <= c.p; ++r) ASSERT_EQ(static_cast<int>(d.levels[r].size()), c.p + 1 - r);
      for (int j = 0; j <= c.p; ++j) EXPECT_EQ(d.levels[0][j], c.P[d.span - c.p + j]);
      for (const auto& row : d.alphas)
        for (double a : row) {
          EXPECT_GE(a, 0.0);
          EXPECT_LE(a, 1.0);
        }
      EXPECT_LE(dist(d.point, curve_point(c, u)), kSameCurve * scale_of(c)) << "u=" << u;
    }
  }
}

TEST(CurveDerivs, MatchFiniteDifferences) {
  // C' and C'' (A3.2, A4.2 for NURBS) against differences of C and C' with
  // h = 1e-3 of the knot span, inside each span (where C is smooth).
  CurveMaker make(207);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    std::vector<double> us;
    for (int k = c.p; k <= c.n(); ++k)
      if (c.U[k] < c.U[k + 1])
        for (double f : {0.13, 0.5, 0.91}) us.push_back(c.U[k] + f * (c.U[k + 1] - c.U[k]));
    double size1 = 1, size2 = 1;
    for (double u : us) {
      const auto d = curve_derivs(c, u, 2);
      size1 = std::max(size1, norm(d[1]));
      size2 = std::max(size2, norm(d[2]));
    }
    for (double u : us) {
      const int span = find_span(c.n(), c.p, u, c.U);
      const double h = 1e-3 * (c.U[span + 1] - c.U[span]);
      const auto d = curve_derivs(c, u, 2);
      auto C = [&](double s) { return curve_point(c, s); };
      auto dC = [&](double s) { return curve_derivs(c, s, 1)[1]; };
      const Vec3 fd1 = richardson(C, u, h);
      const Vec3 fd2 = richardson(dC, u, h);
      EXPECT_LE(dist(d[0], curve_point(c, u)), kSameCurve * scale_of(c));
      EXPECT_LE(dist(d[1], fd1), kFiniteDifference * size1) << "C' at u=" << u << " p=" << c.p;
      if (c.p >= 2 || c.rational()) {
        EXPECT_LE(dist(d[2], fd2), kFiniteDifference * size2) << "C'' at u=" << u << " p=" << c.p;
      }
    }
  }
}

TEST(CurveDerivs, OrdersAbovePVanishForPolynomialCurves) {
  CurveMaker make(208);
  for (int trial = 0; trial < kRandomCurves / 3; ++trial) {
    const BsplineCurve c = make.make(false, true);
    const auto d = curve_derivs(c, samples(c)[40], c.p + 2);
    EXPECT_EQ(d[c.p + 1], Vec3{});
    EXPECT_EQ(d[c.p + 2], Vec3{});
  }
}

// ---- batched evaluation -----------------------------------------------------------------

TEST(CurvePoints, BatchedEvaluatorEqualsPerPointEvaluator) {
  // Sorted parameters with repeats, every knot in the domain and both ends.
  CurveMaker make(301);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0, trial % 5 == 0 ? 1 : 0);
    std::vector<double> us = samples(c, 257);
    for (double k : c.U)
      if (k >= c.U[c.p] && k <= c.U[c.n() + 1]) us.push_back(k);
    us.push_back(us[100]);
    std::sort(us.begin(), us.end());
    std::vector<Vec3> pts, pts2, ders;
    curve_points(c, us, pts);
    curve_points(c, us, pts2, ders);
    ASSERT_EQ(pts.size(), us.size());
    ASSERT_EQ(ders.size(), us.size());
    double size1 = 1;
    for (double u : us) size1 = std::max(size1, norm(curve_derivs(c, u, 1)[1]));
    for (std::size_t k = 0; k < us.size(); ++k) {
      const auto d = curve_derivs(c, us[k], 1);
      EXPECT_LE(dist(pts[k], curve_point(c, us[k])), kSameCurve * scale_of(c)) << "u=" << us[k];
      EXPECT_LE(dist(pts2[k], d[0]), kSameCurve * scale_of(c)) << "u=" << us[k];
      EXPECT_LE(dist(ders[k], d[1]), kSameCurve * size1) << "C' at u=" << us[k];
    }
  }
}

TEST(CurvePoints, RejectsUnsortedAndOutOfDomainParameters) {
  const BsplineCurve c = clamped_curve({{0, 0, 0}, {1, 2, 0}, {3, 1, 0}, {4, 0, 0}}, 3);
  std::vector<Vec3> out;
  EXPECT_ERROR_HAS(curve_points(c, {0.0, 0.5, 0.25}, out), "u[2]=0.25 < u[1]=0.5");
  EXPECT_ERROR_HAS(curve_points(c, {0.0, 0.5, 1.5}, out), "u=1.5 is outside the domain [0, 1]");
  EXPECT_ERROR_HAS(curve_points(c, {0.0, std::nan("")}, out), "u[1]=nan is not finite");
  curve_points(c, {}, out);
  EXPECT_TRUE(out.empty());
}

// ---- knot insertion -------------------------------------------------------------------------

TEST(KnotInsert, LectureExampleInsertsHalfIntoCubic) {
  // Ch. 1 §1.6 "Knot insertion, Example": U = (0,0,0,0,.2,.4,.6,.8,1,1,1,1),
  // t = 0.5 in [u_5, u_6): a_5 = 1/6, a_4 = 1/2, a_3 = 5/6; the new polygon is
  // d0, d1, d2, q3, q4, q5, d5, d6, d7 with q_i = (1 - a_i) d_{i-1} + a_i d_i
  // and the knots (0,0,0,0,.2,.4,.5,.6,.8,1,1,1,1).
  BsplineCurve c;
  c.p = 3;
  c.U = {0, 0, 0, 0, .2, .4, .6, .8, 1, 1, 1, 1};
  for (int i = 0; i < 8; ++i) c.P.push_back({double(i), double((i * 7) % 5), double(i * i) / 10});
  const KnotInsertStep step = knot_insert_step(c, 0.5);
  EXPECT_EQ(step.k, 5);
  EXPECT_EQ(step.first, 3);
  ASSERT_EQ(step.a.size(), 3u);
  EXPECT_NEAR(step.a[0], 5.0 / 6, kRounding);  // a_3
  EXPECT_NEAR(step.a[1], 1.0 / 2, kRounding);  // a_4
  EXPECT_NEAR(step.a[2], 1.0 / 6, kRounding);  // a_5
  const std::vector<double> expected_U = {0, 0, 0, 0, .2, .4, .5, .6, .8, 1, 1, 1, 1};
  EXPECT_EQ(step.curve.U, expected_U);
  ASSERT_EQ(step.curve.P.size(), 9u);
  const auto& d = c.P;
  auto q = [&](int i, double a) { return (1 - a) * d[i - 1] + a * d[i]; };
  const std::vector<Vec3> expected_P = {d[0], d[1], d[2], q(3, 5.0 / 6), q(4, 0.5), q(5, 1.0 / 6), d[5], d[6], d[7]};
  for (std::size_t i = 0; i < expected_P.size(); ++i)
    EXPECT_LE(dist(step.curve.P[i], expected_P[i]), 4 * kRounding * scale_of(c)) << "point " << i;
  // A5.1 gives the same polygon, and the curve does not change.
  const BsplineCurve book = knot_insert(c, 0.5);
  EXPECT_EQ(book.U, expected_U);
  for (std::size_t i = 0; i < expected_P.size(); ++i)
    EXPECT_LE(dist(book.P[i], expected_P[i]), 4 * kRounding * scale_of(c)) << "point " << i;
  expect_same_curve(c, step.curve, samples(c), "lecture insertion");
}

// Ch. 1 §1.6 "Knot insertion", the example, prints q_5 = (1 - 1/6 d_4) + 1/6 d_5 (and so q_4,
// q_3): the bracket closes after the weight, q_5 = (1 - 1/6) d_4 + 1/6 d_5. With d_i = (i, i^2, 0),
// by hand: q_3 = 1/6 d_2 + 5/6 d_3 = (17/6, 49/6), q_4 = (d_3 + d_4)/2 = (7/2, 25/2),
// q_5 = 5/6 d_4 + 1/6 d_5 = (25/6, 35/2).
TEST(KnotInsert, LectureExampleWeightsMultiplyThePointsNotesSlip) {
  BsplineCurve c;
  c.p = 3;
  c.U = {0, 0, 0, 0, .2, .4, .6, .8, 1, 1, 1, 1};
  for (int i = 0; i < 8; ++i) c.P.push_back({double(i), double(i * i), 0});
  const std::vector<Vec3> P = knot_insert_step(c, 0.5).curve.P;
  ASSERT_EQ(P.size(), 9u);
  const Vec3 q3{17.0 / 6, 49.0 / 6, 0}, q4{3.5, 12.5, 0}, q5{25.0 / 6, 17.5, 0};
  EXPECT_LE(dist(P[3], q3), 4 * kRounding * scale_of(c));
  EXPECT_LE(dist(P[4], q4), 4 * kRounding * scale_of(c));
  EXPECT_LE(dist(P[5], q5), 4 * kRounding * scale_of(c));
}

// Notes "Higher Order Surfaces", "Knot Insertion": for t_j <= t' < t_{j+1} they print
// p'_i = (1 - a_i) p_i + a_i p_{i+1}, which with their own a_i = 1 for small i would drop p_1
// (p'_1 = p_2). Boehm's rule is p'_i = a_i p_i + (1 - a_i) p_{i-1}. The same page also counts k
// as the degree in a_i, while the notes' knot vector t_0..t_{n+k} makes k the order
// ("#knots = #control points + order"); with k the order, a_i = 1 for i <= j - k + 1,
// (t' - t_i)/(t_{i+k-1} - t_i) for j - k + 2 <= i <= j, and 0 for i >= j + 1. That rule,
// written out here, must give the core's polygon, for a cubic and a quadratic on uneven knots.
TEST(KnotInsert, HigherOrderSurfacesRuleTakesPiMinus1NotesSlip) {
  struct Case {
    int p;
    std::vector<double> U;
    double t;
  };
  for (const Case& k_case : {Case{3, {0, 0, 0, 0, 1, 3, 4, 7, 7, 7, 7}, 2.0},
                             Case{2, {0, 0, 0, 1, 2.5, 4, 6, 6, 6}, 3.0}}) {
    BsplineCurve c;
    c.p = k_case.p;
    c.U = k_case.U;
    const int n = static_cast<int>(c.U.size()) - c.p - 2;
    for (int i = 0; i <= n; ++i) c.P.push_back({double(i), double((i * 5) % 7), double(i * i) / 4});
    const int k = c.p + 1;  // the order, as the notes count
    int j = 0;
    while (!(c.U[j] <= k_case.t && k_case.t < c.U[j + 1])) ++j;
    std::vector<Vec3> expected(n + 2);
    expected[0] = c.P[0];
    expected[n + 1] = c.P[n];
    for (int i = 1; i <= n; ++i) {
      const double a = i <= j - k + 1 ? 1.0
                       : i >= j + 1   ? 0.0
                                      : (k_case.t - c.U[i]) / (c.U[i + k - 1] - c.U[i]);
      expected[i] = a * c.P[i] + (1 - a) * c.P[i - 1];
    }
    const std::vector<Vec3> P = knot_insert_step(c, k_case.t).curve.P;
    ASSERT_EQ(P.size(), expected.size()) << "degree " << c.p;
    for (std::size_t i = 0; i < P.size(); ++i)
      EXPECT_LE(dist(P[i], expected[i]), 4 * kRounding * scale_of(c))
          << "degree " << c.p << ", point " << i;
  }
}

TEST(KnotInsert, LeavesRandomCurvesUnchanged) {
  // Insert a random parameter r times (up to multiplicity p), and an existing
  // knot once; the curve is the same at 101 parameters (ch. 1 §1.6 "without
  // changing the shape of the curve").
  CurveMaker make(401);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    const ParamInterval d = domain(c);
    const double u = make.real(d.a, d.b);
    const int r = make.integer(1, c.p);
    const BsplineCurve ins = knot_insert(c, u, r);
    EXPECT_EQ(ins.P.size(), c.P.size() + r);
    EXPECT_EQ(knot_multiplicity(ins.U, u), r);
    expect_same_curve(c, ins, samples(c), "knot_insert r=" + std::to_string(r));
    const KnotInsertStep step = knot_insert_step(c, u);
    expect_same_curve(c, step.curve, samples(c), "knot_insert_step");
    for (double k : c.U) {
      if (k > d.a && k < d.b && knot_multiplicity(c.U, k) < c.p) {
        expect_same_curve(c, knot_insert(c, k), samples(c), "insert existing knot");
        expect_same_curve(c, knot_insert_step(c, k).curve, samples(c), "lecture step at existing knot");
        break;
      }
    }
  }
}

TEST(KnotInsert, AtTheEndsOfAnUnclampedDomain) {
  // Edge: u == U[p] and u == U[n+1] of a uniform (unclamped) cubic.
  BsplineCurve c;
  c.p = 3;
  c.P = {{0, 0, 0}, {1, 3, 0}, {2, -1, 1}, {4, 2, 0}, {5, 0, 2}, {6, 1, 0}};
  c.U = uniform_knots(c.n(), c.p);
  const ParamInterval d = domain(c);
  for (double u : {d.a, d.b}) {
    expect_same_curve(c, knot_insert(c, u, 1), samples(c), "insert at domain end");
    expect_same_curve(c, knot_insert(c, u, 2), samples(c), "insert at domain end to multiplicity p");
    EXPECT_ERROR_HAS(knot_insert(c, u, 3), "onto multiplicity 1 gives 4 > p=3");
    expect_same_curve(c, knot_insert_step(c, u).curve, samples(c), "lecture step at domain end");
  }
}

TEST(KnotInsert, BeyondMultiplicityPThrows) {
  const BsplineCurve c = clamped_curve({{0, 0, 0}, {1, 2, 0}, {3, 1, 0}, {4, 0, 0}, {5, 1, 0}}, 3);
  // The clamped end knot 0 already has multiplicity p + 1 = 4.
  EXPECT_ERROR_HAS(knot_insert(c, 0.0), "inserting u=0 1 time(s) onto multiplicity 4 gives 5 > p=3");
  EXPECT_ERROR_HAS(knot_insert(c, 0.25, 4), "onto multiplicity 0 gives 4 > p=3");
  EXPECT_ERROR_HAS(knot_insert(c, 1.5), "u=1.5 is outside the domain [0, 1]");
}

TEST(KnotRefine, LeavesRandomCurvesUnchanged) {
  // A5.4 with a random sorted set of new knots, including existing knot
  // values and (for unclamped curves) the domain ends.
  CurveMaker make(402);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    const ParamInterval d = domain(c);
    std::vector<double> X;
    const int count = make.integer(1, 12);
    for (int j = 0; j < count; ++j) X.push_back(make.real(d.a, d.b));
    for (std::size_t i = 0; i < c.U.size(); ++i) {
      const double k = c.U[i];
      const bool first_copy = i == 0 || c.U[i - 1] != k;
      if (first_copy && k >= d.a && k <= d.b && knot_multiplicity(c.U, k) < c.p && make.integer(0, 2) == 0)
        X.push_back(k);
    }
    std::sort(X.begin(), X.end());
    const BsplineCurve fine = knot_refine(c, X);
    EXPECT_EQ(fine.P.size(), c.P.size() + X.size());
    std::vector<double> merged = c.U;
    merged.insert(merged.end(), X.begin(), X.end());
    std::sort(merged.begin(), merged.end());
    EXPECT_EQ(fine.U, merged);
    expect_same_curve(c, fine, samples(c), "knot_refine");
  }
}

TEST(KnotRefine, ResultEqualsRepeatedInsertion) {
  CurveMaker make(403);
  for (int trial = 0; trial < kRandomCurves / 3; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, true);
    const ParamInterval d = domain(c);
    std::vector<double> X = {make.real(d.a, d.b), make.real(d.a, d.b), make.real(d.a, d.b)};
    std::sort(X.begin(), X.end());
    BsplineCurve one = c;
    for (double x : X) one = knot_insert(one, x);
    const BsplineCurve all = knot_refine(c, X);
    ASSERT_EQ(one.P.size(), all.P.size());
    for (std::size_t i = 0; i < one.P.size(); ++i)
      EXPECT_LE(dist(one.P[i], all.P[i]), kSameCurve * scale_of(c)) << "point " << i;
  }
}

// ---- decomposition, splitting, elevation ----------------------------------------------

TEST(BezierDecompose, PiecesReproduceTheCurve) {
  // Ch. 1 §1.6 "Displaying B-spline curves": every knot at multiplicity
  // p turns the polygon into Bézier points. Each piece, evaluated by an
  // independent de Casteljau, equals the B-spline on its interval.
  CurveMaker make(501);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(false, trial % 2 == 0, trial % 4 == 0 ? 1 : 0);
    const ParamInterval d = domain(c);
    const std::vector<BezierCurve> pieces = bezier_decompose(c);
    int spans = 0;
    for (int k = c.p; k <= c.n(); ++k) spans += c.U[k] < c.U[k + 1] ? 1 : 0;
    ASSERT_EQ(static_cast<int>(pieces.size()), spans);
    EXPECT_EQ(pieces.front().a, d.a);
    EXPECT_EQ(pieces.back().b, d.b);
    for (std::size_t j = 0; j < pieces.size(); ++j) {
      ASSERT_EQ(static_cast<int>(pieces[j].P.size()), c.p + 1);
      if (j > 0) {
        EXPECT_EQ(pieces[j].a, pieces[j - 1].b);
      }
    }
    const double tol = kSameCurve * scale_of(c);
    for (double u : samples(c)) {
      // The piece whose interval holds u (the last one at the end).
      std::size_t j = 0;
      while (j + 1 < pieces.size() && u >= pieces[j].b) ++j;
      EXPECT_LE(dist(de_casteljau(pieces[j], u), curve_point(c, u)), tol) << "u=" << u;
    }
  }
}

TEST(BezierDecompose, RationalCurvesUseBezierSegments) {
  CurveMaker make(502);
  for (int trial = 0; trial < kRandomCurves / 3; ++trial) {
    const BsplineCurve c = make.make(true, trial % 2 == 0);
    EXPECT_ERROR_HAS(bezier_decompose(c), "rational");
    const std::vector<BsplineCurve> pieces = bezier_segments(c);
    const double tol = kSameCurve * scale_of(c);
    for (double u : samples(c)) {
      std::size_t j = 0;
      while (j + 1 < pieces.size() && u >= pieces[j].U.back()) ++j;
      EXPECT_LE(dist(curve_point(pieces[j], u), curve_point(c, u)), tol) << "u=" << u;
    }
  }
}

TEST(Split, TwoHalvesReproduceTheCurve) {
  CurveMaker make(503);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    const ParamInterval d = domain(c);
    // A random parameter, or an existing interior knot every third time.
    double u = make.real(d.a + 0.01 * (d.b - d.a), d.b - 0.01 * (d.b - d.a));
    if (trial % 3 == 1)
      for (double k : c.U)
        if (k > d.a && k < d.b) u = k;
    const auto [left, right] = split(c, u);
    EXPECT_EQ(domain(left).a, d.a);
    EXPECT_EQ(domain(left).b, u);
    EXPECT_EQ(domain(right).a, u);
    EXPECT_EQ(domain(right).b, d.b);
    const double tol = kSameCurve * scale_of(c);
    for (double s : samples(c)) {
      const Vec3 q = curve_point(c, s);
      if (s <= u) {
        EXPECT_LE(dist(curve_point(left, s), q), tol) << "left at " << s;
      }
      if (s >= u) {
        EXPECT_LE(dist(curve_point(right, s), q), tol) << "right at " << s;
      }
    }
    // The halves are clamped at u: the left one ends, the right one starts, at C(u).
    EXPECT_LE(dist(left.P.back(), curve_point(c, u)), tol);
    EXPECT_LE(dist(right.P.front(), curve_point(c, u)), tol);
  }
}

TEST(Split, AtTheDomainEndThrows) {
  const BsplineCurve c = clamped_curve({{0, 0, 0}, {1, 2, 0}, {3, 1, 0}, {4, 0, 0}}, 2);
  EXPECT_ERROR_HAS(split(c, 1.0), "split: u=1 must lie strictly inside the domain (0, 1)");
  EXPECT_ERROR_HAS(split(c, 0.0), "split: u=0 must lie strictly inside the domain (0, 1)");
}

TEST(DegreeElevate, LeavesRandomCurvesUnchanged) {
  // A5.9 by t = 1..3 on clamped and unclamped, polynomial and rational curves.
  CurveMaker make(504);
  for (int trial = 0; trial < kRandomCurves; ++trial) {
    const BsplineCurve c = make.make(trial % 2 == 0, trial % 3 == 0);
    const int t = make.integer(1, 3);
    const BsplineCurve e = degree_elevate(c, t);
    EXPECT_EQ(e.p, c.p + t);
    // Each interior knot gains t copies (C^{p-s} stays C^{p-s} at degree p + t).
    for (double k : e.U)
      if (k > domain(e).a && k < domain(e).b) {
        EXPECT_EQ(knot_multiplicity(e.U, k), knot_multiplicity(c.U, k) + t) << "knot " << k;
      }
    expect_same_curve(c, e, samples(c), "degree_elevate t=" + std::to_string(t));
  }
}

TEST(DegreeElevate, CurveWithABreakKeepsTheBreak) {
  // Notes "B-Spline Polynomials" case D (an interior knot of multiplicity p + 1 = 4) survives
  // elevation: the curve still jumps there, and is unchanged elsewhere.
  BsplineCurve c;
  c.p = 3;
  c.U = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2};
  c.P = {{0, 0, 0}, {1, 2, 0}, {2, 2, 0}, {3, 0, 0}, {4, 1, 0}, {5, 3, 0}, {6, 1, 0}, {7, 0, 0}};
  const BsplineCurve e = degree_elevate(c, 2);
  EXPECT_EQ(e.p, 5);
  EXPECT_EQ(knot_multiplicity(e.U, 1.0), 6);
  expect_same_curve(c, e, samples(c), "elevate with break");
  EXPECT_LE(dist(curve_point(e, 1.0, Side::Left), c.P[3]), kSameCurve * scale_of(c));
  EXPECT_LE(dist(curve_point(e, 1.0, Side::Right), c.P[4]), kSameCurve * scale_of(c));
}

TEST(DegreeElevate, LinePolygonBecomesAQuadraticWithMidpoints) {
  // By hand: elevating the polyline (0,0)-(2,0)-(2,2), U = {0,0,1,2,2}, to
  // degree 2 gives points (0,0), (1,0), (2,0), (2,1), (2,2) on U = {0,0,0,1,1,2,2,2}.
  BsplineCurve c;
  c.p = 1;
  c.U = {0, 0, 1, 2, 2};
  c.P = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}};
  const BsplineCurve e = degree_elevate(c, 1);
  const std::vector<double> U = {0, 0, 0, 1, 1, 2, 2, 2};
  EXPECT_EQ(e.U, U);
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}};
  ASSERT_EQ(e.P.size(), P.size());
  for (std::size_t i = 0; i < P.size(); ++i) EXPECT_LE(dist(e.P[i], P[i]), kRounding * 4) << "point " << i;
}

// ---- knot vectors and closed curves -----------------------------------------------------

TEST(KnotVectors, ClampedUniformMatchesLectureFormula) {
  // Notes "Higher Order Surfaces" "Uniform nonperiodic knot vectors" with order k = p + 1:
  // t_i = 0 (i < k), i - k + 1 (k <= i <= n), n - k + 2 (n < i <= n + k),
  // here divided by n - k + 2 so the domain is [0, 1]. (The lecture's ranges
  // read "k..n-1" and "n..n+k-1", one short; those give n + k knots, not n + k + 1.)
  for (int p = 1; p <= 5; ++p)
    for (int n = p; n <= p + 6; ++n) {
      const int k = p + 1;
      const std::vector<double> U = clamped_uniform_knots(n, p);
      ASSERT_EQ(static_cast<int>(U.size()), n + k + 1);
      for (int i = 0; i <= n + k; ++i) {
        const double printed = i < k ? 0.0 : (i <= n ? i - k + 1 : n - k + 2);
        EXPECT_NEAR(U[i], printed / (n - k + 2), kRounding) << "p=" << p << " n=" << n << " i=" << i;
      }
      const std::vector<double> V = uniform_knots(n, p);
      for (int i = 0; i <= n + k; ++i) EXPECT_EQ(V[i], i);  // notes "Higher Order Surfaces", "knots = 0, 1, 2, ..."
    }
  EXPECT_ERROR_HAS(clamped_uniform_knots(2, 3), "needs 1 <= p <= n, got p=3, n=2");
}

TEST(PeriodicCurve, ClosesWithContinuityPMinus1) {
  // Notes "B-Spline Polynomials" "Closed cubic B-splines: make last 3 control points coincide with
  // 1st 3", for p = 1..5: C and its derivatives up to p - 1 agree at both ends.
  CurveMaker make(601);
  for (int trial = 0; trial < 60; ++trial) {
    const int p = 1 + trial % 5;
    std::vector<Vec3> pts;
    const int count = make.integer(2, 9);
    for (int i = 0; i < count; ++i) pts.push_back({make.real(-5, 5), make.real(-5, 5), 0});
    const BsplineCurve c = periodic_curve(pts, p, 2);
    EXPECT_EQ(static_cast<int>(c.P.size()), count + p);
    const ParamInterval d = domain(c);
    EXPECT_EQ(d.a, p);
    EXPECT_EQ(d.b, p + count);
    const auto start = curve_derivs(c, d.a, p - 1);
    const auto end = curve_derivs(c, d.b, p - 1);
    for (int k = 0; k < p; ++k) {
      double size = 1;
      for (const Vec3& q : start) size = std::max(size, norm(q));
      EXPECT_LE(dist(start[k], end[k]), kSameCurve * size * 16) << "order " << k << " p=" << p;
    }
  }
}

TEST(PeriodicCurve, LectureClosedCubicWithM6) {
  // Notes "B-Spline Polynomials" example m = 6: P0..P6 with P4 = P0, P5 = P1, P6 = P2 ("0 <--> m-2,
  // 1 <--> m-1, 2 <--> m"), from 4 distinct points.
  const std::vector<Vec3> pts = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const BsplineCurve c = periodic_curve(pts, 3, 2);
  ASSERT_EQ(c.P.size(), 7u);
  EXPECT_EQ(c.P[4], c.P[0]);
  EXPECT_EQ(c.P[5], c.P[1]);
  EXPECT_EQ(c.P[6], c.P[2]);
  // Start point by the d of the notes "B-Spline Polynomials": (P0 + 4 P1 + P2) / 6 = ((0 + 8 + 2) / 6, (0 + 0 + 2) / 6) = (5/3, 1/3).
  const Vec3 start = curve_point(c, domain(c).a);
  EXPECT_NEAR(start.x, 5.0 / 3, kRounding * 4);
  EXPECT_NEAR(start.y, 1.0 / 3, kRounding * 4);
  EXPECT_LE(dist(start, curve_point(c, domain(c).b)), kRounding * 8);
}

// ---- uniform cubic matrix form (notes "B-Spline Polynomials", "Higher Order Surfaces") ---

TEST(UniformCubic, MatrixIsTheLectureMatrix) {
  // Notes "Higher Order Surfaces" "Matrix form": 1/6 [[-1,3,-3,1],[3,-6,3,0],[-3,0,3,0],[1,4,1,0]].
  const double printed[4][4] = {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 0, 3, 0}, {1, 4, 1, 0}};
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col) EXPECT_EQ(kUniformCubicMatrix[r][col], printed[r][col] / 6.0);
}

TEST(UniformCubic, BasisEqualsTimesMatrixAndLectureBlendingFunctions) {
  // Notes "Higher Order Surfaces": [B0 B1 B2 B3] = [t^3 t^2 t 1] M, with B0 = (1-t)^3/6,
  // B1 = (3t^3 - 6t^2 + 4)/6, B2 = (-3t^3 + 3t^2 + 3t + 1)/6, B3 = t^3/6.
  for (int k = 0; k <= 100; ++k) {
    const double t = k / 100.0;
    const double T[4] = {t * t * t, t * t, t, 1};
    const auto B = uniform_cubic_basis(t);
    double sum = 0;
    for (int j = 0; j < 4; ++j) {
      double tm = 0;
      for (int r = 0; r < 4; ++r) tm += T[r] * kUniformCubicMatrix[r][j];
      EXPECT_NEAR(B[j], tm, 4 * kRounding) << "t=" << t << " j=" << j;
      EXPECT_GE(B[j], 0.0);
      sum += B[j];
    }
    EXPECT_NEAR(sum, 1.0, 4 * kRounding);
    EXPECT_NEAR(B[0], std::pow(1 - t, 3) / 6, 4 * kRounding);
    EXPECT_NEAR(B[3], t * t * t / 6, 4 * kRounding);
  }
  // the ends of the notes "B-Spline Polynomials": B(0) = (1/6, 4/6, 1/6, 0), B(1) = (0, 1/6, 4/6, 1/6).
  const auto B0 = uniform_cubic_basis(0), B1 = uniform_cubic_basis(1);
  const double e0[4] = {1.0 / 6, 4.0 / 6, 1.0 / 6, 0}, e1[4] = {0, 1.0 / 6, 4.0 / 6, 1.0 / 6};
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(B0[j], e0[j], kRounding);
    EXPECT_NEAR(B1[j], e1[j], kRounding);
  }
}

TEST(UniformCubic, LectureCoefficientsAndContinuityConditions) {
  // Notes "B-Spline Polynomials" "Solution": a = (-P0 + 3P1 - 3P2 + P3)/6, b = (3P0 - 6P1 + 3P2)/6,
  // c = (-3P0 + 3P2)/6, d = (P0 + 4P1 + P2)/6, and conditions 1 and 3:
  // Q'(0) = (P2 - P0)/2, Q''(0) = 2b = P2 - 2P1 + P0.
  const Vec3 P0{0, 0, 1}, P1{1, 3, 0}, P2{4, 3, 2}, P3{5, 0, -1};
  const auto [a, b, c, d] = uniform_cubic_coefficients(P0, P1, P2, P3);
  EXPECT_LE(dist(a, (-1.0 * P0 + 3.0 * P1 - 3.0 * P2 + P3) / 6.0), 8 * kRounding);
  EXPECT_LE(dist(b, (3.0 * P0 - 6.0 * P1 + 3.0 * P2) / 6.0), 8 * kRounding);
  EXPECT_LE(dist(c, (-3.0 * P0 + 3.0 * P2) / 6.0), 8 * kRounding);
  EXPECT_LE(dist(d, (P0 + 4.0 * P1 + P2) / 6.0), 8 * kRounding);
  EXPECT_LE(dist(c, (P2 - P0) / 2.0), 8 * kRounding);
  EXPECT_LE(dist(2.0 * b, P2 - 2.0 * P1 + P0), 8 * kRounding);
}

// Notes "B-Spline Polynomials", "Could also be written in terms of blending functions", print
// B_{i-1,4} = 1/6 (-3t^3 + 3t^2 - 3t + 1). The weight of P_{i-1} is the third column of their
// own matrix read against [t^3 t^2 t 1]: (-3t^3 + 3t^2 + 3t + 1)/6. At t = 1 it is 4/6 (the
// point under the knot pulls 4 times as hard as its neighbours); with -3t it would be -1/3.
TEST(UniformCubic, BlendingFunctionOfPiMinus1HasPlus3tNotesSlip) {
  for (int s = 0; s <= 100; ++s) {
    const double t = s / 100.0;
    const double expected = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6;
    EXPECT_NEAR(uniform_cubic_basis(t)[2], expected, 4 * kRounding) << "t=" << t;
  }
  EXPECT_NEAR(uniform_cubic_basis(1)[2], 4.0 / 6, kRounding);
}

// Notes "Higher Order Surfaces", "B Splines": C^d at the joint is sum_k p_{i+k} B_k^(d)(1) =
// sum_k p_{i+k+1} B_k^(d)(0). p_i appears only on the left, so its coefficient B_0^(d)(1) is 0
// for d = 0, 1, 2, as the notes write for d = 0; for C1 and C2 they print B_0'(1) = 1 and
// B_0''(1) = 1. By hand, B_0 = (1 - t)^3/6, B_0' = -(1 - t)^2/2, B_0'' = 1 - t: 0 at t = 1,
// -1/2 and 1 at t = 0. Derivatives by A2.3 on the uniform knots 0..7, span [3, 4], where
// N_{j,3}(3 + t) = B_j(t).
TEST(UniformCubic, B0HasZeroSlopeAndBendAtOneNotesSlip) {
  const std::vector<double> U = {0, 1, 2, 3, 4, 5, 6, 7};
  const auto at0 = ders_basis_funs(3, 3.0, 3, 2, U), at1 = ders_basis_funs(3, 4.0, 3, 2, U);
  for (int d = 0; d <= 2; ++d) {
    EXPECT_NEAR(at1[d][0], 0, 8 * kRounding) << "B_0^(" << d << ")(1)";
    EXPECT_NEAR(at0[d][3], 0, 8 * kRounding) << "B_3^(" << d << ")(0)";
    for (int k = 1; k <= 3; ++k)
      EXPECT_NEAR(at1[d][k], at0[d][k - 1], 8 * kRounding) << "B_" << k << "^(" << d << ")(1)";
  }
  EXPECT_NEAR(at0[1][0], -0.5, 8 * kRounding);
  EXPECT_NEAR(at0[2][0], 1.0, 8 * kRounding);
}

TEST(UniformCubic, MatrixFormEqualsDeBoorOnUniformKnots) {
  // Segment i of the matrix form is the B-spline on U = 0, 1, 2, ... at
  // u = 3 + i + t (notes "Higher Order Surfaces", "U = u + i", shifted to the domain start U[3]).
  CurveMaker make(701);
  std::vector<Vec3> P;
  for (int i = 0; i < 9; ++i) P.push_back({make.real(-5, 5), make.real(-5, 5), make.real(-5, 5)});
  BsplineCurve c;
  c.p = 3;
  c.P = P;
  c.U = uniform_knots(c.n(), 3);
  for (int i = 0; i + 3 < static_cast<int>(P.size()); ++i)
    for (int k = 0; k <= 100; ++k) {
      const double t = k / 100.0;
      EXPECT_LE(dist(uniform_cubic_point(P, i, t), curve_point(c, 3 + i + t)), kSameCurve * scale_of(c))
          << "segment " << i << " t=" << t;
    }
  EXPECT_ERROR_HAS(uniform_cubic_point(P, 6, 0.5), "segment i=6 needs P[i..i+3], but there are 9 points");
  EXPECT_ERROR_HAS(uniform_cubic_point(P, 0, 1.5), "t=1.5 is outside [0, 1]");
}

// ---- notes "B-Spline Polynomials" cases A–D: continuity drops with multiplicity ----------------------------

/// Cubic on 8 points, the multiple knot at t_4 = 4 with multiplicity mult.
BsplineCurve lecture_case(int mult) {
  BsplineCurve c;
  c.p = 3;
  c.P = {{0, 0, 0}, {1, 2, 0}, {2, 3, 0}, {3, 1, 0}, {5, 2, 0}, {6, 0, 0}, {7, 3, 0}, {8, 1, 0}};
  // t_0..t_3 = 0..3, then mult copies of 4, then 5, 6, ... up to 12 knots.
  for (int i = 0; i < 4; ++i) c.U.push_back(i);
  for (int i = 0; i < mult; ++i) c.U.push_back(4);
  for (double v = 5; c.U.size() < 12; ++v) c.U.push_back(v);
  validate(c);
  return c;
}

/// |jump| of the k-th derivative at u, relative to its size.
std::vector<double> jumps_at(const BsplineCurve& c, double u) {
  const auto left = curve_derivs(c, u, 3, Side::Left);
  const auto right = curve_derivs(c, u, 3, Side::Right);
  std::vector<double> j;
  for (int k = 0; k <= 3; ++k)
    j.push_back(dist(left[k], right[k]) / std::max({1.0, norm(left[k]), norm(right[k])}));
  return j;
}

TEST(Continuity, LectureCaseASimpleKnotIsC2) {
  // Notes "B-Spline Polynomials" case A, knots (0,1,2,3,4,5,...): C, C', C'' continuous at t_4;
  // the third derivative (piecewise constant) jumps.
  const auto j = jumps_at(lecture_case(1), 4.0);
  EXPECT_LE(j[0], kContinuity);
  EXPECT_LE(j[1], kContinuity);
  EXPECT_LE(j[2], kContinuity);
  EXPECT_GT(j[3], kJump);
}

TEST(Continuity, LectureCaseBDoubleKnotIsC1AndOnLineP2P3) {
  // Notes "B-Spline Polynomials" case B, t_4 = t_5: C and C' continuous, C'' jumps; the
  // degenerate segment Q_4 "must lie on line connecting P2 & P3".
  const BsplineCurve c = lecture_case(2);
  const auto j = jumps_at(c, 4.0);
  EXPECT_LE(j[0], kContinuity);
  EXPECT_LE(j[1], kContinuity);
  EXPECT_GT(j[2], kJump);
  const Vec3 q = curve_point(c, 4.0);
  const Vec3 along = c.P[3] - c.P[2];
  EXPECT_LE(std::abs(cross(along, q - c.P[2]).z), kSameCurve * scale_of(c) * norm(along));
  const double s = dot(q - c.P[2], along) / dot(along, along);
  EXPECT_GE(s, 0.0);
  EXPECT_LE(s, 1.0);
}

TEST(Continuity, LectureCaseCTripleKnotIsC0AndInterpolatesP3) {
  // Notes "B-Spline Polynomials" case C, t_4 = t_5 = t_6: only C continuous; the curve passes
  // through P3 ("interpolates it").
  const BsplineCurve c = lecture_case(3);
  const auto j = jumps_at(c, 4.0);
  EXPECT_LE(j[0], kContinuity);
  EXPECT_GT(j[1], kJump);
  EXPECT_LE(dist(curve_point(c, 4.0), c.P[3]), kSameCurve * scale_of(c));
}

TEST(Continuity, LectureCaseDQuadrupleKnotBreaksTheCurve) {
  // Notes "B-Spline Polynomials" case D, t_4 = ... = t_7: "Q3 and Q7 share no control points"; the
  // curve breaks at t_4: Q3 (P0..P3) ends at P3, Q7 (P4..P7) starts at P4.
  const BsplineCurve c = lecture_case(4);
  const auto j = jumps_at(c, 4.0);
  EXPECT_GT(j[0], kJump);
  EXPECT_LE(dist(curve_point(c, 4.0, Side::Left), c.P[3]), kSameCurve * scale_of(c));
  EXPECT_LE(dist(curve_point(c, 4.0, Side::Right), c.P[4]), kSameCurve * scale_of(c));
  EXPECT_LE(dist(curve_point(c, 4.0), c.P[4]), kSameCurve * scale_of(c));  // the default is the right side
}

// ---- errors name their values ------------------------------------------------------------

BsplineCurve good_quadratic() {
  BsplineCurve c;
  c.p = 2;
  c.U = {0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1};
  for (int i = 0; i < 7; ++i) c.P.push_back({double(i), double(i % 2), 0});
  return c;
}

TEST(Validate, DecreasingKnotsNameBothValues) {
  BsplineCurve c = good_quadratic();
  c.U = {0, 0, 0, 0.2, 0.6, 0.4, 0.8, 1, 1, 1};
  EXPECT_EQ(error_of([&] { validate(c); }), "knot vector: U[5]=0.4 < U[4]=0.6 (must be non-decreasing)");
}

TEST(Validate, KnotCountNamesPointsAndDegree) {
  BsplineCurve c = good_quadratic();
  c.U.pop_back();
  EXPECT_EQ(error_of([&] { validate(c); }), "knot vector has 9 knots, needs n + p + 2 = 10 (7 points, degree 2)");
}

TEST(Validate, DegreeOutOfRange) {
  BsplineCurve c = good_quadratic();
  c.p = 0;
  EXPECT_ERROR_HAS(validate(c), "degree p=0 must be >= 1");
  c.p = 7;
  EXPECT_ERROR_HAS(validate(c), "degree p=7 needs at least p + 1 = 8 control points, has 7");
}

TEST(Validate, OneControlPointIsNotACurve) {
  BsplineCurve c;
  c.p = 1;
  c.P = {{1, 2, 3}};
  c.U = {0, 0, 1};
  EXPECT_ERROR_HAS(validate(c), "degree p=1 needs at least p + 1 = 2 control points, has 1");
}

TEST(Validate, EmptyInput) {
  BsplineCurve c;
  EXPECT_ERROR_HAS(validate(c), "no control points (empty input)");
  EXPECT_ERROR_HAS(curve_point(c, 0.0), "no control points (empty input)");
}

TEST(Validate, WeightZeroOrNegativeNamesIndexAndValue) {
  BsplineCurve c = good_quadratic();
  c.w.assign(7, 1.0);
  c.w[2] = 0.0;
  EXPECT_ERROR_HAS(validate(c), "weights: w[2]=0 must be > 0");
  c.w[2] = -1.5;
  EXPECT_ERROR_HAS(validate(c), "weights: w[2]=-1.5 must be > 0");
  c.w.assign(6, 1.0);
  EXPECT_ERROR_HAS(validate(c), "6 weights for 7 control points");
}

TEST(Validate, NanOrInfNamesArrayAndIndex) {
  BsplineCurve c = good_quadratic();
  c.P[3].y = std::nan("");
  EXPECT_ERROR_HAS(validate(c), "control points: P[3]=(3, nan, 0) is not finite");
  c = good_quadratic();
  c.U[4] = std::numeric_limits<double>::infinity();
  EXPECT_ERROR_HAS(validate(c), "knot vector: U[4]=inf is not finite");
  c = good_quadratic();
  c.w.assign(7, 1.0);
  c.w[6] = std::nan("");
  EXPECT_ERROR_HAS(validate(c), "weights: w[6]=nan is not finite");
  EXPECT_ERROR_HAS(curve_point(good_quadratic(), std::nan("")), "u=nan is not finite");
}

TEST(Validate, DimensionAndMultiplicity) {
  BsplineCurve c = good_quadratic();
  c.dimension = 4;
  EXPECT_ERROR_HAS(validate(c), "dimension=4 must be 2 or 3");
  c = good_quadratic();
  c.dimension = 2;
  validate(c);
  c.P[1].z = 0.5;
  EXPECT_ERROR_HAS(validate(c), "P[1]=(1, 1, 0.5) has z != 0 in a 2D curve");
  c = good_quadratic();
  c.U = {0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1};
  EXPECT_ERROR_HAS(validate(c), "knot 0.5 has multiplicity 4 (U[3..6]), more than p + 1 = 3");
}

TEST(Validate, EmptyDomain) {
  BsplineCurve c;
  c.p = 1;
  c.P = {{0, 0, 0}, {1, 0, 0}};
  c.U = {0, 1, 1, 2};  // domain [U[1], U[2]] = [1, 1]
  EXPECT_ERROR_HAS(validate(c), "the domain [U[1], U[2]] = [1, 1] is empty");
}

TEST(CurvePoint, DomainEndsEvaluateAndOutsideThrows) {
  // u == U[p] and u == U[n+1] are inside; just outside is not.
  const BsplineCurve c = good_quadratic();
  EXPECT_NO_THROW(curve_point(c, 0.0));
  EXPECT_NO_THROW(curve_point(c, 1.0));
  EXPECT_ERROR_HAS(curve_point(c, 1.0000001), "u=1.0000001 is outside the domain [0, 1]");
  EXPECT_ERROR_HAS(curve_derivs(c, -1.0, 1), "u=-1 is outside the domain [0, 1]");
  EXPECT_ERROR_HAS(curve_derivs(c, 0.5, -1), "derivative order d=-1 must be >= 0");
  EXPECT_ERROR_HAS(de_boor(c, 2.0), "u=2 is outside the domain [0, 1]");
}

// ---- Greville abscissae ---------------------------------------------------------

TEST(GrevilleAbscissae, KnotAveragesOfTheNurbsBookP68Knots) {
  // U = {0,0,0,1,2,3,4,4,5,5,5}, p = 2 (The NURBS Book, p. 68): xi_i is the
  // average of U[i+1], U[i+2], worked out by hand: 0, 1/2, 3/2, 5/2, 7/2, 4, 9/2, 5.
  const std::vector<double> xi = greville_abscissae(2, {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5});
  const std::vector<double> expected = {0, 0.5, 1.5, 2.5, 3.5, 4, 4.5, 5};
  EXPECT_EQ(xi, expected);
}

TEST(GrevilleAbscissae, AsControlValuesReproduceTheParameter) {
  // Property (linear precision): the curve with control values xi_i is u
  // itself on the domain, for clamped and unclamped knots and any multiplicity.
  CurveMaker maker(4242);
  for (int k = 0; k < kRandomCurves; ++k) {
    BsplineCurve c = maker.make(false, k % 2 == 0, 1);
    const std::vector<double> xi = greville_abscissae(c.p, c.U);
    ASSERT_EQ(xi.size(), c.P.size());
    for (std::size_t i = 0; i < xi.size(); ++i) c.P[i] = {xi[i], 0, 0};
    // Rounding of the sums, relative to the largest knot magnitude.
    const double tol = kRounding * std::max({1.0, std::abs(c.U.front()), std::abs(c.U.back())});
    for (double u : samples(c)) ASSERT_NEAR(curve_point(c, u).x, u, tol) << "curve " << k << " at u=" << u;
  }
}

TEST(GrevilleAbscissae, DegreeBelowOneOrTooFewKnotsThrow) {
  EXPECT_ERROR_HAS(greville_abscissae(0, {0, 1}), "greville_abscissae: p=0 must be >= 1");
  EXPECT_ERROR_HAS(greville_abscissae(3, {0, 0, 1, 1}),
                   "greville_abscissae: 4 knots for degree 3 leave no control point (at least p + 2 = 5 needed)");
}

// ---- from_bezier_segments: the inverse of bezier_decompose -------------------------

// Ch. 1 §1.6: a B-spline with every knot of multiplicity p has the Bézier
// points as control points. Round trip: decompose random polynomial curves,
// join the pieces, decompose again: the same pieces, and the same curve.
TEST(FromBezierSegments, RoundTripWithBezierDecompose) {
  CurveMaker make(61);
  for (int c = 0; c < kRandomCurves; ++c) {
    const BsplineCurve curve = make.make(false, make.integer(0, 1) == 1);
    const std::vector<BezierCurve> pieces = bezier_decompose(curve);
    const BsplineCurve joined = from_bezier_segments(pieces);
    EXPECT_EQ(joined.p, curve.p);
    EXPECT_EQ(joined.P.size(), pieces.size() * curve.p + 1);
    const ParamInterval dom = domain(curve);
    EXPECT_EQ(domain(joined).a, dom.a);
    EXPECT_EQ(domain(joined).b, dom.b);
    expect_same_curve(curve, joined, samples(curve), "joined pieces");
    const std::vector<BezierCurve> again = bezier_decompose(joined);
    ASSERT_EQ(again.size(), pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i)
      for (std::size_t j = 0; j < pieces[i].P.size(); ++j) EXPECT_EQ(again[i].P[j], pieces[i].P[j]) << i << "," << j;
  }
}

TEST(FromBezierSegments, KnotsAndPointsOfTwoCubics) {
  BezierCurve s0, s1;
  s0.P = {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}};
  s0.a = 0, s0.b = 2, s0.dimension = 2;
  s1.P = {{3, 0, 0}, {4, -1, 0}, {5, -1, 0}, {6, 0, 0}};
  s1.a = 2, s1.b = 3, s1.dimension = 2;
  const BsplineCurve c = from_bezier_segments({s0, s1});
  EXPECT_EQ(c.U, (std::vector<double>{0, 0, 0, 0, 2, 2, 2, 3, 3, 3, 3}));
  ASSERT_EQ(c.P.size(), 7u);
  EXPECT_EQ(c.P[3], (Vec3{3, 0, 0}));
  EXPECT_EQ(c.dimension, 2);
}

TEST(FromBezierSegments, ErrorsNameTheSegment) {
  BezierCurve s0, s1;
  s0.P = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
  s1.P = {{2, 0, 0}, {3, 1, 0}, {4, 0, 0}};
  s1.a = 1, s1.b = 2;
  EXPECT_ERROR_HAS(from_bezier_segments({}), "no segments");
  BezierCurve gap = s1;
  gap.a = 1.5;
  EXPECT_ERROR_HAS(from_bezier_segments({s0, gap}), "segment[1] starts at t=1.5, segment[0] ends at t=1");
  BezierCurve moved = s1;
  moved.P[0] = {2, 0.5, 0};
  EXPECT_ERROR_HAS(from_bezier_segments({s0, moved}), "segment[1] starts at (2, 0.5, 0), segment[0] ends at (2, 0, 0)");
  BezierCurve cubic = s1;
  cubic.P.push_back({5, 0, 0});
  EXPECT_ERROR_HAS(from_bezier_segments({s0, cubic}), "segment[1] has degree 3, segment[0] degree 2");
  BezierCurve point = s0;
  point.P = {{0, 0, 0}};
  EXPECT_ERROR_HAS(from_bezier_segments({point}), "segment[0] has degree 0");
}

// ---- CurveEvaluator: checked once, the same values ---------------------------------

// The evaluator runs the same algorithms as curve_point and curve_derivs (A3.1,
// A3.2, A4.1, A4.2) without re-checking the curve: the values are identical.
TEST(CurveEvaluator, GivesExactlyWhatTheCheckedCallsGive) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> coord(-2, 2), weight(0.5, 2), unit(0, 1);
  for (bool rational : {false, true}) {
    BsplineCurve c = clamped_curve({{0, 0, 0}, {1, 2, 1}, {2, -1, 0}, {3, 1, 2}, {4, 0, 0}, {5, 2, 1}}, 3);
    if (rational)
      for (std::size_t i = 0; i < c.P.size(); ++i) c.w.push_back(weight(rng));
    const CurveEvaluator e(c);
    for (int k = 0; k < 200; ++k) {
      const double u = k == 0 ? 0.0 : k == 1 ? 1.0 : unit(rng);
      EXPECT_EQ(e.point(u), curve_point(c, u)) << "u = " << u;
      EXPECT_EQ(e.derivs(u, 3), curve_derivs(c, u, 3)) << "u = " << u;
    }
  }
}

TEST(CurveEvaluator, ChecksTheCurveOnceAndEveryParameter) {
  BsplineCurve bad = clamped_curve({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, 2);
  bad.U[3] = -1;  // decreasing
  EXPECT_THROW(CurveEvaluator{bad}, SplineError);
  const CurveEvaluator e(clamped_curve({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, 2));
  EXPECT_ERROR_HAS(e.point(1.5), "u=1.5");
  EXPECT_ERROR_HAS(e.derivs(std::nan(""), 1), "u=nan");
  EXPECT_ERROR_HAS(e.derivs(0.5, -1), "d=-1");
}

TEST(CurveLimits, ControlPointsHaveALimit) {
  BsplineCurve c;
  c.p = 1;
  c.P.assign(kMaxControlPoints + 1, Vec3{});
  c.U = clamped_uniform_knots(static_cast<int>(c.P.size()) - 1, 1);
  EXPECT_ERROR_HAS(validate(c), "1000001 control points, more than the limit of 1000000");
}

}  // namespace
}  // namespace gllab::spline
