// tests/labs/08_blobby_objects_test.cpp — what lab 08 promises (lecture notes
// ch. 1, §1.5 Blobby objects):
//  - two blobs are one surface exactly when their centres are closer than the
//    distance where the field at the midpoint is c: 2 f(d*/2) = c. For the
//    notes' density f(t) = a H0(t/b) with a = b = 1, c = 0.5 that is the root
//    s in (0, 1) of 1 - 3 s^2 + 2 s^3 = 1/4, d* = 2 s = 1.3473, found here by
//    bisection, independently of the core's closed form;
//  - one blob's mesh lies within the grid's O(h^2) of the gluSphere of radius r,
//    f(r) = c: r = 0.5 exactly for c = 1/2 (H0(1/2) = 1/2);
//  - the density view states the radius the density predicts.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "08_blobby_objects";

// 2 s with 1 - 3 s^2 + 2 s^3 = 1/4 on (0, 1), by bisection (H0 decreases there).
double merge_distance_by_bisection() {
  double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const double s = (lo + hi) / 2;
    (1 - 3 * s * s + 2 * s * s * s > 0.25 ? lo : hi) = s;
  }
  return lo + hi;  // 2 * midpoint
}

bool has_line(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& line : lines)
    if (line == text) return true;
  return false;
}

TEST(BlobbyObjectsLab, CaptionStatesTheMergeDistance) {
  ScratchDir dir("lab08");
  const std::vector<double> d = numbers_after(view_text(kLab, dir, "two_blobs"), "d = 1.40, they merge at d* = ");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NEAR(d[0], merge_distance_by_bisection(), 5e-5);  // printed to 4 decimals
}

TEST(BlobbyObjectsLab, BlobsMergeExactlyAtThePredictedDistance) {
  ScratchDir dir("lab08");
  const double merge = merge_distance_by_bisection();
  // 0.03 either side: the neck then is wider than the 40^3 grid's spacing.
  const auto apart = view_text(kLab, dir, "two_blobs", {"distance=" + std::to_string(merge + .03)});
  const auto joined = view_text(kLab, dir, "two_blobs", {"distance=" + std::to_string(merge - .03)});
  EXPECT_TRUE(has_line(apart, "surface: 2 components"));
  EXPECT_TRUE(has_line(joined, "surface: 1 component"));
  // The merging view's sequence: apart until 1.02 d*, one surface from 0.97 d* on.
  const auto sequence = view_text(kLab, dir, "merging");
  int two = 0, one = 0;
  for (const std::string& line : sequence) two += line == "2 components", one += line == "1 component";
  EXPECT_EQ(two, 3);
  EXPECT_EQ(one, 3);
}

TEST(BlobbyObjectsLab, BlobMeshLiesOnTheGluSphereOfThePredictedRadius) {
  ScratchDir dir("lab08");
  for (const char* grid : {"grid=24", "grid=48"}) {
    const auto text = view_text(kLab, dir, "vs_glu_sphere", {grid});
    ASSERT_EQ(numbers_after(text, "gluSphere(q, r = ").size(), 1u);
    EXPECT_DOUBLE_EQ(numbers_after(text, "gluSphere(q, r = ")[0], 0.5);
    const std::vector<double> lo = numbers_after(text, "vertices ");
    ASSERT_EQ(lo.size(), 1u);
    // A vertex is where the linear interpolant along a grid edge crosses c, so it
    // is off the sphere by O(h^2); h^2 (h = 2.1 / (n - 1), the lab's box 2.1 b
    // wide) bounds it with room to spare.
    const double n = std::stod(std::string(grid).substr(5)), h = 2.1 / (n - 1);
    EXPECT_LE(0.5 - lo[0], h * h) << grid;
    EXPECT_GT(lo[0], 0.45) << grid;
  }
}

}  // namespace
