// tests/grading/switches_test.cpp — the views exercise what the labs teach
// (docs/lab_form.md, "Views are functions"): for every state or path a lab
// teaches, some graded view looks different when it is wrong, so a grade can
// see it. tests/grading/switches/<lab>.json lists them, each as the change
// that turns it off (built by CMakeLists.txt here) or as the mistake fixture
// that does; each build is graded on every view of its lab (build profile)
// and must fail at least one.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using gllab::testing::kBinDir;
using gllab::testing::kSourceDir;

const fs::path kFixtures = GLLAB_FIXTURES_DIR;
const fs::path kSpecs = kSourceDir / "tests" / "grading";

json read_json(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return json::parse(std::string(std::istreambuf_iterator<char>(in), {}));
}

class Switches : public ::testing::TestWithParam<std::string> {};

TEST_P(Switches, EveryTaughtSwitchChangesAGradedView) {
  const std::string lab = GetParam();
  const fs::path spec_file = kSpecs / "switches" / (lab + ".json");
  ASSERT_TRUE(fs::exists(spec_file)) << lab << " lists nothing it teaches: write " << spec_file;
  const json spec = read_json(spec_file);
  ASSERT_GE(spec["switches"].size(), 1u) << spec_file;
  gllab::testing::ScratchDir dir("switches");
  for (std::size_t k = 0; k < spec["switches"].size(); ++k) {
    const json& s = spec["switches"][k];
    ASSERT_TRUE(s.contains("teaches")) << spec_file << ", switch " << k << ": no \"teaches\"";
    const std::string what = s["teaches"];
    if (s.contains("mistake")) {
      // A mistake fixture of this lab turns it off; the calibration asserts that it fails its view.
      const fs::path mistake = kSpecs / "mistakes" / (s["mistake"].get<std::string>() + ".json");
      ASSERT_TRUE(fs::exists(mistake)) << what << ": no " << mistake;
      EXPECT_EQ(read_json(mistake)["lab"], lab) << what << ": " << mistake << " is another lab's";
      continue;
    }
    const fs::path build = kFixtures / "switches" / lab / std::to_string(k);
    // A switch whose program was not built would fail every view for that alone.
    ASSERT_TRUE(fs::exists(build / lab)) << what << ": " << build << " was not built";
    const fs::path report = dir / std::to_string(k);
    const gllab::ProcessResult r =
        gllab::run_process({(kBinDir / "labgrade").string(), "--build", build.string(), "--labs", lab, "--profile",
                            "build", "--quiet", "--report", report.string(), "--out", (report / "out").string()});
    ASSERT_TRUE(r.exit_status == 0 || r.exit_status == 1) << r.out << r.err;
    std::string failed;
    const json results = read_json(report / "results.json");  // named: a temporary would die before the loop
    for (const json& v : results["results"])
      if (v["result"] == "fail") failed += (failed.empty() ? "" : ", ") + v["view"].get<std::string>();
    EXPECT_FALSE(failed.empty()) << lab << ": turning off \"" << what
                                 << "\" changes no graded view: add or change a view that shows it";
    if (!failed.empty()) std::printf("%s: \"%s\" off fails %s\n", lab.c_str(), what.c_str(), failed.c_str());
  }
}

INSTANTIATE_TEST_SUITE_P(EveryLab, Switches, ::testing::ValuesIn(gllab::testing::lab_ids()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
