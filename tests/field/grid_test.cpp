// tests/field/grid_test.cpp — the grids: bilinear and trilinear
// interpolation (lecture notes ch. 1, §1.7 Surface representations,
// Iso-surfaces: the trilinear volume of degree-1 B-splines is exactly
// trilinear interpolation) and the sampled test fields.
#include "field/grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gllab::field {
namespace {

// Any trilinear function a + b x + c y + d z + e xy + f yz + g zx + h xyz.
double trilin(const Vec3& p) {
  return 0.3 + 1.1 * p.x - 0.7 * p.y + 0.4 * p.z + 0.9 * p.x * p.y - 0.5 * p.y * p.z +
         0.2 * p.z * p.x + 1.3 * p.x * p.y * p.z;
}

Grid3 trilinear_grid() { return sample(trilin, Vec3{-1, -0.5, 0}, Vec3{1.2, 0.7, 0.9}, 7, 5, 4); }

TEST(Grid3, TrilinearReproducesTheGridValues) {
  const Grid3 g = trilinear_grid();
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        EXPECT_NEAR(g.trilinear(g.point(i, j, k)), g.at(i, j, k), 1e-6) << i << j << k;
}

TEST(Grid3, TrilinearIsExactOnATrilinearFunction) {
  // Per cell the interpolant is the trilinear polynomial through the 8
  // corners; a trilinear function is its own interpolant (to float rounding
  // of the stored values).
  const Grid3 g = trilinear_grid();
  for (const Vec3& x : {Vec3{0.13, 0.21, 0.33}, Vec3{-0.91, -0.44, 0.02}, Vec3{1.19, 0.69, 0.88},
                        Vec3{0.5, 0.1, 0.6}})
    EXPECT_NEAR(g.trilinear(x), trilin(x), 1e-6);
}

TEST(Grid3, TrilinearGradientMatchesFiniteDifferences) {
  const Grid3 g = trilinear_grid();
  const Vec3 x{0.13, 0.21, 0.33};  // inside one cell
  const double e = 1e-6;
  const Vec3 grad = g.trilinear_gradient(x);
  EXPECT_NEAR(grad.x, (g.trilinear(x + Vec3{e, 0, 0}) - g.trilinear(x - Vec3{e, 0, 0})) / (2 * e),
              1e-6);
  EXPECT_NEAR(grad.y, (g.trilinear(x + Vec3{0, e, 0}) - g.trilinear(x - Vec3{0, e, 0})) / (2 * e),
              1e-6);
  EXPECT_NEAR(grad.z, (g.trilinear(x + Vec3{0, 0, e}) - g.trilinear(x - Vec3{0, 0, e})) / (2 * e),
              1e-6);
}

TEST(Grid3, GridGradientIsCentralDifferences) {
  // On a linear function central and one-sided differences are exact.
  const Grid3 g = sample([](const Vec3& p) { return 2 * p.x - 3 * p.y + 0.5 * p.z; }, Vec3{0, 0, 0},
                         Vec3{1, 1, 1}, 5, 5, 5);
  for (int i : {0, 2, 4}) {
    const Vec3 d = g.grid_gradient(i, 4 - i, 2);
    EXPECT_NEAR(d.x, 2, 1e-5);
    EXPECT_NEAR(d.y, -3, 1e-5);
    EXPECT_NEAR(d.z, 0.5, 1e-5);
  }
}

TEST(Grid2, BilinearIsExactOnABilinearFunction) {
  auto f = [](double x, double y) { return 0.5 + x - 2 * y + 3 * x * y; };
  const Grid2 g = sample(f, -1, -1, 1, 2, 5, 7);
  EXPECT_NEAR(g.bilinear(-1, -1), f(-1, -1), 1e-14);
  EXPECT_NEAR(g.bilinear(0.37, 1.21), f(0.37, 1.21), 1e-14);
  EXPECT_NEAR(g.bilinear(1, 2), f(1, 2), 1e-14);
}

TEST(Fields, SphereAndTorusAreSignedDistances) {
  EXPECT_DOUBLE_EQ(sphere_field(Vec3{0.3, 0.4, 0}, Vec3{0, 0, 0}, 1), 0.5);
  EXPECT_DOUBLE_EQ(torus_field(Vec3{1, 0, 0}, 1, 0.25), 0.25);   // on the ring
  EXPECT_DOUBLE_EQ(torus_field(Vec3{0, 1.25, 0}, 1, 0.25), 0);   // on the tube
  EXPECT_DOUBLE_EQ(torus_field(Vec3{0, 0, 0}, 1, 0.25), -0.75);  // the hole's centre
}

TEST(Fields, TwoBlobBenchmarkField) {
  const Grid3 g = two_blob_benchmark_field(16);
  EXPECT_EQ(g.nx, 16);
  EXPECT_EQ(g.values.size(), 16u * 16 * 16);
  EXPECT_DOUBLE_EQ(g.origin.x, -1);
  EXPECT_DOUBLE_EQ(g.spacing.z, 2.0 / 15);
}

}  // namespace
}  // namespace gllab::field
