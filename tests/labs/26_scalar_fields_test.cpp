// tests/labs/26_scalar_fields_test.cpp — what lab 26 promises:
//  - the terrain is a scalar field (lecture notes ch. 1, §1.7 Surface
//    representations, "Scalar fields"): only the heights of its control points
//    are data, x and y stay on the grid;
//  - the iso-line spacing changes the map.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::pixels_differing;
using gllab::testing::render_view;
using gllab::testing::ScratchDir;

const std::string kLab = "26_scalar_fields";

// H[14] is (-2/3, -2/3, 1.8): x and y are its Greville abscissae, z the data.
TEST(ScalarFieldsLab, TerrainReadsOnlyTheHeights) {
  ScratchDir dir("lab26");
  for (const char* view : {"terrain", "terrain_map"}) {
    const gllab::Image base = render_view(kLab, dir, view);
    EXPECT_EQ(pixels_differing(base, render_view(kLab, dir, view, {"H[14]=0.25,1.5,1.8"})), 0) << view;
    EXPECT_GT(pixels_differing(base, render_view(kLab, dir, view, {"H[14]=-0.667,-0.667,1.5"})), 0) << view;
  }
}

TEST(ScalarFieldsLab, IsoStepChangesTheMap) {
  ScratchDir dir("lab26");
  const gllab::Image map = render_view(kLab, dir, "terrain_map", {"labels=0"});
  EXPECT_GT(pixels_differing(map, render_view(kLab, dir, "terrain_map", {"labels=0", "iso_step=0.1"})), 0);
}

}  // namespace
