// tests/io/isotool_test.cpp — runs the built isotool (tools/isotool.cpp) as a
// process: help, one-line errors with splinetool's exit codes, the measures
// of surfaces whose topology is known (a sphere: closed, Euler characteristic
// 2; a torus: 0), and OBJ output that matches the measures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_support.h"
#include "tool_test_support.h"
#include "process.h"

namespace gllab::io {
namespace {

using testing::kExamplesDir;
using testing::BadRun;
using testing::joined;
using testing::ScratchDir;

constexpr int kBadInput = 2;  // isotool --help: bad input or usage
constexpr int kFailed = 1;    // the output cannot be written
constexpr double kPi = 3.141592653589793;

const std::string kTool = GLLAB_ISOTOOL;
const std::string kPhantom = (kExamplesDir / "ct_phantom.nrrd").string();

ProcessResult isotool(std::vector<std::string> args) {
  args.insert(args.begin(), kTool);
  return run_process(args, {}, 120);
}

/// The --stats lines as name -> value.
std::map<std::string, std::string> stats(const std::vector<std::string>& args) {
  const ProcessResult r = isotool(args);
  EXPECT_EQ(r.exit_status, 0) << joined(args) << "\n" << r.err;
  EXPECT_EQ(r.err, "") << joined(args);
  std::map<std::string, std::string> out;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    const std::size_t space = line.find(' ');
    EXPECT_NE(space, std::string::npos) << line;
    if (space != std::string::npos) out[line.substr(0, space)] = line.substr(space + 1);
  }
  for (const char* key :
       {"vertices", "triangles", "components", "euler", "closed", "area", "volume", "time"})
    EXPECT_TRUE(out.count(key)) << joined(args) << ": no '" << key << "' line in\n" << r.out;
  return out;
}

double number(const std::map<std::string, std::string>& s, const std::string& key) {
  const auto it = s.find(key);
  return it == s.end() ? std::nan("") : std::stod(it->second);
}

/// Counts an OBJ text's lines and checks every face index.
struct ObjCounts {
  std::size_t v = 0, vn = 0, f = 0, bad_indices = 0;
};
ObjCounts count_obj(const std::string& text) {
  ObjCounts c;
  std::istringstream in(text);
  std::vector<std::string> faces;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0)
      ++c.v;
    else if (line.rfind("vn ", 0) == 0)
      ++c.vn;
    else if (line.rfind("f ", 0) == 0)
      faces.push_back(line.substr(2));
  }
  c.f = faces.size();
  for (const std::string& face : faces) {
    std::istringstream corners(face);
    int n = 0;
    for (std::string corner; corners >> corner; ++n) {
      const std::size_t slash = corner.find("//");
      if (slash == std::string::npos || slash == 0 || slash + 2 >= corner.size()) {
        ++c.bad_indices;
        continue;
      }
      const long a = std::stol(corner.substr(0, slash)), b = std::stol(corner.substr(slash + 2));
      if (a != b || a < 1 || std::size_t(a) > c.v) ++c.bad_indices;
    }
    if (n != 3) ++c.bad_indices;
  }
  return c;
}

// ---- help ------------------------------------------------------------------------------

TEST(IsotoolHelp, ExitsZeroAndExplainsEveryOption) {
  for (const char* flag : {"--help", "-h"}) {
    const ProcessResult r = isotool({flag});
    EXPECT_EQ(r.exit_status, 0);
    EXPECT_EQ(r.err, "");
    for (const char* word : {"--iso", "--grid", "--faces", "--out", "--stats", "sphere", "torus",
                             "two_blobs", ".nrrd", ".json", "decider", "lorensen-cline"})
      EXPECT_NE(r.out.find(word), std::string::npos) << word;
  }
}

// ---- bad input: one line naming the value -------------------------------------------------


TEST(IsotoolErrors, EveryBadInputIsOneLineNamingTheValue) {
  ScratchDir dir("isotool");
  const std::string bad_json = (dir / "bad_scene.json").string();
  std::ofstream(bad_json) << R"({"type": "blob_scene", "blobs": [{"centre": [0, 0, 0], "a": 0}]})";
  const std::string not_nrrd = (dir / "text.nrrd").string();
  std::ofstream(not_nrrd) << "this is no volume\n";
  const std::vector<BadRun> runs = {
      {{}, kBadInput, "no INPUT"},
      {{"sphere", "--bogus", "1"}, kBadInput, "unknown option '--bogus'"},
      {{"sphere", "--iso"}, kBadInput, "--iso needs a value"},
      {{"sphere", "--grid"}, kBadInput, "--grid needs a value"},
      {{"sphere", "--grid", "1"}, kBadInput, "--grid: 1 (must be 2..512)"},
      {{"sphere", "--grid", "100000"}, kBadInput, "--grid: 100000 (must be 2..512)"},
      {{"sphere", "--grid", "abc"}, kBadInput, "--grid: 'abc' is not a whole number"},
      {{"sphere", "--grid=3.5"}, kBadInput, "--grid: '3.5' is not a whole number"},
      {{"sphere", "--iso", "nan"}, kBadInput, "--iso: 'nan' is not finite"},
      {{"sphere", "--iso", "inf"}, kBadInput, "--iso: 'inf' is not finite"},
      {{"sphere", "--iso", "0.5x"}, kBadInput, "--iso: '0.5x' is not a number"},
      {{"sphere", "--iso", "1", "--iso", "2"}, kBadInput, "--iso given twice"},
      {{"sphere", "--faces", "marching"},
       kBadInput,
       "--faces: 'marching' (decider or lorensen-cline)"},
      {{"sphere", "--stats=yes"}, kBadInput, "--stats takes no value"},
      {{"sphere", "extra"}, kBadInput, "unexpected argument 'extra'"},
      {{"cube"}, kBadInput, "unknown field 'cube'"},
      {{"missing.nrrd", "--iso", "1"},
       kBadInput,
       "missing.nrrd: cannot open (No such file or directory)"},
      {{"missing.json"}, kBadInput, "missing.json: cannot open (No such file or directory)"},
      {{not_nrrd, "--iso", "1"}, kBadInput, not_nrrd + ": couldn't parse"},
      {{bad_json}, kBadInput, bad_json + ": blobs[0].a: 0 (must be > 0"},
      {{kPhantom, "--grid", "32", "--iso", "10"},
       kBadInput,
       "--grid applies to fields, not to volume files"},
      {{kPhantom},
       kBadInput,
       "a volume needs --iso (the values of '" + kPhantom + "' run over [0, 255])"},
      {{"sphere", "--grid", "8", "--out", (dir / "no_dir" / "s.obj").string()},
       kFailed,
       (dir / "no_dir" / "s.obj").string() + ": cannot write"},
  };
  for (const BadRun& run : runs) testing::expect_bad_run(isotool(run.args), run, "isotool: ");
}

TEST(IsotoolErrors, AFailedWriteToStdoutExitsOne) {
  const ProcessResult r =
      run_process({"/bin/sh", "-c", "exec \"$0\" sphere --grid 16 > /dev/full", kTool}, {}, 60);
  EXPECT_EQ(r.exit_status, kFailed) << r.err;
  EXPECT_NE(r.err.find("isotool: stdout: cannot write"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// ---- surfaces of known topology --------------------------------------------------------------

TEST(IsotoolStats, SphereIsClosedWithEulerTwo) {
  const auto s = stats({"sphere", "--grid", "32", "--stats"});
  EXPECT_EQ(s.at("closed"), "yes");
  EXPECT_EQ(s.at("euler"), "2");
  EXPECT_EQ(s.at("components"), "1");
  EXPECT_EQ(s.at("iso"), "0");
  EXPECT_EQ(s.at("grid"), "32 x 32 x 32");
  // The unit sphere: area 4 pi, volume 4/3 pi; marching cubes' chords cut
  // inside by about h^2 / 8 (h = 2.5 / 31).
  EXPECT_NEAR(number(s, "area"), 4 * kPi, 0.02 * 4 * kPi);
  EXPECT_NEAR(number(s, "volume"), 4 * kPi / 3, 0.02 * 4 * kPi / 3);
  EXPECT_GE(number(s, "time"), 0);
}

TEST(IsotoolStats, TorusHasEulerZero) {
  const auto s = stats({"torus", "--grid", "48", "--stats"});
  EXPECT_EQ(s.at("closed"), "yes");
  EXPECT_EQ(s.at("euler"), "0");
  EXPECT_EQ(s.at("components"), "1");
  // 2 pi R * 2 pi r with R = 1, r = 0.4; the volume pi r^2 * 2 pi R.
  EXPECT_NEAR(number(s, "area"), 4 * kPi * kPi * 0.4, 0.03 * 4 * kPi * kPi * 0.4);
  EXPECT_NEAR(number(s, "volume"), 2 * kPi * kPi * 0.16, 0.03 * 2 * kPi * kPi * 0.16);
}

TEST(IsotoolStats, BlobScenesAreOneClosedSurface) {
  const auto builtin = stats({"two_blobs", "--stats"});
  EXPECT_EQ(builtin.at("closed"), "yes");
  EXPECT_EQ(builtin.at("components"), "1");  // just merged
  EXPECT_EQ(builtin.at("euler"), "2");
  EXPECT_EQ(builtin.at("iso"), "0.5");
  const auto file = stats({(kExamplesDir / "two_blobs.json").string(), "--stats"});
  for (const char* key : {"vertices", "triangles", "area", "volume"})
    EXPECT_EQ(file.at(key), builtin.at(key)) << key << ": the file and the built-in differ";
  // Apart at iso 0.6: 2 H0(0.65) = 0.56 < 0.6.
  const auto apart = stats({"two_blobs", "--iso", "0.6", "--stats"});
  EXPECT_EQ(apart.at("components"), "2");
  EXPECT_EQ(apart.at("euler"), "4");

  const auto molecule =
      stats({(kExamplesDir / "molecule.json").string(), "--grid", "48", "--stats"});
  EXPECT_EQ(molecule.at("closed"), "yes");
  EXPECT_EQ(molecule.at("components"), "1");
  EXPECT_EQ(molecule.at("euler"), "2");
}

TEST(IsotoolStats, PhantomVolumeWorks) {
  // Between the ventricles (0) and the brain (51): the head's outer surface
  // and the ventricles' walls, all closed.
  const auto s = stats({kPhantom, "--iso", "25", "--stats"});
  EXPECT_EQ(s.at("closed"), "yes");
  EXPECT_EQ(s.at("grid"), "48 x 48 x 48");
  EXPECT_GT(number(s, "triangles"), 1000);
  EXPECT_GE(number(s, "components"), 2);
  const auto skull = stats({kPhantom, "--iso", "200", "--stats", "--faces", "lorensen-cline"});
  EXPECT_GT(number(skull, "triangles"), 0);
}

// ---- OBJ output -------------------------------------------------------------------------------

TEST(IsotoolObj, LinesMatchTheStats) {
  ScratchDir dir("isotool");
  const std::string obj = (dir / "sphere.obj").string();
  const auto s = stats({"sphere", "--grid", "20", "--out", obj, "--stats"});
  const ObjCounts c = count_obj(testing::read_file(obj));
  EXPECT_EQ(double(c.v), number(s, "vertices"));
  EXPECT_EQ(c.vn, c.v);
  EXPECT_EQ(double(c.f), number(s, "triangles"));
  EXPECT_EQ(c.bad_indices, 0u);
  EXPECT_GT(c.f, 100u);

  // Without --out the OBJ goes to stdout, the same text.
  const ProcessResult r = isotool({"sphere", "--grid", "20"});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_EQ(r.out, testing::read_file(obj));
  EXPECT_EQ(r.out.rfind("# isotool sphere: iso 0, grid 20 x 20 x 20, faces decider\n", 0), 0u);
}

TEST(IsotoolObj, VolumeToFile) {
  ScratchDir dir("isotool");
  const std::string obj = (dir / "head.obj").string();
  const auto s = stats({kPhantom, "--iso", "25", "--out=" + obj, "--stats"});
  const ObjCounts c = count_obj(testing::read_file(obj));
  EXPECT_EQ(double(c.v), number(s, "vertices"));
  EXPECT_EQ(double(c.f), number(s, "triangles"));
  EXPECT_EQ(c.bad_indices, 0u);
}

}  // namespace
}  // namespace gllab::io
