// tests/labs/22_trimmed_nurbs_test.cpp — what lab 22 promises about its views,
// read from the numbers they print (--print-text):
//  - reversed_outer_loop is an error view: headless it exits 1 with GLU's
//    NURBS error 28, while the same loops with the outer one counter-
//    clockwise render;
//  - outline_patch counts the triangles default makes.
// (GLU's slivers and the own trimmed tessellation: lab 25.)
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::headless;
using gllab::testing::numbers_after;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "22_trimmed_nurbs";
constexpr int kFrameErrorStatus = 1;  // headless --help: a GL or GLU error in the frame

// glu.h's GLU_NURBS_ERROR28 as gluErrorString spells it, for a clockwise outer
// loop; GLU 9.0.2 raises it and loses it on the way to the lab's callback, and
// every lab program catches it (common/gl/glu_errors.cpp, docs/glu.md).
TEST(TrimmedNurbsLab, ReversedOuterLoopExitsOneWithGluError28) {
  ScratchDir dir("lab22");
  const auto out = dir / "x.png";
  const gllab::ProcessResult r =
      gllab::run_process({headless(kLab), "--view", "reversed_outer_loop", "--out", out.string()});
  EXPECT_EQ(r.exit_status, kFrameErrorStatus) << r.err;
  EXPECT_EQ(gllab::testing::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("view 'reversed_outer_loop': GLU NURBS error 28 (intersecting or misoriented trim "
                       "curves), lost by GLU 9.0.2 before its error callback"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  // The harness knows it for an error view (lab.h kErrorView).
  const gllab::ProcessResult views = gllab::run_process({headless(kLab), "--list-views"});
  EXPECT_NE(views.out.find("\nreversed_outer_loop expect_error\n"), std::string::npos) << views.out;
}

// The negative check: the same five loops with the outer one counter-clockwise.
TEST(TrimmedNurbsLab, TheSameLoopsCorrectlyOrientedRenderWithoutError) {
  ScratchDir dir("lab22");
  const std::vector<double> n = gllab::testing::numbers_before(view_text(kLab, dir, "default"), " triangles");
  ASSERT_EQ(n.size(), 1u);
  EXPECT_GT(n[0], 0);
}

// outline_patch: GLU_OUTLINE_PATCH draws lines only; the right panel counts
// the same triangles as default (the same loops, the same properties).
TEST(TrimmedNurbsLab, OutlinePatchCountsTheTrianglesOfDefault) {
  ScratchDir dir("lab22");
  const std::vector<double> a = gllab::testing::numbers_before(view_text(kLab, dir, "default"), " triangles");
  const std::vector<double> b =
      gllab::testing::numbers_before(view_text(kLab, dir, "outline_patch"), " triangles");
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(a[0], b[0]);
}

}  // namespace
