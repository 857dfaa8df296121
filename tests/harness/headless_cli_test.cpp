// tests/harness/headless_cli_test.cpp — bad input gives one line and a
// non-zero exit, never a crash, never a half-written file (issue "Done when").
#include <gtest/gtest.h>

#include <filesystem>

#include "image/image.h"
#include "test_support.h"

namespace {

using gllab::run_process;
using gllab::testing::headless;
using gllab::testing::line_count;
using gllab::testing::ScratchDir;

constexpr int kUsageStatus = 2;    // documented in --help: bad arguments
constexpr int kFailureStatus = 1;  // documented in --help: GL error or unwritable file

const std::string kLab = "01_immediate_mode";

struct BadInput {
  std::vector<std::string> args;
  int status;
  std::string named;  // the offending value the one line must name
};

class HeadlessBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(HeadlessBadInput, PrintsOneLineNamingTheValueAndExitsNonZero) {
  ScratchDir dir("cli");
  std::vector<std::string> argv = {headless(kLab)};
  for (std::string a : GetParam().args) {
    if (a == "OUT") a = (dir / "x.png").string();
    argv.push_back(a);
  }
  const gllab::ProcessResult r = run_process(argv);
  EXPECT_EQ(r.exit_status, GetParam().status) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(GetParam().named), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, HeadlessBadInput,
    ::testing::Values(
        BadInput{{"--view", "nosuch", "--out", "OUT"}, kUsageStatus, "'nosuch'"},
        BadInput{{"--size", "12x", "--out", "OUT"}, kUsageStatus, "'12x'"},
        BadInput{{"--size", "axb", "--out", "OUT"}, kUsageStatus, "'axb'"},
        BadInput{{"--size", "0x512", "--out", "OUT"}, kUsageStatus, "'0x512'"},
        BadInput{{"--size", "99999x16", "--out", "OUT"}, kUsageStatus, "99999"},
        BadInput{{"--size", "512", "--out", "OUT"}, kUsageStatus, "'512'"},
        BadInput{{"--set", "nosuchkey=1", "--out", "OUT"}, kUsageStatus, "'nosuchkey'"},
        BadInput{{"--set", "spin=abc", "--out", "OUT"}, kUsageStatus, "'abc'"},
        BadInput{{"--set", "spin=999", "--out", "OUT"}, kUsageStatus, "spin=999"},
        BadInput{{"--set", "spin", "--out", "OUT"}, kUsageStatus, "'spin'"},
        BadInput{{"--frobnicate", "--out", "OUT"}, kUsageStatus, "'--frobnicate'"},
        BadInput{{"--view"}, kUsageStatus, "--view"},
        BadInput{{"--views", "default,wireframe", "--out", "OUT"}, kUsageStatus, "--views goes with --out -"},
        BadInput{{"--views", "default,nosuch", "--out", "-"}, kUsageStatus, "'nosuch'"},
        BadInput{{"--views", ",", "--out", "-"}, kUsageStatus, "--views needs view names"},
        BadInput{{"--view", "default"}, kUsageStatus, "--out"},
        BadInput{{"--out", "/nonexistent-dir/x.png"}, kFailureStatus, "/nonexistent-dir/x.png"},
        BadInput{{"--out", "/proc/gllab.png"}, kFailureStatus, "/proc/gllab.png"}));

TEST(HeadlessCli, ListViewsPrintsOneViewPerLine) {
  const gllab::ProcessResult r = run_process({headless(kLab), "--list-views"});
  EXPECT_EQ(r.exit_status, 0);
  // The views lab 01's issue requires.
  for (const char* view : {"default\n", "wireframe\n", "invalid_polygons\n"})
    EXPECT_NE(r.out.find(view), std::string::npos) << r.out;
}

// --print-text prints the text the frame drew, one string per line, after
// writing the PNG: lab 01's default view labels its primitives by their GL
// names (labs/01_immediate_mode). Without it a successful run prints nothing.
TEST(HeadlessCli, PrintTextPrintsTheLabelsTheFrameDrew) {
  ScratchDir dir("print_text");
  const auto out = dir / "x.png";
  const gllab::ProcessResult r = run_process({headless(kLab), "--print-text", "--out", out.string()});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  for (const char* label : {"GL_POLYGON\n", "GL_TRIANGLE_STRIP\n"})
    EXPECT_NE(r.out.find(label), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(out));
  const gllab::ProcessResult quiet = run_process({headless(kLab), "--out", out.string()});
  EXPECT_EQ(quiet.out, "");
}

TEST(HeadlessCli, HelpNamesEveryOption) {
  const gllab::ProcessResult r = run_process({headless(kLab), "--help"});
  EXPECT_EQ(r.exit_status, 0);
  for (const char* option : {"--headless", "--view", "--size", "--out", "--set", "--list-views", "--help"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST(HeadlessCli, SizeOptionSetsThePngSize) {
  ScratchDir dir("size");
  const auto out = dir / "small.png";
  ASSERT_EQ(run_process({headless(kLab), "--size", "64x48", "--out", out.string()}).exit_status, 0);
  const gllab::Image image = gllab::read_png(out.string());
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
}

TEST(HeadlessCli, GlErrorInDisplayExitsNonZeroAndNamesTheError) {
  ScratchDir dir("glerror");
  const auto out = dir / "x.png";
  const gllab::ProcessResult r = run_process(
      {gllab::testing::kFixtureLab.string(), "--set", "gl_error=1", "--out", out.string()});
  EXPECT_EQ(r.exit_status, kFailureStatus);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  // The fixture calls glEnable(GL_TRUE): an invalid capability (GL spec 2.5).
  EXPECT_NE(r.err.find("GL_INVALID_ENUM"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A view's draw function that throws (the spline core on bad input, e.g. two
// interpolation nodes dragged onto one another) is a frame error like a GL
// error: one line naming the view and the message, exit 1, no image. The
// matrices and attributes it left pushed are popped (no GL stack error).
TEST(HeadlessCli, ExceptionInDisplayIsAFrameErrorNamingTheView) {
  ScratchDir dir("throws");
  const auto out = dir / "x.png";
  const gllab::ProcessResult r =
      run_process({gllab::testing::kFixtureLab.string(), "--set", "throws=1", "--out", out.string()});
  EXPECT_EQ(r.exit_status, kFailureStatus);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("view 'default': fixture: thrown in draw() on purpose"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("GL_STACK"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// An exception from a view's draw after text was drawn: one line and exit 1, not
// a crash (Mesa crashed destroying the context with glBitmap calls still
// queued; the headless context now finishes before it is destroyed).
TEST(HeadlessCli, ExceptionInDisplayAfterTextIsOneLineNotACrash) {
  ScratchDir dir("throw");
  const auto out = dir / "x.png";
  const gllab::ProcessResult r = run_process(
      {gllab::testing::kFixtureLab.string(), "--set", "throw_after_text=1", "--out", out.string()});
  EXPECT_EQ(r.exit_status, kFailureStatus) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("draw() gave up after its label"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(WindowCli, WithoutADisplayNamesTheHeadlessCommandAndExits2) {
  const gllab::ProcessResult r = run_process(
      {(gllab::testing::kBinDir / kLab).string(), "--view", "wireframe"}, {"DISPLAY="});
  EXPECT_EQ(r.exit_status, kUsageStatus);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(kLab + " --headless --view wireframe"), std::string::npos) << r.err;
}

TEST(WindowCli, BadViewIsReportedBeforeOpeningAWindow) {
  const gllab::ProcessResult r =
      run_process({(gllab::testing::kBinDir / kLab).string(), "--view", "nosuch"}, {"DISPLAY="});
  EXPECT_EQ(r.exit_status, kUsageStatus);
  EXPECT_NE(r.err.find("'nosuch'"), std::string::npos) << r.err;
}

// The EGL backend (harness/offscreen_egl.cpp) fails with one line, exit 1 and no
// file when what it needs is missing: GLVND with no EGL vendor has no surfaceless
// platform, and Mesa told to offer GL 2.1 drops GL_MESA_framebuffer_flip_y (a
// GL 4.3 extension), without which the frame would differ from OSMesa's.
// An OSMesa build has no EGL (GLLAB_HAVE_WINDOW is 0 there).
TEST(HeadlessEgl, WhatTheBackendNeedsIsCheckedWithOneLine) {
  if (!GLLAB_HAVE_WINDOW) GTEST_SKIP() << "this build's headless backend is OSMesa, not EGL";
  ScratchDir dir("egl");
  const auto out = dir / "x.png";
  const struct {
    const char* environment;
    const char* message;
  } cases[] = {
      {"__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json",
       ": EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)"},
      {"MESA_GL_VERSION_OVERRIDE=2.1", ": GL_MESA_framebuffer_flip_y is missing ("},
  };
  for (const auto& c : cases) {
    const gllab::ProcessResult r = run_process({headless(kLab), "--out", out.string()}, {c.environment});
    EXPECT_EQ(r.exit_status, kFailureStatus) << c.environment << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind(kLab + c.message, 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.environment;
  }
  const gllab::ProcessResult info = run_process({headless(kLab), "--info"});
  EXPECT_EQ(info.out.rfind("backend: EGL surfaceless\n", 0), 0u) << info.out;
}

}  // namespace
