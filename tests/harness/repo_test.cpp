// tests/harness/repo_test.cpp — the repository stays in step with the one
// CMake lab list: lab folders, README table, reference images, linking.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

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

// docs/platform.md: a program that links both libGL and libOSMesa renders nothing,
// silently. One program per lab: with EGL it links GLVND's libraries (window and
// headless) and never OSMesa; with OSMesa (no window) no libGL, GLX, libOpenGL or glut.
// The OSMesa twins of make backends (build/osmesa/), when built, are checked too.
void expect_osmesa_only(const std::string& program) {
  const gllab::ProcessResult r = run_process({"/usr/bin/readelf", "-d", program});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("[libOSMesa"), std::string::npos) << program;
  for (const char* gl : {"[libGL.so", "[libGLX", "[libOpenGL", "[libglut", "[libEGL"})
    EXPECT_EQ(r.out.find(gl), std::string::npos) << program << " needs " << gl;
}

TEST(Linking, NoProgramLinksBothLibGlAndOsmesa) {
  for (const std::string& lab : lab_ids()) {
    const std::string program = (kBinDir / lab).string();
    if (GLLAB_HAVE_WINDOW) {
      const gllab::ProcessResult r = run_process({"/usr/bin/readelf", "-d", program});
      ASSERT_EQ(r.exit_status, 0) << r.err;
      EXPECT_EQ(r.out.find("[libOSMesa"), std::string::npos) << lab;
      for (const char* gl : {"[libEGL", "[libOpenGL", "[libGLX", "[libglut"})
        EXPECT_NE(r.out.find(gl), std::string::npos) << lab << " does not link " << gl;
    } else {
      expect_osmesa_only(program);
    }
    const std::filesystem::path twin = kBinDir.parent_path() / "osmesa" / lab;
    if (std::filesystem::exists(twin)) expect_osmesa_only(twin.string());
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
      if (std::string("hvVp0").find(key) != std::string::npos) continue;  // the runner's
      ++count;
      EXPECT_NE(readme.find(std::string("`") + key + "`"), std::string::npos)
          << lab << ": key '" << key << "' (" << line.substr(4) << ") is not in its README";
    }
    EXPECT_GT(count, 0) << lab << " lists no keys of its own";
  }
}

}  // namespace

namespace {

// ---- the form of a lab (docs/lab_form.md) --------------------------------------
// One idea on one page: at most 250 lines and 100 columns (bytes, as mawk's
// `length` counts them) per lab, the median at most 200, at most 6 views and 8
// keys of the lab's own.
constexpr std::size_t kMaxLines = 250, kMaxMedianLines = 200, kMaxColumns = 100;
constexpr std::size_t kMaxViews = 6, kMaxKeys = 8;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string lab_source(const std::string& lab) {
  return read_text(kSourceDir / "labs" / lab / (lab + ".cpp"));
}

// The lab's own keys, as the window program's --help lists them after the
// runner's (the test above reads the same section).
std::vector<char> lab_keys(const std::string& lab) {
  const gllab::ProcessResult help = run_process({(kBinDir / lab).string(), "--help"});
  std::vector<char> keys;
  const auto at = help.out.find("\nkeys:\n");
  if (at == std::string::npos) return keys;
  std::istringstream lines(help.out.substr(at + 7));
  for (std::string line; std::getline(lines, line) && !line.empty();)
    if (line.size() >= 4 && line[3] == ' ' && line.compare(0, 2, "  ") == 0 &&
        std::string("hvVp0").find(line[2]) == std::string::npos)
      keys.push_back(line[2]);
  return keys;
}

std::vector<std::string> view_names(const std::string& lab) {
  std::vector<std::string> names;
  for (const std::string& line : lines_of(run_process({gllab::testing::headless(lab), "--list-views"}).out))
    names.push_back(line.substr(0, line.find(' ')));
  return names;
}

TEST(LabForm, EveryLabFitsOnOnePage) {
  std::vector<std::size_t> sizes;
  for (const std::string& lab : lab_ids()) {
    const std::vector<std::string> lines = lines_of(lab_source(lab));
    sizes.push_back(lines.size());
    EXPECT_LE(lines.size(), kMaxLines) << lab << " has " << lines.size() << " lines";
    for (std::size_t i = 0; i < lines.size(); ++i)
      EXPECT_LE(lines[i].size(), kMaxColumns) << lab << ".cpp:" << i + 1 << " is " << lines[i].size()
                                              << " bytes wide";
    EXPECT_LE(view_names(lab).size(), kMaxViews) << lab;
    EXPECT_LE(lab_keys(lab).size(), kMaxKeys) << lab;
  }
  ASSERT_FALSE(sizes.empty());
  std::sort(sizes.begin(), sizes.end());
  const std::size_t n = sizes.size();
  const double median = n % 2 ? sizes[n / 2] : (sizes[n / 2 - 1] + sizes[n / 2]) / 2.0;
  EXPECT_LE(median, kMaxMedianLines) << "median lab length over " << n << " labs";
}

// Views are declared with the function that draws them, so no lab needs its
// view's name: a lab that reads it could dispatch on a misspelt string and
// fall through to another picture. (A view without a draw function is refused
// when the lab starts: tests/harness/state_test.cpp.)
TEST(LabForm, NoLabDispatchesOnItsViewsName) {
  const std::regex reads_view(R"((\.|->)(view|view_index|views)\(\))");
  for (const std::string& lab : lab_ids()) {
    const std::vector<std::string> lines = lines_of(lab_source(lab));
    for (std::size_t i = 0; i < lines.size(); ++i)
      EXPECT_FALSE(std::regex_search(lines[i], reads_view)) << lab << ".cpp:" << i + 1 << ": " << lines[i];
  }
}

// The header lists the lab's keys for the student who reads the file: every
// key the lab defines appears as [k] in its "// Keys:" lines.
TEST(LabForm, HeaderListsEveryKey) {
  for (const std::string& lab : lab_ids()) {
    std::string header;
    bool in_keys = false;
    for (const std::string& line : lines_of(lab_source(lab))) {
      if (line.rfind("// Keys:", 0) == 0) in_keys = true;
      else if (in_keys && line.rfind("//   ", 0) != 0) break;
      if (in_keys) header += line + "\n";
    }
    ASSERT_FALSE(header.empty()) << lab << ".cpp has no // Keys: line";
    for (char k : lab_keys(lab))
      EXPECT_NE(header.find(std::string("[") + k + "]"), std::string::npos)
          << lab << ": key '" << k << "' is not in the header's // Keys: lines";
  }
}

// ./lab list prints every view of every lab: the header's "// Views:" list,
// continued on "//   " lines, against what the program declares.
TEST(LabForm, LabListPrintsEveryView) {
  const gllab::ProcessResult r = run_process({"/bin/sh", (kSourceDir / "lab").string(), "list"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  for (const std::string& lab : lab_ids()) {
    std::string listed;
    for (std::size_t i = 0; i + 1 < lines.size(); ++i)
      if (lines[i].rfind(lab + " ", 0) == 0) listed = lines[i + 1];
    const auto at = listed.find("views: ");
    ASSERT_NE(at, std::string::npos) << lab << " is not in ./lab list:\n" << r.out;
    std::vector<std::string> names;
    std::string rest = listed.substr(at + 7);
    for (std::size_t start = 0; start <= rest.size();) {
      const std::size_t comma = rest.find(", ", start);
      std::string name = rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      name = name.substr(0, name.find(' '));  // "reversed_outer_loop (an error view)"
      names.push_back(name);
      if (comma == std::string::npos) break;
      start = comma + 2;
    }
    EXPECT_EQ(names, view_names(lab)) << lab << ": ./lab list says '" << listed << "'";
  }
}

// The repository stands alone: a student has a clone, nothing else. No file
// points to the project's private folder beside it or to the lecture notes'
// file names; the notes are cited by chapter and title (docs/lecture_notes.md).
TEST(Repository, NoFilePointsOutsideTheRepository) {
  const std::vector<std::string> outside = {std::string("../") + "shared", std::string("seed ") + "00",
                                            std::string("seeds") + "/"};
  std::vector<std::string> found;
  for (auto it = fs::recursive_directory_iterator(kSourceDir); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path& p = it->path();
    const std::string name = p.filename().string();
    if (it->is_directory() && (name == ".git" || name.rfind("build", 0) == 0 || name == "out")) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file() || p.extension() == ".png" || fs::file_size(p) > (1 << 22)) continue;
    const std::vector<std::string> lines = lines_of(read_text(p));
    for (std::size_t i = 0; i < lines.size(); ++i)
      for (const std::string& o : outside)
        if (lines[i].find(o) != std::string::npos)
          found.push_back(fs::relative(p, kSourceDir).string() + ":" + std::to_string(i + 1) + ": " + lines[i]);
  }
  EXPECT_TRUE(found.empty()) << found.size() << " lines, the first: " << (found.empty() ? "" : found[0]);
}

}  // namespace
