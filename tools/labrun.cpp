// tools/labrun.cpp — the reference images themselves: `make references`
// renders them (--update-references), the repository test checks that every
// lab view has one and every one a view (--check-references). Grading renders
// against them is labgrade's job (tools/labgrade.cpp, `./lab run`).
//
//   labrun --update-references [--labs 01,15] [--views NAME,...] [--refs DIR] [--env NAME=VALUE]...
//   labrun --check-references  [--bin DIR] [--refs DIR]
//
// An error view (harness/lab.h View::expect_error; --list-views prints
// "name expect_error") has no reference image: --update-references skips it
// and --check-references expects none.
//
// Exit status: 0 done / all present, 1 a reference missing or stray, 2 usage or input error.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "process.h"

namespace fs = std::filesystem;

namespace {

// Tolerance written to MANIFEST by --update-references and read back by
// labgrade (calibrated in tests/grading/ and README.md "Grading"):
//  - lighting differs between llvmpipe and softpipe by at most 8 per channel;
//  - softpipe draws one-pixel lines one pixel over (up to 0.4% of a
//    wireframe view's pixels), which a shift radius of 1 excuses;
//  - what remains must be under 0.1% of the pixels (262 of 512x512): with
//    all 17 labs softpipe's worst view left 101 (0.039%), the closest real
//    mistake 1785; 262 is 2.6x the one and 1/6.8 of the other (it was 0.05%
//    with labs 01-07, whose worst was 76, a margin of 1.3x once the surface
//    labs came).
constexpr int kDefaultChannelThreshold = 24;
constexpr int kDefaultShiftRadius = 1;
constexpr double kDefaultMaxDifferingShare = 0.001;

struct Settings {
  std::vector<std::string> labs;  // empty: all
  std::set<std::string> views;    // empty: all
  fs::path bin, refs;
  std::vector<std::string> env;
  bool update = false, check = false;
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, sep);)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

const std::vector<std::string>& all_labs() {
  static const std::vector<std::string> labs = split(GLLAB_LABS, ';');
  return labs;
}

// "01" or "01_immediate_mode" -> "01_immediate_mode".
std::string resolve_lab(const std::string& name) {
  for (const std::string& lab : all_labs())
    if (lab == name || lab.substr(0, lab.find('_')) == name) return lab;
  std::string known;
  for (const std::string& lab : all_labs()) known += (known.empty() ? "" : ", ") + lab;
  throw UsageError("unknown lab '" + name + "' (labs: " + known + ")");
}

fs::path own_directory() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : self.parent_path();
}

Settings parse(int argc, char** argv) {
  Settings s;
  s.bin = own_directory();
  s.refs = GLLAB_REFERENCE_DIR;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--labs") {
      for (const std::string& l : split(value(), ',')) s.labs.push_back(resolve_lab(l));
    } else if (a == "--views") {
      for (const std::string& v : split(value(), ',')) s.views.insert(v);
    } else if (a == "--bin") s.bin = value();
    else if (a == "--refs") s.refs = value();
    else if (a == "--env") {
      const std::string e = value();
      if (e.find('=') == std::string::npos || e.front() == '=')
        throw UsageError("malformed --env '" + e + "' (expected NAME=VALUE)");
      s.env.push_back(e);
    } else if (a == "--update-references") s.update = true;
    else if (a == "--check-references") s.check = true;
    else if (a == "--help" || a == "-h") {
      std::puts(
          "usage: labrun --update-references [--labs 01,15] [--views NAME,...] [--refs DIR]\n"
          "              [--env NAME=VALUE]...\n"
          "       labrun --check-references [--bin DIR] [--refs DIR]\n\n"
          "  --update-references  render every view of the labs with build/bin/<lab>_headless\n"
          "                       into the reference folder and rewrite its MANIFEST\n"
          "  --check-references   fail when a view has no reference or a reference no view\n"
          "  --env NAME=VALUE     set for the renderer\n\n"
          "To grade renders against the references: labgrade (./lab run, ./lab grade).\n"
          "Exit status: 0 done, 1 a reference missing or stray, 2 usage or input error.");
      std::exit(0);
    } else throw UsageError("unknown option '" + a + "' (try --help)");
  }
  if (!s.update && !s.check) throw UsageError("give --update-references or --check-references (try --help)");
  if (s.labs.empty()) s.labs = all_labs();
  return s;
}

fs::path renderer_of(const Settings& s, const std::string& lab) { return s.bin / (lab + "_headless"); }

// One line of --list-views: "name", then optionally "expect_error" for an
// error view (harness/lab.h kErrorView: headless it exits 1, it has no
// reference) and "same_as=OTHER" (View::same_as, read by the tests).
struct ViewEntry {
  std::string name;
  bool expect_error = false;
};

std::vector<ViewEntry> views_of(const Settings& s, const std::string& lab) {
  const gllab::ProcessResult r = gllab::run_process({renderer_of(s, lab).string(), "--list-views"});
  if (!r.started || r.exit_status != 0)
    throw UsageError(lab + ": cannot list views: " + gllab::first_line(r.err));
  std::vector<ViewEntry> views;
  for (const std::string& line : split(r.out, '\n')) {
    const std::vector<std::string> words = split(line, ' ');
    if (words.empty()) continue;
    bool expect_error = false;
    for (std::size_t k = 1; k < words.size(); ++k) {
      if (words[k] == "expect_error") expect_error = true;
      else if (words[k].rfind("same_as=", 0) != 0)
        throw UsageError(lab + ": --list-views printed '" + line +
                         "' (expected a name, optionally 'expect_error' and 'same_as=OTHER')");
    }
    if (s.views.empty() || s.views.count(words[0])) views.push_back({words[0], expect_error});
  }
  return views;
}

std::string reference_name(const std::string& lab, const std::string& view) {
  return lab + "__" + view + ".png";
}

int check_references(const Settings& s) {
  std::set<std::string> expected;
  int problems = 0;
  for (const std::string& lab : s.labs)
    for (const ViewEntry& view : views_of(s, lab)) {
      const std::string name = reference_name(lab, view.name);
      if (view.expect_error) {
        if (fs::exists(s.refs / name)) {
          std::printf("reference for an error view (it exits 1, it has none): %s\n", (s.refs / name).c_str());
          ++problems;
        }
        continue;
      }
      expected.insert(name);
      if (!fs::exists(s.refs / name)) {
        std::printf("missing reference: %s\n", (s.refs / name).c_str());
        ++problems;
      }
    }
  if (s.labs == all_labs() && s.views.empty())
    for (const auto& entry : fs::directory_iterator(s.refs)) {
      const std::string name = entry.path().filename().string();
      if (entry.path().extension() == ".png" && !expected.count(name)) {
        std::printf("reference without a lab view: %s\n", entry.path().c_str());
        ++problems;
      }
    }
  std::printf("%zu views, %d problem%s\n", expected.size(), problems, problems == 1 ? "" : "s");
  return problems ? 1 : 0;
}

std::string installed_version(const std::string& package) {
  const gllab::ProcessResult r =
      gllab::run_process({"/usr/bin/dpkg-query", "-W", "-f=${Version}", package});
  return r.exit_status == 0 && !r.out.empty() ? r.out : "unknown";
}

int update_references(const Settings& s) {
  fs::create_directories(s.refs);
  std::string renderer_info;
  int count = 0;
  for (const std::string& lab : s.labs) {
    if (renderer_info.empty()) {
      const gllab::ProcessResult info = gllab::run_process({renderer_of(s, lab).string(), "--info"}, s.env);
      if (info.exit_status != 0) throw UsageError(lab + ": --info failed: " + gllab::first_line(info.err));
      renderer_info = info.out;
    }
    for (const ViewEntry& entry : views_of(s, lab)) {
      const std::string& view = entry.name;
      if (entry.expect_error) {
        std::printf("skipped %s %s: an error view has no reference\n", lab.c_str(), view.c_str());
        continue;
      }
      const fs::path target = s.refs / reference_name(lab, view);
      const gllab::ProcessResult r = gllab::run_process(
          {renderer_of(s, lab).string(), "--view", view, "--out", target.string()}, s.env);
      if (r.exit_status != 0) throw UsageError(lab + " " + view + ": " + gllab::first_line(r.err));
      std::printf("wrote %s\n", target.c_str());
      ++count;
    }
  }
  std::ofstream m(s.refs / "MANIFEST");
  m << "# reference_images/MANIFEST: how the reference images were made.\n"
    << "# Regenerate all of them with: make references\n"
    << "# A pixel differs when a channel (R, G, B or A, 0..255) differs from the\n"
    << "# reference by more than tolerance_channel_threshold. It is excused when a\n"
    << "# shift of up to tolerance_shift_radius pixels explains it (lines drawn one\n"
    << "# pixel over). A render passes when at most tolerance_max_differing_share of\n"
    << "# its pixels differ unexcused.\n"
    << renderer_info
    << "mesa_package: libosmesa6 " << installed_version("libosmesa6") << "\n"
    << "glu_package: libglu1-mesa " << installed_version("libglu1-mesa") << "\n"
    << "size: 512x512\n"
    << "tolerance_channel_threshold: " << kDefaultChannelThreshold << "\n"
    << "tolerance_shift_radius: " << kDefaultShiftRadius << "\n"
    << "tolerance_max_differing_share: " << kDefaultMaxDifferingShare << "\n";
  if (!m) throw UsageError("cannot write " + (s.refs / "MANIFEST").string());
  std::printf("%d reference images and MANIFEST written to %s\n", count, s.refs.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Settings s = parse(argc, argv);
    if (s.update) return update_references(s);
    return check_references(s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "labrun: %s\n", e.what());
    return 2;
  }
}
