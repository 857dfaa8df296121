// tests/labs/35_quadric_coordinates_test.cpp — what lab 35 promises about its
// views: the sphere built from spherical coordinates and the cylinder built
// from cylindrical ones cover exactly what gluSphere and gluCylinder cover at
// any slices and stacks (no orange left in the overlay), and level_of_detail
// prints for each sphere the fewest slices whose sagitta on screen stays within
// error_px, with that sagitta.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::numbers_before;
using gllab::testing::Rgb8;
using gllab::testing::ScratchDir;

const std::string kLab = "35_quadric_coordinates";

// The overlay cell: x = 2.2 of ortho_fit(3.3) in a 512 x 512 image, 256/3.3
// = 77.6 px per unit; the cell is the right third, [341, 512) (its neighbour's
// centre is at 256). The lab's colours, round(255 x): GLU orange (0.95, 0.55,
// 0.2), own green (0.3, 0.75, 0.35), unlit.
constexpr int kOverlayLeft = 341;
const Rgb8 kOrange{242, 140, 51}, kGreen{77, 191, 89};
// A sphere of radius 0.9 units covers pi (0.9 x 77.6)^2 = 15,300 px; the tilted
// cylinder (radius 0.6, height 1.4) less. At least this many must be green.
constexpr long long kMinGreen = 8000;

long long overlay_pixels(const gllab::Image& im, Rgb8 colour) {
  return gllab::testing::mask_count(gllab::testing::colour_mask(im, {colour}, kOverlayLeft, 0));
}

// Property: own = GLU vertex for vertex (the same angles, GLU's order: slice 0
// at +y, clockwise), so own, drawn over GLU with a polygon offset of a few depth
// units, hides GLU everywhere. Counts that are multiples of 4 and counts that
// are not (there a sphere started at theta = 0 would differ), and GLU's minimum.
TEST(QuadricCoordinatesLab, OwnSphereAndCylinderCoverGluExactly) {
  ScratchDir dir("lab35");
  const std::vector<std::vector<std::string>> counts = {
      {}, {"slices=7", "stacks=5"}, {"slices=2", "stacks=1"}, {"slices=20", "stacks=3"},
      {"slices=64", "stacks=64"}};
  for (const std::string view : {"spherical_vs_glu", "cylindrical_vs_glu"})
    for (const std::vector<std::string>& sets : counts) {
      const gllab::Image im = gllab::testing::render_view(kLab, dir, view, sets);
      const std::string what = view + (sets.empty() ? "" : " " + sets[0]);
      EXPECT_EQ(overlay_pixels(im, kOrange), 0) << what;
      // Two slices make flat quads in the plane x = 0, seen edge on: no area to count.
      if (sets.empty() || sets[0] != "slices=2") {
        EXPECT_GT(overlay_pixels(im, kGreen), kMinGreen) << what;
      }
    }
}

// level_of_detail with the lab's data: gluPerspective(40 deg) in 512 px, so
// f = 256 / tan(20 deg) = 703.3 px; spheres of radius 0.5 at eye depths
// 4.5 x 2^k, k = 0..4; r_px = 0.5 f / d. The expected n is found here by
// counting up from 4 until r_px (1 - cos(pi / n)) <= error_px (the definition,
// not the core's closed form); the fixed row keeps the lab's default 18 slices.
struct Expected {
  std::vector<double> fixed_error, n, error;
  double triangles = 0;
};

Expected expected_lod(double error_px, double zoom) {
  Expected x;
  const double f = zoom * 256 / std::tan(20 * M_PI / 180);
  for (int k = 0; k < 5; ++k) {
    const double r_px = 0.5 * f / (4.5 * std::pow(2.0, k));
    int n = 4;
    while (r_px * (1 - std::cos(M_PI / n)) > error_px) ++n;
    x.fixed_error.push_back(r_px * (1 - std::cos(M_PI / 18)));
    x.n.push_back(n);
    x.error.push_back(r_px * (1 - std::cos(M_PI / n)));
    x.triangles += 2 * n * ((n + 1) / 2 - 1);  // gluSphere: 2 fans of n, 2 per quad (GLU quad.c)
  }
  return x;
}

constexpr double kPrinted = 0.005;  // errors are printed with two decimals

void check_lod(const std::vector<std::string>& text, const Expected& want, double error_px) {
  const std::vector<double> n = numbers_after(text, "n="), px = numbers_before(text, " px");
  ASSERT_EQ(n.size(), 10u);
  ASSERT_EQ(px.size(), 10u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(n[k], 18) << "fixed row, sphere " << k;
    EXPECT_NEAR(px[k], want.fixed_error[k], kPrinted) << "fixed row, sphere " << k;
    EXPECT_EQ(n[5 + k], want.n[k]) << "sphere " << k;
    EXPECT_NEAR(px[5 + k], want.error[k], kPrinted) << "sphere " << k;
    EXPECT_LE(px[5 + k], error_px + kPrinted) << "sphere " << k;
  }
  EXPECT_EQ(numbers_before(text, " triangles").back(), want.triangles);
}

TEST(QuadricCoordinatesLab, LevelOfDetailPrintsTheFewestSlicesWithinHalfAPixel) {
  ScratchDir dir("lab35");
  const std::vector<std::string> text = gllab::testing::view_text(kLab, dir, "level_of_detail");
  check_lod(text, expected_lod(0.5, 1), 0.5);
  // The nearest sphere, 78 px in radius, needs 28 slices; 18 leave it 1.19 px off.
  EXPECT_EQ(numbers_after(text, "n=")[5], 28);
}

TEST(QuadricCoordinatesLab, LevelOfDetailFollowsTheErrorBound) {
  ScratchDir dir("lab35");
  check_lod(gllab::testing::view_text(kLab, dir, "level_of_detail", {"error_px=2"}),
            expected_lod(2, 1), 2);
}

// The wheel's zoom scales the projection: every sphere covers twice the pixels,
// and the counts follow (the lab reads f from the projection matrix).
TEST(QuadricCoordinatesLab, LevelOfDetailFollowsTheZoom) {
  ScratchDir dir("lab35");
  const gllab::ProcessResult r = gllab::run_process(
      {gllab::testing::headless(kLab), "--view", "level_of_detail", "--camera", "0,0,2",
       "--print-text", "--out", (dir / "zoom.png").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  std::vector<std::string> text;
  std::stringstream in(r.out);
  for (std::string line; std::getline(in, line);) text.push_back(line);
  const Expected want = expected_lod(0.5, 2);
  const std::vector<double> n = numbers_after(text, "n=");
  ASSERT_EQ(n.size(), 10u);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(n[5 + k], want.n[k]) << "sphere " << k;
}

}  // namespace
