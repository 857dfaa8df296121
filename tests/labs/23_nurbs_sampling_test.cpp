// tests/labs/23_nurbs_sampling_test.cpp — what lab 23 promises: every GLU
// sampling method makes more triangles as its tolerance shrinks, in the ratio
// an edge length or an error bound predicts; GLU_DOMAIN_DISTANCE exactly
// 2 n^2; a screen-space method follows the picture's size, an object-space
// one does not.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::numbers_before;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "23_nurbs_sampling";

std::vector<double> triangles(const ScratchDir& dir, const std::string& view, const std::vector<std::string>& sets) {
  return numbers_before(view_text(kLab, dir, view, sets), " triangles");
}

// The sampling panels, in the lab's order (kMethods): GLU_PATH_LENGTH,
// GLU_PARAMETRIC_ERROR, GLU_DOMAIN_DISTANCE, GLU_OBJECT_PATH_LENGTH,
// GLU_OBJECT_PARAMETRIC_ERROR. finer = f divides every tolerance by 2^f and
// multiplies the steps by 2^f (the lab's `sampling`).
TEST(NurbsSamplingLab, EverySamplingMethodMakesMoreTrianglesAsItsToleranceShrinks) {
  ScratchDir dir("lab23");
  std::vector<std::vector<double>> counts;
  for (const char* finer : {"finer=-1", "finer=0", "finer=1"}) {
    counts.push_back(triangles(dir, "methods", {finer}));
    ASSERT_EQ(counts.back().size(), 5u) << finer;
  }
  // Halving an edge length (GLU_PATH_LENGTH, GLU_OBJECT_PATH_LENGTH) about
  // quadruples the triangles of a tiling (measured 2.7 to 3.7 per step); an
  // error bound falls like the square of the edge, so halving it about
  // doubles them (measured 1.54 to 2.23). The bounds leave room below both.
  const double at_least[5] = {2.0, 1.3, 4.0, 2.0, 1.3};
  for (int k = 0; k < 5; ++k)
    for (int step = 0; step < 2; ++step)
      EXPECT_GE(counts[step + 1][k], at_least[k] * counts[step][k]) << "method " << k << ", step " << step;
  // GLU_DOMAIN_DISTANCE on the domain [0, 1]^2: steps x steps quads, two
  // triangles each (GLU sends quad strips; the capture counts 2 per quad).
  EXPECT_EQ(counts[0][2], 2 * 4 * 4);
  EXPECT_EQ(counts[1][2], 2 * 8 * 8);
  EXPECT_EQ(counts[2][2], 2 * 16 * 16);
}

// gluNurbsProperty(3G): GLU_PATH_LENGTH's tolerance is "the maximum length, in
// pixels", GLU_OBJECT_PATH_LENGTH's "in object space". So zooming the picture
// in makes more triangles for the first (measured 389 at zoom 1, 637 at 1.5,
// 1069 at 2: the edges in pixels grow with the zoom, their count about with
// its square) and exactly the same ones for the second (484).
TEST(NurbsSamplingLab, ScreenSpaceSamplingFollowsThePictureAndObjectSpaceDoesNot) {
  ScratchDir dir("lab23");
  const std::vector<double> n = triangles(dir, "picture_size", {"zoom=2"});
  ASSERT_EQ(n.size(), 4u);  // path length at zoom 1 and 2, object path length at zoom 1 and 2
  EXPECT_GT(n[1], 2 * n[0]);
  EXPECT_EQ(n[3], n[2]);
  const std::vector<double> same = triangles(dir, "picture_size", {"zoom=1"});
  ASSERT_EQ(same.size(), 4u);
  EXPECT_EQ(same[1], same[0]);  // the same picture twice: the same triangles
}

}  // namespace
