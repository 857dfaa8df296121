// tests/labs/06_polygon_mesh_test.cpp — what lab 06 promises about its views:
// splitting vertices at feature edges is the only difference between its two
// feature_edges panels, so without feature edges the panels are the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::headless;
using gllab::testing::ScratchDir;

const std::string kLab = "06_polygon_mesh";

// A view of this lab with --set arguments (lab_test_support.h).
gllab::Image render(const ScratchDir& dir, const std::string& view, const std::vector<std::string>& sets) {
  return gllab::testing::render_view(kLab, dir, view, sets);
}

// Pixels whose left-half value differs from the right-half value one half
// width further on. The panels sit at x = -1.25 and +1.25 in a view 5 units
// wide (lab 06 enter_panel), so at 512 px they are exactly 256 px apart.
long long halves_differing(const gllab::Image& im) {
  long long n = 0;
  const int half = im.width / 2;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < half; ++x) {
      const std::uint8_t *a = im.pixel(x, y), *b = im.pixel(x + half, y);
      n += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
    }
  return n;
}

// At feature_angle=180 no edge is a feature, so the split arrays (left) hold
// the averaged normals of the right panel: the two objects look the same.
TEST(PolygonMeshLab, WithoutFeatureEdgesSplitEqualsAveraged) {
  ScratchDir dir("lab06");
  const gllab::Image none = render(dir, "feature_edges", {"labels=0", "feature_angle=180"});
  EXPECT_EQ(halves_differing(none), 0);
}

// At the default 30 degrees the rims are features: the left panel shades its
// caps flat and draws the rims as lines, so many pixels change. Measured:
// 33,900 of the 131,072 in a half (33,483 without the lines); the bound is
// well below that, and far above the 0 of the test before.
TEST(PolygonMeshLab, FeatureEdgesChangeTheShading) {
  constexpr long long kAtLeast = 10000;
  ScratchDir dir("lab06");
  EXPECT_GT(halves_differing(render(dir, "feature_edges", {"labels=0"})), kAtLeast);
  EXPECT_GT(halves_differing(render(dir, "feature_edges", {"labels=0", "edges=0"})), kAtLeast);
}

// data_structure's panel counts the cube from the mesh (common/gl/mesh_view.h,
// data_structure_counts): 8 corners, the cube's 12 edges plus the lid's
// diagonal, its 6 faces with the lid split in two; Euler's V - E + F = 2 for a
// closed surface without holes. Each corner meets 3 faces across feature edges
// (90 degrees > 30): 3 render vertices per corner, 24 in all; the diagonal is
// virtual, so the lid's two triangles are one smoothing group.
TEST(PolygonMeshLab, DataStructurePanelCountsTheCube) {
  ScratchDir dir("lab06");
  const std::vector<std::string> text = gllab::testing::view_text(kLab, dir, "data_structure");
  const auto has = [&](const std::string& line) {
    return std::find(text.begin(), text.end(), line) != text.end();
  };
  EXPECT_TRUE(has("2 surfaces: box 5 polygons, lid 2"));
  EXPECT_TRUE(has("V 8  E 13  F 7  V-E+F = 2"));
  EXPECT_TRUE(has("12 feature edges (orange), 1 virtual (blue, dashed)"));
  EXPECT_TRUE(has("edge 4-7 is used by polygons 1 and 2"));
  EXPECT_TRUE(has("24 vertices sent to GL: one per corner and smoothing group"));
}

// The lab rejects parameters outside their range with one line and exit 2.
TEST(PolygonMeshLab, RejectsAFeatureAngleAbove180) {
  ScratchDir dir("lab06");
  const gllab::ProcessResult r = gllab::run_process(
      {headless(kLab), "--set", "feature_angle=181", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("feature_angle"), std::string::npos) << r.err;
}

}  // namespace
