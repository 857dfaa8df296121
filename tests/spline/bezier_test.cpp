// tests/spline/bezier_test.cpp — common/spline/bezier.{h,cpp}.
//
// Expected values come from the worked examples of ch. 1 §1.6 (de Casteljau
// at t = 0.6, Bézier interpolation), the formulas printed in ch. 1 and the notes "Geometric Modeling" and "Higher Order Surfaces"
// (Bernstein cubics, the Bézier matrix, end-point derivatives, midpoint
// subdivision, the parabola b = (0,1,0), (1,1,0), (0,2,0) worked by hand; variation
// diminishing against 10^4 random lines with exact crossing counts), or from properties checked over many random curves (fixed
// seeds): partition of unity, convex hull, endpoint interpolation, affine
// invariance, symmetry, subdivision and degree elevation leave the curve
// unchanged, monomial round trip.
#include "spline_test_support.h"
#include "spline/bezier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/interpolation.h"
#include "spline/quadrature.h"

namespace gllab::spline {
namespace {

// ---- tolerances ----------------------------------------------------------------
// Relative to the size of the data: max(1, max |P_i|), or the size of the terms
// a formula sums where a test says so.
constexpr double kExact = 1e-12;  // "the same number" up to round-off
// The lecture solves its interpolation example from a 2x2 system whose
// coefficients it rounded to two decimals. Solving that printed system exactly
// already moves b2.x by 0.095 from the exact solution (the system amplifies a
// 0.005 rounding about 20 times), so the lecture's printed b1, b2 can only be
// expected within 0.1. The exact solution is checked at kExact separately.
constexpr double kLectureTwoDecimalSystem = 0.1;

// Round-off allowances for the lecture's small examples: kExact times the size of
// the numbers involved (the lecture cubic's coordinates reach 11, its derivatives
// |X'''| = 51; the interpolation example's points reach 6.8).
constexpr double kLecturePointTol = kExact * 11;
constexpr double kLectureDerivativeTol = kExact * 100;

constexpr int kRandomCases = 200;  // random curves per property test
constexpr int kSamples = 101;      // parameters per curve comparison
constexpr int kMaxRandomDegree = 12;

// ---- helpers -----------------------------------------------------------------------

using testing::error_of;
using testing::expect_contains;
using testing::expect_near_vec;

double scale_of(const std::vector<Vec3>& P) {
  double s = 1;
  for (const Vec3& p : P) s = std::max({s, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  return s;
}

Vec3 random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-5, 5);
  return {u(rng), u(rng), u(rng)};
}

/// A random curve of degree (case_index / 2) mod (max_degree + 1): cases 2k
/// and 2k + 1 have the same degree, the even one on [0, 1], the odd one on a
/// random [a, b] with |a| <= 2 and 0.5 <= b - a <= 3.
BezierCurve random_curve(std::mt19937& rng, int case_index, int max_degree = kMaxRandomDegree) {
  BezierCurve c;
  const int n = (case_index / 2) % (max_degree + 1);
  for (int i = 0; i <= n; ++i) c.P.push_back(random_point(rng));
  if (case_index % 2 == 1) {
    std::uniform_real_distribution<double> start(-2, 2), length(0.5, 3);
    c.a = start(rng);
    c.b = c.a + length(rng);
  }
  return c;
}

/// The k-th parameter of kSamples evenly spaced ones over [a, b], ends exact.
double sample(double a, double b, int k) {
  if (k == kSamples - 1) return b;
  return a + (b - a) * k / (kSamples - 1);
}

double binomial(int n, int k) {
  double r = 1;
  for (int j = 1; j <= k; ++j) r = r * (n - k + j) / j;
  return r;
}

/// The lecture's example curve: control polygon (0,0), (2,4.5), (8.5,6.5), (11,2)
/// (ch. 1 §1.6, "Example (de Casteljau algorithm)").
BezierCurve lecture_cubic(double a = 0, double b = 1) {
  BezierCurve c;
  c.P = {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}};
  c.a = a;
  c.b = b;
  c.dimension = 2;
  return c;
}

// ---- de Casteljau: the lecture's worked example -------------------------------------

TEST(DeCasteljau, LectureExampleSchemeAtPoint6) {
  // ch. 1 §1.6, "Example (de Casteljau algorithm)", t = 0.6 (splitting
  // ratio 0.4 : 0.6). Level 1 and 2 are printed exactly; the lecture prints the
  // point rounded to two decimals as (6.63, 4.54). Exactly it is
  // 0.4 (4.02, 4.5) + 0.6 (8.36, 4.56) = (6.624, 4.536) = (828/125, 567/125):
  // 4.536 rounds to 4.54, but 6.624 rounds to 6.62 (the lecture's 6.63 is a slip).
  const DeCasteljau d = de_casteljau(lecture_cubic(), 0.6);
  ASSERT_EQ(d.levels.size(), 4u);
  const double tol = kLecturePointTol;
  const std::vector<std::vector<Vec3>> printed = {
      {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}},
      {{1.2, 2.7, 0}, {5.9, 5.7, 0}, {10, 3.8, 0}},
      {{4.02, 4.5, 0}, {8.36, 4.56, 0}},
      {{828.0 / 125, 567.0 / 125, 0}}};
  for (std::size_t j = 0; j < printed.size(); ++j) {
    ASSERT_EQ(d.levels[j].size(), printed[j].size()) << j;
    for (std::size_t i = 0; i < printed[j].size(); ++i) expect_near_vec(d.levels[j][i], printed[j][i], tol);
  }
  expect_near_vec(d.point, {6.624, 4.536, 0}, tol);
  EXPECT_EQ(d.point, d.levels[3][0]);
  EXPECT_EQ(d.s, 0.6);
  expect_near_vec(bezier_point(lecture_cubic(), 0.6), {6.624, 4.536, 0}, tol);
}

TEST(DeCasteljau, LectureExampleDerivativesAtPoint6) {
  // ch. 1 §1.6, "Example (continued)": X'(0.6) = 3 (b_3^2 - b_2^2) = (13.02, 0.18),
  // X''(0.6) = 6 (b_3^1 - 2 b_2^1 + b_1^1) = (-3.6, -29.4), both exact in the lecture.
  // X''' of a cubic is constant: 6 (b3 - 3 b2 + 3 b1 - b0) = (-51, -24)
  // (ch. 1 §1.6 "Derivatives at end points", by hand).
  const BezierCurve c = lecture_cubic();
  const double tol = kLectureDerivativeTol;
  const std::vector<Vec3> ders = bezier_derivatives(c, 0.6, 3);
  ASSERT_EQ(ders.size(), 4u);
  expect_near_vec(ders[0], {6.624, 4.536, 0}, tol);
  expect_near_vec(ders[1], {13.02, 0.18, 0}, tol);
  expect_near_vec(ders[2], {-3.6, -29.4, 0}, tol);
  expect_near_vec(ders[3], {-51, -24, 0}, tol);
  // The hodograph route gives the same vectors.
  expect_near_vec(bezier_derivative_at(c, 0.6, 1), {13.02, 0.18, 0}, tol);
  expect_near_vec(bezier_derivative_at(c, 0.6, 2), {-3.6, -29.4, 0}, tol);
  expect_near_vec(bezier_derivative_at(c, 0.6, 3), {-51, -24, 0}, tol);
}

TEST(DeCasteljau, LectureExampleOnIntervalTwoToSeven) {
  // ch. 1 §1.6 "Generalization": on [a, b] = [2, 7] the point at
  // t = 2 + 0.6 * 5 = 5 is the same, "the p-th derivative gets scaled by
  // 1/(b-a)^p": X' / 5 and X'' / 25.
  const BezierCurve c = lecture_cubic(2, 7);
  const double tol = kLectureDerivativeTol;
  const std::vector<Vec3> ders = bezier_derivatives(c, 5.0, 2);
  expect_near_vec(ders[0], {6.624, 4.536, 0}, tol);
  expect_near_vec(ders[1], Vec3{13.02, 0.18, 0} / 5, tol);
  expect_near_vec(ders[2], Vec3{-3.6, -29.4, 0} / 25, tol);
  expect_near_vec(bezier_derivative_at(c, 5.0, 2), Vec3{-3.6, -29.4, 0} / 25, tol);
  EXPECT_EQ(de_casteljau(c, 5.0).s, 0.6);
}

TEST(DeCasteljau, GeometricModelingParabolaExample) {
  // notes "Geometric Modeling", "Another parabola construction": b0 = (0,1,0),
  // b1 = (1,1,0), b2 = (0,2,0). The notes print the points only; the values below
  // follow by hand from the notes' formulas on that page. At t = 1/2:
  //   b0^1 = (b0 + b1) / 2 = (1/2, 1, 0),  b1^1 = (b1 + b2) / 2 = (1/2, 3/2, 0),
  //   b0^2 = (b0^1 + b1^1) / 2 = (1/2, 5/4, 0)
  // = (1-t)^2 b0 + 2t(1-t) b1 + t^2 b2 = b0/4 + b1/2 + b2/4 (the page's closed form).
  // Expanded in powers of t (the page's "Parabolas" form x(t) = p0 + t p1 + t^2 p2):
  //   p0 = b0 = (0,1,0), p1 = 2 (b1 - b0) = (2,0,0), p2 = b0 - 2 b1 + b2 = (-2,1,0).
  // All of these are dyadic, so the scheme reproduces them to round-off (kExact).
  BezierCurve c;
  c.P = {{0, 1, 0}, {1, 1, 0}, {0, 2, 0}};
  const DeCasteljau d = de_casteljau(c, 0.5);
  ASSERT_EQ(d.levels.size(), 3u);
  expect_near_vec(d.levels[1][0], {0.5, 1, 0}, kExact);
  expect_near_vec(d.levels[1][1], {0.5, 1.5, 0}, kExact);
  expect_near_vec(d.levels[2][0], {0.5, 1.25, 0}, kExact);
  expect_near_vec(d.point, {0.5, 1.25, 0}, kExact);
  const std::vector<Vec3> m = monomial_coefficients(c);
  ASSERT_EQ(m.size(), 3u);
  expect_near_vec(m[0], {0, 1, 0}, kExact);
  expect_near_vec(m[1], {2, 0, 0}, kExact);
  expect_near_vec(m[2], {-2, 1, 0}, kExact);
  // The closed form x = 2t - 2t^2, y = 1 + t^2, z = 0 ("planar curve, even if
  // defined in R^3") at every sample; ends are b0 and b2.
  for (int k = 0; k < kSamples; ++k) {
    const double t = sample(0, 1, k);
    expect_near_vec(bezier_point(c, t), {2 * t - 2 * t * t, 1 + t * t, 0}, kExact * 2);
  }
  expect_near_vec(bezier_point(c, 0), c.P[0], kExact);
  expect_near_vec(bezier_point(c, 1), c.P[2], kExact);
}

// ---- variation diminishing ------------------------------------------------------------

constexpr int kVariationCases = 10000;   // random (curve, line) pairs
constexpr int kVariationMaxDepth = 50;   // bisections before an interval counts as degenerate

/// g(s) = sum_i d_i B_i^n(s) by de Casteljau on the scalars d (written here).
double bernstein_sum(std::vector<double> d, double s) {
  for (std::size_t r = 1; r < d.size(); ++r)
    for (std::size_t i = 0; i + r < d.size(); ++i) d[i] = (1 - s) * d[i] + s * d[i + 1];
  return d[0];
}

/// Roots of odd multiplicity (sign changes) of g in [a, b], with g(a), g(b) != 0, or -1
/// when undecidable. Rigorous bounds, not Descartes' rule (which is the property under
/// test): |g'| <= L1 = n max|d_{i+1} - d_i| and |g''| <= L2 = n(n-1) max|second
/// differences| on [0, 1] (the derivative's Bézier coefficients bound it, convex hull).
/// If |g(m)| > L1 (b - a)/2 at the midpoint m, g has no root in [a, b]; if |g'(m)| >
/// L2 (b - a)/2, g is monotone there and has a root iff g(a), g(b) differ in sign.
/// Otherwise bisect; an interval still undecided after kVariationMaxDepth halvings is a
/// near-tangency and the case is skipped (counted).
int count_crossings(const std::vector<double>& d, const std::vector<double>& d1, double L1,
                    double L2, double a, double b, double ga, double gb, int depth) {
  const double m = (a + b) / 2, gm = bernstein_sum(d, m), half = (b - a) / 2;
  if (std::fabs(gm) > L1 * half) return 0;
  if (!d1.empty() && std::fabs(bernstein_sum(d1, m)) > L2 * half) return (ga < 0) != (gb < 0);
  if (depth >= kVariationMaxDepth || gm == 0) return -1;
  const int left = count_crossings(d, d1, L1, L2, a, m, ga, gm, depth + 1);
  const int right = count_crossings(d, d1, L1, L2, m, b, gm, gb, depth + 1);
  return left < 0 || right < 0 ? -1 : left + right;
}

TEST(BezierProperties, VariationDiminishingAgainstRandomLines) {
  // ch. 1 §1.6, Bézier properties, "2) Variation diminishing", and notes "Geometric
  // Modeling", "Properties of Bezier curves": an arbitrary straight line intersects the
  // (planar) curve as often or less than the control polygon. For the line n.x = c put
  // d_i = n.b_i - c: the curve's crossings are the sign changes of g(s) = sum d_i B_i^n(s)
  // on (0, 1), the polygon's are the sign changes of the sequence d_0..d_n (a d_i of
  // exactly 0 is skipped). Counts are exact (count_crossings), not sampled.
  std::mt19937 rng(1906);  // fixed seed
  std::uniform_real_distribution<double> angle(0, 2 * 3.14159265358979323846), unit(0, 1);
  int skipped = 0, tested = 0, with_crossings = 0;
  for (int k = 0; k < kVariationCases; ++k) {
    const int n = 1 + k % 10;
    std::vector<Vec3> P;
    for (int i = 0; i <= n; ++i) P.push_back({unit(rng) * 10 - 5, unit(rng) * 10 - 5, 0});
    const double th = angle(rng);
    const Vec3 normal = {std::cos(th), std::sin(th), 0};
    const Vec3 through = P[static_cast<std::size_t>(k) % P.size()] * unit(rng);
    std::vector<double> d;
    for (const Vec3& p : P) d.push_back(dot(normal, p) - dot(normal, through));
    int polygon = 0;
    bool zero = false;
    for (std::size_t i = 0; i < d.size(); ++i) {
      zero = zero || d[i] == 0;
      if (i > 0) polygon += (d[i - 1] < 0) != (d[i] < 0);
    }
    std::vector<double> d1;
    double L1 = 0, L2 = 0;
    for (int i = 0; i < n; ++i) {
      d1.push_back(n * (d[i + 1] - d[i]));
      L1 = std::max(L1, std::fabs(d1.back()));
    }
    // g' has coefficients d1; for n = 1 it is constant (L2 = 0: monotone everywhere).
    for (int i = 0; i + 1 < n; ++i) L2 = std::max(L2, (n - 1) * std::fabs(d1[i + 1] - d1[i]));
    const int curve = zero ? -1 : count_crossings(d, d1, L1, L2, 0, 1, d.front(), d.back(), 0);
    if (curve < 0) {
      ++skipped;
      continue;
    }
    ++tested;
    with_crossings += curve > 0;
    EXPECT_LE(curve, polygon) << "case " << k << ", degree " << n;
    // Parity: both counts have the parity of sign(d_0) != sign(d_n).
    EXPECT_EQ(curve % 2, polygon % 2) << "case " << k;
  }
  // Degenerate (tangent or exactly-through-a-vertex) cases are measure zero for random data.
  EXPECT_LE(skipped, kVariationCases / 100) << skipped << " skipped";
  EXPECT_GE(with_crossings, kVariationCases / 10) << "too few lines meet their curve";
  EXPECT_EQ(tested + skipped, kVariationCases);
  RecordProperty("skipped", skipped);
  RecordProperty("with_crossings", with_crossings);
}

TEST(DeCasteljau, SchemeHasEveryIntermediatePolygon) {
  // levels[j] has n + 1 - j points, and each is the convex combination of two
  // points of the level above (ch. 1 §1.6 recursion).
  std::mt19937 rng(101);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    const double t = sample(curve.a, curve.b, c % kSamples);
    const DeCasteljau d = de_casteljau(curve, t);
    const std::size_t n = curve.P.size() - 1;
    ASSERT_EQ(d.levels.size(), n + 1);
    for (std::size_t j = 0; j <= n; ++j) ASSERT_EQ(d.levels[j].size(), n + 1 - j);
    for (std::size_t j = 1; j <= n; ++j)
      for (std::size_t i = 0; i + j <= n; ++i)
        EXPECT_EQ(d.levels[j][i], lerp(d.levels[j - 1][i], d.levels[j - 1][i + 1], d.s));
    EXPECT_EQ(d.point, bezier_point(curve, t));  // same arithmetic, same doubles
  }
}

// ---- Bernstein -----------------------------------------------------------------------

TEST(Bernstein, LectureCubicClosedForms) {
  // notes "Higher Order Surfaces", "Cubic case": B03 = (1-u)^3, B13 = 3u(1-u)^2, B23 = 3u^2(1-u), B33 = u^3;
  // notes "Geometric Modeling", "The first three Bernstein bases" for degrees 0..2.
  for (int k = 0; k < kSamples; ++k) {
    const double u = sample(0, 1, k), v = 1 - u;
    const std::vector<double> B3 = bernstein_all(3, u);
    EXPECT_NEAR(B3[0], v * v * v, kExact);
    EXPECT_NEAR(B3[1], 3 * u * v * v, kExact);
    EXPECT_NEAR(B3[2], 3 * u * u * v, kExact);
    EXPECT_NEAR(B3[3], u * u * u, kExact);
    EXPECT_EQ(bernstein(0, 0, u), 1.0);
    EXPECT_NEAR(bernstein(0, 1, u), v, kExact);
    EXPECT_NEAR(bernstein(1, 1, u), u, kExact);
    EXPECT_NEAR(bernstein(0, 2, u), v * v, kExact);
    EXPECT_NEAR(bernstein(1, 2, u), 2 * u * v, kExact);
    EXPECT_NEAR(bernstein(2, 2, u), u * u, kExact);
  }
}

TEST(Bernstein, PartitionOfUnityNonNegativeAndSymmetric) {
  // ch. 1 §1.6 property 6: B_i^n(t) = B_{n-i}^n(1-t), B_i^n >= 0 on [0, 1],
  // sum B_i^n = 1; and the definition C(n, i) t^i (1-t)^(n-i) (property 5).
  for (int n = 0; n <= 30; ++n) {
    for (int k = 0; k < kSamples; ++k) {
      const double s = sample(0, 1, k);
      const std::vector<double> B = bernstein_all(n, s);
      const std::vector<double> mirrored = bernstein_all(n, 1 - s);
      ASSERT_EQ(B.size(), static_cast<std::size_t>(n) + 1);
      double sum = 0;
      for (int i = 0; i <= n; ++i) {
        const double Bi = B[static_cast<std::size_t>(i)];
        EXPECT_GE(Bi, 0.0);
        sum += Bi;
        EXPECT_NEAR(Bi, mirrored[static_cast<std::size_t>(n - i)], kExact);
        EXPECT_NEAR(Bi, bernstein(i, n, s), kExact);
        EXPECT_NEAR(Bi, binomial(n, i) * std::pow(s, i) * std::pow(1 - s, n - i), kExact);
      }
      EXPECT_NEAR(sum, 1.0, kExact);
    }
  }
}

TEST(Bernstein, MaximumAtIOverN) {
  // ch. 1 §1.6 property 8: max(B_i^n) = B_i^n(i/n).
  for (int n = 1; n <= 12; ++n)
    for (int i = 0; i <= n; ++i) {
      const double peak = bernstein(i, n, static_cast<double>(i) / n);
      for (int k = 0; k < kSamples; ++k) EXPECT_LE(bernstein(i, n, sample(0, 1, k)), peak + kExact);
    }
}

TEST(Bernstein, GeneralIntervalUsesTheLocalParameter) {
  // ch. 1 §1.6 "Generalization": B_i^n((t - a) / (b - a)) =
  // C(n, i) (t - a)^i (b - t)^(n - i) / (b - a)^n.
  const double a = -1.5, b = 2.5;
  for (int n = 0; n <= 8; ++n)
    for (int k = 0; k < kSamples; ++k) {
      const double t = sample(a, b, k);
      const std::vector<double> B = bernstein_all(n, t, a, b);
      for (int i = 0; i <= n; ++i) {
        const double printed = binomial(n, i) * std::pow(t - a, i) * std::pow(b - t, n - i) / std::pow(b - a, n);
        EXPECT_NEAR(B[static_cast<std::size_t>(i)], printed, kExact);
        EXPECT_NEAR(bernstein(i, n, t, a, b), printed, kExact);
      }
    }
}

TEST(Bernstein, IndexOutsideZeroToNIsZero) {
  // ch. 1 §1.6 property 11: "B_{-1}^{n-1}, B_n^{n-1} := 0".
  EXPECT_EQ(bernstein(-1, 3, 0.5), 0.0);
  EXPECT_EQ(bernstein(4, 3, 0.5), 0.0);
}

// ---- matrix and monomial form ------------------------------------------------------

TEST(BezierMatrix, LectureCubicMatrix) {
  // ch. 1 §1.6 "basis transformation (to monomials)" and notes "Higher Order Surfaces", "Matrix Form".
  const std::vector<std::vector<double>> printed = {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}};
  EXPECT_EQ(bezier_matrix(3), printed);
  EXPECT_EQ(bezier_matrix(0), (std::vector<std::vector<double>>{{1}}));
}

TEST(BezierMatrix, PowerRowTimesMatrixGivesBernstein) {
  // notes "Higher Order Surfaces": [B_0(u) ... B_n(u)] = U M with U = (u^n ... u 1).
  for (int n = 0; n <= 10; ++n) {
    const auto M = bezier_matrix(n);
    for (int k = 0; k < kSamples; ++k) {
      const double u = sample(0, 1, k);
      const std::vector<double> B = bernstein_all(n, u);
      for (int i = 0; i <= n; ++i) {
        double sum = 0, terms = 0;
        for (int r = 0; r <= n; ++r) {
          const double term = std::pow(u, n - r) * M[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)];
          sum += term;
          terms += std::fabs(term);
        }
        EXPECT_NEAR(sum, B[static_cast<std::size_t>(i)], kExact * terms);
      }
    }
  }
}

TEST(BezierMonomial, PowerFormEvaluatesToTheCurve) {
  // The power form X(t) = sum c_j t^j (global t) equals de Casteljau; its
  // accuracy is that of the terms it sums, sum |c_j| |t|^j.
  std::mt19937 rng(111);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c, 8);
    const std::vector<Vec3> coeff = monomial_coefficients(curve);
    ASSERT_EQ(coeff.size(), curve.P.size());
    for (int k = 0; k < kSamples; ++k) {
      const double t = sample(curve.a, curve.b, k);
      double terms = 0;
      for (std::size_t j = 0; j < coeff.size(); ++j) terms += norm(coeff[j]) * std::pow(std::fabs(t), static_cast<int>(j));
      expect_near_vec(monomial_value(coeff, t), bezier_point(curve, t), kExact * std::max(terms, scale_of(curve.P)));
    }
  }
}

TEST(BezierMonomial, RoundTripReturnsTheControlPoints) {
  // Bézier -> monomial -> Bézier gives the points back. The power form is the
  // badly conditioned one (one reason CAD keeps the Bernstein form): over 500
  // random curves per degree the worst relative error grows about 3x per degree on
  // [0, 1] (2e-15 at n = 3, 2e-13 at n = 7, 4e-12 at n = 10) and about 12x per
  // degree on the random intervals, where the global t is re-expanded
  // (1e-13 at n = 3, 2e-11 at n = 5). So kExact holds up to
  // kMaxRoundTripDegreeUnit on [0, 1] and kMaxRoundTripDegreeInterval elsewhere.
  constexpr int kMaxRoundTripDegreeUnit = 7, kMaxRoundTripDegreeInterval = 3;
  std::mt19937 rng(121);
  for (int c = 0; c < kRandomCases; ++c) {
    const bool unit = c % 2 == 0;  // random_curve: even cases are on [0, 1]
    const BezierCurve curve = random_curve(rng, c, unit ? kMaxRoundTripDegreeUnit : kMaxRoundTripDegreeInterval);
    const BezierCurve back = bezier_from_monomial(monomial_coefficients(curve), curve.a, curve.b);
    ASSERT_EQ(back.P.size(), curve.P.size());
    EXPECT_EQ(back.a, curve.a);
    EXPECT_EQ(back.b, curve.b);
    for (std::size_t i = 0; i < curve.P.size(); ++i) expect_near_vec(back.P[i], curve.P[i], kExact * scale_of(curve.P));
  }
}

TEST(BezierMonomial, LectureCubicExpansion) {
  // ch. 1 §1.6: X(t) = b0 (-t^3 + 3t^2 - 3t + 1) + b1 (3t^3 - 6t^2 + 3t)
  // + b2 (-3t^3 + 3t^2) + b3 t^3. For the lecture's cubic: c0 = b0 = (0, 0),
  // c1 = 3 (b1 - b0) = (6, 13.5), c2 = 3 b0 - 6 b1 + 3 b2 = (13.5, -7.5),
  // c3 = -b0 + 3 b1 - 3 b2 + b3 = (-8.5, -4)   (by hand; c0 + c1 + c2 + c3 = b3 = (11, 2)).
  const std::vector<Vec3> c = monomial_coefficients(lecture_cubic());
  ASSERT_EQ(c.size(), 4u);
  expect_near_vec(c[0], {0, 0, 0}, kLecturePointTol);
  expect_near_vec(c[1], {6, 13.5, 0}, kLecturePointTol);
  expect_near_vec(c[2], {13.5, -7.5, 0}, kLecturePointTol);
  expect_near_vec(c[3], {-8.5, -4, 0}, kLecturePointTol);
}

// ---- properties over random curves ---------------------------------------------------

TEST(BezierProperty, EndpointInterpolation) {
  // ch. 1 §1.6 property 3: X(a) = b_0, X(b) = b_n, exactly (de Casteljau
  // at s = 0 or 1 only copies points).
  std::mt19937 rng(131);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    EXPECT_EQ(bezier_point(curve, curve.a), curve.P.front());
    EXPECT_EQ(bezier_point(curve, curve.b), curve.P.back());
  }
}

TEST(BezierProperty, ConvexHull) {
  // ch. 1 §1.6 property 1: X(t) lies in the convex hull of the b_i. A point
  // p is in the hull iff for every direction d, min d.b_i <= d.p <= max d.b_i;
  // checked for 24 random directions.
  std::mt19937 rng(141);
  std::normal_distribution<double> gauss(0, 1);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    const double tol = kExact * scale_of(curve.P);
    for (int dir = 0; dir < 24; ++dir) {
      const Vec3 d = normalized({gauss(rng), gauss(rng), gauss(rng)});
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const Vec3& p : curve.P) {
        lo = std::min(lo, dot(d, p));
        hi = std::max(hi, dot(d, p));
      }
      for (int k = 0; k < kSamples; ++k) {
        const double h = dot(d, bezier_point(curve, sample(curve.a, curve.b, k)));
        EXPECT_GE(h, lo - tol);
        EXPECT_LE(h, hi + tol);
      }
    }
  }
}

TEST(BezierProperty, AffineInvariance) {
  // ch. 1 §1.6 property 4: phi(X(t)) = Y(t) for phi(p) = A p + v, Y the
  // curve of the points phi(b_i).
  std::mt19937 rng(151);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    double A[3][3];
    for (auto& row : A)
      for (double& x : row) x = u(rng);
    const Vec3 v = random_point(rng);
    auto phi = [&](Vec3 p) {
      return Vec3{A[0][0] * p.x + A[0][1] * p.y + A[0][2] * p.z, A[1][0] * p.x + A[1][1] * p.y + A[1][2] * p.z,
                  A[2][0] * p.x + A[2][1] * p.y + A[2][2] * p.z} +
             v;
    };
    BezierCurve mapped = curve;
    for (Vec3& p : mapped.P) p = phi(p);
    const double tol = kExact * scale_of(mapped.P);
    for (int k = 0; k < kSamples; ++k) {
      const double t = sample(curve.a, curve.b, k);
      expect_near_vec(bezier_point(mapped, t), phi(bezier_point(curve, t)), tol);
    }
  }
}

TEST(BezierProperty, SymmetryUnderReversal) {
  // ch. 1 §1.6 property 7: reversing the points gives Y(t) = X(1 - t); on
  // [a, b], Y(t) = X(a + b - t).
  std::mt19937 rng(161);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    BezierCurve reversed = curve;
    std::reverse(reversed.P.begin(), reversed.P.end());
    for (int k = 0; k < kSamples; ++k) {
      const double t = sample(curve.a, curve.b, k);
      const double mirrored = sample(curve.a, curve.b, kSamples - 1 - k);  // a + b - t up to round-off
      expect_near_vec(bezier_point(reversed, t), bezier_point(curve, mirrored), kExact * scale_of(curve.P));
    }
  }
}

TEST(BezierProperty, CollinearPointsGiveASegment) {
  // notes "Geometric Modeling", "Linear precision": collinear b_i -> the curve is a line segment.
  std::mt19937 rng(171);
  std::uniform_real_distribution<double> lambda(-1, 2);
  for (int c = 0; c < kRandomCases; ++c) {
    const Vec3 origin = random_point(rng), dir = normalized(random_point(rng));
    BezierCurve curve = random_curve(rng, c);
    for (Vec3& p : curve.P) p = origin + lambda(rng) * dir;
    for (int k = 0; k < kSamples; ++k) {
      const Vec3 off = cross(bezier_point(curve, sample(curve.a, curve.b, k)) - origin, dir);
      EXPECT_LE(norm(off), kExact * scale_of(curve.P));
    }
  }
}

// ---- subdivision ---------------------------------------------------------------------

TEST(BezierSubdivide, PiecesMatchTheCurve) {
  // ch. 1 §1.6 property 10: left(u) = X(u) on [a, t], right(u) = X(u) on
  // [t, b], at kSamples parameters each, relative kExact.
  std::mt19937 rng(181);
  std::uniform_real_distribution<double> where(0.02, 0.98);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    const double t = curve.a + where(rng) * (curve.b - curve.a);
    const BezierSplit split = subdivide(curve, t);
    ASSERT_EQ(split.left.P.size(), curve.P.size());
    ASSERT_EQ(split.right.P.size(), curve.P.size());
    EXPECT_EQ(split.left.a, curve.a);
    EXPECT_EQ(split.left.b, t);
    EXPECT_EQ(split.right.a, t);
    EXPECT_EQ(split.right.b, curve.b);
    EXPECT_EQ(split.left.P.back(), split.right.P.front());  // both are b_0^n = X(t)
    const double tol = kExact * scale_of(curve.P);
    for (int k = 0; k < kSamples; ++k) {
      const double ul = sample(curve.a, t, k), ur = sample(t, curve.b, k);
      expect_near_vec(bezier_point(split.left, ul), bezier_point(curve, ul), tol);
      expect_near_vec(bezier_point(split.right, ur), bezier_point(curve, ur), tol);
    }
  }
}

TEST(BezierSubdivide, LectureExampleAtPoint6TakesTheSchemeEdges) {
  // ch. 1 §1.6: the new points are b_0^i and b_i^(n-i) of the t = 0.6 scheme above.
  const BezierSplit split = subdivide(lecture_cubic(), 0.6);
  const double tol = kLecturePointTol;
  const std::vector<Vec3> left = {{0, 0, 0}, {1.2, 2.7, 0}, {4.02, 4.5, 0}, {6.624, 4.536, 0}};
  const std::vector<Vec3> right = {{6.624, 4.536, 0}, {8.36, 4.56, 0}, {10, 3.8, 0}, {11, 2, 0}};
  for (std::size_t i = 0; i < 4; ++i) {
    expect_near_vec(split.left.P[i], left[i], tol);
    expect_near_vec(split.right.P[i], right[i], tol);
  }
  EXPECT_EQ(split.left.dimension, 2);
}

TEST(BezierSubdivide, LectureMidpointFormulasForACubic) {
  // notes "Higher Order Surfaces", "Midpoint subdivision (u = 0.5)": q0 = p0, q1 = (p0 + p1)/2,
  // q2 = q1/2 + (p1 + p2)/4, q3 = (q2 + r1)/2 = r0, r1 = r2/2 + (p1 + p2)/4,
  // r2 = (p2 + p3)/2, r3 = p3. (Powers of two: exact.)
  std::mt19937 rng(191);
  for (int c = 0; c < kRandomCases; ++c) {
    BezierCurve curve;
    for (int i = 0; i < 4; ++i) curve.P.push_back(random_point(rng));
    const auto& p = curve.P;
    const Vec3 q1 = (p[0] + p[1]) / 2, q2 = q1 / 2 + (p[1] + p[2]) / 4;
    const Vec3 r2 = (p[2] + p[3]) / 2, r1 = r2 / 2 + (p[1] + p[2]) / 4, q3 = (q2 + r1) / 2;
    const BezierSplit split = subdivide(curve, 0.5);
    const double tol = kExact * scale_of(p);
    const std::vector<Vec3> left = {p[0], q1, q2, q3}, right = {q3, r1, r2, p[3]};
    for (std::size_t i = 0; i < 4; ++i) {
      expect_near_vec(split.left.P[i], left[i], tol);
      expect_near_vec(split.right.P[i], right[i], tol);
    }
  }
}

// ---- degree elevation ------------------------------------------------------------------

TEST(BezierDegreeElevate, OnceLeavesTheCurveUnchanged) {
  // ch. 1 §1.6 property 9, at kSamples parameters, relative kExact.
  std::mt19937 rng(201);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    const BezierCurve e = degree_elevate(curve);
    ASSERT_EQ(e.P.size(), curve.P.size() + 1);
    EXPECT_EQ(e.a, curve.a);
    EXPECT_EQ(e.b, curve.b);
    EXPECT_EQ(e.P.front(), curve.P.front());
    EXPECT_EQ(e.P.back(), curve.P.back());
    for (int k = 0; k < kSamples; ++k) {
      const double t = sample(curve.a, curve.b, k);
      expect_near_vec(bezier_point(e, t), bezier_point(curve, t), kExact * scale_of(curve.P));
    }
  }
}

TEST(BezierDegreeElevate, RepeatedInOneStepEqualsOneStepRepeated) {
  // The NURBS Book eq. (5.36) (all steps at once) against the lecture's formula
  // applied `times` times; and the curve is still unchanged.
  std::mt19937 rng(211);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c, 8);
    const int times = 2 + c % 5;
    const BezierCurve direct = degree_elevate(curve, times);
    BezierCurve stepwise = curve;
    for (int r = 0; r < times; ++r) stepwise = degree_elevate(stepwise);
    ASSERT_EQ(direct.P.size(), curve.P.size() + static_cast<std::size_t>(times));
    ASSERT_EQ(stepwise.P.size(), direct.P.size());
    const double tol = kExact * scale_of(curve.P);
    for (std::size_t i = 0; i < direct.P.size(); ++i) expect_near_vec(direct.P[i], stepwise.P[i], tol);
    for (int k = 0; k < kSamples; ++k) {
      const double t = sample(curve.a, curve.b, k);
      expect_near_vec(bezier_point(direct, t), bezier_point(curve, t), tol);
    }
  }
}

TEST(BezierDegreeElevate, LectureFormulaOnACubic) {
  // ch. 1 §1.6 property 9 for n = 3: b'_0 = b0, b'_1 = (b0 + 3 b1)/4,
  // b'_2 = (2 b1 + 2 b2)/4, b'_3 = (3 b2 + b3)/4, b'_4 = b3. For the lecture's cubic:
  // (0,0), (1.5,3.375), (5.25,5.5), (9.125,5.375), (11,2)   (by hand).
  // (notes "Higher Order Surfaces" prints the second point as (P0 + P1)/(n+1); the factor n on P1
  // is missing there. Its last inner point (n P_{n-1} + P_n)/(n+1) is right.)
  const BezierCurve e = degree_elevate(lecture_cubic());
  const std::vector<Vec3> expected = {{0, 0, 0}, {1.5, 3.375, 0}, {5.25, 5.5, 0}, {9.125, 5.375, 0}, {11, 2, 0}};
  ASSERT_EQ(e.P.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) expect_near_vec(e.P[i], expected[i], kLecturePointTol);
}

TEST(BezierDegreeElevate, ZeroTimesIsTheSameCurve) {
  const BezierCurve curve = lecture_cubic();
  EXPECT_EQ(degree_elevate(curve, 0).P, curve.P);
}

// ---- derivatives ---------------------------------------------------------------------------

/// The k-th derivative of sum c_j t^j at t, and the size of the terms it sums.
struct PowerDerivative {
  Vec3 value;
  double terms = 0;
};
PowerDerivative power_derivative(const std::vector<Vec3>& c, int k, double t) {
  PowerDerivative d;
  for (int j = k; j < static_cast<int>(c.size()); ++j) {
    double falling = 1;
    for (int q = 0; q < k; ++q) falling *= j - q;
    const Vec3 term = falling * std::pow(t, j - k) * c[static_cast<std::size_t>(j)];
    d.value += term;
    d.terms += norm(term);
  }
  return d;
}

TEST(BezierDerivative, HodographDeCasteljauEndFormulasAndPowerFormAgree) {
  // Four routes to X^(k)(t): the hodograph (property 11), the de Casteljau
  // scheme, the end-point formulas, and differentiating the power form here.
  std::mt19937 rng(221);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c, 7);
    const int n = bezier_degree(curve);
    const std::vector<Vec3> power = monomial_coefficients(curve);
    for (int k = 0; k <= n + 1; ++k) {
      const BezierCurve hodograph = bezier_derivative(curve, k);
      EXPECT_EQ(hodograph.P.size(), static_cast<std::size_t>(std::max(n - k, 0)) + 1);
      const double scale = scale_of(hodograph.P);
      for (int q = 0; q < kSamples; q += 10) {
        const double t = sample(curve.a, curve.b, q);
        const Vec3 hodo = bezier_derivative_at(curve, t, k);
        const std::vector<Vec3> ders = bezier_derivatives(curve, t, k);
        expect_near_vec(ders[static_cast<std::size_t>(k)], hodo, kExact * scale);
        const PowerDerivative pd = power_derivative(power, k, t);
        expect_near_vec(pd.value, hodo, kExact * std::max(scale, pd.terms));
      }
      expect_near_vec(bezier_start_derivative(curve, k), bezier_derivative_at(curve, curve.a, k), kExact * scale);
      expect_near_vec(bezier_end_derivative(curve, k), bezier_derivative_at(curve, curve.b, k), kExact * scale);
    }
  }
}

TEST(BezierDerivative, LectureEndPointFormulasForTheLectureCubic) {
  // ch. 1 §1.6 "Derivatives at end points", n = 3, by hand for b0..b3 =
  // (0,0), (2,4.5), (8.5,6.5), (11,2):
  //   X'(0)   = 3 (b1 - b0)                = (6, 13.5)
  //   X''(0)  = 6 (b2 - 2 b1 + b0)         = (27, -15)
  //   X'''(0) = 6 (b3 - 3 b2 + 3 b1 - b0)  = (-51, -24)
  //   X'(1)   = 3 (b3 - b2)                = (7.5, -13.5)
  //   X''(1)  = 6 (b3 - 2 b2 + b1)         = (-24, -39)
  //   X'''(1) = X'''(0)                    = (-51, -24)
  const BezierCurve c = lecture_cubic();
  const double tol = kLectureDerivativeTol;
  expect_near_vec(bezier_start_derivative(c, 1), {6, 13.5, 0}, tol);
  expect_near_vec(bezier_start_derivative(c, 2), {27, -15, 0}, tol);
  expect_near_vec(bezier_start_derivative(c, 3), {-51, -24, 0}, tol);
  expect_near_vec(bezier_end_derivative(c, 1), {7.5, -13.5, 0}, tol);
  expect_near_vec(bezier_end_derivative(c, 2), {-24, -39, 0}, tol);
  expect_near_vec(bezier_end_derivative(c, 3), {-51, -24, 0}, tol);
  EXPECT_EQ(bezier_start_derivative(c, 4), Vec3{});
  EXPECT_EQ(bezier_start_derivative(c, 0), c.P.front());
  EXPECT_EQ(bezier_end_derivative(c, 0), c.P.back());
  // The hodograph points, ch. 1 §1.6 property 11: b'_i = n (b_{i+1} - b_i).
  const BezierCurve h = bezier_derivative(c, 1);
  const std::vector<Vec3> expected = {{6, 13.5, 0}, {19.5, 6, 0}, {7.5, -13.5, 0}};
  ASSERT_EQ(h.P.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) expect_near_vec(h.P[i], expected[i], tol);
}

TEST(BezierDerivative, ChainRuleFactorOnAGeneralInterval) {
  // ch. 1 §1.6 "Generalization": the same points on [a, b] and on [0, 1];
  // X_[a,b]^(k)(a + s h) = X_[0,1]^(k)(s) / h^k.
  std::mt19937 rng(231);
  for (int c = 0; c < kRandomCases; ++c) {
    BezierCurve on_ab = random_curve(rng, 2 * c + 1, 8);  // odd index: random [a, b]
    BezierCurve on_01 = on_ab;
    on_01.a = 0;
    on_01.b = 1;
    const double h = on_ab.b - on_ab.a;
    for (int k = 0; k <= 3; ++k)
      for (int q = 0; q < kSamples; q += 10) {
        const double s = sample(0, 1, q);
        const Vec3 expected = bezier_derivative_at(on_01, s, k) / std::pow(h, k);
        expect_near_vec(bezier_derivative_at(on_ab, on_ab.a + s * h, k), expected,
                        kExact * scale_of(bezier_derivative(on_01, k).P) / std::pow(std::min(h, 1.0), k));
      }
  }
}

TEST(BezierDerivative, OrderZeroIsTheCurveAndAboveDegreeIsZero) {
  const BezierCurve c = lecture_cubic(1, 3);
  EXPECT_EQ(bezier_derivative(c, 0).P, c.P);
  const BezierCurve zero = bezier_derivative(c, 4);
  ASSERT_EQ(zero.P.size(), 1u);
  EXPECT_EQ(zero.P[0], Vec3{});
  EXPECT_EQ(zero.a, 1.0);
  EXPECT_EQ(zero.b, 3.0);
  const std::vector<Vec3> ders = bezier_derivatives(c, 2.0, 6);
  ASSERT_EQ(ders.size(), 7u);
  EXPECT_EQ(ders[4], Vec3{});
  EXPECT_EQ(ders[6], Vec3{});
}

// ---- integral ------------------------------------------------------------------------------

TEST(BezierIntegral, LectureCubicAgreesWithSimpson) {
  // ch. 1 §1.6: int_a^b X = (b-a)/(n+1) (b0 + ... + bn) = (21.5, 13)/4 on [0, 1].
  // Independent check: Simpson's rule (h/6)(X(a) + 4 X(mid) + X(b)) is exact for cubics.
  for (const auto& [a, b] : {std::pair{0.0, 1.0}, std::pair{-1.0, 3.0}}) {
    const BezierCurve c = lecture_cubic(a, b);
    const Vec3 simpson =
        (b - a) / 6 * (bezier_point(c, a) + 4 * bezier_point(c, (a + b) / 2) + bezier_point(c, b));
    expect_near_vec(bezier_integral(c), simpson, kLectureDerivativeTol);
    expect_near_vec(bezier_integral(c), (b - a) * Vec3{5.375, 3.25, 0}, kLectureDerivativeTol);
  }
}

TEST(BezierIntegral, EqualsTheIntegralOfThePowerForm) {
  // int_a^b sum c_j t^j dt = sum c_j (b^(j+1) - a^(j+1)) / (j+1), term by term.
  std::mt19937 rng(241);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c, 8);
    const std::vector<Vec3> power = monomial_coefficients(curve);
    Vec3 exact;
    double terms = 0;
    for (std::size_t j = 0; j < power.size(); ++j) {
      const double e = static_cast<double>(j) + 1;
      const Vec3 term = (std::pow(curve.b, e) - std::pow(curve.a, e)) / e * power[j];
      exact += term;
      terms += norm(term);
    }
    expect_near_vec(bezier_integral(curve), exact, kExact * std::max(terms, scale_of(curve.P)));
  }
}

// ch. 1 §1.6, "Integrating a Bézier segment", prints the segment as
// sum b_i B_i^n((1 - a)/(b - a)) and its integral as (b - a)/(m + 1) (b_0 + ... + b_m). The
// argument is (t - a)/(b - a) (as in "Generalization"), and the sum runs over the segment's own
// n + 1 points: int_0^1 B_i^n = 1/(n + 1).
// A quartic on [2, 7]: (b - a)/(n + 1) = 5/5 = 1, so the integral is the sum of the points,
// (6, 6, 5) by hand. Independent check: 3-point Gauss-Legendre, exact up to degree 5.
TEST(BezierIntegral, LocalParameterAndDegreeNNotesSlip) {
  BezierCurve c;
  c.P = {{0, 1, 2}, {3, -1, 0}, {4, 4, 1}, {-2, 0, 5}, {1, 2, -3}};
  c.a = 2;
  c.b = 7;
  const Vec3 sum_of_points{6, 6, 5};
  expect_near_vec(bezier_integral(c), sum_of_points, kExact * 10);
  const GaussRule rule = gauss_legendre(3);
  Vec3 gauss;
  const double half = (c.b - c.a) / 2, mid = (c.a + c.b) / 2;
  for (std::size_t k = 0; k < rule.x.size(); ++k)
    gauss += half * rule.w[k] * bezier_point(c, mid + half * rule.x[k]);
  expect_near_vec(gauss, sum_of_points, kExact * 10);
}

TEST(BezierAntiderivative, DifferentiatesBackToTheCurve) {
  // Y' = X (property 11 applied to Y), Y(a) = start, Y(b) - Y(a) = the integral.
  std::mt19937 rng(251);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve curve = random_curve(rng, c);
    const Vec3 start = random_point(rng);
    const BezierCurve Y = bezier_antiderivative(curve, start);
    ASSERT_EQ(Y.P.size(), curve.P.size() + 1);
    EXPECT_EQ(bezier_point(Y, curve.a), start);
    const BezierCurve dY = bezier_derivative(Y, 1);
    const double tol = kExact * scale_of(curve.P) * std::max(1.0, 1 / (curve.b - curve.a));
    for (std::size_t i = 0; i < curve.P.size(); ++i) expect_near_vec(dY.P[i], curve.P[i], tol);
    expect_near_vec(bezier_point(Y, curve.b) - start, bezier_integral(curve), kExact * scale_of(Y.P));
  }
}

// ---- interpolation ---------------------------------------------------------------------------

TEST(BezierInterpolate, LectureExampleChordalCubic) {
  // ch. 1 §1.6 "Interpolating with Bézier segments", example: P0 = (1,2),
  // P1 = (2,1), P2 = (4,2), P3 = (6,6) at the lecture's (rounded) chordal
  // parameters t = 0, 1.42, 3.66, 8.13 on [a, b] = [0, 8.13].
  // (The lecture's last condition reads "(1,2) = ... = b_3"; it means P3 = (6,6).)
  const std::vector<Vec3> Q = {{1, 2, 0}, {2, 1, 0}, {4, 2, 0}, {6, 6, 0}};
  const std::vector<double> t = {0, 1.42, 3.66, 8.13};
  const BezierCurve c = bezier_interpolate(Q, t, 0, 8.13);
  ASSERT_EQ(c.P.size(), 4u);
  EXPECT_EQ(c.a, 0.0);
  EXPECT_EQ(c.b, 8.13);

  // The lecture's own reduction: b0 = P0, b3 = P3 and a 2x2 system for b1, b2,
  //   B1(s_j) b1 + B2(s_j) b2 = P_j - B0(s_j) P0 - B3(s_j) P3,  j = 1, 2,
  // solved here by Cramer's rule with the cubic Bernstein closed forms.
  auto B = [](int i, double s) {
    const double v = 1 - s;
    return i == 0 ? v * v * v : i == 1 ? 3 * s * v * v : i == 2 ? 3 * s * s * v : s * s * s;
  };
  const double s1 = 1.42 / 8.13, s2 = 3.66 / 8.13;
  const double m11 = B(1, s1), m12 = B(2, s1), m21 = B(1, s2), m22 = B(2, s2);
  const double det = m11 * m22 - m12 * m21;
  const Vec3 r1 = Q[1] - B(0, s1) * Q[0] - B(3, s1) * Q[3];
  const Vec3 r2 = Q[2] - B(0, s2) * Q[0] - B(3, s2) * Q[3];
  const Vec3 b1 = (m22 * r1 - m12 * r2) / det, b2 = (m11 * r2 - m21 * r1) / det;
  const double tol = kLecturePointTol;
  expect_near_vec(c.P[0], Q[0], tol);
  expect_near_vec(c.P[1], b1, tol);
  expect_near_vec(c.P[2], b2, tol);
  expect_near_vec(c.P[3], Q[3], tol);
  // The same numbers from exact rational arithmetic on the lecture's data
  // (Python fractions, rounded to double): the coefficients are 0.35693,
  // 0.07554, 0.40827, 0.33429 (lecture: 0.36, 0.07, 0.41, 0.33) and the right-hand
  // sides 1.40582, 3.28637 (x) and -0.15638, 1.12016 (y) (lecture: 1.38, 3.29, -0.18, 1.12).
  expect_near_vec(c.P[1], {2.5058317197147955, -1.5471395461440598, 0}, tol);
  expect_near_vec(c.P[2], {6.770585289334301, 5.2404396375074782, 0}, tol);
  // The lecture prints b1 = (2.5, -1.51), b2 = (6.86, 5.27) from its two-decimal
  // system (see kLectureTwoDecimalSystem).
  expect_near_vec(c.P[1], {2.5, -1.51, 0}, kLectureTwoDecimalSystem);
  expect_near_vec(c.P[2], {6.86, 5.27, 0}, kLectureTwoDecimalSystem);
  // And the curve passes through the four points.
  for (std::size_t j = 0; j < 4; ++j) expect_near_vec(bezier_point(c, t[j]), Q[j], tol);
  // Without an interval the overload takes [min t, max t] = [0, 8.13].
  const BezierCurve same = bezier_interpolate(Q, t);
  EXPECT_EQ(same.a, 0.0);
  EXPECT_EQ(same.b, 8.13);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(same.P[i], c.P[i]);
}

TEST(BezierInterpolate, ReproducesItsPointsAndEqualsTheLagrangeCurve) {
  // X(t_j) = Q_j, and the interpolant is unique (ch. 1 §1.6: "the solution
  // could be computed using the Lagrange basis as well").
  std::mt19937 rng(261);
  std::uniform_real_distribution<double> jitter(0, 0.5), start(-2, 2), length(0.5, 3);
  for (int c = 0; c < kRandomCases; ++c) {
    const int r = c % 8;
    const double a = start(rng), b = a + length(rng);
    std::vector<double> t;
    std::vector<Vec3> Q;
    for (int j = 0; j <= r; ++j) {
      t.push_back(r == 0 ? a + jitter(rng) * (b - a) : a + (b - a) * (j + jitter(rng)) / (r + 0.5));
      Q.push_back(random_point(rng));
    }
    std::shuffle(t.begin(), t.end(), rng);  // the order of the conditions does not matter
    const BezierCurve curve = bezier_interpolate(Q, t, a, b);
    ASSERT_EQ(curve.P.size(), Q.size());
    // Round-off is relative to the control points, which can be much larger than Q.
    const double tol = kExact * scale_of(curve.P);
    for (std::size_t j = 0; j < Q.size(); ++j) expect_near_vec(bezier_point(curve, t[j]), Q[j], tol);
    for (int k = 0; k < kSamples; ++k) {
      const double u = sample(a, b, k);
      expect_near_vec(bezier_point(curve, u), lagrange_value(t, Q, u), tol);
    }
  }
}

// ---- edges ------------------------------------------------------------------------------------

// ---- convex hull (ch. 1 §1.6 property 1) ----------------------------------------

TEST(ConvexHullXy, SquareDropsInteriorAndEdgePointsCounterClockwise) {
  // Corners of the unit square given out of order, with its centre and the
  // midpoint of an edge: only the corners remain, counter-clockwise from the
  // lowest-leftmost one (Andrew 1979 keeps strict left turns only).
  const std::vector<Vec3> hull =
      convex_hull_xy({{1, 1, 0}, {0.5, 0.5, 0}, {0, 0, 0}, {0.5, 0, 0}, {0, 1, 0}, {1, 0, 0}});
  const std::vector<Vec3> want = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  ASSERT_EQ(hull.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(hull[i], want[i]) << i;
}

TEST(ConvexHullXy, LecturePolygonIsItsOwnHull) {
  // The lecture's control polygon (0,0), (2,4.5), (8.5,6.5), (11,2) is convex:
  // all four points are corners, in the order (0,0), (11,2), (8.5,6.5), (2,4.5).
  const std::vector<Vec3> hull = convex_hull_xy(lecture_cubic().P);
  const std::vector<Vec3> want = {{0, 0, 0}, {11, 2, 0}, {8.5, 6.5, 0}, {2, 4.5, 0}};
  ASSERT_EQ(hull.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(hull[i], want[i]) << i;
}

TEST(ConvexHullXy, DegenerateInputs) {
  // Collinear points: the two ends. Repeated points: one corner.
  const std::vector<Vec3> line = convex_hull_xy({{2, 2, 0}, {0, 0, 0}, {1, 1, 0}, {3, 3, 0}});
  ASSERT_EQ(line.size(), 2u);
  EXPECT_EQ(line[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(line[1], (Vec3{3, 3, 0}));
  EXPECT_EQ(convex_hull_xy({{1, 2, 0}, {1, 2, 0}}).size(), 1u);
  expect_contains(error_of([] { convex_hull_xy({}); }), "convex_hull_xy: no points");
  expect_contains(error_of([] { convex_hull_xy({{0, 0, 0}, {NAN, 1, 0}}); }), "P[1]=(nan, 1, 0) is not finite");
}

TEST(ConvexHullXy, EveryCurvePointLiesInTheHullOfItsControlPoints) {
  // Property 1 of ch. 1 §1.6 across random planar curves: no sample is to
  // the right of a counter-clockwise hull edge (beyond round-off).
  std::mt19937 rng(7);
  for (int c = 0; c < kRandomCases; ++c) {
    BezierCurve curve = random_curve(rng, c);
    for (Vec3& p : curve.P) p.z = 0;
    const std::vector<Vec3> hull = convex_hull_xy(curve.P);
    if (hull.size() < 3) continue;
    const double tol = kExact * scale_of(curve.P) * scale_of(curve.P);
    for (int k = 0; k < kSamples; ++k) {
      const Vec3 x = bezier_point(curve, sample(curve.a, curve.b, k));
      for (std::size_t e = 0; e < hull.size(); ++e) {
        const Vec3 a = hull[e], b = hull[(e + 1) % hull.size()];
        EXPECT_GE((b.x - a.x) * (x.y - a.y) - (b.y - a.y) * (x.x - a.x), -tol) << "case " << c << " k " << k;
      }
    }
  }
}

TEST(BezierEdge, DegreeZeroIsOnePoint) {
  BezierCurve c;
  c.P = {{1, 2, 3}};
  c.a = -1;
  c.b = 2;
  for (int k = 0; k < kSamples; ++k) EXPECT_EQ(bezier_point(c, sample(c.a, c.b, k)), c.P[0]);
  const DeCasteljau d = de_casteljau(c, 0.5);
  ASSERT_EQ(d.levels.size(), 1u);
  EXPECT_EQ(d.point, c.P[0]);
  EXPECT_EQ(bezier_derivative_at(c, 0.5, 1), Vec3{});
  EXPECT_EQ(bezier_derivatives(c, 0.5, 2), (std::vector<Vec3>{c.P[0], {}, {}}));
  const BezierSplit split = subdivide(c, 0.5);
  EXPECT_EQ(split.left.P, c.P);
  EXPECT_EQ(split.right.P, c.P);
  EXPECT_EQ(degree_elevate(c).P, (std::vector<Vec3>{c.P[0], c.P[0]}));
  EXPECT_EQ(bezier_integral(c), 3.0 * c.P[0]);  // (b - a) / 1 * b0
  EXPECT_EQ(bernstein_all(0, 0.3), std::vector<double>{1.0});
  const BezierCurve one = bezier_interpolate({{4, 5, 6}}, {0.25}, 0, 1);
  EXPECT_EQ(one.P, (std::vector<Vec3>{{4, 5, 6}}));
}

TEST(BezierEdge, ParameterAtTheEndsAndRoundOffPastThem) {
  const BezierCurve c = lecture_cubic(0.1, 0.7);
  EXPECT_EQ(bezier_point(c, 0.1), c.P.front());
  EXPECT_EQ(bezier_point(c, 0.7), c.P.back());
  EXPECT_EQ(de_casteljau(c, 0.7).s, 1.0);
  // One ulp past b (what a + i (b - a) / N can produce) counts as b ...
  const double past_b = std::nextafter(0.7, 1.0), before_a = std::nextafter(0.1, 0.0);
  EXPECT_EQ(bezier_point(c, past_b), c.P.back());
  EXPECT_EQ(bezier_point(c, before_a), c.P.front());
  // ... a visible step past it does not.
  expect_contains(error_of([&] { bezier_point(c, 0.7 + 1e-9); }), "(above b)");
}

// ---- errors name the values ---------------------------------------------------------------

TEST(BezierErrors, EmptyControlPoints) {
  const BezierCurve empty;
  expect_contains(error_of([&] { bezier_point(empty, 0.5); }), "bezier_point: no control points (P is empty)");
  expect_contains(error_of([&] { de_casteljau(empty, 0.5); }), "no control points");
  expect_contains(error_of([&] { degree_elevate(empty); }), "no control points");
  expect_contains(error_of([&] { bezier_integral(empty); }), "no control points");
  expect_contains(error_of([&] { validate(empty); }), "no control points");
  expect_contains(error_of([] { bezier_interpolate({}, {}, 0, 1); }), "no points to interpolate");
  expect_contains(error_of([] { bezier_from_monomial({}); }), "no coefficients");
}

TEST(BezierErrors, ParameterOutsideTheIntervalSaysWhichEnd) {
  const BezierCurve c = lecture_cubic();
  expect_contains(error_of([&] { bezier_point(c, 1.5); }), "bezier_point: t=1.5 is outside [a, b] = [0, 1] (above b)");
  expect_contains(error_of([&] { de_casteljau(c, -0.25); }), "t=-0.25 is outside [a, b] = [0, 1] (below a)");
  expect_contains(error_of([&] { bezier_derivatives(c, 2, 1); }), "t=2 is outside");
  expect_contains(error_of([&] { bezier_derivative_at(c, -1, 1); }), "(below a)");
  expect_contains(error_of([&] { bernstein(1, 3, 1.25); }), "bernstein: t=1.25 is outside [a, b] = [0, 1] (above b)");
  expect_contains(error_of([&] { bernstein_all(3, 4.0, 1, 3); }), "t=4 is outside [a, b] = [1, 3] (above b)");
  expect_contains(error_of([&] { subdivide(c, 0.0); }), "subdivide: t=0 is an end of [a, b] = [0, 1]");
  expect_contains(error_of([&] { subdivide(c, 1.0); }), "need a < t < b");
}

TEST(BezierErrors, NotFiniteValuesAreNamed) {
  BezierCurve c = lecture_cubic();
  expect_contains(error_of([&] { bezier_point(c, NAN); }), "bezier_point: t=nan is not finite");
  expect_contains(error_of([&] { bezier_point(c, INFINITY); }), "t=inf is not finite");
  c.P[1].y = NAN;
  expect_contains(error_of([&] { bezier_point(c, 0.5); }), "P[1]=(2, nan, 0) is not finite");
  c = lecture_cubic();
  c.b = INFINITY;
  expect_contains(error_of([&] { bezier_point(c, 0.5); }), "b=inf is not finite");
  expect_contains(error_of([] { bezier_interpolate({{0, 0, 0}, {1, NAN, 0}}, {0, 1}); }), "Q[1]=(1, nan, 0) is not finite");
  expect_contains(error_of([] { bezier_interpolate({{0, 0, 0}, {1, 1, 0}}, {0, NAN}); }), "t[1]=nan is not finite");
  expect_contains(error_of([] { bezier_from_monomial({{0, 0, 0}, {NAN, 0, 0}}); }), "c[1]=(nan, 0, 0) is not finite");
  expect_contains(error_of([] { bezier_antiderivative(lecture_cubic(), {NAN, 0, 0}); }), "start=(nan, 0, 0) is not finite");
}

TEST(BezierErrors, EmptyOrReversedInterval) {
  BezierCurve c = lecture_cubic(1, 1);
  expect_contains(error_of([&] { bezier_point(c, 1); }), "interval [a, b] = [1, 1] is empty (need a < b)");
  c = lecture_cubic(2, 1);
  expect_contains(error_of([&] { degree_elevate(c); }), "[a, b] = [2, 1] is empty");
  expect_contains(error_of([] { bernstein(0, 2, 0.5, 1, 0); }), "[a, b] = [1, 0] is empty");
  expect_contains(error_of([] { bezier_from_monomial({{1, 0, 0}}, 3, 3); }), "[a, b] = [3, 3] is empty");
}

TEST(BezierErrors, NegativeOrdersAndDegrees) {
  const BezierCurve c = lecture_cubic();
  expect_contains(error_of([&] { bezier_derivative(c, -1); }), "bezier_derivative: derivative order k=-1 is negative");
  expect_contains(error_of([&] { bezier_derivative_at(c, 0.5, -2); }), "derivative order k=-2 is negative");
  expect_contains(error_of([&] { bezier_derivatives(c, 0.5, -1); }), "derivative order d=-1 is negative");
  expect_contains(error_of([&] { bezier_start_derivative(c, -1); }), "k=-1 is negative");
  expect_contains(error_of([&] { bezier_end_derivative(c, -3); }), "k=-3 is negative");
  expect_contains(error_of([&] { degree_elevate(c, -1); }), "degree_elevate: times=-1 is negative");
  expect_contains(error_of([] { bernstein(0, -1, 0.5); }), "degree n=-1 is negative");
  expect_contains(error_of([] { bezier_matrix(-2); }), "degree n=-2 is negative");
}

TEST(BezierErrors, InterpolationData) {
  const std::vector<Vec3> Q = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
  expect_contains(error_of([&] { bezier_interpolate(Q, {0, 1}, 0, 1); }), "3 points but 2 parameters");
  expect_contains(error_of([&] { bezier_interpolate(Q, {0, 0.5, 0.5}, 0, 1); }), "t[1]=0.5 and t[2]=0.5 coincide");
  expect_contains(error_of([&] { bezier_interpolate(Q, {0, 0.5, 1.5}, 0, 1); }),
                  "t[2]=1.5 is outside [a, b] = [0, 1] (above b)");
  expect_contains(error_of([] { bezier_interpolate({{1, 1, 1}}, {0.5}); }), "pass a and b explicitly");
}

// ---- joining segments: continuation_points (ch. 1 §1.6 "Bézier splines"; notes "Higher Order Surfaces") ----

// The lecture's conditions at the joint of a cubic on [t_i, t_{i+1}] = [1, 3]
// (Delta_i = 2) and the next segment of length Delta_{i+1} = 3.
TEST(ContinuationPoints, SatisfyTheLecturesC1AndC2ConditionsAndEquations2And3) {
  const BezierCurve a = lecture_cubic(1, 3);
  const double d0 = 2, d1 = 3;
  const BezierContinuation c = continuation_points(a, 2, d1);
  ASSERT_EQ(c.points.size(), 3u);
  EXPECT_DOUBLE_EQ(c.tau, 2.5);  // (t_{i+2} - t_i) / Delta_i
  const Vec3 a1 = a.P[1], a2 = a.P[2], a3 = a.P[3], b0 = c.points[0], b1 = c.points[1], b2 = c.points[2];
  const double tol = kLecturePointTol;
  expect_near_vec(b0, a3, 0);                                                  // C0
  expect_near_vec((a3 - a2) / d0, (b1 - b0) / d1, tol);                        // C1
  expect_near_vec((a3 - 2 * a2 + a1) / (d0 * d0), (b2 - 2 * b1 + b0) / (d1 * d1), tol);  // C2
  // The lecture's eq. 1-3 with b_{3(i+1)} = a3: the de Boor point d and the next points.
  const Vec3 d = a2 + d1 / d0 * (a2 - a1);
  expect_near_vec(b1, a3 + d1 / d0 * (a3 - a2), tol);
  expect_near_vec(c.levels[1][0], d, tol);
  expect_near_vec(b2, b1 + d1 / d0 * (b1 - d), tol);
  // The construction lines: each level's point lies on the line through two of the previous.
  for (std::size_t r = 1; r < c.levels.size(); ++r)
    for (std::size_t j = 0; j < c.levels[r].size(); ++j)
      expect_near_vec(c.levels[r][j], lerp(c.levels[r - 1][j], c.levels[r - 1][j + 1], c.tau), tol);
}

// Property: the first k derivatives agree at the joint (bezier_end_derivative
// of a, bezier_start_derivative of the next segment over [b, b + L]) for
// random curves of degree 0..6 and every k <= n. With k = n all n + 1
// derivatives agree: the next segment is a's polynomial continued.
TEST(ContinuationPoints, DerivativesAgreeUpToOrderK) {
  std::mt19937 rng(41);
  for (int c = 0; c < kRandomCases; ++c) {
    const BezierCurve a = random_curve(rng, c, 6);
    const int n = bezier_degree(a);
    const double h = a.b - a.a, L = std::uniform_real_distribution<double>(0.3, 2.5)(rng);
    for (int k = 0; k <= n; ++k) {
      BezierCurve next;
      next.a = a.b;
      next.b = a.b + L;
      next.P = continuation_points(a, k, L).points;
      while (static_cast<int>(next.P.size()) <= n) next.P.push_back(random_point(rng));
      // de Casteljau at tau > 1 grows round-off by up to (2 tau - 1) per level,
      // and an r-th derivative is the points times (n / interval)^r.
      const double tau = 1 + L / h;
      for (int r = 0; r <= k; ++r)
        expect_near_vec(bezier_start_derivative(next, r), bezier_end_derivative(a, r),
                        kExact * scale_of(a.P) * std::pow(2 * tau - 1, n) * std::pow(n / std::min(h, L), r));
    }
  }
}

// Notes "Higher Order Surfaces": G1 is p_n - p_{n-1} = k (r_1 - r_0); it is the C1 point for a next
// interval of Delta_i / k (the same direction, another speed).
TEST(ContinuationPoints, G1WithFactorKIsTheC1PointForLengthDeltaOverK) {
  const BezierCurve a = lecture_cubic(0, 2);
  for (double k : {0.5, 1.0, 2.0, 3.0}) {
    const std::vector<Vec3> r = continuation_points(a, 1, (a.b - a.a) / k).points;
    expect_near_vec(a.P[3] - a.P[2], k * (r[1] - r[0]), kLecturePointTol);
  }
}

TEST(ContinuationPoints, ErrorsNameKAndTheLength) {
  const BezierCurve a = lecture_cubic();
  EXPECT_ERROR_HAS(continuation_points(a, 4, 1), "continuity k=4 must lie in [0, 3]");
  EXPECT_ERROR_HAS(continuation_points(a, -1, 1), "continuity k=-1");
  EXPECT_ERROR_HAS(continuation_points(a, 1, 0), "next_length=0 must be > 0");
  EXPECT_ERROR_HAS(continuation_points(a, 1, std::nan("")), "next_length=nan is not finite");
}

// kMaxBezierDegree: degree 64 is a curve, 65 is refused with one line, by every
// entry point that would build or evaluate one (issue 20: degree 20,000 took 8 s
// and 4.7 GB for one point).
TEST(BezierLimits, DegreeAboveTheLimitIsRefused) {
  BezierCurve ok;
  for (int i = 0; i <= kMaxBezierDegree; ++i) ok.P.push_back({double(i), 0, 0});
  EXPECT_NO_THROW(validate(ok));
  EXPECT_NEAR(bezier_point(ok, 0.5).x, kMaxBezierDegree / 2.0, 1e-12);  // linear precision
  BezierCurve too_high = ok;
  too_high.P.push_back({0, 0, 0});
  expect_contains(error_of([&] { validate(too_high); }), "degree n=65 is above the limit of 64");
  expect_contains(error_of([&] { bezier_point(too_high, 0.5); }), "degree n=65");
  expect_contains(error_of([&] { degree_elevate(ok, 1); }), "degree n=65");
  expect_contains(error_of([] { bernstein(0, 1000000000, 0.5); }), "degree n=1000000000");
  expect_contains(error_of([] { bernstein_all(65, 0.5); }), "degree n=65");
  expect_contains(error_of([] { bezier_matrix(65); }), "degree n=65");
}

}  // namespace
}  // namespace gllab::spline
