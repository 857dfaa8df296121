// tests/gl/glut_shapes_test.cpp — the headless glut shapes
// (common/gl/glut_shapes_replay.cpp) draw exactly what freeglut draws.
//
// Origins of the expectations:
// - freeglut itself: each recorded call is drawn with real freeglut in a
//   window under Xvfb, and with the replay both in a window (same renderer:
//   any differing pixel is a replay error) and headless (docs/platform.md: measured
//   llvmpipe through GLX and OSMesa byte-identical for lit polygons).
// - the recorder: re-recording now must give the committed file, else
//   freeglut (or the recorder) changed and the recording must be redone.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include "image/compare.h"
#include "image/image.h"
#include "test_support.h"

namespace {

using gllab::run_process;
using gllab::testing::kSourceDir;
using gllab::testing::ScratchDir;
using gllab::testing::xvfb_run;

const std::string kWindowLab = GLLAB_GLUT_SHAPES_LAB;
const std::string kHeadlessLab = GLLAB_GLUT_SHAPES_LAB;  // run with --out: headless, the replay
const std::string kReplayWindowLab = GLLAB_GLUT_SHAPES_LAB_REPLAY_WINDOW;
const std::string kRecorder = GLLAB_GLUT_RECORD;
// A shape that fills little of the frame still covers thousands of pixels at
// 512x512 (the smallest, the wire tetrahedron, covers about 1700); fewer
// means nothing was drawn and an identical comparison would prove nothing.
constexpr long long kMinShapePixels = 500;

struct GlutCall {
  std::string name;              // test name
  std::vector<std::string> sets;  // --set arguments of glut_shapes_lab
};

// Every call the recording must hold (gl/glut_shapes.h): the 9 shapes with
// canonical arguments and glut*Sphere(1, 2*stacks, stacks), stacks 2..24,
// each solid and wire.
std::vector<GlutCall> all_calls() {
  const char* shapes[] = {"Sphere", "Cube", "Cone", "Torus", "Tetrahedron",
                          "Octahedron", "Dodecahedron", "Icosahedron", "Teapot"};
  std::vector<GlutCall> calls;
  for (int solid : {1, 0}) {
    const std::string kind = solid ? "Solid" : "Wire";
    for (std::size_t i = 0; i < std::size(shapes); ++i)
      calls.push_back({kind + shapes[i], {"shape=" + std::to_string(i), "solid=" + std::to_string(solid)}});
    for (int stacks = 2; stacks <= 24; ++stacks)
      calls.push_back({kind + "Sphere_radius1_stacks" + std::to_string(stacks),
                       {"stacks=" + std::to_string(stacks), "solid=" + std::to_string(solid)}});
  }
  return calls;
}

std::vector<std::string> with_sets(std::vector<std::string> argv, const std::vector<std::string>& sets) {
  for (const std::string& s : sets) {
    argv.push_back("--set");
    argv.push_back(s);
  }
  return argv;
}

long long pixels_unlike_background(const gllab::Image& image) {
  const std::uint8_t* bg = image.pixel(0, 0);
  long long n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!std::equal(bg, bg + 3, image.pixel(x, y))) ++n;
  return n;
}

void PrintTo(const GlutCall& call, std::ostream* os) { *os << call.name; }

class EveryGlutCall : public ::testing::TestWithParam<GlutCall> {
 protected:
  // Renders the call with a window program under Xvfb into dir_/<tag>.png.
  gllab::Image window(const std::string& program, const std::string& tag, const std::vector<std::string>& sets) {
    const auto png = dir_ / (tag + ".png");
    std::vector<std::string> argv = xvfb_run(dir_);
    argv.insert(argv.end(), {program, "--capture", png.string()});
    // ASAN_OPTIONS: Mesa's GLX driver leaks per window (lab_views_test.cpp).
    const gllab::ProcessResult r = run_process(with_sets(argv, sets), {"ASAN_OPTIONS=detect_leaks=0"});
    EXPECT_EQ(r.exit_status, 0) << tag << ": " << r.out << r.err;
    return r.exit_status == 0 ? gllab::read_png(png.string()) : gllab::Image();
  }
  gllab::Image headless(const std::vector<std::string>& sets) {
    const auto png = dir_ / "headless.png";
    const gllab::ProcessResult r = run_process(with_sets({kHeadlessLab, "--out", png.string()}, sets));
    EXPECT_EQ(r.exit_status, 0) << r.err;
    return r.exit_status == 0 ? gllab::read_png(png.string()) : gllab::Image();
  }
  ScratchDir dir_{"glut-shapes"};
};

// The replay against freeglut on one renderer (llvmpipe through GLX): the
// same GL calls with the same data must give the same pixels, lit and
// depth-tested, wire shapes included.
TEST_P(EveryGlutCall, ReplayEqualsFreeglutInTheSameWindow) {
  const gllab::Image freeglut = window(kWindowLab, "freeglut", GetParam().sets);
  const gllab::Image replay = window(kReplayWindowLab, "replay", GetParam().sets);
  ASSERT_FALSE(HasFailure());
  EXPECT_GT(pixels_unlike_background(freeglut), kMinShapePixels) << "freeglut drew (almost) nothing";
  const gllab::Comparison c = gllab::compare_images(freeglut, replay, 0);
  EXPECT_EQ(c.differing_pixels, 0) << "max delta " << c.max_delta;
}

// What graders see (headless, OSMesa) against what students see (freeglut in
// a window). Lit wire shapes are drawn without the depth test here: their
// coincident edges z-fight, and GLX and OSMesa settle those ties differently
// even for freeglut's own calls (the test above shows the replay is exact).
TEST_P(EveryGlutCall, HeadlessReplayEqualsFreeglutInAWindow) {
  std::vector<std::string> sets = GetParam().sets;
  if (std::find(sets.begin(), sets.end(), "solid=0") != sets.end()) sets.push_back("depth=0");
  const gllab::Image freeglut = window(kWindowLab, "freeglut", sets);
  const gllab::Image replay = headless(sets);
  ASSERT_FALSE(HasFailure());
  EXPECT_GT(pixels_unlike_background(freeglut), kMinShapePixels) << "freeglut drew (almost) nothing";
  const gllab::Comparison c = gllab::compare_images(freeglut, replay, 0);
  EXPECT_EQ(c.differing_pixels, 0) << "max delta " << c.max_delta;
}

INSTANTIATE_TEST_SUITE_P(GlutShapes, EveryGlutCall, ::testing::ValuesIn(all_calls()),
                         [](const ::testing::TestParamInfo<GlutCall>& info) { return info.param.name; });

// The replay window program must really replay (if the link picked freeglut's
// draw_glut_shape, the test above would compare freeglut with itself): an
// unrecorded call, which freeglut would draw, is an error there.
TEST(GlutReplay, ReplayWindowProgramReplays) {
  ScratchDir dir("glut-replay-window");
  std::vector<std::string> argv = xvfb_run(dir);
  argv.insert(argv.end(), {kReplayWindowLab, "--set", "stacks=3", "--set", "slices=5", "--capture",
                           (dir / "x.png").string()});
  const gllab::ProcessResult r = run_process(argv, {"ASAN_OPTIONS=detect_leaks=0"});
  EXPECT_EQ(r.exit_status, 1) << r.err;
  EXPECT_NE(r.err.find("glutSolidSphere(1, 5, 3) is not recorded"), std::string::npos) << r.err;
}

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(GlutRecording, ReRecordingGivesTheCommittedFile) {
  ScratchDir dir("glut-record");
  std::vector<std::string> argv = xvfb_run(dir);
  argv.push_back(kRecorder);
  argv.push_back((dir / "glut_shapes.dat").string());
  const gllab::ProcessResult r = run_process(argv, {"ASAN_OPTIONS=detect_leaks=0"});
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const std::string committed = file_bytes(kSourceDir / "common/gl/glut_shapes.dat");
  ASSERT_FALSE(committed.empty());
  EXPECT_TRUE(file_bytes(dir / "glut_shapes.dat") == committed)
      << "freeglut now draws differently from common/gl/glut_shapes.dat (freeglut upgraded?): "
         "re-record it as common/gl/README.md says, then run these tests again";
}

TEST(GlutRecording, RecordsEveryCallTheApiPromises) {
  const std::string data = file_bytes(kSourceDir / "common/gl/glut_shapes.dat");
  int calls = 0;
  for (std::size_t at = data.find("\ncall "); at != std::string::npos; at = data.find("\ncall ", at + 1)) ++calls;
  EXPECT_EQ(calls, int(all_calls().size()));
  EXPECT_NE(data.find("\ncall glutSolidSphere(1, 48, 24)\n"), std::string::npos);
  EXPECT_NE(data.find("\ncall glutWireTeapot(0.6)\n"), std::string::npos);
}

// An argument set that was not recorded is one error line naming the call and
// what is recorded, and a non-zero exit (no crash, no silent blank shape).
TEST(GlutReplay, UnrecordedCallIsAFrameErrorNamingIt) {
  ScratchDir dir("glut-unrecorded");
  const gllab::ProcessResult h = run_process(
      {kHeadlessLab, "--set", "stacks=3", "--set", "slices=5", "--out", (dir / "x.png").string()});
  EXPECT_EQ(h.exit_status, 1);
  EXPECT_EQ(gllab::testing::line_count(h.err), 1) << h.err;
  EXPECT_NE(h.err.find("glutSolidSphere(1, 5, 3) is not recorded"), std::string::npos) << h.err;
  EXPECT_NE(h.err.find("stacks 2..24"), std::string::npos) << h.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
