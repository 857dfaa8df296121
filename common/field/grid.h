// common/field/grid.h — sampled scalar fields: 2-D and 3-D grids of values
// with bilinear / trilinear interpolation, and analytic test fields
// (lecture notes ch. 1, §1.7 Surface representations, "Iso-surfaces": the
// trilinear volume f(s, t, u) = sum d_ijk N_i(s) N_j(t) N_k(u) of degree-1
// B-splines N on the grid's knots is exactly trilinear interpolation of the
// grid values d_ijk).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "spline/vec.h"

namespace gllab::field {

using spline::Vec3;

/// nx x ny values over a rectangle: value(i, j) at (x0 + i hx, y0 + j hy).
struct Grid2 {
  int nx = 0, ny = 0;  // at least 2 each
  double x0 = 0, y0 = 0, hx = 1, hy = 1;
  std::vector<double> values;  // i fastest: values[j * nx + i]

  double at(int i, int j) const { return values[std::size_t(j) * nx + i]; }
  double bilinear(double x, double y) const;  // clamped to the rectangle
};

/// nx x ny x nz float values (x fastest, as VTK and NRRD store them): value(i,
/// j, k) at origin + (i hx, j hy, k hz). float, because volumes are large
/// (256^3 = 64 MB) and CT data is rarely more precise.
struct Grid3 {
  int nx = 0, ny = 0, nz = 0;  // at least 2 each
  Vec3 origin{0, 0, 0};
  Vec3 spacing{1, 1, 1};
  std::vector<float> values;  // values[(k * ny + j) * nx + i]

  float at(int i, int j, int k) const { return values[(std::size_t(k) * ny + j) * nx + i]; }
  Vec3 point(int i, int j, int k) const;
  /// The trilinear interpolant at x (clamped to the box), and its exact
  /// gradient (piecewise bilinear in each component, discontinuous across
  /// cell faces; one-sided at the box's faces).
  double trilinear(const Vec3& x) const;
  Vec3 trilinear_gradient(const Vec3& x) const;
  /// The central-difference gradient at a grid point (one-sided at the
  /// border), as VTK's and the marching cubes' vertex normals use it.
  Vec3 grid_gradient(int i, int j, int k) const;
};

using Field3 = std::function<double(const Vec3&)>;
using Field2 = std::function<double(double, double)>;

/// f sampled at n points per axis over [lo, hi] (n >= 2, hi > lo each axis).
/// Throws std::invalid_argument naming the value otherwise.
Grid3 sample(const Field3& f, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz);
Grid2 sample(const Field2& f, double x0, double y0, double x1, double y1, int nx, int ny);

// Analytic test fields, positive inside (so {f > c} is the solid):
/// r - |x - centre|: the signed distance, iso 0 is the sphere.
double sphere_field(const Vec3& x, const Vec3& centre, double r);
/// R_tube - dist(x, circle of radius R_ring around z): iso 0 is the torus.
double torus_field(const Vec3& x, double R_ring, double r_tube);

/// The benchmark field (bench/iso_bench.cpp, common/field/README.md): n^3
/// points over [-1, 1]^3 of two Hermite blobs a = 1, b = 0.45 at (+-d/2, 0, 0),
/// d = 1.4 b as in lab 08's default: at iso 0.5 two spheres of radius about
/// b/2, just apart (they merge at d = 1.347 b). Throws std::invalid_argument
/// naming n < 2.
Grid3 two_blob_benchmark_field(int n);

}  // namespace gllab::field
