// tests/harness/repo_test.cpp — the repository stays in step with the one
// CMake lab list: lab folders, README table, reference images, linking.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <set>

#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using gllab::run_process;
using gllab::testing::kBinDir;
using gllab::testing::kSourceDir;
using gllab::testing::lab_ids;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(Repository, EveryLabFolderIsInTheCMakeListAndViceVersa) {
  std::set<std::string> folders;
  for (const auto& e : fs::directory_iterator(kSourceDir / "labs"))
    if (e.is_directory()) folders.insert(e.path().filename().string());
  const std::vector<std::string> labs = lab_ids();
  EXPECT_EQ(folders, std::set<std::string>(labs.begin(), labs.end()));
  for (const std::string& lab : labs) {
    EXPECT_TRUE(fs::exists(kSourceDir / "labs" / lab / (lab + ".cpp"))) << lab;
    EXPECT_TRUE(fs::exists(kSourceDir / "labs" / lab / "README.md")) << lab;
  }
}

// README.md has a table row per lab, its thumbnail the lab's first view (the
// one a window opens with):
// | NN | topic | `build/bin/<lab>` | ![](reference_images/<lab>__<first view>.png) |
TEST(Repository, ReadmeLabTableMatchesTheCMakeList) {
  const std::string readme = read_text(kSourceDir / "README.md");
  const std::regex row(
      R"(\|\s*(\d\d)\s*\|[^|\n]*\|\s*`build/bin/(\w+)`\s*\|\s*!\[[^\]]*\]\(reference_images/(\w+)__(\w+)\.png\)\s*\|)");
  std::vector<std::string> listed;
  for (std::sregex_iterator it(readme.begin(), readme.end(), row), end; it != end; ++it) {
    const std::smatch& m = *it;
    EXPECT_EQ(m[2].str().substr(0, 2), m[1].str()) << m[0];
    EXPECT_EQ(m[2].str(), m[3].str()) << m[0];
    const gllab::ProcessResult views = run_process({gllab::testing::headless(m[2].str()), "--list-views"});
    EXPECT_EQ(views.out.substr(0, views.out.find('\n')), m[4].str()) << m[0] << ": not the lab's first view";
    EXPECT_TRUE(fs::exists(kSourceDir / "reference_images" / (m[3].str() + "__" + m[4].str() + ".png"))) << m[0];
    listed.push_back(m[2].str());
  }
  EXPECT_EQ(listed, lab_ids());
}

TEST(Repository, EveryViewHasAReferenceAndEveryReferenceAView) {
  const gllab::ProcessResult r = run_process({(kBinDir / "labrun").string(), "--check-references"});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
}

// DESIGN.md: a program that links both libGL and libOSMesa renders nothing,
// silently. Window programs must not load OSMesa; headless ones no libGL/GLX.
TEST(Linking, NoProgramLinksBothLibGlAndOsmesa) {
  for (const std::string& lab : lab_ids()) {
    const gllab::ProcessResult window = run_process({"/usr/bin/readelf", "-d", (kBinDir / lab).string()});
    const gllab::ProcessResult headless =
        run_process({"/usr/bin/readelf", "-d", gllab::testing::headless(lab)});
    ASSERT_EQ(window.exit_status, 0) << window.err;
    ASSERT_EQ(headless.exit_status, 0) << headless.err;
    EXPECT_EQ(window.out.find("libOSMesa"), std::string::npos) << lab;
    EXPECT_NE(headless.out.find("libOSMesa"), std::string::npos) << lab;
    for (const char* gl : {"[libGL.so", "[libGLX", "[libOpenGL", "[libglut"})
      EXPECT_EQ(headless.out.find(gl), std::string::npos) << lab << "_headless needs " << gl;
  }
}

}  // namespace

namespace {

// Issue 6: every lab's keys are listed in its help overlay (frame.cpp lists
// Lab::keys, so that holds by construction) and in its README. The keys come
// from the window program's --help ("keys:" section, after the runner's own);
// each must appear in labs/<lab>/README.md in backquotes, as `k` or as part of
// a pair like `k`/`K`.
TEST(Repository, EveryLabKeyIsInTheLabsReadme) {
  for (const std::string& lab : lab_ids()) {
    const gllab::ProcessResult help = run_process({(kBinDir / lab).string(), "--help"});
    ASSERT_EQ(help.exit_status, 0) << lab << ": " << help.err;
    const std::string readme = read_text(kSourceDir / "labs" / lab / "README.md");
    const auto keys_at = help.out.find("\nkeys:\n");
    ASSERT_NE(keys_at, std::string::npos) << lab;
    std::istringstream lines(help.out.substr(keys_at + 7));
    int count = 0;
    for (std::string line; std::getline(lines, line) && !line.empty();) {
      // "  k       what": the lab's keys follow the runner's (v / V, h, p, Ctrl+S, Esc).
      if (line.size() < 4 || line[3] != ' ' || line.compare(0, 2, "  ") != 0) continue;
      const char key = line[2];
      if (std::string("hvVp").find(key) != std::string::npos) continue;
      ++count;
      EXPECT_NE(readme.find(std::string("`") + key + "`"), std::string::npos)
          << lab << ": key '" << key << "' (" << line.substr(4) << ") is not in its README";
    }
    EXPECT_GT(count, 0) << lab << " lists no keys of its own";
  }
}

}  // namespace
