// tests/harness/headless_cli_test.cpp — bad input gives one line and a
// non-zero exit, never a crash, never a half-written file (issue "Done when").
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

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

// The lines of text, and a line's fields split at spaces.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; in >> f;) fields.push_back(f);
  return fields;
}

// The lines of a --help section ("parameters:", "point lists:"), up to the blank line.
std::vector<std::string> help_section(const std::string& help, const std::string& title) {
  const auto at = help.find("\n" + title + "\n");
  if (at == std::string::npos) return {};
  const auto start = at + title.size() + 2;
  std::vector<std::string> lines = lines_of(help.substr(start, help.find("\n\n", start) - start));
  if (lines == std::vector<std::string>{"  (none)"}) lines.clear();
  return lines;
}

// --list-params (options.h list_params_text) of every lab lists each of its
// Params and point lists, as --help lists them from the same Lab ("name=value
// [lo..hi]", "P[0..n] 2D"), with no display: both runners print it, the same.
TEST(ListParams, EveryLabListsEveryParamAndPointListOfItsHelp) {
  for (const std::string& lab : gllab::testing::lab_ids()) {
    const gllab::ProcessResult list = run_process({headless(lab), "--list-params"}, {"DISPLAY="});
    ASSERT_EQ(list.exit_status, 0) << lab << ": " << list.err;
    EXPECT_EQ(list.err, "") << lab;
    EXPECT_EQ(run_process({headless(lab), "--headless", "--list-params"}).out, list.out) << lab;
    const gllab::ProcessResult help = run_process({headless(lab), "--help"});
    ASSERT_EQ(help.exit_status, 0) << lab;
    std::vector<std::string> params, lists;  // as --help would print them
    std::string last_list;
    std::size_t count = 0;
    const auto close_list = [&](const std::string& dimension) {
      if (!last_list.empty())
        lists.push_back(last_list + "[0.." + std::to_string(count - 1) + "] " + dimension + "D");
    };
    std::string dimension;
    for (const std::string& line : lines_of(list.out)) {
      const std::vector<std::string> f = fields_of(line);
      ASSERT_FALSE(f.empty()) << lab << ": an empty line";
      if (f[0] == "param") {
        ASSERT_EQ(f.size(), 5u) << lab << ": " << line;
        std::ostringstream shown;  // usage_text prints the numbers with <<
        shown << f[1] << '=' << std::stod(f[2]) << " [" << std::stod(f[3]) << ".." << std::stod(f[4]) << "]";
        params.push_back(shown.str());
      } else {
        ASSERT_EQ(f[0], "points") << lab << ": " << line;
        ASSERT_EQ(f.size(), 7u) << lab << ": " << line;
        if (f[1] != last_list) {
          close_list(dimension);
          last_list = f[1];
          count = 0;
        }
        EXPECT_EQ(f[2], std::to_string(count)) << lab << ": " << line;  // 0, 1, ... in order
        ++count;
        dimension = f[3];
      }
    }
    close_list(dimension);
    const std::vector<std::string> help_params = help_section(help.out, "parameters:");
    const std::vector<std::string> help_lists = help_section(help.out, "point lists:");
    ASSERT_EQ(params.size(), help_params.size()) << lab << "\n" << list.out;
    ASSERT_EQ(lists.size(), help_lists.size()) << lab << "\n" << list.out;
    for (std::size_t i = 0; i < params.size(); ++i)
      EXPECT_EQ(help_params[i].rfind("  " + params[i] + " ", 0), 0u) << lab << ": " << help_params[i];
    for (std::size_t i = 0; i < lists.size(); ++i)
      EXPECT_EQ(help_lists[i].rfind("  " + lists[i] + " ", 0), 0u) << lab << ": " << help_lists[i];
  }
}

// Setting every default --list-params prints, each param and each point
// with --set, renders every view exactly as the default does: the numbers
// read back as the lab's own (lab 12: 2D points; lab 17: 3D points).
TEST(ListParams, SettingEveryListedDefaultRendersTheDefaultPictures) {
  for (const std::string lab : {"12_bezier_curves", "17_bezier_surfaces"}) {
    const gllab::ProcessResult list = run_process({headless(lab), "--list-params"});
    ASSERT_EQ(list.exit_status, 0) << list.err;
    std::vector<std::string> sets;
    for (const std::string& line : lines_of(list.out)) {
      const std::vector<std::string> f = fields_of(line);
      ASSERT_GE(f.size(), 5u) << line;
      if (f[0] == "param") sets.insert(sets.end(), {"--set", f[1] + "=" + f[2]});
      else
        sets.insert(sets.end(), {"--set", f[1] + "[" + f[2] + "]=" + f[4] + "," + f[5] + "," + f[6]});
    }
    ASSERT_FALSE(sets.empty()) << lab << " has nothing to set";
    std::string views;
    for (const std::string& line : lines_of(run_process({headless(lab), "--list-views"}).out))
      if (line.find("expect_error") == std::string::npos)
        views += (views.empty() ? "" : ",") + fields_of(line)[0];
    const std::vector<std::string> render = {headless(lab), "--views", views, "--out", "-"};
    const gllab::ProcessResult plain = run_process(render);
    ASSERT_EQ(plain.exit_status, 0) << plain.err;
    std::vector<std::string> with_sets = render;
    with_sets.insert(with_sets.end(), sets.begin(), sets.end());
    const gllab::ProcessResult set = run_process(with_sets);
    ASSERT_EQ(set.exit_status, 0) << set.err;
    EXPECT_TRUE(set.out == plain.out) << lab << ": setting the listed defaults changed a view (" << views
                                      << ")";
  }
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
  for (const char* option :
       {"--headless", "--view", "--size", "--out", "--set", "--list-views", "--list-params", "--help"})
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
