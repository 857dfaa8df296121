// tests/harness/tolerance_test.cpp — the tolerance in reference_images/MANIFEST
// passes renderer noise and fails real mistakes (foundation issue).
//
// The fixture lab (fixture_lab.cpp) draws lit polygons, lines, points and
// text; its `mistake` parameter reproduces a wrong colour, a missing
// primitive and a vertex moved by 1% of the frame. Its llvmpipe render is the
// reference; each case is judged with the MANIFEST's images profile (the one
// for a foreign renderer such as softpipe), as labgrade --images does.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "image/compare.h"
#include "image/image.h"
#include "test_support.h"

namespace {

using gllab::run_process;
using gllab::testing::ScratchDir;

gllab::Tolerance manifest_tolerance() {
  std::ifstream in(gllab::testing::kSourceDir / "reference_images" / "MANIFEST");
  std::map<std::string, std::string> m;
  for (std::string line; std::getline(in, line);) {
    const auto colon = line.find(": ");
    if (line.empty() || line[0] == '#' || colon == std::string::npos) continue;
    m[line.substr(0, colon)] = line.substr(colon + 2);
  }
  gllab::Tolerance t;
  t.channel_threshold = std::stoi(m.at("images_channel_threshold"));
  t.max_differing_share = std::stod(m.at("images_max_unexcused_share"));
  t.shift_radius = std::stoi(m.at("images_shift_radius"));
  t.edge_contrast = std::stoi(m.at("images_edge_contrast"));
  t.max_shifted_share = std::stod(m.at("images_max_shifted_share"));
  return t;
}

gllab::Image render_fixture(const ScratchDir& dir, const std::string& name,
                            std::vector<std::string> sets, std::vector<std::string> env = {}) {
  std::vector<std::string> argv = {gllab::testing::kFixtureLab.string(), "--out", (dir / name).string()};
  for (const std::string& s : sets) {
    argv.push_back("--set");
    argv.push_back(s);
  }
  const gllab::ProcessResult r = run_process(argv, env);
  EXPECT_EQ(r.exit_status, 0) << r.err;
  return gllab::read_png((dir / name).string());
}

class Tolerance : public ::testing::Test {
 protected:
  void SetUp() override { reference_ = render_fixture(dir_, "reference.png", {}); }
  gllab::Comparison judge(const gllab::Image& image) const {
    return gllab::compare_images(reference_, image, tolerance_);
  }
  ScratchDir dir_{"tolerance"};
  gllab::Tolerance tolerance_ = manifest_tolerance();
  gllab::Image reference_;
};

TEST_F(Tolerance, SoftpipeRenderOfTheSameScenePasses) {
  const gllab::Comparison c =
      judge(render_fixture(dir_, "softpipe.png", {}, {"GALLIUM_DRIVER=softpipe"}));
  EXPECT_TRUE(c.passes(tolerance_)) << c.mismatched_pixels << " mismatched pixels";
}

TEST_F(Tolerance, WrongColourFails) {
  const gllab::Comparison c = judge(render_fixture(dir_, "colour.png", {"mistake=1"}));
  EXPECT_FALSE(c.passes(tolerance_)) << c.mismatched_pixels << " mismatched pixels";
}

TEST_F(Tolerance, MissingPrimitiveFails) {
  const gllab::Comparison c = judge(render_fixture(dir_, "missing.png", {"mistake=2"}));
  EXPECT_FALSE(c.passes(tolerance_)) << c.mismatched_pixels << " mismatched pixels";
}

TEST_F(Tolerance, VertexMovedByOnePercentFails) {
  const gllab::Comparison c = judge(render_fixture(dir_, "moved.png", {"mistake=3"}));
  EXPECT_FALSE(c.passes(tolerance_)) << c.mismatched_pixels << " mismatched pixels";
}

}  // namespace
