// tests/labs/34_patch_subdivision_test.cpp — what lab 34's views promise: the
// piece count printed is the core's split_adaptive (lecture notes "Higher Order
// Surfaces", "Splitting Termination"), and cracks_closed shows less background
// than cracks (the T-junction cracks of "Patch Cracking" are filled).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"
#include "spline/patch_subdivision.h"

namespace {

using gllab::testing::colour_mask;
using gllab::testing::mask_count;
using gllab::testing::numbers_before;
using gllab::testing::render_view;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;
namespace sp = gllab::spline;

const std::string kLab = "34_patch_subdivision";
// The lab's patch (labs/34_patch_subdivision, "Lab data") and its maximum depth.
const std::vector<sp::Vec3> kPatch = {
    {-1.15, -0.78, 0.0}, {-0.75, -0.31, 0.0}, {-0.75, 0.31, 0.0}, {-1.15, 0.78, 0.0},
    {-0.80, -1.39, 0.0}, {-0.10, -0.55, 0.0}, {-0.10, 0.55, 0.0}, {-0.80, 1.39, 0.0},
    {-0.45, -1.99, 0.0}, {0.56, -0.79, 0.0}, {0.56, 0.79, 0.3}, {-0.45, 1.99, 0.6},
    {-0.10, -2.60, 0.0}, {1.22, -1.03, 0.2}, {1.22, 1.03, 1.2}, {-0.10, 2.60, 2.0}};
constexpr int kMaxDepth = 4;

TEST(PatchSubdivisionLab, PrintedPieceCountIsTheCores) {
  ScratchDir dir("lab34");
  for (const char* tol : {"0.2", "0.1", "0.05"}) {
    const auto lines = view_text(kLab, dir, "cracks", {std::string("tolerance=") + tol});
    const std::vector<double> count = numbers_before(lines, " pieces");
    ASSERT_EQ(count.size(), 1u) << tol;
    const sp::BezierSurface p{3, 3, kPatch};
    EXPECT_EQ(count[0], double(sp::split_adaptive(p, std::stod(tol), kMaxDepth).size())) << tol;
  }
}

// The magenta clear colour (1, 0, 1) below the text panel: cracks show it through
// the gaps, cracks_closed over the same pieces shows strictly less of it.
TEST(PatchSubdivisionLab, ClosedViewFillsTheCracks) {
  ScratchDir dir("lab34");
  const std::vector<gllab::testing::Rgb8> magenta = {{255, 0, 255}};
  const long long open = mask_count(colour_mask(render_view(kLab, dir, "cracks"), magenta, 0, 60));
  const long long closed =
      mask_count(colour_mask(render_view(kLab, dir, "cracks_closed"), magenta, 0, 60));
  EXPECT_GT(open, closed);
  RecordProperty("crack_pixels", std::to_string(open - closed));
}

}  // namespace
