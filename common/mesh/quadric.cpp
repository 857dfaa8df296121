// common/mesh/quadric.cpp — see quadric.h.
#include "mesh/quadric.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gllab {

namespace {

void require_positive(double v, const char* what) {
  if (std::isfinite(v) && v > 0) return;
  std::ostringstream m;
  m << what << "=" << v << " (must be > 0)";
  throw std::invalid_argument(m.str());
}

}  // namespace

double Quadric::operator()(spline::Vec3 p) const {
  return xx * p.x * p.x + yy * p.y * p.y + zz * p.z * p.z + xy * p.x * p.y + yz * p.y * p.z +
         zx * p.z * p.x + x * p.x + y * p.y + z * p.z + c;
}

spline::Vec3 Quadric::gradient(spline::Vec3 p) const {
  return {2 * xx * p.x + xy * p.y + zx * p.z + x, 2 * yy * p.y + xy * p.x + yz * p.z + y,
          2 * zz * p.z + yz * p.y + zx * p.x + z};
}

Quadric sphere_quadric(double r) {
  require_positive(r, "sphere radius r");
  Quadric q;
  q.xx = q.yy = q.zz = 1;
  q.c = -r * r;  // the notes' "= r" means r^2 (quadric.h)
  return q;
}

Quadric ellipsoid_quadric(double rx, double ry, double rz) {
  require_positive(rx, "ellipsoid rx");
  require_positive(ry, "ellipsoid ry");
  require_positive(rz, "ellipsoid rz");
  Quadric q;
  q.xx = 1 / (rx * rx);
  q.yy = 1 / (ry * ry);
  q.zz = 1 / (rz * rz);
  q.c = -1;
  return q;
}

Quadric cylinder_quadric(double r) {
  require_positive(r, "cylinder radius r");
  Quadric q;
  q.xx = q.yy = 1;
  q.c = -r * r;
  return q;
}

Quadric cone_quadric(double base_radius, double height) {
  require_positive(base_radius, "cone base radius");
  require_positive(height, "cone height");
  // x^2 + y^2 - k^2 (h - z)^2 with k = r / h: expand (h - z)^2 = h^2 - 2hz + z^2.
  const double k2 = (base_radius / height) * (base_radius / height);
  Quadric q;
  q.xx = q.yy = 1;
  q.zz = -k2;
  q.z = 2 * k2 * height;
  q.c = -k2 * height * height;
  return q;
}

double torus_implicit(spline::Vec3 p, double R, double r) {
  require_positive(r, "torus tube radius r");
  require_positive(R, "torus ring radius R");
  if (!(r < R)) {
    std::ostringstream m;
    m << "torus tube radius r=" << r << " >= ring radius R=" << R << " (must be smaller)";
    throw std::invalid_argument(m.str());
  }
  const double d2 = dot(p, p), s = d2 + R * R - r * r;
  return s * s - 4 * R * R * (p.x * p.x + p.y * p.y);
}

}  // namespace gllab
