// tests/labs/13_cubic_splines_test.cpp — lab 13's promise about the
// nielson_shear view (and forced_point, below): with the Nielson metric the spline of the sheared
// points IS the sheared spline; with chord lengths it is not.
//
// Origin: lecture notes ch. 1, §1.6 Spline representations, "Nielson metric":
// the metric whitens the points by their covariance, so an affine map A leaves
// every metric length, hence every parameter t_i, unchanged; the cubic spline is linear in its points for fixed
// nodes, so spline(A P) = A spline(P) at every parameter. Chord lengths change
// under a shear, so the nodes and the curve change (Notice in the lab header).
//
// The view's overlay parameter draws row 2 either as the spline of the
// sheared points (overlay=1) or as row 1's spline sheared by GL with
// glMultMatrixd (overlay=2), both as a 2-px polyline through the same 401
// evenly spaced parameters of their domains, in the same ink.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::render_view;
using gllab::testing::ScratchDir;

const std::string kLab = "13_cubic_splines";

// Measured at shears 1.5, -2, 0.5 and 3: the Nielson cell differs in 0 pixels
// (its vertices agree to 2e-15 lab units; GL's float matrices move them by
// far less than llvmpipe's 1/256-pixel grid), the chord-length cell in 321 to
// 1013. So: no pixel may differ, and the wrong one must differ in many.
constexpr long long kSameCurvePixels = 0;
constexpr long long kDifferentCurvePixels = 100;

// Row 2's cells in the lab's layout: ortho_fit(7, 7) on 512 x 512, so lab
// (x, y) is pixel ((x + 7) 512/14, (7 - y) 512/14). Left cell x in [-6.9, -0.1],
// right cell [0.1, 6.9], both y in [-3.6, 2.2].
int px(double lab) { return int((lab + 7) * 512 / 14); }

gllab::Image crop(const gllab::Image& im, int x0, int y0, int x1, int y1) {
  gllab::Image c(x1 - x0, y1 - y0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int k = 0; k < 4; ++k) c.pixel(x - x0, y - y0)[k] = im.pixel(x, y)[k];
  return c;
}
gllab::Image cell(const gllab::Image& im, bool chordal) {  // pixel row of lab y is px(-y)
  return crop(im, chordal ? px(0.1) : px(-6.9), px(-2.2), chordal ? px(6.9) : px(-0.1), px(3.6));
}

class ShearedSpline : public ::testing::TestWithParam<const char*> {};

TEST_P(ShearedSpline, NielsonCommutesWithTheShearChordLengthDoesNot) {
  ScratchDir dir("lab13");
  const std::string shear = std::string("shear=") + GetParam();
  const gllab::Image of_sheared = render_view(kLab, dir, "nielson_shear", {"labels=0", "overlay=1", shear});
  const gllab::Image sheared = render_view(kLab, dir, "nielson_shear", {"labels=0", "overlay=2", shear});
  EXPECT_LE(gllab::testing::pixels_differing(cell(of_sheared, false), cell(sheared, false)), kSameCurvePixels);
  EXPECT_GT(gllab::testing::pixels_differing(cell(of_sheared, true), cell(sheared, true)), kDifferentCurvePixels);
}

INSTANTIATE_TEST_SUITE_P(Shears, ShearedSpline, ::testing::Values("1.5", "-2", "0.5", "3"));

// The comparison can fail where it must: the cells are not empty, and the
// two overlays differ from the default picture (both curves drawn).
TEST(CubicSplinesLab, OverlaysDrawSomethingDifferent) {
  ScratchDir dir("lab13");
  const gllab::Image both = render_view(kLab, dir, "nielson_shear", {"labels=0"});
  const gllab::Image one = render_view(kLab, dir, "nielson_shear", {"labels=0", "overlay=1"});
  EXPECT_GT(gllab::testing::pixels_differing(cell(both, false), cell(one, false)), kDifferentCurvePixels);
}

// forced_point (lecture notes "B-Spline Polynomials", "Forcing Interpolation"): P[3] taken 1, 2
// and 3 times in a uniform cubic B-spline. The joint of segments with Q[i..i+2] = P, P, P is
// (1/6)(P + 4P + P) = P (the matrix form's row t = 0: 1/6, 4/6, 1/6), so at 3 the printed
// distance is 0 up to rounding. At 1 and 2 the curve misses P: the joints nearest to it are
// (P[2] + 4P + P[4])/6, 0.425 away, and (P[2] + 5P)/6, |P[2] - P|/6 = 0.420 away (lab data).
constexpr double kOnThePoint = 5e-5;  // lab units: the view prints %.4f (measured 2.3e-16)

TEST(CubicSplinesLab, TripledControlPointIsOnTheUniformBspline) {
  ScratchDir dir("lab13");
  const std::vector<std::string> text = gllab::testing::view_text(kLab, dir, "forced_point");
  const std::vector<double> once = gllab::testing::numbers_after(text, "P[3] 1 times: distance ");
  const std::vector<double> twice = gllab::testing::numbers_after(text, "P[3] 2 times: distance ");
  const std::vector<double> thrice = gllab::testing::numbers_after(text, "P[3] 3 times: distance ");
  ASSERT_EQ(once.size(), 1u);
  ASSERT_EQ(twice.size(), 1u);
  ASSERT_EQ(thrice.size(), 1u);
  EXPECT_GT(once[0], kOnThePoint);
  EXPECT_GT(twice[0], kOnThePoint);
  EXPECT_LE(twice[0], 0.42);  // at most the joint's distance |P[2] - P|/6 = 0.4197
  EXPECT_LE(std::fabs(thrice[0]), kOnThePoint);
}

// method has the range [0, 4] (uniform .. Nielson): the harness rejects 5.
TEST(CubicSplinesLab, ParameterizationOutsideItsRangeIsOneLineAndExitTwo) {
  ScratchDir dir("lab13");
  const gllab::ProcessResult r =
      gllab::run_process({gllab::testing::headless(kLab), "--set", "method=5", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(gllab::testing::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("[0, 4]"), std::string::npos) << r.err;
}

}  // namespace
