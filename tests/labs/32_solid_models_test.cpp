// tests/labs/32_solid_models_test.cpp — what lab 32 promises (lecture notes, "Geometric
// Modeling", introduction: a solid model decides inside or outside for every point; a surface
// model has no inside):
//  - solid: P classified in the classic object (box edge 1.6 ∩ sphere radius 1.05, minus
//    cylinders of radius 0.45 along x, y and z), by the geometry: (0.6, 0.6, 0) is inside all
//    but the cylinders (0.6 from the x and y axes, 0.85 from z); the origin lies on all three
//    axes, so the cylinders remove it; (0.6, 0.45, 0) is 0.45 from the x axis: on;
//  - surface: a ray from a point inside the open tube crosses it once sideways and not at all
//    along the axis; from above the tube, neither ray crosses it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "32_solid_models";

bool has_line_ending(const std::vector<std::string>& text, const std::string& end) {
  for (const std::string& line : text)
    if (line.size() >= end.size() && line.compare(line.size() - end.size(), end.size(), end) == 0)
      return true;
  return false;
}

TEST(SolidModelsLab, ThePointsOfTheClassicObjectAreClassifiedByItsGeometry) {
  ScratchDir dir("lab32");
  EXPECT_TRUE(has_line_ending(view_text(kLab, dir, "solid", {"P[0]=0.6,0.6", "z=0"}), ": inside"));
  EXPECT_TRUE(has_line_ending(view_text(kLab, dir, "solid", {"P[0]=0,0", "z=0"}), ": outside"));
  EXPECT_TRUE(has_line_ending(view_text(kLab, dir, "solid", {"P[0]=0.6,0.45", "z=0"}), ": on"));
  // Outside the sphere (|P| = 1.21 > 1.05) though inside the box.
  EXPECT_TRUE(has_line_ending(view_text(kLab, dir, "solid", {"P[0]=0.7,0.7", "z=0.7"}), ": outside"));
}

TEST(SolidModelsLab, RaysFromInsideTheOpenTubeDisagree) {
  ScratchDir dir("lab32tube");
  const std::vector<std::string> inside = view_text(kLab, dir, "surface", {"P[0]=0.1,0", "z=0"});
  EXPECT_TRUE(has_line_ending(inside, "ray along +x: 1 crossing, so inside"));
  EXPECT_TRUE(has_line_ending(inside, "ray along +z: 0 crossings, so outside"));
  const std::vector<std::string> above = view_text(kLab, dir, "surface", {"P[0]=0.1,0", "z=1"});
  EXPECT_TRUE(has_line_ending(above, "ray along +x: 0 crossings, so outside"));
  EXPECT_TRUE(has_line_ending(above, "ray along +z: 0 crossings, so outside"));
}

}  // namespace
