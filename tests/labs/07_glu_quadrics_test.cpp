// tests/labs/07_glu_quadrics_test.cpp — what lab 07 promises about its views:
// its GLU error callback names the failing call, the GLU error and the
// arguments; and in ellipsoid_normalize the lighting at the pole follows the
// fixed-function lighting equation only when the normals are rescaled.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"
#include "test_support.h"

namespace {

using gllab::testing::headless;
using gllab::testing::line_count;
using gllab::testing::ScratchDir;

const std::string kLab = "07_glu_quadrics";
constexpr int kFrameErrorStatus = 1;  // headless --help: a GL or GLU error in the frame

gllab::ProcessResult run(const ScratchDir& dir, const std::string& view, const std::vector<std::string>& sets) {
  std::vector<std::string> argv = {headless(kLab), "--view", view, "--out", (dir / "x.png").string()};
  for (const std::string& s : sets) argv.insert(argv.end(), {"--set", s});
  return gllab::run_process(argv);
}

// GLU 9.0.2 (src/libutil/quad.c) rejects slices < 2 in gluSphere, gluCylinder,
// gluDisk and gluPartialDisk with GLU_INVALID_VALUE, which gluErrorString
// spells "invalid value" (gllab::report_glu_error names the enum). The lab's
// callback names the call and the argument GLU rejects (both when both or
// neither are: gllab::glu_quadric_note). The default view draws the sphere
// first, so its call is the one named; the other four quadrics follow as
// "(+4 more)".
TEST(GluQuadricsLab, NegativeSlicesReportsGluInvalidValueWithTheArguments) {
  ScratchDir dir("lab07");
  const gllab::ProcessResult r = run(dir, "default", {"slices=-4"});
  EXPECT_EQ(r.exit_status, kFrameErrorStatus) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("gluSphere slices=-4: GLU error GLU_INVALID_VALUE (invalid value) ("),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("(+4 more)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// quad.c: gluSphere also needs stacks >= 1; gluDisk's loops stay valid.
TEST(GluQuadricsLab, ZeroStacksNamesTheStacksArgument) {
  ScratchDir dir("lab07");
  const gllab::ProcessResult r = run(dir, "normals_orientation", {"stacks=0"});
  EXPECT_EQ(r.exit_status, kFrameErrorStatus) << r.err;
  EXPECT_NE(r.err.find("gluSphere stacks=0: GLU error GLU_INVALID_VALUE (invalid value) ("),
            std::string::npos)
      << r.err;
}

TEST(GluQuadricsLab, TwoInvalidArgumentsAreBothNamed) {
  ScratchDir dir("lab07");
  const gllab::ProcessResult r = run(dir, "default", {"slices=1", "stacks=-1"});
  EXPECT_EQ(r.exit_status, kFrameErrorStatus) << r.err;
  EXPECT_NE(r.err.find("gluSphere slices=1 stacks=-1: GLU error GLU_INVALID_VALUE (invalid value) ("),
            std::string::npos)
      << r.err;
}

// The edge of the range: slices = 2 and stacks = 1 are the smallest values
// quad.c accepts, so the frame renders without error.
TEST(GluQuadricsLab, SmallestValidSlicesAndStacksRender) {
  ScratchDir dir("lab07");
  const gllab::ProcessResult r = run(dir, "default", {"slices=2", "stacks=1"});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "x.png"));
}

// Colour at the pole of each ellipsoid, which the view puts at the centre of
// its cell, looking down the pole so the normal there is (0, 0, 1).
//
// Lighting equation (OpenGL 2.1 compatibility spec §2.14.1) with the lab's
// state: enable_headlight (common/gl/scene.cpp) sets a global ambient of 0.2,
// a white diffuse light from direction (-0.35, 0.45, 1), no specular; with
// GL_COLOR_MATERIAL the colour c = (0.3, 0.6, 0.95) is ambient and diffuse:
//   colour = c * (0.2 + max(0, n . L)),  L = the unit light direction.
// glScale(sx, sy, sz) turns n = (0, 0, 1) into (0, 0, 1/sz) (inverse
// transpose); both rows scale z by 0.5, so the unnormalized n . L doubles.
// GL_RESCALE_NORMAL divides by the length of the inverse matrix's third row
// (here 2), so at the pole it is right in both rows.
constexpr double kColour[3] = {0.3, 0.6, 0.95};
constexpr int kChannelTolerance = 3;  // rounding plus Gouraud blending within 1 px of the pole

std::vector<int> expected_pole(double normal_length) {
  const double light_z = 1.0 / std::sqrt(0.35 * 0.35 + 0.45 * 0.45 + 1.0);
  std::vector<int> rgb;
  for (double c : kColour) rgb.push_back(int(std::lround(255 * std::min(1.0, c * (0.2 + normal_length * light_z)))));
  return rgb;
}

// Cell centres in pixels: the lab uses ortho_fit(512, 512, 3.3, 3.3) and puts
// the cells at x = -2.2, 0, 2.2 and y = 1.35 (row 1), -1.0 (row 2).
int to_pixel(double world, bool is_y) {
  const double px = 256.0 / 3.3 * world;
  return int(std::floor(is_y ? 256.0 - px : 256.0 + px));
}

TEST(GluQuadricsLab, PoleLightingFollowsTheLightingEquationOnlyWhenNormalsAreRescaled) {
  ScratchDir dir("lab07");
  const gllab::ProcessResult r = run(dir, "ellipsoid_normalize", {});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const gllab::Image im = gllab::read_png((dir / "x.png").string());
  const double rows[] = {1.35, -1.0}, columns[] = {-2.2, 0.0, 2.2};
  // Columns: GL_NORMALIZE, neither (normal length 2), GL_RESCALE_NORMAL.
  const double normal_length[] = {1.0, 2.0, 1.0};
  for (double y : rows)
    for (int c = 0; c < 3; ++c) {
      const std::uint8_t* p = im.pixel(to_pixel(columns[c], false), to_pixel(y, true));
      const std::vector<int> want = expected_pole(normal_length[c]);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(p[k], want[k], kChannelTolerance) << "row y=" << y << " column " << c << " channel " << k;
    }
}

// The same check as a plain difference: GL_NORMALIZE off must change the picture.
TEST(GluQuadricsLab, NormalizeOffIsBrighterAtThePole) {
  ScratchDir dir("lab07");
  ASSERT_EQ(run(dir, "ellipsoid_normalize", {}).exit_status, 0);
  const gllab::Image im = gllab::read_png((dir / "x.png").string());
  const int y = to_pixel(-1.0, true);
  const std::uint8_t* right = im.pixel(to_pixel(-2.2, false), y);
  const std::uint8_t* wrong = im.pixel(to_pixel(0.0, false), y);
  EXPECT_GT(wrong[0], right[0] + 40);  // red: 0.3 * 1.07 vs 0.3 * 1.94 of 255
}

}  // namespace
