// tests/mesh/quadric_test.cpp — the implicit equations of common/mesh/quadric.h:
// points of each parametric surface give F = 0, points moved inwards along the
// normal give F < 0, outwards F > 0, and the gradient is the surface normal.
#include "mesh/quadric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>

#include "mesh/coordinates.h"

namespace {

using gllab::Quadric, gllab::spline::Vec3;

// F is of degree 2 (4 for the torus) in coordinates of size <= 3, so a point
// on the surface gives F within a few ulps of its terms, <= 81.
constexpr double kOnSurface = 1e-12;
constexpr double kStep = 1e-3;         // inwards / outwards along the normal
constexpr double kNormalAngle = 1e-9;  // |unit gradient - unit normal|
constexpr int kSamples = 2000;
constexpr unsigned kSeed = 36;

struct Sample {
  Vec3 point, normal;  // normal: outward unit normal of the parametric surface
};

// Samples (theta, phi) or (u, v) at random and returns the surface point and
// its normal from the parametric form.
void for_samples(const std::function<Sample(double, double)>& surface,
                 const std::function<void(const Sample&)>& check) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> a(-M_PI, M_PI), b(0.01, M_PI - 0.01);
  for (int i = 0; i < kSamples; ++i) check(surface(a(rng), b(rng)));
}

void check_implicit(const std::function<double(Vec3)>& f, const Sample& s) {
  EXPECT_NEAR(f(s.point), 0, kOnSurface);
  EXPECT_LT(f(s.point - kStep * s.normal), 0);  // inside
  EXPECT_GT(f(s.point + kStep * s.normal), 0);  // outside
}

void check_gradient(const Quadric& q, const Sample& s) {
  const Vec3 n = gllab::spline::normalized(q.gradient(s.point));
  EXPECT_LT(norm(n - s.normal), kNormalAngle);
}

// Sphere from the notes' spherical coordinates, normal = point / r. The
// notes' "x^2 + y^2 + z^2 = r" is read as r^2 (quadric.h): with r = 2 a point
// at distance 2 must give 0.
TEST(Quadric, SphereFromSphericalCoordinatesIsItsZeroSet) {
  const double r = 2;
  const Quadric q = gllab::sphere_quadric(r);
  EXPECT_NEAR(q({2, 0, 0}), 0, kOnSurface);            // r^2, not r
  EXPECT_NEAR(q({std::sqrt(2.0), 0, 0}), -2, kOnSurface);  // "= r" would put this point on it
  EXPECT_EQ(q({0, 0, 0}), -r * r);
  for_samples(
      [&](double theta, double phi) {
        const Vec3 p = gllab::spherical_to_cartesian({r, theta, phi});
        return Sample{p, p / r};
      },
      [&](const Sample& s) {
        check_implicit(q, s);
        check_gradient(q, s);
      });
}

// Ellipsoid: x = rx sin(phi) cos(theta), ...; its normal is
// (x / rx^2, y / ry^2, z / rz^2) normalized (the gradient of the notes' form, by hand).
TEST(Quadric, EllipsoidOfTheNotesIsItsZeroSet) {
  const double rx = 3, ry = 1, rz = 0.5;
  const Quadric q = gllab::ellipsoid_quadric(rx, ry, rz);
  EXPECT_NEAR(q({rx, 0, 0}), 0, kOnSurface);
  EXPECT_NEAR(q({0, 0, -rz}), 0, kOnSurface);
  for_samples(
      [&](double theta, double phi) {
        const Vec3 u = gllab::spherical_to_cartesian({1, theta, phi});
        const Vec3 p{rx * u.x, ry * u.y, rz * u.z};
        return Sample{p, gllab::spline::normalized({p.x / (rx * rx), p.y / (ry * ry), p.z / (rz * rz)})};
      },
      [&](const Sample& s) {
        check_implicit(q, s);
        check_gradient(q, s);
      });
}

// Cylinder from cylindrical coordinates (r, theta, z), normal (cos, sin, 0).
TEST(Quadric, CylinderFromCylindricalCoordinatesIsItsZeroSet) {
  const double r = 0.6;
  const Quadric q = gllab::cylinder_quadric(r);
  for_samples(
      [&](double theta, double v) {
        const Vec3 p = gllab::cylindrical_to_cartesian({r, theta, 3 * v - 4});
        return Sample{p, {std::cos(theta), std::sin(theta), 0}};
      },
      [&](const Sample& s) {
        check_implicit(q, s);
        check_gradient(q, s);
      });
}

// gluCylinder(q, r, 0, h, ...) as cylindrical coordinates: radius r (1 - z/h)
// at height z; the outward normal of a cone of half-angle atan(r/h) is
// (h cos, h sin, r) / sqrt(h^2 + r^2) (GLU's own normal, quad.c: zNormal = r / length).
TEST(Quadric, ConeOfGluCylinderWithTopRadiusZeroIsItsZeroSet) {
  const double r = 0.6, h = 1.4;
  const Quadric q = gllab::cone_quadric(r, h);
  EXPECT_NEAR(q({0, 0, h}), 0, kOnSurface);  // apex
  for_samples(
      [&](double theta, double v) {
        const double z = h * v / M_PI * 0.98;  // below the apex, where the normal exists
        const Vec3 p = gllab::cylindrical_to_cartesian({r * (1 - z / h), theta, z});
        return Sample{p, gllab::spline::normalized({h * std::cos(theta), h * std::sin(theta), r})};
      },
      [&](const Sample& s) {
        check_implicit(q, s);
        check_gradient(q, s);
      });
}

// The torus ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), normal
// (cos v cos u, cos v sin u, sin v): quartic, with the same signs.
TEST(TorusImplicit, TorusOfLabsThreeToFiveIsItsZeroSet) {
  const double R = 1, r = 0.4;
  for_samples(
      [&](double u, double v) {
        v *= 2;  // the whole tube
        const Vec3 n{std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)};
        return Sample{Vec3{R * std::cos(u), R * std::sin(u), 0} + r * n, n};
      },
      [&](const Sample& s) { check_implicit([&](Vec3 p) { return gllab::torus_implicit(p, R, r); }, s); });
  EXPECT_LT(gllab::torus_implicit({R, 0, 0}, R, r), 0);  // the tube's centre line is inside
  EXPECT_GT(gllab::torus_implicit({0, 0, 0}, R, r), 0);  // the hole is outside
}

TEST(Quadric, BadRadiiThrowNamingTheValue) {
  try {
    gllab::sphere_quadric(-1);
    FAIL() << "negative radius accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("r=-1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gllab::ellipsoid_quadric(1, 0, 1), std::invalid_argument);
  EXPECT_THROW(gllab::cylinder_quadric(NAN), std::invalid_argument);
  EXPECT_THROW(gllab::cone_quadric(1, 0), std::invalid_argument);
  EXPECT_THROW(gllab::torus_implicit({0, 0, 0}, 1, 1), std::invalid_argument);
}

}  // namespace
