// tests/labs/14_bezier_splines_test.cpp — what lab 14 promises about its views:
// each continuity condition makes some Bézier points from the others (their
// list entries are then ignored), C0 does not depend on the node spacing while
// C1 does (lecture notes ch. 1, §1.6 Spline representations, "Bézier splines":
// the conditions carry D_i = t_{i+1} - t_i), and G1 with k = 1 is C1 for equal
// intervals (lecture notes "Higher Order Surfaces", "Joining of Bezier Curves":
// C1 is p_n - p_{n-1} = r_1 - r_0). The images are compared exactly (threshold
// 0): llvmpipe renders the same geometry to the same pixels (every reference
// image renders byte-identical run after run), so "the same" means the lab drew
// the same curve, and any difference means it did not.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::pixels_differing;
using gllab::testing::render_view;
using gllab::testing::ScratchDir;

const std::string kLab = "14_bezier_splines";

gllab::Image render(const ScratchDir& dir, const std::string& view, std::vector<std::string> sets = {}) {
  sets.push_back("labels=0");  // the panels print measured numbers, not the point under test
  return render_view(kLab, dir, view, sets);
}

// A point is free in a view when moving it changes the picture, made when
// the picture stays the same. Moves of 0.3 (the curve spans 6 units, about
// 23 pixels): far more than any rasterisation detail.
struct Case {
  const char* view;
  const char* set;  // the default point moved by (+0.3, 0) or (0, +0.3)
  bool free;
};
const Case kCases[] = {
    {"joining_c0", "B[4]=-0.8,-0.2", true},   // C0: every point free
    {"joining_g1", "B[4]=-0.8,-0.2", false},  // G1 puts b4 on the tangent line
    {"joining_c1", "B[4]=-0.8,-0.2", false},  // C1: b4 = b3 + D1/D0 (b3 - b2)
    {"joining_c1", "B[5]=-0.2,-0.6", true},   // ... but not b5
    {"joining_c2", "B[5]=-0.2,-0.6", false},  // C2 makes b5 too
    {"joining_c2", "B[6]=0,0.1", true},       // the joints stay free
    {"de_boor_points", "B[1]=-2.7,0.5", true},   // the chosen end condition b1
    {"de_boor_points", "B[2]=-1.754,0.905", false},  // b2 comes from the de Boor points
    {"de_boor_points", "B[10]=2.5,0.1", false},
    {"de_boor_points", "B[11]=2.5,-0.6", true},  // b11 = b_{3n-1}, the other end condition
};

TEST(BezierSplinesLab, ConditionsMakeSomePointsAndLeaveTheOthersFree) {
  ScratchDir dir("lab14");
  for (const Case& c : kCases) {
    const long long differing = pixels_differing(render(dir, c.view), render(dir, c.view, {c.set}));
    if (c.free) EXPECT_GT(differing, 0) << c.view << " --set " << c.set << " should move the curve";
    else EXPECT_EQ(differing, 0) << c.view << " --set " << c.set << " should be ignored (the point is made)";
  }
}

// C0 only shares the joints: no D_i anywhere, so chordal nodes change nothing.
// C1 and C2 scale the next leg by D_i / D_{i-1}: chordal nodes move b4.
TEST(BezierSplinesLab, OnlyC1AndAboveDependOnTheNodeSpacing) {
  ScratchDir dir("lab14");
  EXPECT_EQ(pixels_differing(render(dir, "joining_c0"), render(dir, "joining_c0", {"nodes=1"})), 0);
  EXPECT_GT(pixels_differing(render(dir, "joining_c1"), render(dir, "joining_c1", {"nodes=1"})), 0);
  EXPECT_GT(pixels_differing(render(dir, "joining_c2"), render(dir, "joining_c2", {"nodes=2"})), 0);
}

// "Joining of Bezier Curves": G1 is p_n - p_{n-1} = k (r_1 - r_0), C1 the case k = 1 (for equal
// intervals, the lab's default uniform nodes). Any other k is a different curve.
TEST(BezierSplinesLab, G1WithKOneIsC1ForUniformNodes) {
  ScratchDir dir("lab14");
  const gllab::Image c1 = render(dir, "joining_c1");
  EXPECT_EQ(pixels_differing(render(dir, "joining_g1", {"g1_factor=1"}), c1), 0);
  EXPECT_GT(pixels_differing(render(dir, "joining_g1", {"g1_factor=2"}), c1), 0);
  // With chordal nodes D_i differ, and k = 1 is no longer C1.
  EXPECT_GT(pixels_differing(render(dir, "joining_g1", {"g1_factor=1", "nodes=1"}),
                             render(dir, "joining_c1", {"nodes=1"})),
            0);
}

// Chordal nodes need distinct joints (parameterization.h). Dragging b3 onto
// b6 must give the core's message, one line and exit 1 (as a GL error does),
// in the headless program and in the window (which used to abort with
// std::terminate, status 134, when display() threw).
TEST(BezierSplinesLab, CoincidentJointsAreAnErrorNotACrash) {
  ScratchDir dir("lab14");
  const std::vector<std::string> args = {"--view", "joining_c1", "--set", "nodes=1", "--set", "B[3]=0,-0.2"};
  std::vector<std::string> headless = {gllab::testing::headless(kLab), "--out", (dir / "x.png").string()};
  headless.insert(headless.end(), args.begin(), args.end());
  const gllab::ProcessResult h = gllab::run_process(headless);
  EXPECT_EQ(h.exit_status, 1) << h.err;
  EXPECT_EQ(gllab::testing::line_count(h.err), 1) << h.err;
  EXPECT_NE(h.err.find("view 'joining_c1': parameters (chordal): P[1]=(0, -0.2, 0) and P[2]=(0, -0.2, 0) coincide"),
            std::string::npos)
      << h.err;
  if (!GLLAB_HAVE_WINDOW) return;  // an OSMesa build: no window to check
  std::vector<std::string> window = gllab::testing::xvfb_run(dir);
  window.insert(window.end(),
                {(gllab::testing::kBinDir / kLab).string(), "--capture", (dir / "w.png").string()});
  window.insert(window.end(), args.begin(), args.end());
  const gllab::ProcessResult w = gllab::run_process(window, {"ASAN_OPTIONS=detect_leaks=0"});  // Mesa's GLX leaks
  EXPECT_EQ(w.exit_status, 1) << w.err;
  EXPECT_NE(w.err.find("coincide (a zero chord gives no parameter step)"), std::string::npos) << w.err;
}

}  // namespace
