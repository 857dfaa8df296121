// tests/labs/15_bezier_surfaces_test.cpp — lab 15 against OpenGL's own
// evaluator, and what its views construct.
//
// own_vs_evaluator draws the patch twice, in the two halves of the window
// under the same matrices and lighting: left the core's tessellation
// (tessellate_surface on grid x grid cells, normals Xu x Xv from the core),
// right glMap2f + glMapGrid2f + glEvalMesh2 with GL_AUTO_NORMAL on the same
// grid (normals du x dv from Mesa's evaluator). Both put their vertices at
// the same (u_i, v_j) of the same polynomial, so the halves must agree.
//
// Where the tolerance comes from (measured on llvmpipe, nets=0 labels=0):
//  - The core splits each cell along its shorter diagonal; glEvalMesh2's
//    triangle strips always split from (u_i, v_j+1) to (u_i+1, v_j). With
//    the core forced to GL's diagonal (an experiment, not in the code), the
//    halves differed by at most 1 in one pixel at grids 4, 12 and 32: the
//    float evaluator and the double core agree that closely.
//  - With the shorter diagonal, a cell whose diagonals differ is a different
//    pair of triangles: the difference shrinks with the cell size squared.
//    Grid 12 (the default): 73 pixels off by more than 2, max 103 on the
//    silhouette; grid 32: max 2 everywhere (674 pixels off by 1 or 2);
//    grid 64: max 1.
// So at grid 32 no pixel may differ by more than kMaxChannelDelta = 2.
// Mistakes measured against it at grid 32 (max channel difference):
//  - GL_AUTO_NORMAL off (every vertex gets the current normal): 94;
//  - an inner control point moved by 1% of the patch's 3-unit box (0.03),
//    in the own half only: 123 along z, 121 along x; a corner moved: 207.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::pixels_differing;
using gllab::testing::render_view;
using gllab::testing::ScratchDir;

const std::string kLab = "15_bezier_surfaces";
constexpr int kFineGrid = 32;
constexpr int kMaxChannelDelta = 2;  // see the header: shorter vs GL's diagonal at grid 32
// The patch covers 13,574 of the 131,072 pixels of a half (measured): far from empty.
constexpr long long kMinPatchPixels = 10000;

// Half `side` (0 left, 1 right) of a render of own_vs_evaluator.
gllab::Image half(const gllab::Image& im, int side) {
  gllab::Image out(im.width / 2, im.height);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) out.pixel(x, y)[c] = im.pixel(x + side * out.width, y)[c];
  return out;
}

gllab::Image evaluator_view(const ScratchDir& dir, int grid, std::vector<std::string> sets = {}) {
  sets.insert(sets.end(), {"grid=" + std::to_string(grid), "nets=0", "labels=0"});
  return render_view(kLab, dir, "own_vs_evaluator", sets);
}

long long lit_pixels(const gllab::Image& im) {  // the clay surface is red-dominated, the background is not
  long long n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) n += im.pixel(x, y)[0] > 100;
  return n;
}

TEST(BezierSurfacesLab, OwnTessellationMatchesGlEvalMesh2AtTheSameGrid) {
  ScratchDir dir("lab15");
  const gllab::Image both = evaluator_view(dir, kFineGrid);
  const gllab::Image own = half(both, 0), gl = half(both, 1);
  EXPECT_GT(lit_pixels(own), kMinPatchPixels);
  EXPECT_GT(lit_pixels(gl), kMinPatchPixels);
  const gllab::Comparison c = gllab::compare_images(gl, own, kMaxChannelDelta);
  EXPECT_EQ(c.differing_pixels, 0) << "max channel difference " << c.max_delta;
}

// The negative checks: each mistake must break the tolerance.
TEST(BezierSurfacesLab, WithoutAutoNormalTheEvaluatorHalfDiffers) {
  ScratchDir dir("lab15");
  const gllab::Image both = evaluator_view(dir, kFineGrid, {"auto_normal=0"});
  const gllab::Comparison c = gllab::compare_images(half(both, 1), half(both, 0), kMaxChannelDelta);
  EXPECT_GT(c.max_delta, 10 * kMaxChannelDelta);
  EXPECT_GT(c.differing_pixels, kMinPatchPixels / 2) << "the whole patch is lit wrong";
}

TEST(BezierSurfacesLab, AControlPointMovedByOnePercentDiffersFromTheEvaluator) {
  ScratchDir dir("lab15");
  const gllab::Image gl = half(evaluator_view(dir, kFineGrid), 1);
  // P[5] = (-0.5, -0.5, 1.68) by default; 0.03 is 1% of the 3-unit patch.
  for (const char* moved : {"P[5]=-0.5,-0.5,1.71", "P[5]=-0.47,-0.5,1.68", "P[15]=1.5,1.5,1.29"}) {
    const gllab::Image own = half(evaluator_view(dir, kFineGrid, {moved}), 0);
    const gllab::Comparison c = gllab::compare_images(gl, own, kMaxChannelDelta);
    EXPECT_GT(c.differing_pixels, 0) << moved;
    EXPECT_GT(c.max_delta, 10 * kMaxChannelDelta) << moved;
  }
}

// The default grid 12 as students see it: the shorter-diagonal cells differ,
// but the halves pass the grading tolerance of reference_images/MANIFEST
// (channel 24, one-pixel shift excused): 0 unexcused of 1 raw (measured).
TEST(BezierSurfacesLab, DefaultGridPassesTheGradingTolerance) {
  ScratchDir dir("lab15");
  const gllab::Image both = evaluator_view(dir, 12);
  EXPECT_EQ(gllab::compare_images(half(both, 1), half(both, 0), 24, 1).mismatched_pixels, 0);
}

// Points a view constructs ignore their list entries (threshold 0: same
// geometry, same pixels on llvmpipe). zero_twist keeps the edges through b00
// (P[0..3], P[0], P[4], P[8], P[12]); constant_twist also b33 = P[15]; the
// join views make rows 0..k of the right patch, whose rows 1..3 are Q[0..11].
TEST(BezierSurfacesLab, ConstructedPointsIgnoreTheirListEntries) {
  ScratchDir dir("lab15");
  struct Case {
    const char* view;
    const char* set;
    bool free;
  };
  const Case cases[] = {
      {"de_casteljau", "P[5]=-0.5,-0.5,1.98", true},   {"zero_twist", "P[5]=-0.5,-0.5,1.98", false},
      {"constant_twist", "P[5]=-0.5,-0.5,1.98", false}, {"constant_twist", "P[15]=1.5,1.5,1.56", true},
      {"zero_twist", "P[15]=1.5,1.5,1.56", false},      {"zero_twist", "P[4]=-0.5,-1.5,0.72", true},
      {"join_c0", "Q[1]=2.5,-0.5,1.6", true},           {"join_c1", "Q[1]=2.5,-0.5,1.6", false},
      {"join_c1", "Q[5]=3.5,-0.5,0.8", true},           {"join_c2", "Q[5]=3.5,-0.5,0.8", false},
  };
  for (const Case& c : cases) {
    const long long differing =
        pixels_differing(render_view(kLab, dir, c.view, {"labels=0"}), render_view(kLab, dir, c.view, {"labels=0", c.set}));
    if (c.free) EXPECT_GT(differing, 0) << c.view << " --set " << c.set << " should change the patch";
    else EXPECT_EQ(differing, 0) << c.view << " --set " << c.set << " should be ignored (the point is made)";
  }
}

}  // namespace
