// tests/labs/21_nurbs_surfaces_test.cpp — what lab 21 promises about its views,
// read from the numbers they show (--print-text) and from their pixels:
//  - display_list: at zoom 1 the list and the direct call are the same
//    triangles and (to a rounding step) pixels; zoomed, only the direct call
//    gets finer;
//  - display_modes: without GL_AUTO_NORMAL the lit surface is one colour,
//    the one the lighting equation gives for the normal (0, 0, 1);
//  - default: both degrees with their clamped knots.
// (Its sampling methods: lab 23; the own tessellation against GLU's: lab 24.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::numbers_before;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "21_nurbs_surfaces";

std::vector<double> triangles(const ScratchDir& dir, const std::string& view, const std::vector<std::string>& sets) {
  return numbers_before(view_text(kLab, dir, view, sets), " triangles");
}

// Pixels that differ by more than kRounding in a channel between the left and
// the right half, below the captions at the top and above those at the
// bottom (the two panels are the same size and have the same projection:
// panels.h). Replaying the list, Mesa lights one vertex a rounding step apart
// from the direct call (measured: one pixel, green 149 against 150).
long long halves_differing(const gllab::Image& im) {
  constexpr int kCaptionRows = 40;  // two text lines and margins at each end
  constexpr int kRounding = 1;
  long long n = 0;
  const int half = im.width / 2;
  for (int y = kCaptionRows; y < im.height - kCaptionRows; ++y)
    for (int x = 0; x < half; ++x) {
      const std::uint8_t *a = im.pixel(x, y), *b = im.pixel(x + half, y);
      n += std::abs(a[0] - b[0]) > kRounding || std::abs(a[1] - b[1]) > kRounding || std::abs(a[2] - b[2]) > kRounding;
    }
  return n;
}

// Lecture notes ch. 1, §1.6 Spline representations, "Displaying B-splines with
// OpenGL", comment: "if you use display lists to generate B-splines OpenGL
// cannot regenerate the approximation since it is already stored in the
// display list". The list is compiled at zoom 1 with GLU_PATH_LENGTH.
TEST(NurbsSurfacesLab, DisplayListKeepsItsTrianglesWhenTheDirectCallRetessellates) {
  ScratchDir dir("lab17");
  const std::vector<double> at1 = triangles(dir, "display_list", {"zoom=1"});
  const std::vector<double> at3 = triangles(dir, "display_list", {"zoom=3"});
  ASSERT_EQ(at1.size(), 2u);  // direct call, display list
  ASSERT_EQ(at3.size(), 2u);
  EXPECT_EQ(at1[0], at1[1]);
  EXPECT_EQ(at3[1], at1[1]);  // the list: as compiled
  // Three times the pixels per unit: up to nine times the triangles at the
  // same edge length in pixels (measured 2060 against 389, 5.3 times).
  EXPECT_GT(at3[0], 3 * at1[0]);
  const gllab::Image one = gllab::testing::render_view(kLab, dir, "display_list", {"zoom=1"});
  const gllab::Image three = gllab::testing::render_view(kLab, dir, "display_list", {"zoom=3"});
  EXPECT_EQ(halves_differing(one), 0);
  // Measured: 47,265 of the 110,592 pixels compared differ (the list's larger
  // facets and their edges); a tenth of that is still far from the 0 above.
  EXPECT_GT(halves_differing(three), 4700);
}

// Colours in a 256 x 232 panel of display_modes below its caption, without
// the background. Panels: 0 GLU_FILL (top left), 3 GLU_FILL without
// GL_AUTO_NORMAL (bottom right).
std::set<std::array<int, 3>> panel_colours(const gllab::Image& im, int panel) {
  constexpr int kCaption = 24;
  const std::uint8_t* bg = im.pixel(0, im.height / 2);
  std::set<std::array<int, 3>> colours;
  const int x0 = (panel % 2) * im.width / 2, y0 = (panel / 2) * im.height / 2;
  for (int y = y0 + kCaption; y < y0 + im.height / 2; ++y)
    for (int x = x0; x < x0 + im.width / 2; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      if (p[0] != bg[0] || p[1] != bg[1] || p[2] != bg[2]) colours.insert({p[0], p[1], p[2]});
    }
  return colours;
}

// Without GL_AUTO_NORMAL GLU sends no normals: every vertex keeps the current
// one, (0, 0, 1) (the lab sets it before the fourth panel). Lighting equation (OpenGL 2.1 §2.14.1)
// with enable_headlight (scene.cpp: ambient 0.2, white diffuse light from
// eye direction (-0.35, 0.45, 1)) and GL_COLOR_MATERIAL: colour = c (0.2 +
// n . L), c = (0.95, 0.6, 0.25) (kGlu). The camera turns (0, 0, 1) by -60°
// about x (the turn about z leaves it alone): n = (0, sin 60°, cos 60°).
TEST(NurbsSurfacesLab, WithoutAutoNormalTheLitSurfaceIsOneColour) {
  constexpr double kColour[3] = {0.95, 0.6, 0.25};
  constexpr int kChannelTolerance = 1;  // rounding to 8 bits
  ScratchDir dir("lab17");
  const gllab::Image im = gllab::testing::render_view(kLab, dir, "display_modes");
  const std::set<std::array<int, 3>> flat = panel_colours(im, 3);
  ASSERT_EQ(flat.size(), 1u);
  const double L = std::sqrt(0.35 * 0.35 + 0.45 * 0.45 + 1.0);
  const double n_dot_l = (std::sin(M_PI / 3) * 0.45 + std::cos(M_PI / 3) * 1.0) / L;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR((*flat.begin())[k], std::lround(255 * kColour[k] * (0.2 + n_dot_l)), kChannelTolerance) << k;
  // With GL_AUTO_NORMAL the same surface is shaded: hundreds of colours (measured 459).
  EXPECT_GT(panel_colours(im, 0).size(), 100u);
}

// default: the knot vectors the core's clamped_uniform_knots gives 5 points
// (lecture notes "Higher Order Surfaces", "Nonperiodic Knot Vectors",
// normalised to [0, 1]).
TEST(NurbsSurfacesLab, DefaultShowsBothDegreesWithTheirClampedKnots) {
  ScratchDir dir("lab17");
  const std::vector<std::string> text = view_text(kLab, dir, "default");
  const auto has = [&](const std::string& line) { return std::find(text.begin(), text.end(), line) != text.end(); };
  EXPECT_TRUE(has("U = V = 0 0 0 0 0.5 1 1 1 1"));
  EXPECT_TRUE(has("U = V = 0 0 0 0.33 0.67 1 1 1"));
  const std::vector<double> n = numbers_before(text, " triangles");
  ASSERT_EQ(n.size(), 2u);
  EXPECT_GT(n[0], 0);
  EXPECT_GT(n[1], 0);
}

}  // namespace
