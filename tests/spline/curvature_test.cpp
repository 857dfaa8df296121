// tests/spline/curvature_test.cpp — common/spline/curvature.{h,cpp}.
//
// Expected values come from curves whose curvature is known in closed form
// (do Carmo, "Differential Geometry of Curves and Surfaces", §1-5): a circle of
// radius r has curvature 1/r at any speed, a line 0, the helix
// (a cos u, a sin u, b u) has a / (a^2 + b^2); and from the property that the
// curvature does not depend on the parameterization (the lecture cubic on [0, 1]
// and on [2, 7]).
#include "spline_test_support.h"
#include "spline/curvature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "spline/bezier.h"

namespace gllab::spline {
namespace {

using testing::error_of;
using testing::expect_contains;
using testing::expect_near_vec;
using testing::kRounding;

// A handful of products and one division of numbers near 1: a few units of
// round-off relative to the result.
constexpr double kFewUlps = 8 * kRounding;

// X(u) = (r cos(w u), r sin(w u), 0): X' = r w (-sin, cos), X'' = -r w^2 (cos, sin).
struct CirclePoint {
  Vec3 d1, d2, towards_centre;
};
CirclePoint circle(double r, double w, double u) {
  const double c = std::cos(w * u), s = std::sin(w * u);
  return {{-r * w * s, r * w * c, 0}, {-r * w * w * c, -r * w * w * s, 0}, {-c, -s, 0}};
}

TEST(Curvature, CircleIsOneOverRadiusAtAnySpeed) {
  for (double w : {0.25, 1.0, 3.0, -2.0})
    for (double u : {0.0, 0.7, 2.0}) {
      const CirclePoint p = circle(2.0, w, u);
      EXPECT_NEAR(curvature(p.d1, p.d2), 0.5, kFewUlps) << "w " << w << " u " << u;
      // Counter-clockwise (w > 0) turns left: +1/r; clockwise: -1/r.
      EXPECT_NEAR(signed_curvature(p.d1, p.d2), w > 0 ? 0.5 : -0.5, kFewUlps) << "w " << w;
      // The curvature vector points to the centre, length 1/r.
      expect_near_vec(curvature_vector(p.d1, p.d2), 0.5 * p.towards_centre, kFewUlps);
    }
}

TEST(Curvature, StraightLineIsZero) {
  // d2 parallel to d1 (a line run at changing speed): no bending.
  EXPECT_EQ(curvature({1, 2, 3}, {2, 4, 6}), 0);
  EXPECT_EQ(signed_curvature({1, 2, 0}, {-3, -6, 0}), 0);
  EXPECT_EQ(curvature_vector({1, 0, 0}, {5, 0, 0}), (Vec3{0, 0, 0}));
}

TEST(Curvature, HelixIsAOverASquaredPlusBSquared) {
  // do Carmo §1-5: the helix (a cos u, a sin u, b u) has curvature a / (a^2 + b^2).
  const double a = 2, b = 1.5, u = 0.8;
  const Vec3 d1{-a * std::sin(u), a * std::cos(u), b}, d2{-a * std::cos(u), -a * std::sin(u), 0};
  EXPECT_NEAR(curvature(d1, d2), a / (a * a + b * b), kFewUlps);
  // Its principal normal points to the axis, horizontally.
  expect_near_vec(curvature_vector(d1, d2), a / (a * a + b * b) * Vec3{-std::cos(u), -std::sin(u), 0}, kFewUlps);
  // The signed planar curvature is the projection's: the circle of radius a.
  EXPECT_NEAR(signed_curvature(d1, d2), 1 / a, kFewUlps);
}

TEST(Curvature, DoesNotDependOnTheParameterization) {
  // The lecture cubic (ch. 1 §1.6, de Casteljau example) at t = 0.6 on [0, 1]
  // and at the same point, t = 5, on [2, 7]: derivatives scale by 1/5 and
  // 1/25 there ("Generalization"), the curvature must not change.
  BezierCurve c;
  c.P = {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}};
  const std::vector<Vec3> unit = bezier_derivatives(c, 0.6, 2);
  c.a = 2;
  c.b = 7;
  const std::vector<Vec3> wide = bezier_derivatives(c, 5.0, 2);
  const double k = signed_curvature(unit[1], unit[2]);
  EXPECT_LT(k, 0);  // the lecture cubic turns right (clockwise) at 0.6
  EXPECT_NEAR(signed_curvature(wide[1], wide[2]), k, kFewUlps * std::fabs(k));
  EXPECT_NEAR(curvature(wide[1], wide[2]), -k, kFewUlps * std::fabs(k));
}

TEST(CurvatureErrors, NoTangentOrNotFinite) {
  expect_contains(error_of([] { curvature({0, 0, 0}, {1, 0, 0}); }),
                  "curvature: d1=(0, 0, 0) is zero (no tangent: the curve is not regular here)");
  expect_contains(error_of([] { curvature_vector({0, 0, 0}, {1, 0, 0}); }), "curvature_vector: d1=(0, 0, 0) is zero");
  expect_contains(error_of([] { signed_curvature({0, 0, 1}, {1, 0, 0}); }),
                  "signed_curvature: d1=(0, 0, 1) has no xy component");
  expect_contains(error_of([] { curvature({NAN, 0, 0}, {1, 0, 0}); }), "d1=(nan, 0, 0) is not finite");
  expect_contains(error_of([] { signed_curvature({1, 0, 0}, {0, INFINITY, 0}); }), "d2=(0, inf, 0) is not finite");
}

}  // namespace
}  // namespace gllab::spline
