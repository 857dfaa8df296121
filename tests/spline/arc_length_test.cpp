// tests/spline/arc_length_test.cpp — arc length, its inverse and equal-length
// steps (common/spline/arc_length.cpp).
//
// Every expected value names its origin: a circle's circumference 2 pi r and
// arc r theta (the NURBS circle's angle is not proportional to u, so the
// inverse is really tested), a straight line's length |X(u) - X(0)| whatever
// its speed, the closed-form length of the parabola y = x^2 (calculus), or a
// property (s and u invert each other; the error estimate bounds the error).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "spline/arc_length.h"
#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/nurbs.h"
#include "spline_test_support.h"

namespace gllab::spline {
namespace {

using testing::error_of;

// ---- tolerances (named, never loosened to pass) -----------------------------

/// Length against a closed form, relative: the Gauss rule's own error on the
/// accepted panels is below the 1e-14 asked; the sum of 8 to 100 panel values
/// adds a few roundings more.
constexpr double kLength = 2e-14;
/// The bound for the inverse s -> u, in units of the curve (absolute
/// for the radius-1 to 3 circles below).
constexpr double kInverse = 1e-12;

const double kPi = std::acos(-1.0);

/// The angle of p about c in [0, 2 pi).
double angle_of(Vec3 p, Vec3 c) {
  const double a = std::atan2(p.y - c.y, p.x - c.x);
  return a < 0 ? a + 2 * kPi : a;
}

TEST(ArcLength, CircleIsTwoPiR) {
  for (double r : {0.25, 1.0, 3.0, 1000.0}) {
    const ArcLength al(circle({1, -2, 0}, r));
    EXPECT_NEAR(al.length(), 2 * kPi * r, kLength * 2 * kPi * r) << "r = " << r;
    EXPECT_LE(al.error_estimate(), kLength * al.length()) << "r = " << r;
  }
}

// s -> u -> point: the point's angle times r is s, to 1e-12. The NURBS circle's
// speed is not constant (it is highest at the ends of each quarter, lowest in its
// middle, a ratio of 2 (2 - sqrt 2) = 1.17), so u is not s / (2 pi r).
TEST(ArcLength, InverseOnTheCircleGivesTheAngle) {
  for (double r : {1.0, 3.0}) {
    const Vec3 c{0.5, 0.25, 0};
    const BsplineCurve curve = circle(c, r);
    const ArcLength al(curve);
    double speed_min = 1e300, speed_max = 0;
    for (int k = 0; k < 1000; ++k) {
      const double s = al.length() * k / 1000;
      const double u = al.u(s);
      EXPECT_NEAR(angle_of(curve_point(curve, u), c) * r, s, kInverse) << "r = " << r << ", k = " << k;
      speed_min = std::min(speed_min, al.speed(u));
      speed_max = std::max(speed_max, al.speed(u));
    }
    EXPECT_NEAR(speed_max / speed_min, 2 * (2 - std::sqrt(2.0)), 1e-6) << "the test needs a speed that varies";
    EXPECT_EQ(al.u(al.length()), 1.0);
    EXPECT_EQ(al.u(0), 0.0);
  }
}

TEST(ArcLength, SAndUInvertEachOther) {
  const BsplineCurve curve =
      clamped_curve({{0, 0, 0}, {1, 2, 0.5}, {3, -1, 1}, {4, 3, 0}, {6, 0, -1}, {7, 1, 0}}, 3);
  const ArcLength al(curve);
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 2000; ++k) {
    const double u = unit(rng);
    EXPECT_NEAR(al.u(al.s(u)), u, kInverse) << "u = " << u;
  }
  // s is increasing and additive over the panels.
  double last = -1;
  for (int k = 0; k <= 400; ++k) {
    const double s = al.s(k / 400.0);
    EXPECT_GT(s, last);
    last = s;
  }
  EXPECT_EQ(al.s(1.0), al.length());
}

// A straight line run at a very uneven speed (control points bunched at one
// end): its length from X(0) to X(u) is the distance |X(u) - X(0)| for every u.
TEST(ArcLength, StraightLineAtUnevenSpeedIsTheDistance) {
  const Vec3 dir = normalized(Vec3{3, 4, 12});
  const BsplineCurve line = clamped_curve({0.0 * dir, 0.01 * dir, 0.02 * dir, 5.0 * dir}, 3);
  const ArcLength al(line);
  EXPECT_NEAR(al.length(), 5.0, kLength * 5);
  for (int k = 0; k <= 100; ++k) {
    const double u = k / 100.0;
    EXPECT_NEAR(al.s(u), norm(curve_point(line, u)), kLength * 5) << "u = " << u;
  }
  // Equal steps of s are equal steps along the line, though the speed varies 500-fold.
  const std::vector<double> steps = al.equal_steps(11);
  for (int k = 0; k <= 10; ++k) EXPECT_NEAR(norm(curve_point(line, steps[k])), 0.5 * k, kInverse);
  EXPECT_GT(al.speed(1.0) / al.speed(0.0), 400.0);
}

// y = x^2 on [0, 1] as the quadratic Bézier (0,0), (1/2,0), (1,1):
// length integral_0^1 sqrt(1 + 4x^2) dx = (2 sqrt 5 + asinh 2) / 4.
TEST(ArcLength, ParabolaHasItsClosedFormLength) {
  const ArcLength al(clamped_curve({{0, 0, 0}, {0.5, 0, 0}, {1, 1, 0}}, 2));
  const double exact = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4;
  EXPECT_NEAR(al.length(), exact, kLength * exact);
  EXPECT_NEAR(al.s(0.5), (std::sqrt(2.0) + std::asinh(1.0)) / 4, kLength * exact);  // to x = 1/2
}

// A coarse tolerance: the estimate still bounds the true error (against the
// default table), and a finer tolerance never gives fewer panels.
TEST(ArcLength, ErrorEstimateBoundsTheError) {
  const BsplineCurve wiggle = clamped_curve(
      {{0, 0, 0}, {1, 3, 0}, {2, -3, 0}, {3, 3, 0}, {4, -3, 0}, {5, 3, 0}, {6, 0, 0}}, 5);
  const ArcLength fine(wiggle);
  std::size_t panels = 0;
  for (double tol : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10}) {
    const ArcLength coarse(wiggle, tol);
    EXPECT_LE(std::fabs(coarse.length() - fine.length()), coarse.error_estimate() + 1e-13)
        << "tolerance " << tol;
    EXPECT_LE(coarse.error_estimate(), tol * coarse.length() * coarse.panels()) << "tolerance " << tol;
    EXPECT_GE(coarse.panels(), panels);
    panels = coarse.panels();
  }
}

// A cubic with a cusp (speed 0 at one u): the speed has a kink there, the
// panels pile up around it, and the inverse (Newton with a zero derivative)
// falls back to bisection and still inverts.
TEST(ArcLength, CuspIsHandled) {
  const BsplineCurve cusp = clamped_curve({{0, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0}}, 3);
  const ArcLength al(cusp);
  // The cusp is at u = 1/2: X'(1/2) = 3/4 ((P1 - P0) + 2 (P2 - P1) + (P3 - P2)) = 0.
  EXPECT_NEAR(al.speed(0.5), 0.0, 1e-15);
  // By symmetry about u = 1/2 (the net is symmetric under x -> 1 - x, u -> 1 - u), s(1/2) = L / 2.
  EXPECT_NEAR(al.s(0.5), al.length() / 2, 1e-13);
  EXPECT_NEAR(al.u(al.length() / 2), 0.5, kInverse);
  EXPECT_LT(al.panels(), kArcLengthMaxPanels);
  for (int k = 0; k <= 100; ++k) EXPECT_NEAR(al.u(al.s(k / 100.0)), k / 100.0, kInverse);
}

TEST(ArcLength, EqualStepsOnTheCircleAreEqualChords) {
  const double r = 2;
  const BsplineCurve curve = circle({}, r);
  const std::vector<double> u = ArcLength(curve).equal_steps(13);  // 12 arcs of 30 degrees
  ASSERT_EQ(u.size(), 13u);
  const double chord = 2 * r * std::sin(kPi / 12);
  for (int k = 0; k < 12; ++k)
    EXPECT_NEAR(norm(curve_point(curve, u[k + 1]) - curve_point(curve, u[k])), chord, kInverse) << k;
}

TEST(ArcLength, BadInputIsNamed) {
  const BsplineCurve curve = circle({}, 1);
  EXPECT_ERROR_HAS(ArcLength(curve, 0.0), "tolerance=0");
  EXPECT_ERROR_HAS(ArcLength(curve, 0.5), "tolerance=0.5");
  EXPECT_ERROR_HAS(ArcLength(curve, std::nan("")), "tolerance=nan");
  const ArcLength al(curve);
  EXPECT_ERROR_HAS(al.u(-0.5), "s=-0.5");
  EXPECT_ERROR_HAS(al.u(7), "s=7");
  EXPECT_ERROR_HAS(al.s(1.5), "u=1.5");
  EXPECT_ERROR_HAS(al.equal_steps(1), "count=1");
  BsplineCurve broken = curve;
  broken.U[3] = 2;  // decreasing
  EXPECT_THROW(ArcLength{broken}, SplineError);
}

}  // namespace
}  // namespace gllab::spline
