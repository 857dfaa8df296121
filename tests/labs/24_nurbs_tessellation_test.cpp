// tests/labs/24_nurbs_tessellation_test.cpp — what lab 24 promises: the own
// tessellation keeps its tolerance and is not needlessly finer than it; GLU's
// vertices lie on the own surface to float precision, and far off it when fed
// (x, y, z, w) unmultiplied.
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

const std::string kLab = "24_nurbs_tessellation";

// tessellate.h: every triangle within the tolerance (parametric error); the
// view measures it with spline::mesh_fidelity and prints it under the panel.
TEST(NurbsTessellationLab, OwnTessellationKeepsItsTolerance) {
  ScratchDir dir("lab24");
  for (const char* finer : {"finer=-1", "finer=0", "finer=2"}) {
    const std::vector<std::string> text = view_text(kLab, dir, "own_vs_glu", {finer});
    const std::vector<double> tol = numbers_after(text, "tolerance ");
    const std::vector<double> off = numbers_after(text, "max deviation ");
    ASSERT_EQ(tol.size(), 2u) << finer;  // GLU's panel, the own panel
    ASSERT_EQ(off.size(), 2u) << finer;
    // The tolerance is printed with %g (6 digits); the deviation with 3.
    EXPECT_LE(off[1], tol[1] * (1 + 1e-5)) << finer;
    EXPECT_GT(off[1], tol[1] / 10) << finer << ": the own mesh is not needlessly fine";
  }
}

// docs/glu.md: GLU's tessellator vertices lie on the true surface to about
// 1e-6 (float); measured here 1.9e-7. Fed unmultiplied, GLU draws the surface
// whose middle control point is P(2, 2) / w: off by 0.52 (measured).
TEST(NurbsTessellationLab, GluVerticesLieOnTheOwnSurfaceUnlessNotPremultiplied) {
  constexpr double kFloatSurface = 1e-6;
  constexpr double kMistakeAtLeast = 0.1;
  ScratchDir dir("lab24");
  const std::string max = "max |GLU - S(u,v)| = ";
  const std::vector<double> right = numbers_after(view_text(kLab, dir, "difference"), max);
  const std::vector<double> wrong = numbers_after(view_text(kLab, dir, "difference", {"mistake=1"}), max);
  ASSERT_EQ(right.size(), 1u);
  ASSERT_EQ(wrong.size(), 1u);
  EXPECT_LT(right[0], kFloatSurface);
  EXPECT_GT(wrong[0], kMistakeAtLeast);
  // With weight 1 the surface is polynomial: the mistake changes nothing.
  EXPECT_LT(numbers_after(view_text(kLab, dir, "difference", {"mistake=1", "weight=1"}), max).at(0), kFloatSurface);
}

}  // namespace
