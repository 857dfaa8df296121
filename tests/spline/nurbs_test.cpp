// tests/spline/nurbs_test.cpp — NURBS helpers (common/spline/nurbs.cpp):
// homogeneous points, conic sections by the lecture's r, the exact circle.
//
// Every expected value names its origin: ch. 1 §1.6 ("Conic sections"),
// The NURBS Book (Piegl & Tiller, 2nd ed.) §7.5 for the circle, a closed
// form derived in the comment, or an implicit-equation check.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/nurbs.h"
#include "spline_test_support.h"

namespace gllab::spline {
namespace {

using testing::error_of;
using testing::kRounding;
using testing::kSameCurve;

// ---- tolerances (named, never loosened to pass) -----------------------------

/// The exact circle: every point at distance radius from the centre (the card
/// asks 1e-14 for the unit circle), relative to the radius.
constexpr double kCircle = 1e-14;
/// A point on a conic satisfies its implicit equation to this, relative to the
/// size of the coefficients times the squared size of the coordinates.
constexpr double kConicResidual = 1e-12;
/// The discriminant B^2 - 4AC counts as zero (parabola) below this, relative
/// to A^2 + B^2 + C^2; ellipses and hyperbolas here are far beyond it.
constexpr double kDiscriminantZero = 1e-10;
// kRounding and kSameCurve: spline_test_support.h.

constexpr int kSamples = 1001;

double dist(Vec3 a, Vec3 b) { return norm(a - b); }

// ---- homogeneous form -----------------------------------------------------------

TEST(Homogeneous, PremultipliedPointsForGlu) {
  // docs/glu.md: GLU takes (w x, w y, w z, w).
  BsplineCurve c;
  c.p = 2;
  c.U = {0, 0, 0, 1, 1, 1};
  c.P = {{1, 2, 3}, {4, 5, 6}, {-1, 0, 2}};
  c.w = {1, 0.5, 2};
  const std::vector<Vec4> Pw = to_homogeneous(c);
  ASSERT_EQ(Pw.size(), 3u);
  EXPECT_EQ(Pw[0], (Vec4{1, 2, 3, 1}));
  EXPECT_EQ(Pw[1], (Vec4{2, 2.5, 3, 0.5}));
  EXPECT_EQ(Pw[2], (Vec4{-2, 0, 4, 2}));
  // A polynomial curve has w = 1.
  c.w.clear();
  EXPECT_EQ(to_homogeneous(c)[1], (Vec4{4, 5, 6, 1}));
}

TEST(Homogeneous, RoundTripKeepsTheCurve) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-10, 10), weight(0.2, 5);
  for (int trial = 0; trial < 100; ++trial) {
    BsplineCurve c;
    c.p = 1 + trial % 4;
    const int n = c.p + trial % 5;
    for (int i = 0; i <= n; ++i) {
      c.P.push_back({coord(rng), coord(rng), coord(rng)});
      c.w.push_back(weight(rng));
    }
    c.U = clamped_uniform_knots(n, c.p);
    const BsplineCurve back = from_homogeneous(c.p, c.U, to_homogeneous(c));
    ASSERT_EQ(back.P.size(), c.P.size());
    for (std::size_t i = 0; i < c.P.size(); ++i) {
      EXPECT_LE(dist(back.P[i], c.P[i]), 4 * kRounding * 10) << "point " << i;
      EXPECT_EQ(back.w[i], c.w[i]);
    }
  }
}

TEST(Homogeneous, ZeroOrNegativeWeightIsNamed) {
  const std::vector<double> U = {0, 0, 0, 1, 1, 1};
  EXPECT_ERROR_HAS(from_homogeneous(2, U, {{0, 0, 0, 1}, {1, 1, 0, 0}, {2, 0, 0, 1}}), "Pw[1].w=0 must be > 0");
  EXPECT_ERROR_HAS(from_homogeneous(2, U, {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, -2}}), "Pw[2].w=-2 must be > 0");
  EXPECT_ERROR_HAS(from_homogeneous(2, U, {{0, 0, 0, 1}, {1, 1, 0, std::nan("")}, {2, 0, 0, 1}}),
                   "Pw[1].w=nan is not finite");
  EXPECT_ERROR_HAS(from_homogeneous(2, U, {}), "no control points (empty input)");
}

// ---- conic sections by r (ch. 1 §1.6) ------------------------------------------

/// det of an n x n matrix (Gaussian elimination with partial pivoting).
double det(std::vector<std::vector<double>> a) {
  const std::size_t n = a.size();
  double d = 1;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
    if (a[piv][c] == 0) return 0;
    if (piv != c) {
      std::swap(a[piv], a[c]);
      d = -d;
    }
    d *= a[c][c];
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
    }
  }
  return d;
}

/// The conic A x^2 + B xy + C y^2 + D x + E y + F = 0 through five points:
/// the coefficients are the signed 5 x 5 minors of the 5 x 6 system.
std::vector<double> conic_through(const std::vector<Vec3>& pts) {
  std::vector<std::vector<double>> rows;
  for (const Vec3& q : pts) rows.push_back({q.x * q.x, q.x * q.y, q.y * q.y, q.x, q.y, 1});
  std::vector<double> coef(6);
  for (int j = 0; j < 6; ++j) {
    std::vector<std::vector<double>> minor;
    for (const auto& r : rows) {
      std::vector<double> m;
      for (int k = 0; k < 6; ++k)
        if (k != j) m.push_back(r[k]);
      minor.push_back(m);
    }
    coef[j] = (j % 2 == 0 ? 1 : -1) * det(minor);
  }
  double size = 0;
  for (double v : coef) size = std::max(size, std::abs(v));
  for (double& v : coef) v /= size;
  return coef;
}

double conic_value(const std::vector<double>& k, Vec3 q) {
  return k[0] * q.x * q.x + k[1] * q.x * q.y + k[2] * q.y * q.y + k[3] * q.x + k[4] * q.y + k[5];
}

/// Fits the conic through 5 points of the arc, checks that every sampled point
/// satisfies it, and returns the type its discriminant B^2 - 4AC gives.
ConicType implicit_type(const BsplineCurve& arc) {
  std::vector<Vec3> five;
  for (double u : {0.0, 0.2, 0.5, 0.7, 1.0}) five.push_back(curve_point(arc, u));
  const std::vector<double> k = conic_through(five);
  double scale = 1;
  for (const Vec3& q : arc.P) scale = std::max({scale, std::abs(q.x), std::abs(q.y)});
  for (double u : uniform_params(arc, kSamples)) {
    const double residual = conic_value(k, curve_point(arc, u));
    EXPECT_LE(std::abs(residual), kConicResidual * scale * scale) << "u=" << u;
  }
  const double A = k[0], B = k[1], C = k[2];
  const double disc = B * B - 4 * A * C;
  const double size = A * A + B * B + C * C;
  if (std::abs(disc) <= kDiscriminantZero * size) return ConicType::Parabola;
  return disc < 0 ? ConicType::Ellipse : ConicType::Hyperbola;
}

TEST(Conic, ClassificationByR) {
  // Ch. 1 §1.6: r > 1/2 hyperbola, r = 1/2 parabola, r < 1/2 ellipse, r = 0 line.
  EXPECT_EQ(classify_conic(0.0), ConicType::Line);
  EXPECT_EQ(classify_conic(0.25), ConicType::Ellipse);
  EXPECT_EQ(classify_conic(0.5), ConicType::Parabola);
  EXPECT_EQ(classify_conic(0.75), ConicType::Hyperbola);
  EXPECT_STREQ(to_string(ConicType::Hyperbola), "hyperbola");
  // The middle weight r / (1 - r): 1/3, 1, 3.
  EXPECT_NEAR(conic_weight(0.25), 1.0 / 3, kRounding);
  EXPECT_EQ(conic_weight(0.5), 1.0);
  EXPECT_EQ(conic_weight(0.75), 3.0);
  EXPECT_EQ(conic_r(1.0), 0.5);
  EXPECT_ERROR_HAS(classify_conic(1.0), "r=1 must satisfy 0 <= r < 1");
  EXPECT_ERROR_HAS(conic_weight(-0.125), "r=-0.125 must satisfy 0 <= r < 1");
  EXPECT_ERROR_HAS(classify_conic(std::nan("")), "r=nan is not finite");
  EXPECT_ERROR_HAS(conic_r(-1.0), "w1=-1 must be >= 0");
}

TEST(Conic, ImplicitEquationAgreesWithRAcrossRandomTriangles) {
  // For random control triangles and r on both sides of 1/2, the implicit
  // conic through the arc has the type the lecture gives for r.
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> coord(-5, 5);
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3 P0{coord(rng), coord(rng), 0}, P1{coord(rng), coord(rng), 0}, P2{coord(rng), coord(rng), 0};
    if (std::abs(cross(Vec2{P1.x - P0.x, P1.y - P0.y}, Vec2{P2.x - P0.x, P2.y - P0.y})) < 1.0) continue;  // thin
    for (double r : {0.1, 0.3, 0.45, 0.5, 0.55, 0.7, 0.9}) {
      const BsplineCurve arc = conic_arc(P0, P1, P2, r, 2);
      EXPECT_EQ(implicit_type(arc), classify_conic(r)) << "r=" << r << " trial " << trial;
    }
  }
}

TEST(Conic, HalfGivesTheParabolaYEqualsXSquared) {
  // r = 1/2 (w1 = 1) on P0 = (-1, 1), P1 = (0, -1), P2 = (1, 1): by hand,
  // x(u) = 2u - 1 and y(u) = (1-u)^2 - 2u(1-u) + u^2 = (2u - 1)^2, so y = x^2.
  const BsplineCurve arc = conic_arc({-1, 1, 0}, {0, -1, 0}, {1, 1, 0}, 0.5, 2);
  for (double u : uniform_params(arc, kSamples)) {
    const Vec3 q = curve_point(arc, u);
    EXPECT_NEAR(q.y, q.x * q.x, 4 * kRounding) << "u=" << u;
    EXPECT_NEAR(q.x, 2 * u - 1, 4 * kRounding) << "u=" << u;
  }
}

TEST(Conic, BelowHalfGivesTheQuarterCircle) {
  // w1 = sqrt(2)/2 on (1,0), (1,1), (0,1) is the unit quarter circle (The NURBS
  // Book §7.5); its r = w1 / (1 + w1) = 0.414... < 1/2: an ellipse, as the lecture says.
  const double w1 = std::sqrt(2.0) / 2;
  const double r = conic_r(w1);
  EXPECT_EQ(classify_conic(r), ConicType::Ellipse);
  const BsplineCurve arc = conic_arc({1, 0, 0}, {1, 1, 0}, {0, 1, 0}, r, 2);
  EXPECT_NEAR(arc.w[1], w1, kRounding);
  for (double u : uniform_params(arc, kSamples)) {
    const Vec3 q = curve_point(arc, u);
    EXPECT_NEAR(std::hypot(q.x, q.y), 1.0, kCircle) << "u=" << u;
  }
}

TEST(Conic, AboveHalfGivesTheHyperbolaXSquaredMinusYSquared) {
  // The branch x^2 - y^2 = 1 from (c, -s) to (c, s), c = cosh 1, s = sinh 1.
  // The tangents x c -/+ y s = 1 meet at the apex (1/c, 0); the shoulder
  // point (u = 1/2) is the vertex (1, 0) when (2c + 2 w1 / c) / (2 + 2 w1) = 1,
  // i.e. w1 = c > 1, so r = c / (1 + c) > 1/2: a hyperbola, as the lecture says.
  const double c = std::cosh(1.0), s = std::sinh(1.0);
  const double r = c / (1 + c);
  EXPECT_EQ(classify_conic(r), ConicType::Hyperbola);
  const BsplineCurve arc = conic_arc({c, -s, 0}, {1 / c, 0, 0}, {c, s, 0}, r, 2);
  for (double u : uniform_params(arc, kSamples)) {
    const Vec3 q = curve_point(arc, u);
    EXPECT_NEAR(q.x * q.x - q.y * q.y, 1.0, 16 * kRounding) << "u=" << u;
  }
  const Vec3 vertex = curve_point(arc, 0.5);
  EXPECT_NEAR(vertex.x, 1.0, 4 * kRounding);
  EXPECT_NEAR(vertex.y, 0.0, 4 * kRounding);
}

TEST(Conic, ZeroGivesTheStraightSegment) {
  // r = 0: weight 0 on the apex; the lecture's curve is the segment P0P2, from
  // conic_point directly and from conic_arc (a polynomial with midpoint apex).
  const Vec3 P0{0, 0, 0}, P1{3, 4, 0}, P2{4, 0, 0};
  const BsplineCurve arc = conic_arc(P0, P1, P2, 0.0, 2);
  EXPECT_FALSE(arc.rational());
  EXPECT_EQ(arc.P[1], (Vec3{2, 0, 0}));
  for (int k = 0; k <= 100; ++k) {
    const double u = k / 100.0;
    for (const Vec3 q : {conic_point(P0, P1, P2, 0.0, u), curve_point(arc, u)}) {
      EXPECT_NEAR(q.y, 0.0, kRounding) << "u=" << u;
      EXPECT_GE(q.x, 0.0);
      EXPECT_LE(q.x, 4.0);
    }
  }
}

TEST(Conic, ArcEqualsTheLectureFormula) {
  // conic_arc (evaluated by A4.1) and conic_point (the lecture formula) agree.
  const Vec3 P0{-2, 1, 0}, P1{0.5, 3, 0}, P2{3, -1, 0};
  for (double r : {0.1, 0.3, 0.5, 0.7, 0.95}) {
    const BsplineCurve arc = conic_arc(P0, P1, P2, r, 2);
    for (int k = 0; k <= 100; ++k) {
      const double u = k / 100.0;
      EXPECT_LE(dist(curve_point(arc, u), conic_point(P0, P1, P2, r, u)), 8 * kRounding * 3) << "r=" << r;
    }
  }
  EXPECT_ERROR_HAS(conic_point(P0, P1, P2, 0.5, 1.5), "u=1.5 is outside the domain [0, 1]");
}

// ---- the exact circle -----------------------------------------------------------------

TEST(Circle, NineControlPointsOfTheNurbsBook) {
  // The NURBS Book §7.5: degree 2, 9 points, weights 1, √2/2 alternating,
  // knots {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}.
  const BsplineCurve c = circle();
  EXPECT_EQ(c.p, 2);
  EXPECT_EQ(c.dimension, 2);
  const std::vector<double> U = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  EXPECT_EQ(c.U, U);
  ASSERT_EQ(c.P.size(), 9u);
  const std::vector<Vec3> P = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}, {-1, 0, 0},
                               {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
  for (int i = 0; i < 9; ++i) {
    EXPECT_EQ(c.P[i], P[i]) << "point " << i;
    EXPECT_EQ(c.w[i], i % 2 == 0 ? 1.0 : std::sqrt(2.0) / 2) << "weight " << i;
  }
}

TEST(Circle, EverySampledPointIsAtDistanceOne) {
  // 100001 parameters by the batched evaluator, 1001 by curve_point.
  const BsplineCurve c = circle();
  std::vector<Vec3> pts;
  curve_points(c, uniform_params(c, 100001), pts);
  double worst = 0;
  for (const Vec3& q : pts) worst = std::max(worst, std::abs(norm(q) - 1.0));
  EXPECT_LE(worst, kCircle);
  for (double u : uniform_params(c, kSamples)) EXPECT_NEAR(norm(curve_point(c, u)), 1.0, kCircle) << "u=" << u;
}

TEST(Circle, QuarterParametersAreTheAxisPoints) {
  // The knots k/4 are where the arcs meet: (1,0), (0,1), (-1,0), (0,-1), (1,0).
  const BsplineCurve c = circle();
  const Vec3 axis[5] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}};
  for (int k = 0; k <= 4; ++k) EXPECT_LE(dist(curve_point(c, k / 4.0), axis[k]), kRounding) << "u=" << k / 4.0;
}

TEST(Circle, OffsetCentreAndRadius) {
  const Vec3 centre{3, -2, 0.5};
  const double radius = 2.5;
  const BsplineCurve c = circle(centre, radius);
  EXPECT_EQ(c.dimension, 3);
  for (double u : uniform_params(c, kSamples)) {
    const Vec3 q = curve_point(c, u);
    EXPECT_NEAR(norm(q - centre), radius, kCircle * radius * 4) << "u=" << u;  // coordinates up to 5.5: 4 ulps
    EXPECT_EQ(q.z, 0.5);
  }
  EXPECT_ERROR_HAS(circle({}, 0.0), "circle: radius=0 must be > 0");
  EXPECT_ERROR_HAS(circle({}, -1.0), "circle: radius=-1 must be > 0");
}

TEST(Circle, DerivativesAreTangentAndMatchTheEndpointFormula) {
  // C'(u) is perpendicular to C(u) - centre (A4.2). At u = 0 the first arc is a
  // rational Bézier on [0, 1/4]; differentiating the quotient by hand gives
  // C'(0) = p / (1/4) * (w1 / w0) * (P1 - P0) = 8 * (√2/2) * (0, 1) = (0, 4√2).
  const BsplineCurve c = circle();
  for (double u : uniform_params(c, kSamples)) {
    const auto d = curve_derivs(c, u, 2);
    EXPECT_LE(std::abs(dot(d[1], d[0])), 64 * kRounding * norm(d[1])) << "u=" << u;
    EXPECT_GT(norm(d[1]), 1.0);
  }
  const Vec3 d0 = curve_derivs(c, 0.0, 1)[1];
  EXPECT_NEAR(d0.x, 0.0, 8 * kRounding);
  EXPECT_NEAR(d0.y, 4 * std::sqrt(2.0), 8 * kRounding * 8);
}

TEST(Circle, KnotInsertionAndElevationKeepTheCircle) {
  // Rational algorithms run on Pw (A5.1, A5.4, A5.9): the result is still the
  // unit circle and still the same curve.
  const BsplineCurve c = circle();
  const std::vector<BsplineCurve> changed = {knot_insert(c, 0.1), knot_insert(c, 0.6, 2),
                                             knot_refine(c, {0.05, 0.3, 0.3, 0.9}), degree_elevate(c, 1),
                                             degree_elevate(c, 3), reversed(c)};
  for (std::size_t j = 0; j < changed.size(); ++j) {
    for (double u : uniform_params(c, kSamples)) {
      const Vec3 q = curve_point(changed[j], u);
      EXPECT_NEAR(norm(q), 1.0, kSameCurve) << "variant " << j << " u=" << u;
      if (j + 1 < changed.size()) {  // the last one, reversed(c), runs the other way
        EXPECT_LE(dist(q, curve_point(c, u)), kSameCurve) << "variant " << j << " u=" << u;
      }
    }
  }
  // Split at a quarter: each half keeps its part of the circle.
  const auto [a, b] = split(c, 0.25);
  EXPECT_LE(dist(curve_point(a, 0.25), Vec3{0, 1, 0}), kSameCurve);
  EXPECT_LE(dist(curve_point(b, 0.25), Vec3{0, 1, 0}), kSameCurve);
}

}  // namespace
}  // namespace gllab::spline
