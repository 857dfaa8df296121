// common/field/phantom.cpp — see phantom.h.
#include "field/phantom.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gllab::field {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

const std::vector<PhantomEllipsoid>& shepp_logan_ellipsoids() {
  // The 3-D Shepp–Logan head phantom of Kak and Slaney, "Principles of
  // Computerized Tomographic Imaging" (IEEE Press 1988, ch. 3), in the form
  // of M. Schabel's phantom3d ("3D Shepp-Logan phantom", MATLAB Central File
  // Exchange 9416, 2005): semi-axes and centres in units of the half field of
  // view [-1, 1], Euler angles in degrees. The densities are the "modified"
  // ones of P. Toft, "The Radon Transform" (PhD thesis, DTU 1996, pp. 199-200):
  // 1, -0.8, -0.2, ... instead of Shepp and Logan's 2, -0.98, -0.02, ..., so
  // that the structures inside the brain differ by 0.1 instead of 0.01.
  // One difference from phantom3d: here the centre is subtracted before the
  // rotation (x' = R (x - centre)), so every centre is where the table says;
  // phantom3d rotates first, which moves the two tilted ventricles slightly.
  // With theta = 0 the two z rotations add: the ventricles are turned by
  // phi + psi = -8 and 28 degrees about z, as in phantom3d.
  //
  //  density   semi-axes (a, b, c)        centre (x, y, z)            phi theta psi
  static const std::vector<PhantomEllipsoid> table = {
      {1.0, {0.6900, 0.920, 0.810}, {0.00, 0.0000, 0.00}, 0, 0, 0},      // skull
      {-0.8, {0.6624, 0.874, 0.780}, {0.00, -0.0184, 0.00}, 0, 0, 0},    // brain
      {-0.2, {0.1100, 0.310, 0.220}, {0.22, 0.0000, 0.00}, -18, 0, 10},  // right ventricle
      {-0.2, {0.1600, 0.410, 0.280}, {-0.22, 0.0000, 0.00}, 18, 0, 10},  // left ventricle
      {0.1, {0.2100, 0.250, 0.410}, {0.00, 0.3500, -0.15}, 0, 0, 0},
      {0.1, {0.0460, 0.046, 0.050}, {0.00, 0.1000, 0.25}, 0, 0, 0},
      {0.1, {0.0460, 0.046, 0.050}, {0.00, -0.1000, 0.25}, 0, 0, 0},
      {0.1, {0.0460, 0.023, 0.050}, {-0.08, -0.6050, 0.00}, 0, 0, 0},
      {0.1, {0.0230, 0.023, 0.020}, {0.00, -0.6060, 0.00}, 0, 0, 0},
      {0.1, {0.0230, 0.046, 0.020}, {0.06, -0.6050, 0.00}, 0, 0, 0},
  };
  return table;
}

namespace {

/// An ellipsoid ready for testing points: its rotation R (z-x-z Euler
/// angles, the matrix of phantom3d) and 1 / semi-axes squared.
struct Prepared {
  double density;
  Vec3 centre;
  std::array<double, 9> R;  // row-major
  Vec3 inv_sq;
};

std::vector<Prepared> prepare() {
  std::vector<Prepared> out;
  for (const PhantomEllipsoid& e : shepp_logan_ellipsoids()) {
    const double phi = e.phi * kPi / 180, theta = e.theta * kPi / 180, psi = e.psi * kPi / 180;
    const double cphi = std::cos(phi), sphi = std::sin(phi);
    const double ctheta = std::cos(theta), stheta = std::sin(theta);
    const double cpsi = std::cos(psi), spsi = std::sin(psi);
    Prepared p;
    p.density = e.density;
    p.centre = e.centre;
    p.R = {cpsi * cphi - ctheta * sphi * spsi,
           cpsi * sphi + ctheta * cphi * spsi,
           spsi * stheta,
           -spsi * cphi - ctheta * sphi * cpsi,
           -spsi * sphi + ctheta * cphi * cpsi,
           cpsi * stheta,
           stheta * sphi,
           -stheta * cphi,
           ctheta};
    p.inv_sq = {1 / (e.semi_axes.x * e.semi_axes.x), 1 / (e.semi_axes.y * e.semi_axes.y),
                1 / (e.semi_axes.z * e.semi_axes.z)};
    out.push_back(p);
  }
  return out;
}

const std::vector<Prepared>& prepared() {
  static const std::vector<Prepared> table = prepare();
  return table;
}

}  // namespace

double shepp_logan_density(const Vec3& x) {
  double sum = 0;
  for (const Prepared& e : prepared()) {
    const double dx = x.x - e.centre.x, dy = x.y - e.centre.y, dz = x.z - e.centre.z;
    const double u = e.R[0] * dx + e.R[1] * dy + e.R[2] * dz;
    const double v = e.R[3] * dx + e.R[4] * dy + e.R[5] * dz;
    const double w = e.R[6] * dx + e.R[7] * dy + e.R[8] * dz;
    if (u * u * e.inv_sq.x + v * v * e.inv_sq.y + w * w * e.inv_sq.z <= 1) sum += e.density;
  }
  return sum;
}

Grid3 shepp_logan_phantom(int n) {
  if (n < 2 || n > 1024)
    throw std::invalid_argument("shepp_logan_phantom: n = " + std::to_string(n) +
                                " (need 2 <= n <= 1024 points per axis)");
  Grid3 g;
  g.nx = g.ny = g.nz = n;
  const double h = 2.0 / (n - 1);
  g.origin = {-1, -1, -1};
  g.spacing = {h, h, h};
  g.values.resize(std::size_t(n) * n * n);
  // Coordinates of point i, and the two sub-sample offsets around it.
  std::vector<double> c(n);
  for (int i = 0; i < n; ++i) c[i] = i + 1 == n ? 1.0 : -1.0 + h * i;
  const double d[2] = {-h / 4, h / 4};
  std::size_t at = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double sum = 0;
        for (double dz : d)
          for (double dy : d)
            for (double dx : d) sum += shepp_logan_density({c[i] + dx, c[j] + dy, c[k] + dz});
        g.values[at++] = static_cast<float>(sum / 8);
      }
  return g;
}

}  // namespace gllab::field
