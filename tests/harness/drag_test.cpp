// tests/harness/drag_test.cpp — the mouse drags points in a real window (Xvfb,
// driven by xdotool), and what the window prints renders the same headless.
//
// Where the expected numbers come from (not from the code under test): GLUT
// reports integer pixels (x, y) with y down; the runner uses GL window
// coordinates (x, 511 - y); drag_lab's projection is ortho_fit(512, 512, 3, 3),
// i.e. glOrtho(-3, 3, -3, 3), which maps window x to -3 + 6 x / 512 and
// window y to -3 + 6 y / 512 (the OpenGL spec's viewport transform inverted);
// then the cell's own translation and rotation are undone. Dropping P[1] at
// GLUT pixel (160, 128): x = -3 + 6 * 160 / 512 + 1.5 = 0.375,
// y = -3 + 6 * 383 / 512 = 1.48828125, snapped to 1/1000: 1.488.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "test_support.h"

namespace {

using gllab::testing::ScratchDir;

const std::string kDragLab = GLLAB_DRAG_LAB;  // one program: a window, or headless with --out

// Runs the window program under Xvfb in `dir` and sends it `actions`
// (xdotool words after the window is found). Returns what the program printed.
gllab::ProcessResult drive_window(const ScratchDir& dir, const std::string& actions) {
  // xdotool search --sync waits until the window is mapped; the lab is the
  // only window on the server (no window manager: it sits at 0, 0).
  const std::string script = "cd '" + dir.path().string() + "' && '" + kDragLab + "' & program=$!; " +
                             "window=$(xdotool search --sync --name 'drag lab'); " +
                             "xdotool mousemove --window $window 256 256 sleep 0.3 " + actions + "; " +
                             "wait $program";
  std::vector<std::string> argv = gllab::testing::xvfb_run(dir);
  argv.insert(argv.end(), {"/bin/sh", "-c", script});
  return gllab::run_process(argv, {"ASAN_OPTIONS=detect_leaks=0"});  // Mesa's GLX leaks (lab_views_test.cpp)
}

// Where drag_lab draws P[1] = (0, 1) in GLUT pixels: x = (0 - 1.5 + 3) * 512 / 6 = 128,
// GL window y = (1 + 3) * 512 / 6 = 341.33, GLUT y = 511 - 341.33 = 169.67.
constexpr int kP1X = 128, kP1Y = 170;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(Drag, MouseMovesAPointAndPPrintsTheSetLine) {
  GLLAB_SKIP_WITHOUT_WINDOW();
  ScratchDir dir("drag");
  const gllab::ProcessResult r = drive_window(
      dir, "mousemove --window $window " + std::to_string(kP1X) + " " + std::to_string(kP1Y) +
               " mousedown 1 mousemove --window $window 200 150 sleep 0.1 mousemove --window $window 160 128"
               " sleep 0.2 mouseup 1 sleep 0.2 key p sleep 0.2 key Escape");
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 2u) << r.out;
  EXPECT_EQ(lines[0], "P[1] = (0.375, 1.488)");  // printed when the button is let go
  EXPECT_EQ(lines[1], "./lab render drag_lab --view default --set P[1]=0.375,1.488 --out default.png");
}

TEST(Drag, APointOfA3dListMovesParallelToTheScreen) {
  GLLAB_SKIP_WITHOUT_WINDOW();
  // The right half is translated by +1.5 in x and turned by glRotatef(-60, 1,
  // 0, 0): (y, z) -> (y', z') = (c y - s z, s y + c z), c = cos(-60 deg) = 1/2,
  // s = sin(-60 deg). H[1] = (0.5, 0, 0.5) lands at x' = 2, y' = 0.433,
  // z' = 0.25: GLUT pixel (426.7, 218.1). Dropped at GLUT (459, 218) and at
  // the same depth z' it is x = -3 + 6 * 459 / 512 - 1.5 and, with
  // y' = -3 + 6 * (511 - 218) / 512, (y, z) = (c y' + s z', -s y' + c z').
  const double c = 0.5, s = -std::sqrt(3.0) / 2, y_screen = -3 + 6.0 * (511 - 218) / 512, z_eye = 0.25;
  const auto snap = [](double v) { return std::round(v * 1000) / 1000; };
  char expected[96];
  std::snprintf(expected, sizeof expected, "H[1] = (%.3f, %.3f, %.3f)", snap(-3 + 6.0 * 459 / 512 - 1.5),
                snap(c * y_screen + s * z_eye), snap(-s * y_screen + c * z_eye));
  ScratchDir dir("drag3d");
  const gllab::ProcessResult r = drive_window(
      dir, "mousemove --window $window 427 218 mousedown 1 mousemove --window $window 440 218 sleep 0.1 "
           "mousemove --window $window 459 218 sleep 0.2 mouseup 1 sleep 0.2 key Escape");
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 1u) << r.out;
  EXPECT_EQ(lines[0], expected);
}

TEST(Drag, CtrlSSavesTheCurveAndLoadRendersWhatSetRenders) {
  GLLAB_SKIP_WITHOUT_WINDOW();
  ScratchDir dir("save");
  const gllab::ProcessResult r = drive_window(
      dir, "mousemove --window $window " + std::to_string(kP1X) + " " + std::to_string(kP1Y) +
               " mousedown 1 mousemove --window $window 200 150 sleep 0.1 mousemove --window $window 160 128"
               " sleep 0.2 mouseup 1 sleep 0.2 key ctrl+s sleep 0.3 key Escape");
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 2u) << r.out;
  EXPECT_EQ(lines[1], "./lab render drag_lab --view default --set P[1]=0.375,1.488 --load drag_lab__default.json "
                      "--out default.png");
  ASSERT_TRUE(std::filesystem::exists(dir / "drag_lab__default.json"));

  // The printed command's two ways to the same state give the same pixels.
  const auto from_set = dir / "set.png", from_file = dir / "file.png", unmoved = dir / "unmoved.png";
  ASSERT_EQ(gllab::run_process({kDragLab, "--set", "P[1]=0.375,1.488", "--out", from_set.string()}).exit_status, 0);
  const gllab::ProcessResult load = gllab::run_process(
      {kDragLab, "--load", (dir / "drag_lab__default.json").string(), "--out", from_file.string()});
  ASSERT_EQ(load.exit_status, 0) << load.err;
  ASSERT_EQ(gllab::run_process({kDragLab, "--out", unmoved.string()}).exit_status, 0);
  const gllab::Image set_image = gllab::read_png(from_set.string());
  EXPECT_EQ(gllab::compare_images(set_image, gllab::read_png(from_file.string()), 0).differing_pixels, 0);
  // And the drag changed the picture (the comparison can fail).
  EXPECT_GT(gllab::compare_images(set_image, gllab::read_png(unmoved.string()), 0).differing_pixels, 100);
}

// ---- the orbit camera of a 3D view (harness/lab.h kOrbit) -----------------------
// Expected values from the runner's stated rules (window_main.cpp): a right-
// button drag turns yaw by 0.5 degree per pixel to the right and pitch by 0.5
// per pixel down, from where the button went down; one wheel step up (X
// button 4, GLUT button 3) multiplies the zoom by 1.25. A drag of (+40, +20)
// pixels and one step up: yaw 20, pitch 10, zoom 1.25.
gllab::ProcessResult drive(const std::string& program, const std::string& title, const ScratchDir& dir,
                           const std::vector<std::string>& args, const std::string& actions) {
  std::string argv;
  for (const std::string& a : args) argv += " '" + a + "'";
  const std::string script = "cd '" + dir.path().string() + "' && '" + program + "'" + argv +
                             " & program=$!; window=$(xdotool search --sync --name '" + title + "'); " +
                             "xdotool mousemove --window $window 256 256 sleep 0.3 " + actions + "; wait $program";
  std::vector<std::string> command = gllab::testing::xvfb_run(dir);
  command.insert(command.end(), {"/bin/sh", "-c", script});
  return gllab::run_process(command, {"ASAN_OPTIONS=detect_leaks=0"});  // Mesa's GLX leaks (lab_views_test.cpp)
}

const std::string kTurnAndZoom =
    "mousedown 3 mousemove --window $window 276 266 sleep 0.1 mousemove --window $window 296 276 "
    "sleep 0.2 mouseup 3 sleep 0.2 click 4 sleep 0.3 key p sleep 0.2 key Escape";

// What the window printed: the camera where the button was let go, then p's command.
void expect_turned(const gllab::ProcessResult& r, const std::string& lab, const std::string& view) {
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 2u) << r.out;
  EXPECT_EQ(lines[0], "camera yaw=20 pitch=10 zoom=1");
  EXPECT_EQ(lines[1], "./lab render " + lab + " --view " + view + " --camera 20,10,1.25 --out " + view + ".png");
}

// The printed command renders headless exactly what the window showed last,
// and the turn changed the picture (the comparison can fail).
void expect_same_pixels_headless(const ScratchDir& dir, const std::string& headless, const std::string& view) {
  const auto turned = dir / "turned.png", plain = dir / "plain.png";
  ASSERT_EQ(gllab::run_process({headless, "--view", view, "--camera", "20,10,1.25", "--out", turned.string()})
                .exit_status, 0);
  ASSERT_EQ(gllab::run_process({headless, "--view", view, "--out", plain.string()}).exit_status, 0);
  const gllab::Image window = gllab::read_png((dir / "window.png").string());
  EXPECT_EQ(gllab::compare_images(window, gllab::read_png(turned.string()), 0).differing_pixels, 0);
  EXPECT_GT(gllab::compare_images(window, gllab::read_png(plain.string()), 0).differing_pixels, 1000);
}

TEST(Orbit, RightDragAndWheelTurnTheCameraPPrintsItAndHeadlessRendersTheSame) {
  GLLAB_SKIP_WITHOUT_WINDOW();
  ScratchDir dir("orbit");
  const gllab::ProcessResult r =
      drive(kDragLab, "drag lab", dir, {"--view", "box", "--capture-at-exit", "window.png"}, kTurnAndZoom);
  expect_turned(r, "drag_lab", "box");
  expect_same_pixels_headless(dir, kDragLab, "box");
}

// The same with a real lab whose GLU tessellation depends on the matrices
// (GLU_PATH_LENGTH samples in pixels): the window and the printed command agree.
TEST(Orbit, ALabsWindowAndItsPrintedCommandShowTheSamePixels) {
  GLLAB_SKIP_WITHOUT_WINDOW();
  const std::string lab = "21_nurbs_surfaces";
  ScratchDir dir("orbit21");
  const gllab::ProcessResult r = drive((gllab::testing::kBinDir / lab).string(), "lab 21", dir,
                                       {"--capture-at-exit", "window.png"}, kTurnAndZoom);
  expect_turned(r, lab, "default");
  expect_same_pixels_headless(dir, gllab::testing::headless(lab), "default");
}

// A view without kOrbit ignores the right button and the wheel.
TEST(Orbit, AFlatViewIgnoresTheRightButton) {
  GLLAB_SKIP_WITHOUT_WINDOW();
  ScratchDir dir("flat");
  const gllab::ProcessResult r = drive(kDragLab, "drag lab", dir, {}, kTurnAndZoom);
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "./lab render drag_lab --view default --out default.png\n");
}

TEST(Drag, HeadlessRejectsABadPointAssignmentWithOneLine) {
  ScratchDir dir("bad");
  const gllab::ProcessResult r =
      gllab::run_process({kDragLab, "--set", "P[7]=1,2", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "drag_lab: point P[7] does not exist (P has points 0..2)\n");
}

}  // namespace
