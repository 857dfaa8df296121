// tests/mesh/coordinates_test.cpp — Cartesian, spherical and cylindrical
// coordinates (common/mesh/coordinates.h): the notes' formula at hand-computed
// points, the poles and the axis, and round trips on seeded random points.
#include "mesh/coordinates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace {

using gllab::Cylindrical, gllab::Spherical, gllab::spline::Vec3;

// A few ulps of numbers of size 1 (each conversion is a handful of
// operations, each within half an ulp, 1.1e-16).
constexpr double kExact = 1e-15;
// Round trips on points up to 173 from the origin, relative to |p| (or in
// radians): measured worst 4.4e-16 over the random points below (2 ulps);
// the bound is about 9 times that.
constexpr double kRoundTripRelative = 4e-15;
constexpr int kRandomPoints = 10000;
constexpr unsigned kSeed = 36;

void expect_near(Vec3 a, Vec3 b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// The notes' formula by hand: rho = 2, theta = 60 deg, phi = 45 deg gives
// x = 2 sin45 cos60 = sqrt(2)/2, y = 2 sin45 sin60 = sqrt(6)/2, z = 2 cos45 = sqrt(2).
TEST(SphericalToCartesian, NotesFormulaAtSixtyAndFortyFiveDegrees) {
  expect_near(gllab::spherical_to_cartesian({2, M_PI / 3, M_PI / 4}),
              {std::sqrt(2.0) / 2, std::sqrt(6.0) / 2, std::sqrt(2.0)}, kExact);
}

// Which angle is which: theta turns in the xy-plane from +x towards +y, phi
// leaves +z. phi = 0 is the north pole whatever theta is.
TEST(SphericalToCartesian, AxesAndPoles) {
  expect_near(gllab::spherical_to_cartesian({1, 0, M_PI / 2}), {1, 0, 0}, kExact);
  expect_near(gllab::spherical_to_cartesian({1, M_PI / 2, M_PI / 2}), {0, 1, 0}, kExact);
  expect_near(gllab::spherical_to_cartesian({3, 1.234, 0}), {0, 0, 3}, kExact);
  expect_near(gllab::spherical_to_cartesian({3, -2.5, M_PI}), {0, 0, -3}, 3 * kExact);
}

// Known values back: the axes by inspection, and the convention of the
// header for the undefined angles (theta = 0 on the z axis, phi = 0 at the origin).
TEST(CartesianToSpherical, AxesPolesAndOrigin) {
  struct Case { Vec3 p; Spherical want; };
  const Case cases[] = {{{1, 0, 0}, {1, 0, M_PI / 2}},        {{0, 1, 0}, {1, M_PI / 2, M_PI / 2}},
                        {{-1, 0, 0}, {1, M_PI, M_PI / 2}},    {{0, -2, 0}, {2, -M_PI / 2, M_PI / 2}},
                        {{0, 0, 5}, {5, 0, 0}},               {{0, 0, -5}, {5, 0, M_PI}},
                        {{-0.0, -0.0, 5}, {5, 0, 0}},         {{0, 0, 0}, {0, 0, 0}},
                        {{-0.0, 0.0, -0.0}, {0, 0, 0}},       {{1, 1, std::sqrt(2.0)}, {2, M_PI / 4, M_PI / 4}}};
  for (const Case& c : cases) {
    const Spherical s = gllab::cartesian_to_spherical(c.p);
    EXPECT_NEAR(s.rho, c.want.rho, kExact) << c.p.x << " " << c.p.y << " " << c.p.z;
    EXPECT_NEAR(s.theta, c.want.theta, kExact) << c.p.x << " " << c.p.y << " " << c.p.z;
    EXPECT_NEAR(s.phi, c.want.phi, kExact) << c.p.x << " " << c.p.y << " " << c.p.z;
  }
}

TEST(CartesianToCylindrical, AxisAndOrigin) {
  const Cylindrical on_axis = gllab::cartesian_to_cylindrical({-0.0, 0.0, -7});
  EXPECT_EQ(on_axis.r, 0);
  EXPECT_EQ(on_axis.theta, 0);  // not atan2(+0, -0) = pi
  EXPECT_EQ(on_axis.z, -7);
  const Cylindrical c = gllab::cartesian_to_cylindrical({-3, 0, 2});
  EXPECT_NEAR(c.r, 3, kExact);
  EXPECT_NEAR(c.theta, M_PI, kExact);  // the negative x axis: theta = pi, not -pi
  expect_near(gllab::cylindrical_to_cartesian({2, M_PI / 2, 4}), {0, 2, 4}, kExact);
}

// The two systems share theta; z = rho cos(phi) and r = rho sin(phi).
TEST(Coordinates, SphericalAndCylindricalAgreeOnThetaAndRadius) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> u(-100, 100);
  for (int i = 0; i < kRandomPoints; ++i) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Spherical s = gllab::cartesian_to_spherical(p);
    const Cylindrical c = gllab::cartesian_to_cylindrical(p);
    EXPECT_EQ(s.theta, c.theta);
    EXPECT_NEAR(c.r, s.rho * std::sin(s.phi), kRoundTripRelative * s.rho);
    EXPECT_NEAR(c.z, s.rho * std::cos(s.phi), kRoundTripRelative * s.rho);
  }
}

// Cartesian -> spherical -> Cartesian and Cartesian -> cylindrical ->
// Cartesian on seeded random points in [-100, 100]^3, a few near the axis.
TEST(Coordinates, RoundTripsFromCartesian) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> u(-100, 100), tiny(-1e-9, 1e-9);
  for (int i = 0; i < kRandomPoints; ++i) {
    const bool near_axis = i % 10 == 0;
    const Vec3 p{near_axis ? tiny(rng) : u(rng), near_axis ? tiny(rng) : u(rng), u(rng)};
    const double tol = kRoundTripRelative * norm(p);
    expect_near(gllab::spherical_to_cartesian(gllab::cartesian_to_spherical(p)), p, tol);
    expect_near(gllab::cylindrical_to_cartesian(gllab::cartesian_to_cylindrical(p)), p, tol);
  }
}

// The other way, from canonical coordinates (rho > 0, theta in (-pi, pi),
// phi in (0, pi), kept away from the poles where theta is undefined).
TEST(Coordinates, RoundTripsFromSphericalAndCylindrical) {
  std::mt19937 rng(kSeed + 1);
  std::uniform_real_distribution<double> radius(0.01, 100), theta(-3.1, 3.1), phi(0.01, 3.13),
      z(-100, 100);
  for (int i = 0; i < kRandomPoints; ++i) {
    const Spherical s{radius(rng), theta(rng), phi(rng)};
    const Spherical back = gllab::cartesian_to_spherical(gllab::spherical_to_cartesian(s));
    EXPECT_NEAR(back.rho, s.rho, kRoundTripRelative * s.rho);
    EXPECT_NEAR(back.theta, s.theta, kRoundTripRelative / std::sin(s.phi));
    EXPECT_NEAR(back.phi, s.phi, kRoundTripRelative);
    const Cylindrical c{radius(rng), theta(rng), z(rng)};
    const Cylindrical cb = gllab::cartesian_to_cylindrical(gllab::cylindrical_to_cartesian(c));
    EXPECT_NEAR(cb.r, c.r, kRoundTripRelative * c.r);
    EXPECT_NEAR(cb.theta, c.theta, kRoundTripRelative);
    EXPECT_EQ(cb.z, c.z);
  }
}

// Angles outside the canonical range still give the notes' point; converting
// back returns the canonical angles: theta + 2 pi -> theta, phi -> -phi turns
// the point to theta + pi.
TEST(Coordinates, AnglesOutsideTheRangeComeBackCanonical) {
  const Spherical back = gllab::cartesian_to_spherical(gllab::spherical_to_cartesian({1, 0.5 + 2 * M_PI, -1}));
  EXPECT_NEAR(back.phi, 1, kExact);
  EXPECT_NEAR(back.theta, 0.5 - M_PI, 4 * kExact);
}

TEST(Coordinates, BadInputThrowsNamingTheValue) {
  try {
    gllab::spherical_to_cartesian({-1, 0, 0});
    FAIL() << "negative rho accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rho=-1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gllab::cylindrical_to_cartesian({-0.5, 0, 0}), std::invalid_argument);
  EXPECT_THROW(gllab::cylindrical_to_cartesian({1, NAN, 0}), std::invalid_argument);
  EXPECT_THROW(gllab::cartesian_to_spherical({INFINITY, 0, 0}), std::invalid_argument);
  EXPECT_THROW(gllab::cartesian_to_cylindrical({0, NAN, 0}), std::invalid_argument);
}

}  // namespace
