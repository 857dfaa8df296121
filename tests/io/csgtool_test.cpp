// tests/io/csgtool_test.cpp — runs the built csgtool (tools/csgtool.cpp) as a
// process: help, one-line errors with splinetool's exit codes, points of
// examples/csg/classic.json classified from its geometry, the volume of the unit
// sphere, a rendered PNG read back with common/image, and the outline of a tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "image/image.h"
#include "io_test_support.h"
#include "tool_test_support.h"
#include "process.h"

namespace gllab::io {
namespace {

using testing::kExamplesDir;
using testing::BadRun;
using testing::joined;
using testing::ScratchDir;

constexpr int kBadInput = 2;  // csgtool --help: bad input or usage
constexpr int kFailed = 1;    // an output cannot be written
constexpr double kPi = 3.141592653589793;

const std::string kTool = GLLAB_CSGTOOL;
const std::string kClassic = (kExamplesDir / "csg" / "classic.json").string();
const std::string kSphere = (kExamplesDir / "csg" / "sphere.json").string();

ProcessResult csgtool(std::vector<std::string> args) {
  args.insert(args.begin(), kTool);
  return run_process(args, {}, 120);
}

/// Runs csgtool, expects success and nothing on stderr, returns stdout.
std::string run_ok(const std::vector<std::string>& args) {
  const ProcessResult r = csgtool(args);
  EXPECT_EQ(r.exit_status, 0) << joined(args) << "\n" << r.err;
  EXPECT_EQ(r.err, "") << joined(args);
  return r.out;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// ---- help ------------------------------------------------------------------------------

TEST(CsgtoolHelp, OverviewListsEveryCommand) {
  const ProcessResult r = csgtool({"--help"});
  EXPECT_EQ(r.exit_status, 0);
  EXPECT_EQ(r.err, "");
  for (const char* command : {"classify", "volume", "render", "info"})
    EXPECT_NE(r.out.find(std::string("csgtool ") + command), std::string::npos) << command;
}

TEST(CsgtoolHelp, EveryCommandExplainsItsOptions) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> options = {
      {"classify", {"X,Y,Z", "--tolerance", "inside", "outside", "on"}},
      {"volume", {"--samples", "--seed", "--rays", "monte_carlo", "bounds"}},
      {"render", {"--out", "--size", "--azimuth", "--elevation"}},
      {"info", {"primitives", "products"}}};
  for (const auto& [command, words] : options) {
    const ProcessResult r = csgtool({command, "--help"});
    EXPECT_EQ(r.exit_status, 0) << command;
    EXPECT_NE(r.out.find("usage: csgtool " + command), std::string::npos) << r.out;
    for (const std::string& w : words) EXPECT_NE(r.out.find(w), std::string::npos) << command << " " << w;
  }
}

// ---- classify ----------------------------------------------------------------------------

TEST(CsgtoolClassify, KnownPointsOfTheClassicTree) {
  // classic.json: (box of edge 1.6 ∩ sphere of radius 1.05) − (cylinders of radius
  // 0.45 and height 2.4 along x, y and z). The box is |x|, |y|, |z| <= 0.8.
  struct Case {
    const char* point;
    const char* where;
  };
  const Case cases[] = {
      // On all three cylinder axes: the cylinders remove the centre.
      {"0,0,0", "outside"},
      // In the box, but |p| = 0.7 sqrt 3 = 1.212 > 1.05: outside the sphere.
      {"0.7,0.7,0.7", "outside"},
      // |p| = 0.6 sqrt 3 = 1.039 < 1.05, in the box, 0.6 sqrt 2 = 0.849 > 0.45 from
      // every axis: the solid.
      {"0.6,0.6,0.6", "inside"},
      // |p| = 0.849, 0.6 from the y and z axes and 0.849 from the x axis: inside.
      {"0,0.6,0.6", "inside"},
      // 0.2 sqrt 2 = 0.283 < 0.45 from the x axis only: drilled by "cyl x".
      {"0.6,0.2,0.2", "outside"},
      // ... by "cyl y" only, and by "cyl z" only (the rotations put them there).
      {"0.2,0.6,0.2", "outside"},
      {"0.2,0.2,0.6", "outside"},
      // On the box face x = 0.8: |p| = 0.970 < 1.05, 0.55 from the x axis: on.
      {"0.8,0.55,0", "on"},
      // Exactly 0.45 from the z axis (on "cyl z"), 0.6 from x, 0.75 from y, in the
      // box and the sphere: the drilled hole's wall is on the surface.
      {"0.45,0,0.6", "on"},
      // Beyond the box.
      {"2,0,0", "outside"},
      {"-0.6,-0.6,-0.6", "inside"},
  };
  std::vector<std::string> args = {"classify", kClassic};
  for (const Case& c : cases) args.push_back(c.point);
  const std::vector<std::string> out = lines(run_ok(args));
  ASSERT_EQ(out.size(), std::size(cases));
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::string expected_point = cases[i].point;
    std::replace(expected_point.begin(), expected_point.end(), ',', ' ');
    EXPECT_EQ(out[i], expected_point + " " + cases[i].where) << cases[i].point;
  }
}

TEST(CsgtoolClassify, ToleranceWidensTheSurface) {
  // 0.005 inside the unit sphere: inside with the default 1e-9, on with 0.01.
  EXPECT_EQ(run_ok({"classify", kSphere, "0.995,0,0"}), "0.995 0 0 inside\n");
  EXPECT_EQ(run_ok({"classify", kSphere, "0.995,0,0", "--tolerance", "0.01"}), "0.995 0 0 on\n");
  EXPECT_EQ(run_ok({"classify", kSphere, "--tolerance=0.01", "-1.005,0,0"}), "-1.005 0 0 on\n");
}

// ---- volume --------------------------------------------------------------------------------

struct Estimate {
  double value = 0, error = 0;
};

/// "name V ± E (...)" lines of `csgtool volume`.
std::map<std::string, Estimate> volume(const std::vector<std::string>& args) {
  std::map<std::string, Estimate> out;
  for (const std::string& line : lines(run_ok(args))) {
    std::istringstream in(line);
    std::string name, pm;
    Estimate e;
    in >> name;
    if (name == "bounds") continue;
    in >> e.value >> pm >> e.error;
    EXPECT_TRUE(in && pm == "±") << line;
    out[name] = e;
  }
  EXPECT_TRUE(out.count("monte_carlo") && out.count("rays")) << joined(args);
  return out;
}

TEST(CsgtoolVolume, UnitSphereIsFourThirdsPi) {
  const double exact = 4 * kPi / 3;
  const auto v = volume({"volume", kSphere});
  // Monte Carlo: the error is 3 standard errors, 8 sqrt(p (1 - p) / N) with p = pi / 6:
  // about 0.038 for the default 100000 samples.
  EXPECT_LE(std::fabs(v.at("monte_carlo").value - exact), v.at("monte_carlo").error);
  EXPECT_GT(v.at("monte_carlo").error, 0.01);
  EXPECT_LT(v.at("monte_carlo").error, 0.1);
  // Rays: exact lengths, only the midpoint rule over the disc errs; the estimate
  // (the change from the half grid) bounds it, and both are small at 256 x 256.
  EXPECT_LE(std::fabs(v.at("rays").value - exact), std::max(v.at("rays").error, 1e-6));
  EXPECT_LT(std::fabs(v.at("rays").value - exact), 1e-3);
  // More samples, another seed: still within the (smaller) error.
  const auto w = volume({"volume", kSphere, "--samples", "400000", "--seed", "12345", "--rays", "64"});
  EXPECT_LE(std::fabs(w.at("monte_carlo").value - exact), w.at("monte_carlo").error);
  EXPECT_LT(w.at("monte_carlo").error, v.at("monte_carlo").error);
}

TEST(CsgtoolVolume, TheTwoEstimatesOfTheClassicTreeAgree) {
  const auto v = volume({"volume", kClassic, "--samples", "200000"});
  EXPECT_LE(std::fabs(v.at("monte_carlo").value - v.at("rays").value),
            v.at("monte_carlo").error + v.at("rays").error);
  // Less than box ∩ sphere, which is less than the box (1.6^3 = 4.096).
  EXPECT_GT(v.at("rays").value, 1);
  EXPECT_LT(v.at("rays").value, 4.096);
}

// ---- render ----------------------------------------------------------------------------------

TEST(CsgtoolRender, WritesAPngOfTheRequestedSize) {
  ScratchDir dir("csgtool");
  const std::string png = (dir / "sphere.png").string();
  const std::string out = run_ok({"render", kSphere, "--out", png, "--size", "64x48"});
  EXPECT_NE(out.find("wrote " + png), std::string::npos) << out;
  const Image image = read_png(png);
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  // Corners: the dark grey background (the sphere fills the middle).
  for (const auto& [x, y] : {std::pair{0, 0}, {63, 0}, {0, 47}, {63, 47}}) {
    const std::uint8_t* p = image.pixel(x, y);
    EXPECT_EQ(p[0], 40);
    EXPECT_EQ(p[1], 40);
    EXPECT_EQ(p[2], 40);
    EXPECT_EQ(p[3], 255);
  }
  // The centre looks straight at the sphere (n . v = 1): primitive 0's colour,
  // Okabe-Ito orange (230, 159, 0), at full brightness.
  const std::uint8_t* c = image.pixel(32, 24);
  EXPECT_NEAR(c[0], 230, 3);
  EXPECT_NEAR(c[1], 159, 3);
  EXPECT_NEAR(c[2], 0, 3);
  // Nothing but the PNG is left in the directory (written atomically).
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(CsgtoolRender, TheClassicTreeShowsSeveralPrimitives) {
  ScratchDir dir("csgtool");
  const std::string png = (dir / "classic.png").string();
  run_ok({"render", kClassic, "--out", png, "--size", "96x96", "--azimuth", "-40", "--elevation=30"});
  const Image image = read_png(png);
  ASSERT_EQ(image.width, 96);
  // Count the hues: each primitive has its own palette colour (times its shade), so
  // the box, the sphere and the cylinders' walls give pixels of several colours.
  int background = 0, orange = 0, blue = 0, other = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] == 40 && p[1] == 40 && p[2] == 40)
        ++background;
      else if (p[2] == 0 && p[0] > p[1] && p[1] > 0)  // (230, 159, 0) x shade: the box
        ++orange;
      else if (p[0] > 0 && p[2] > p[1] && p[1] > p[0])  // (86, 180, 233) x shade: the sphere
        ++blue;
      else
        ++other;  // the cylinders' walls: (0, 158, 115), (240, 228, 66), (0, 114, 178)
    }
  EXPECT_GT(background, 0);
  EXPECT_GT(orange, 0);
  EXPECT_GT(blue, 0);
  EXPECT_GT(other, 0);
}

TEST(CsgtoolRender, AnUnwritableOutputExitsOne) {
  ScratchDir dir("csgtool");
  const std::string png = (dir / "no_dir" / "x.png").string();
  const ProcessResult r = csgtool({"render", kSphere, "--out", png, "--size", "8x8"});
  EXPECT_EQ(r.exit_status, kFailed) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(png), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

// ---- info ------------------------------------------------------------------------------------

TEST(CsgtoolInfo, OutlinesTheClassicTree) {
  const std::string out = run_ok({"info", kClassic});
  for (const char* word : {"difference", "intersection", "union", "box size 1.6 x 1.6 x 1.6", "sphere radius 1.05",
                           "cylinder radius 0.45 height 2.4", "\"cyl x\"", "\"classic\"", "transform"})
    EXPECT_NE(out.find(word), std::string::npos) << word << "\n" << out;
  // box ∩ sphere − (x ∪ y ∪ z) = box ∩ sphere − x − y − z: one product of 5 literals.
  EXPECT_NE(out.find("primitives 5\n"), std::string::npos) << out;
  EXPECT_NE(out.find("products 1\n"), std::string::npos) << out;
  EXPECT_NE(out.find("#0 box ∩ #1 sphere − #2 cyl x − #3 cyl y − #4 cyl z"), std::string::npos) << out;
  EXPECT_NE(out.find("bounds "), std::string::npos) << out;
}

TEST(CsgtoolInfo, ANestedDifferenceHasTwoProducts) {
  // box − (sphere − drill) = (box − sphere) ∪ (box ∩ drill).
  const std::string out = run_ok({"info", (kExamplesDir / "csg" / "nested_difference.json").string()});
  EXPECT_NE(out.find("primitives 3\n"), std::string::npos) << out;
  EXPECT_NE(out.find("products 2\n"), std::string::npos) << out;
}

// ---- errors ------------------------------------------------------------------------------------

TEST(CsgtoolErrors, BadArgumentsAndFilesPrintOneLine) {
  ScratchDir dir("csgtool");
  const std::string bad = (dir / "bad.json").string();
  std::ofstream(bad) << R"({"type": "csg", "root": {"op": "union", "children": [)"
                        R"({"primitive": "sphere", "radius": 1}, {"primitive": "sphere", "radius": -1}]}})";
  const std::vector<BadRun> runs = {
      {{}, kBadInput, "no command"},
      {{"frobnicate"}, kBadInput, "unknown command 'frobnicate'"},
      {{"classify"}, kBadInput, "classify needs a TREE.json"},
      {{"classify", kClassic}, kBadInput, "classify needs at least one point"},
      {{"classify", kClassic, "1,2"}, kBadInput, "point '1,2': 2 coordinates (expected X,Y,Z)"},
      {{"classify", kClassic, "1,x,2"}, kBadInput, "point '1,x,2': 'x' is not a number"},
      {{"classify", kClassic, "0,0,inf"}, kBadInput, "'inf' is not finite"},
      {{"classify", kClassic, "0,0,0", "--tolerance", "-1"}, kBadInput, "--tolerance: -1 (must be >= 0)"},
      {{"classify", kClassic, "0,0,0", "--samples", "3"}, kBadInput, "unknown option '--samples' for classify"},
      {{"volume", kSphere, "--rays", "7"}, kBadInput, "--rays: 7 (must be even"},
      {{"volume", kSphere, "--rays", "1"}, kBadInput, "--rays: 1 (must be 2..4096)"},
      {{"volume", kSphere, "--samples", "0"}, kBadInput, "--samples: 0 (must be 1..100000000)"},
      {{"volume", kSphere, "--seed", "-1"}, kBadInput, "--seed: '-1' is not a whole number"},
      {{"volume", kSphere, "--seed"}, kBadInput, "--seed needs a value"},
      {{"volume", kSphere, "--seed", "1", "--seed", "2"}, kBadInput, "--seed given twice"},
      {{"render", kSphere}, kBadInput, "render needs --out IMAGE.png"},
      {{"render", kSphere, "--out", "x.png", "--size", "10"}, kBadInput, "--size: '10' is not WxH"},
      {{"render", kSphere, "--out", "x.png", "--size", "0x10"}, kBadInput, "--size (width): 0 (must be 1..8192)"},
      {{"render", kSphere, "--out", "x.png", "--elevation", "100"}, kBadInput, "--elevation: 100 (must be -90..90)"},
      {{"render", kSphere, "--out", "x.png", "--azimuth", "east"}, kBadInput, "--azimuth: 'east' is not a number"},
      {{"info", kSphere, "extra"}, kBadInput, "unexpected argument 'extra'"},
      {{"info", "/no/such/tree.json"}, kBadInput, "/no/such/tree.json: cannot open"},
      {{"info", bad}, kBadInput, bad + ": root.children[1].radius: -1 (must be > 0: the sphere's radius)"},
      {{"volume", (kExamplesDir / "two_blobs.json").string()},
       kBadInput,
       R"(type: "blob_scene" (this file holds a "csg" tree))"},
  };
  for (const BadRun& run : runs) testing::expect_bad_run(csgtool(run.args), run, "csgtool");
}

TEST(CsgtoolErrors, AFailedWriteToStdoutExitsOne) {
  for (const char* command : {"info", "volume"}) {
    const ProcessResult r =
        run_process({"/bin/sh", "-c", "exec \"$0\" \"$1\" \"$2\" > /dev/full", kTool, command, kClassic}, {}, 60);
    EXPECT_EQ(r.exit_status, kFailed) << command << ": " << r.err;
    EXPECT_NE(r.err.find("stdout: cannot write"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const ProcessResult help = run_process({"/bin/sh", "-c", "exec \"$0\" --help > /dev/full", kTool}, {}, 60);
  EXPECT_EQ(help.exit_status, kFailed) << help.err;
}

}  // namespace
}  // namespace gllab::io
