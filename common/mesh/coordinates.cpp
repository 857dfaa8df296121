// common/mesh/coordinates.cpp — see coordinates.h for the conventions.
#include "mesh/coordinates.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gllab {

namespace {

void require_finite(double v, const char* what) {
  if (std::isfinite(v)) return;
  std::ostringstream m;
  m << what << "=" << v << " is not a finite number";
  throw std::invalid_argument(m.str());
}

void require_finite(spline::Vec3 p, const char* what) {
  if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) return;
  std::ostringstream m;
  m << what << "=(" << p.x << ", " << p.y << ", " << p.z << ") is not finite";
  throw std::invalid_argument(m.str());
}

void require_radius(double v, const char* what) {
  require_finite(v, what);
  if (v >= 0) return;
  std::ostringstream m;
  m << what << "=" << v << " < 0 (a distance from the origin or the axis)";
  throw std::invalid_argument(m.str());
}

// atan2 with the undefined case (x = y = 0, either sign of zero) set to 0:
// atan2(+0, -0) would be pi, atan2(-0, -0) -pi.
double azimuth(double x, double y) { return x == 0 && y == 0 ? 0.0 : std::atan2(y, x); }

}  // namespace

spline::Vec3 spherical_to_cartesian(Spherical s) {
  require_radius(s.rho, "spherical rho");
  require_finite(s.theta, "spherical theta");
  require_finite(s.phi, "spherical phi");
  return {s.rho * std::sin(s.phi) * std::cos(s.theta), s.rho * std::sin(s.phi) * std::sin(s.theta),
          s.rho * std::cos(s.phi)};
}

Spherical cartesian_to_spherical(spline::Vec3 p) {
  require_finite(p, "point");
  const double r_xy = std::hypot(p.x, p.y);
  const double rho = std::hypot(r_xy, p.z);
  // At the origin atan2(0, 0) = 0 already; atan2(0, -0) would be pi.
  return {rho, azimuth(p.x, p.y), rho == 0 ? 0.0 : std::atan2(r_xy, p.z)};
}

spline::Vec3 cylindrical_to_cartesian(Cylindrical c) {
  require_radius(c.r, "cylindrical r");
  require_finite(c.theta, "cylindrical theta");
  require_finite(c.z, "cylindrical z");
  return {c.r * std::cos(c.theta), c.r * std::sin(c.theta), c.z};
}

Cylindrical cartesian_to_cylindrical(spline::Vec3 p) {
  require_finite(p, "point");
  return {std::hypot(p.x, p.y), azimuth(p.x, p.y), p.z};
}

}  // namespace gllab
