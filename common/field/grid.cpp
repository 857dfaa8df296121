// common/field/grid.cpp — sampled grids, bilinear / trilinear interpolation
// and the analytic test fields (lecture notes ch. 1, §1.7 Surface
// representations, Iso-surfaces: the trilinear volume of degree-1 B-splines).
#include "field/grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "field/density.h"
#include "field/internal.h"

namespace gllab::field {

using detail::fail;
using detail::num;

namespace {

/// The cell [i, i + 1] of n points that holds x (clamped to [0, n - 1] in
/// index units) and the local coordinate u in [0, 1] within it.
void locate(double x, double x0, double h, int n, int& i, double& u) {
  const double s = std::clamp((x - x0) / h, 0.0, double(n - 1));
  i = std::min(int(s), n - 2);
  u = s - i;
}

void check_count(const char* what, const char* axis, int n) {
  if (n < 2)
    fail(std::string(what) + ": " + axis + "=" + std::to_string(n) + " (must be at least 2)");
}

void check_range(const char* what, const char* axis, double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo))
    fail(std::string(what) + ": " + axis + " range [" + num(lo) + ", " + num(hi) +
         "] (must be finite with hi > lo)");
}

}  // namespace

// Bilinear interpolation in the cell that holds (x, y) (lecture notes §1.7:
// the tensor product of two degree-1 B-splines).
double Grid2::bilinear(double x, double y) const {
  int i, j;
  double u, v;
  locate(x, x0, hx, nx, i, u);
  locate(y, y0, hy, ny, j, v);
  const double f0 = (1 - u) * at(i, j) + u * at(i + 1, j);
  const double f1 = (1 - u) * at(i, j + 1) + u * at(i + 1, j + 1);
  return (1 - v) * f0 + v * f1;
}

Vec3 Grid3::point(int i, int j, int k) const {
  return {origin.x + i * spacing.x, origin.y + j * spacing.y, origin.z + k * spacing.z};
}

// f(s, t, u) = sum d_ijk N_i(s) N_j(t) N_k(u) with degree-1 B-splines N: in
// the cell, (1-u)(1-v)(1-w) f000 + u (1-v)(1-w) f100 + ... (notes §1.7).
double Grid3::trilinear(const Vec3& x) const {
  int i, j, k;
  double u, v, w;
  locate(x.x, origin.x, spacing.x, nx, i, u);
  locate(x.y, origin.y, spacing.y, ny, j, v);
  locate(x.z, origin.z, spacing.z, nz, k, w);
  auto edge = [&](int jj, int kk) { return (1 - u) * at(i, jj, kk) + u * at(i + 1, jj, kk); };
  const double f0 = (1 - v) * edge(j, k) + v * edge(j + 1, k);
  const double f1 = (1 - v) * edge(j, k + 1) + v * edge(j + 1, k + 1);
  return (1 - w) * f0 + w * f1;
}

// The partial derivatives of the cell's trilinear polynomial: d/dx is the
// bilinear interpolant (in y, z) of the differences f(i+1) - f(i), over hx.
Vec3 Grid3::trilinear_gradient(const Vec3& x) const {
  int i, j, k;
  double u, v, w;
  locate(x.x, origin.x, spacing.x, nx, i, u);
  locate(x.y, origin.y, spacing.y, ny, j, v);
  locate(x.z, origin.z, spacing.z, nz, k, w);
  double f[2][2][2];  // f[dk][dj][di]
  for (int c = 0; c < 8; ++c)
    f[c >> 2][(c >> 1) & 1][c & 1] = at(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
  auto bilin = [](double a00, double a10, double a01, double a11, double s, double t) {
    return (1 - t) * ((1 - s) * a00 + s * a10) + t * ((1 - s) * a01 + s * a11);
  };
  const double dx = bilin(f[0][0][1] - f[0][0][0], f[0][1][1] - f[0][1][0], f[1][0][1] - f[1][0][0],
                          f[1][1][1] - f[1][1][0], v, w);
  const double dy = bilin(f[0][1][0] - f[0][0][0], f[0][1][1] - f[0][0][1], f[1][1][0] - f[1][0][0],
                          f[1][1][1] - f[1][0][1], u, w);
  const double dz = bilin(f[1][0][0] - f[0][0][0], f[1][0][1] - f[0][0][1], f[1][1][0] - f[0][1][0],
                          f[1][1][1] - f[0][1][1], u, v);
  return {dx / spacing.x, dy / spacing.y, dz / spacing.z};
}

// Central differences (f(i+1) - f(i-1)) / 2h, one-sided (f(1) - f(0)) / h at
// the border, as VTK's vtkMarchingCubes computes its point gradients.
Vec3 Grid3::grid_gradient(int i, int j, int k) const {
  auto diff = [](double lo, double hi, int steps, double h) { return (hi - lo) / (steps * h); };
  const int il = std::max(i - 1, 0), ih = std::min(i + 1, nx - 1);
  const int jl = std::max(j - 1, 0), jh = std::min(j + 1, ny - 1);
  const int kl = std::max(k - 1, 0), kh = std::min(k + 1, nz - 1);
  return {diff(at(il, j, k), at(ih, j, k), ih - il, spacing.x),
          diff(at(i, jl, k), at(i, jh, k), jh - jl, spacing.y),
          diff(at(i, j, kl), at(i, j, kh), kh - kl, spacing.z)};
}

Grid3 sample(const Field3& f, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
  check_count("sample", "nx", nx);
  check_count("sample", "ny", ny);
  check_count("sample", "nz", nz);
  check_range("sample", "x", lo.x, hi.x);
  check_range("sample", "y", lo.y, hi.y);
  check_range("sample", "z", lo.z, hi.z);
  Grid3 g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  g.origin = lo;
  g.spacing = {(hi.x - lo.x) / (nx - 1), (hi.y - lo.y) / (ny - 1), (hi.z - lo.z) / (nz - 1)};
  g.values.resize(std::size_t(nx) * ny * nz);
  std::size_t n = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) g.values[n++] = float(f(g.point(i, j, k)));
  return g;
}

Grid2 sample(const Field2& f, double x0, double y0, double x1, double y1, int nx, int ny) {
  check_count("sample", "nx", nx);
  check_count("sample", "ny", ny);
  check_range("sample", "x", x0, x1);
  check_range("sample", "y", y0, y1);
  Grid2 g;
  g.nx = nx;
  g.ny = ny;
  g.x0 = x0;
  g.y0 = y0;
  g.hx = (x1 - x0) / (nx - 1);
  g.hy = (y1 - y0) / (ny - 1);
  g.values.resize(std::size_t(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      g.values[std::size_t(j) * nx + i] = f(x0 + i * g.hx, y0 + j * g.hy);
  return g;
}

double sphere_field(const Vec3& x, const Vec3& centre, double r) { return r - norm(x - centre); }

double torus_field(const Vec3& x, double R_ring, double r_tube) {
  const double ring = std::hypot(x.x, x.y) - R_ring;  // in the plane through the z axis and x
  return r_tube - std::hypot(ring, x.z);
}

// Two Hermite blobs (a = 1, b = 0.45) as in lab 08's default: centres d = 1.4 b
// apart, a little more than their merge distance 1.347 b for iso 0.5
// (density.h), so at iso 0.5 they are two spheres of radius 0.225 (H0(1/2) =
// 1/2), each slightly drawn towards the other. The field is evaluated directly,
// not through sample(): 16.7 M points at n = 256.
Grid3 two_blob_benchmark_field(int n) {
  check_count("two_blob_benchmark_field", "n", n);
  const double a = 1, b = 0.45;
  const double half = 0.7 * b;  // d / 2
  Grid3 g;
  g.nx = g.ny = g.nz = n;
  g.origin = {-1, -1, -1};
  g.spacing = {2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1)};
  g.values.resize(std::size_t(n) * n * n);
  std::size_t m = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 p = g.point(i, j, k);
        const double yz = p.y * p.y + p.z * p.z;
        const double r0 = std::sqrt((p.x + half) * (p.x + half) + yz);
        const double r1 = std::sqrt((p.x - half) * (p.x - half) + yz);
        g.values[m++] = float(hermite_density(r0, a, b) + hermite_density(r1, a, b));
      }
  return g;
}

}  // namespace gllab::field
