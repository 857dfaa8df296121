// tests/field/errors_test.cpp — bad input to the densities and grids throws
// std::invalid_argument with one line naming the value (marching cubes and
// squares: their own test files).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "field/density.h"
#include "field/grid.h"

namespace gllab::field {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(Errors, IsoRadiusNamesC) {
  EXPECT_EQ(message_of([] { iso_radius(Density::kHermite, 1, 1, 0); }),
            "iso_radius: c=0 (must be in (0, a) with a=1)");
  EXPECT_EQ(message_of([] { iso_radius(Density::kWyvill, 2, 1, 2.5); }),
            "iso_radius: c=2.5 (must be in (0, a) with a=2)");
  EXPECT_EQ(message_of([] { iso_radius(Density::kBlinn, 1, -1, 0.5); }),
            "iso_radius: b=-1 (must be positive)");
  EXPECT_EQ(message_of([] { merge_distance(Density::kHermite, 1, 1, 2); }),
            "merge_distance: c=2 (must be in (0, 2a) with a=1)");
  EXPECT_EQ(message_of([] { iso_radius(Density::kHermite, 1, 1, NAN); }),
            "iso_radius: c=nan (must be in (0, a) with a=1)");
}

TEST(Errors, SampleNamesTheCountOrRange) {
  auto f3 = [](const Vec3&) { return 0.0; };
  EXPECT_EQ(message_of([&] {
              sample(f3, Vec3{0, 0, 0}, Vec3{1, 1, 1}, 4, 1, 4);
            }),
            "sample: ny=1 (must be at least 2)");
  EXPECT_EQ(message_of([&] {
              sample(f3, Vec3{0, 0, 2}, Vec3{1, 1, 1}, 4, 4, 4);
            }),
            "sample: z range [2, 1] (must be finite with hi > lo)");
  auto f2 = [](double, double) { return 0.0; };
  EXPECT_EQ(message_of([&] { sample(f2, 0, 0, 1, 1, 0, 3); }), "sample: nx=0 (must be at least 2)");
  EXPECT_EQ(message_of([] { two_blob_benchmark_field(1); }),
            "two_blob_benchmark_field: n=1 (must be at least 2)");
}

}  // namespace
}  // namespace gllab::field
