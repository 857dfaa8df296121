// tests/labs/19_gl_evaluators_test.cpp — lab 19's promise: the own core's
// Bézier curve and patch are what OpenGL's evaluators draw from the same
// control points on the same grid.
//
// curve draws either the core's points X(k / grid) = bezier_point, k =
// 0..grid, as a line strip (source=1), or glMap1f + glMapGrid1f(grid, 0, 1) +
// glEvalMesh1(GL_LINE, 0, grid) on the same control points (source=2), in the
// same ink and width, each with its dot at X(t) (own: bezier_point, GL:
// glEvalCoord1f).
// Origin of the expectation: both evaluate the Bernstein form
// X(u) = sum b_i B_i^n(u) (lecture notes ch. 1, §1.6 Spline representations,
// "Properties of Bézier segments", property 5; the OpenGL 2.1 specification
// §5.1 defines glMap1 by the same polynomials) at the same parameters, so the
// two strips have the same vertices up to rounding: GL evaluates in float,
// the core in double. Measured (the view reads both strips back in feedback
// mode, common/gl/feedback.h): after GL's float transform the vertices agree
// exactly for the notes' polygon; in double the core's points lie within
// 4e-4 px of GL's for the dragged polygons below, far inside llvmpipe's
// 1/256-pixel snapping grid. Measured in pixels: 0 differ at grids 1, 4, 64,
// 256 and for the dragged polygons below (and two more tried while writing
// this test), so the tolerance is 0 (kEvaluatorPixels). A control point moved
// by 2 px changes 519.
//
// surface draws the patch twice, in the two halves of the window under the
// same matrices and lighting: left the core's tessellation
// (tessellate_surface on un x vn cells, normals Xu x Xv from the core),
// right glMap2f + glMapGrid2f + glEvalMesh2 with GL_AUTO_NORMAL on the same
// grid (normals du x dv from Mesa's evaluator), with glEvalMesh2(GL_LINE)'s
// grid lines on top (grid_lines=1, GL's half only). Both put their vertices
// at the same (u_i, v_j) of the same polynomial, so the filled halves must agree.
// Where the tolerance comes from (measured on llvmpipe, nets=0 labels=0
// grid_lines=0, the same number of cells along u and v):
//  - The core splits each cell along its shorter diagonal; glEvalMesh2's
//    triangle strips always split from (u_i, v_j+1) to (u_i+1, v_j). With
//    the core forced to GL's diagonal (an experiment, not in the code), the
//    halves differed by at most 1 in one pixel at grids 4, 12 and 32: the
//    float evaluator and the double core agree that closely.
//  - With the shorter diagonal, a cell whose diagonals differ is a different
//    pair of triangles: the difference shrinks with the cell size squared.
//    Grid 12: 73 pixels off by more than 2, max 103 on the silhouette (the
//    default 12 x 6: 435, max 117); grid 32: max 2 everywhere (674 pixels
//    off by 1 or 2); grid 64: max 1.
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

const std::string kLab = "19_gl_evaluators";

// ---- curve: glMap1f + glEvalMesh1 --------------------------------------------

// Pixels that may differ between the own strip and GL's (threshold 0): the
// measurement above found none, at every grid.
constexpr long long kEvaluatorPixels = 0;
// The grader's tolerance (README, reference_images/MANIFEST): channel 24,
// one-pixel shifts excused.
constexpr int kGraderThreshold = 24, kGraderShift = 1;

gllab::Image curve(const ScratchDir& dir, const std::string& source,
                   std::vector<std::string> sets = {}) {
  sets.insert(sets.end(), {"labels=0", "source=" + source});
  return render_view(kLab, dir, "curve", sets);
}

// The pictures are not empty: the curve and its points cover pixels that the
// clear colour (0.12, 0.13, 0.16 -> 31, 33, 41) does not.
long long drawn_pixels(const gllab::Image& img) {
  long long n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += img.pixel(x, y)[0] != 31 || img.pixel(x, y)[2] != 41;
  return n;
}

struct Case {
  const char* name;
  std::vector<std::string> sets;
};

class OwnAgainstEvaluator : public ::testing::TestWithParam<Case> {};

TEST_P(OwnAgainstEvaluator, SameGridGivesTheSamePixels) {
  ScratchDir dir("lab19");
  const gllab::Image own = curve(dir, "1", GetParam().sets), gl = curve(dir, "2", GetParam().sets);
  EXPECT_GT(drawn_pixels(gl), 1000);  // a 2-px curve over some 500 px, and 4 squares
  EXPECT_LE(pixels_differing(own, gl), kEvaluatorPixels);
}

// grid 1: the chord b_0 b_n; 4: visibly polygonal; 64: the default; 256:
// sub-pixel segments; then polygons a student might drag (3 decimals, as the
// mouse snaps them), one with a loop-like bulge beyond the frame.
INSTANTIATE_TEST_SUITE_P(
    Grids, OwnAgainstEvaluator,
    ::testing::Values(Case{"grid1", {"curve_grid=1"}}, Case{"grid4", {"curve_grid=4"}},
                      Case{"grid64", {"curve_grid=64"}}, Case{"grid256", {"curve_grid=256"}},
                      Case{"dragged100", {"curve_grid=100", "P[1]=2.123,4.456", "P[2]=7.77,6.1"}},
                      Case{"dragged33", {"curve_grid=33", "P[0]=0.311,0.1", "P[3]=10.9,2.4"}},
                      Case{"bulge256", {"curve_grid=256", "P[1]=5,9", "P[2]=6,-3"}}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// Negative checks: a wrong curve must fail the same comparison.
TEST(GlEvaluatorsLab, ControlPointMovedByTwoPixelsFails) {
  // b_2 = (8.5, 6.5) moved down by 0.05 units: about 2 px at the view's scale
  // (39.5 px per unit), at most 0.44 x that on the curve (max B_2^3 = 4/9).
  // Measured: 519 pixels differ. (The grader, which excuses one-pixel shifts,
  // still finds 32: a move this small is below what it is meant to catch.)
  ScratchDir dir("lab19");
  const long long n = pixels_differing(curve(dir, "2"), curve(dir, "1", {"P[2]=8.5,6.45"}));
  EXPECT_GT(n, kEvaluatorPixels);
  EXPECT_GT(n, 100);
}

TEST(GlEvaluatorsLab, ParameterReversedFailsOnlyThroughTheDotAtT) {
  // X(1 - t) instead of X(t): the reversed control polygon (lecture notes
  // ch. 1, §1.6, "Properties of Bézier segments", property 7, symmetry: it
  // gives Y(t) = X(1 - t)). The strip covers the same curve, so only the dot
  // at t can tell: drawn at X(0.4) instead of X(0.6), it differs in 132
  // pixels (measured) and no shift explains it.
  ScratchDir dir("lab19");
  const std::vector<std::string> reversed = {"P[0]=11,2", "P[1]=8.5,6.5", "P[2]=2,4.5", "P[3]=0,0"};
  const gllab::Image gl = curve(dir, "2");
  const gllab::Comparison wrong =
      gllab::compare_images(gl, curve(dir, "1", reversed), kGraderThreshold, kGraderShift);
  EXPECT_GT(wrong.differing_pixels, kEvaluatorPixels);
  EXPECT_GT(wrong.mismatched_pixels, 50);
  // With t = 0.4 as well the dot is back at X(0.6), and the reversed strip
  // differs from GL's only where a line runs one pixel over (6 pixels
  // measured, all excused by a one-pixel shift): the same curve, as property 7 says.
  std::vector<std::string> both = reversed;
  both.push_back("t=0.4");
  const gllab::Comparison same =
      gllab::compare_images(gl, curve(dir, "1", both), kGraderThreshold, kGraderShift);
  EXPECT_EQ(same.mismatched_pixels, 0);
}

// ---- surface: glMap2f + glEvalMesh2 ------------------------------------------

constexpr int kFineGrid = 32;
constexpr int kMaxChannelDelta = 2;  // see the header: shorter vs GL's diagonal at grid 32
// The patch covers 13,574 of the 131,072 pixels of a half (measured): far from empty.
constexpr long long kMinPatchPixels = 10000;

// Half `side` (0 left, 1 right) of a render of surface.
gllab::Image half(const gllab::Image& im, int side) {
  gllab::Image out(im.width / 2, im.height);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) out.pixel(x, y)[c] = im.pixel(x + side * out.width, y)[c];
  return out;
}

// surface with nets and labels off (the net and the captions are in one half only).
gllab::Image surface_view(const ScratchDir& dir, std::vector<std::string> sets) {
  sets.insert(sets.end(), {"nets=0", "labels=0"});
  return render_view(kLab, dir, "surface", sets);
}

// ... on a grid x grid mesh, without the grid lines: the filled patches alone.
gllab::Image surface(const ScratchDir& dir, int grid, std::vector<std::string> sets = {}) {
  const std::string n = std::to_string(grid);
  sets.insert(sets.end(), {"surface_un=" + n, "surface_vn=" + n, "grid_lines=0"});
  return surface_view(dir, sets);
}

long long lit_pixels(const gllab::Image& im) {  // the clay is red-dominated, the background is not
  long long n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) n += im.pixel(x, y)[0] > 100;
  return n;
}

TEST(GlEvaluatorsLab, OwnTessellationMatchesGlEvalMesh2AtTheSameGrid) {
  ScratchDir dir("lab19");
  const gllab::Image both = surface(dir, kFineGrid);
  const gllab::Image own = half(both, 0), gl = half(both, 1);
  EXPECT_GT(lit_pixels(own), kMinPatchPixels);
  EXPECT_GT(lit_pixels(gl), kMinPatchPixels);
  const gllab::Comparison c = gllab::compare_images(gl, own, kMaxChannelDelta);
  EXPECT_EQ(c.differing_pixels, 0) << "max channel difference " << c.max_delta;
}

// The negative checks: each mistake must break the tolerance.
TEST(GlEvaluatorsLab, WithoutAutoNormalTheEvaluatorHalfDiffers) {
  ScratchDir dir("lab19");
  const gllab::Image both = surface(dir, kFineGrid, {"auto_normal=0"});
  const gllab::Comparison c = gllab::compare_images(half(both, 1), half(both, 0), kMaxChannelDelta);
  EXPECT_GT(c.max_delta, 10 * kMaxChannelDelta);
  EXPECT_GT(c.differing_pixels, kMinPatchPixels / 2) << "the whole patch is lit wrong";
}

TEST(GlEvaluatorsLab, AControlPointMovedByOnePercentDiffersFromTheEvaluator) {
  ScratchDir dir("lab19");
  const gllab::Image gl = half(surface(dir, kFineGrid), 1);
  // B[5] = (-0.5, -0.5, 1.68) by default; 0.03 is 1% of the 3-unit patch.
  for (const char* moved : {"B[5]=-0.5,-0.5,1.71", "B[5]=-0.47,-0.5,1.68", "B[15]=1.5,1.5,1.29"}) {
    const gllab::Image own = half(surface(dir, kFineGrid, {moved}), 0);
    const gllab::Comparison c = gllab::compare_images(gl, own, kMaxChannelDelta);
    EXPECT_GT(c.differing_pixels, 0) << moved;
    EXPECT_GT(c.max_delta, 10 * kMaxChannelDelta) << moved;
  }
}

// The default grid 12 x 6 as students see it (the grid lines, GL's half only,
// off): the shorter-diagonal cells differ, but the halves pass the grading
// tolerance of reference_images/MANIFEST (channel 24, one-pixel shift
// excused): 0 unexcused of 9 raw (measured).
TEST(GlEvaluatorsLab, DefaultGridPassesTheGradingTolerance) {
  ScratchDir dir("lab19");
  const gllab::Image both = surface_view(dir, {"grid_lines=0"});
  EXPECT_EQ(gllab::compare_images(half(both, 1), half(both, 0), 24, 1).mismatched_pixels, 0);
}

// glMap2f with its strides swapped (3 for u, 12 for v) maps (u, v) to X(v, u):
// the same surface, so on n x n cells the same picture (the winding and
// GL_AUTO_NORMAL's du x dv both flip, and two-sided lighting lights it the
// same). On 12 x 6 cells it draws what the right map draws on 6 x 12, and the
// grid lines show it: GL's half at 12 x 6 against GL's half at 6 x 12 fails
// the grading tolerance in 723 pixels (measured); without the lines the
// filled patches differ in 80 raw pixels, all excused as one-pixel shifts.
TEST(GlEvaluatorsLab, TheGridLinesTellUFromV) {
  ScratchDir dir("lab19");
  const std::vector<std::string> swap = {"surface_un=6", "surface_vn=12"};
  const gllab::Comparison lines = gllab::compare_images(
      half(surface_view(dir, {}), 1), half(surface_view(dir, swap), 1), 24, 1);
  EXPECT_GT(lines.mismatched_pixels, 300);
  std::vector<std::string> fill_only = swap;
  fill_only.push_back("grid_lines=0");
  const gllab::Comparison fill = gllab::compare_images(
      half(surface_view(dir, {"grid_lines=0"}), 1), half(surface_view(dir, fill_only), 1), 24, 1);
  EXPECT_EQ(fill.mismatched_pixels, 0) << "the filled patch alone cannot tell u from v";
}

}  // namespace
