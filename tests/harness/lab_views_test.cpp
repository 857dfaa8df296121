// tests/harness/lab_views_test.cpp — one test per lab view, discovered from
// the programs themselves (<lab> --list-views), so a new view is
// tested, and needs a reference image, without editing this file.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "image/compare.h"
#include "image/image.h"
#include "image/pam.h"
#include "test_support.h"

namespace {

using gllab::run_process;
using gllab::testing::headless;
using gllab::testing::kBinDir;
using gllab::testing::kSourceDir;
using gllab::testing::ScratchDir;

struct LabView {
  std::string lab, view;
};

// The views of every lab, from the file the build writes by running each
// lab's --list-views (tests/harness/list_views.cmake): "<lab> <view>" per
// view, "<lab> <view> expect_error" for an error view (harness/lab.h
// View::expect_error: those have no reference image and are tested by
// EveryErrorView below), "<lab> LIST_VIEWS_FAILED" when a program could not
// list them. Reading the file keeps this program's start-up short: it starts
// once per test.
std::vector<LabView> all_views(bool error_views) {
  std::vector<LabView> views;
  std::ifstream in(GLLAB_VIEWS_FILE);
  if (!in) return {{"", "VIEWS_FILE_MISSING"}};
  for (std::string line; std::getline(in, line);) {
    std::stringstream fields(line);
    std::string lab, view, flag;
    fields >> lab >> view;
    const bool is_error_view = (fields >> flag) && flag == "expect_error";
    if (view == "LIST_VIEWS_FAILED" ? !error_views : is_error_view == error_views)
      views.push_back({lab, view});
  }
  return views;
}

std::string name_of(const ::testing::TestParamInfo<LabView>& info) {
  return info.param.lab + "__" + info.param.view;
}

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

class EveryLabView : public ::testing::TestWithParam<LabView> {
 protected:
  // labgrade grades this one view of this build, as ./lab run does for all.
  gllab::ProcessResult labgrade(std::vector<std::string> extra = {}) const {
    std::vector<std::string> argv = {(kBinDir / "labgrade").string(), "--build", kBinDir.string(), "--labs",
                                     GetParam().lab, "--views", GetParam().view, "--out",
                                     (dir_.path() / "out").string(), "--quiet"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return run_process(argv);
  }
  ScratchDir dir_{"view"};
};

TEST_P(EveryLabView, HasAReferenceImage) {
  const auto ref = kSourceDir / "reference_images" / (GetParam().lab + "__" + GetParam().view + ".png");
  EXPECT_TRUE(std::filesystem::exists(ref)) << ref << " is missing: run make references";
}

TEST_P(EveryLabView, MatchesItsReference) {
  const gllab::ProcessResult r = labgrade();
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
}

// Softpipe renders of every view against these references: the calibration
// test grades them all at once (tests/grading/calibration_test.cpp).

// Reference images must be reproducible: three headless runs give the same
// bytes, and the same pixels as the committed reference.
TEST_P(EveryLabView, ThreeHeadlessRunsAreByteIdentical) {
  std::vector<std::string> bytes;
  for (int run = 0; run < 3; ++run) {
    const auto out = dir_ / ("run" + std::to_string(run) + ".png");
    ASSERT_EQ(run_process({headless(GetParam().lab), "--view", GetParam().view, "--out", out.string()})
                  .exit_status, 0);
    bytes.push_back(file_bytes(out));
  }
  EXPECT_FALSE(bytes[0].empty());
  EXPECT_EQ(bytes[0], bytes[1]);
  EXPECT_EQ(bytes[0], bytes[2]);
  const auto ref = kSourceDir / "reference_images" / (GetParam().lab + "__" + GetParam().view + ".png");
  if (std::filesystem::exists(ref)) {
    const gllab::Comparison c = gllab::compare_images(gllab::read_png(ref.string()),
                                                      gllab::read_png((dir_ / "run0.png").string()), 0);
    EXPECT_EQ(c.differing_pixels, 0) << "same renderer, different pixels than " << ref;
  }
}

INSTANTIATE_TEST_SUITE_P(Labs, EveryLabView, ::testing::ValuesIn(all_views(false)), name_of);

// An error view exits 1 headless with one error line on stderr and writes no
// image; it has no reference image (so labgrade does not grade it: this test
// is its check).
class EveryErrorView : public ::testing::TestWithParam<LabView> {};

constexpr int kFrameErrorStatus = 1;  // headless --help: a GL or GLU error in the frame

TEST_P(EveryErrorView, ExitsOneWithOneErrorLineAndNoImage) {
  ScratchDir dir("error_view");
  const auto out = dir / "x.png";
  const gllab::ProcessResult r =
      run_process({headless(GetParam().lab), "--view", GetParam().view, "--out", out.string()});
  EXPECT_EQ(r.exit_status, kFrameErrorStatus) << r.err;
  EXPECT_NE(r.err.find("view '" + GetParam().view + "': "), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(kSourceDir / "reference_images" /
                                       (GetParam().lab + "__" + GetParam().view + ".png")));
  // Its reference is that line (labgrade --build grades it: tools/grading.h).
  EXPECT_EQ(file_bytes(kSourceDir / "reference_images" / (GetParam().lab + "__" + GetParam().view + ".error")), r.err);
}

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(EveryErrorView);
INSTANTIATE_TEST_SUITE_P(Labs, EveryErrorView, ::testing::ValuesIn(all_views(true)), name_of);

// The window program draws every view through GLX (--capture-views, one
// window); under Xvfb the pixels must equal the headless (OSMesa) renders.
// docs/platform.md: measured byte-identical, so any difference at all fails
// (and so the grading metric of a window render is 0: README "Grading").
class EveryLabWindow : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryLabWindow, EveryViewUnderXvfbEqualsHeadlessRender) {
  GLLAB_SKIP_WITHOUT_WINDOW();
  ScratchDir dir("window");
  const std::string lab = GetParam();
  // Mesa's GLX driver leaks ~1 MiB per window (valgrind: allocated under
  // glutCreateWindow in libGLX_mesa/swrast_dri.so, and 112 bytes under
  // glBitmap), and it is unloaded before LeakSanitizer runs, so its frames
  // cannot be named in a suppression. Leak checking is off for the window
  // process alone; AddressSanitizer and UBSan still check it.
  std::vector<std::string> argv = gllab::testing::xvfb_run(dir);
  argv.insert(argv.end(), {(kBinDir / lab).string(), "--capture-views", dir.path().string()});
  const gllab::ProcessResult w = run_process(argv, {"ASAN_OPTIONS=detect_leaks=0"});
  ASSERT_EQ(w.exit_status, 0) << w.out << w.err;
  const gllab::ProcessResult list = run_process({headless(lab), "--list-views"});
  std::stringstream views(list.out);
  int compared = 0;
  for (std::string view; std::getline(views, view);) {
    if (view.find(" expect_error") != std::string::npos) continue;  // error views: no picture (EveryErrorView)
    view = view.substr(0, view.find(' '));  // "display_list same_as=immediate"
    ++compared;
    const auto window_png = dir / (lab + "__" + view + ".png"), headless_png = dir / "headless.png";
    ASSERT_TRUE(std::filesystem::exists(window_png)) << window_png;
    ASSERT_EQ(run_process({headless(lab), "--view", view, "--out", headless_png.string()}).exit_status, 0);
    const gllab::Comparison c = gllab::compare_images(gllab::read_png(headless_png.string()),
                                                      gllab::read_png(window_png.string()), 0);
    EXPECT_EQ(c.differing_pixels, 0) << view << ": max delta " << c.max_delta;
  }
  EXPECT_GT(compared, 0);
}

INSTANTIATE_TEST_SUITE_P(Labs, EveryLabWindow, ::testing::ValuesIn(gllab::testing::lab_ids()));

// Two views of a lab never show the same picture, unless the lab declares it
// on purpose (View::same_as, "name same_as=other" in --list-views: lab 05's
// four submission paths). A view that falls through to another's drawing
// fails here. Every view (error views aside) is rendered in one run and the
// frames are compared byte for byte; a declared pair must be identical.
class EveryLabsViews : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryLabsViews, DifferUnlessDeclaredTheSame) {
  const std::string lab = GetParam();
  const gllab::ProcessResult list = run_process({headless(lab), "--list-views"});
  ASSERT_EQ(list.exit_status, 0) << list.err;
  std::vector<std::string> names;
  std::map<std::string, std::string> same_as;  // view -> the view it equals on purpose
  std::stringstream in(list.out);
  for (std::string line; std::getline(in, line);) {
    if (line.find(" expect_error") != std::string::npos) continue;
    const std::string name = line.substr(0, line.find(' '));
    const std::size_t at = line.find(" same_as=");
    if (at != std::string::npos) same_as[name] = line.substr(at + 9, line.find(' ', at + 9) - at - 9);
    names.push_back(name);
  }
  ASSERT_FALSE(names.empty());
  std::string joined;
  for (const std::string& v : names) joined += (joined.empty() ? "" : ",") + v;
  const gllab::ProcessResult r = run_process({headless(lab), "--views", joined, "--out", "-"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  std::vector<gllab::Image> frames;
  std::size_t at = 0;
  for (const std::string& v : names) frames.push_back(gllab::decode_pam_at(r.out, at, lab + " " + v));
  // The root of a view's same_as chain: two views are declared the same when their roots agree.
  const auto root = [&](std::string v) {
    for (int hops = 0; same_as.count(v) && hops < 16; ++hops) v = same_as[v];
    return v;
  };
  for (std::size_t i = 0; i < names.size(); ++i)
    for (std::size_t j = i + 1; j < names.size(); ++j) {
      const bool same = frames[i].rgba == frames[j].rgba;
      const bool declared = root(names[i]) == root(names[j]);
      if (declared) EXPECT_TRUE(same) << lab << ": " << names[j] << " is declared the same as " << names[i];
      else EXPECT_FALSE(same) << lab << ": views " << names[i] << " and " << names[j]
                              << " are byte-identical (declare same_as if that is the lesson)";
    }
}

INSTANTIATE_TEST_SUITE_P(Labs, EveryLabsViews, ::testing::ValuesIn(gllab::testing::lab_ids()));

}  // namespace
