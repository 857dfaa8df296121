// tools/labrun.cpp — render every lab view headless and compare it with its
// reference image. `make run` (and so `./lab run`) calls this; so does the
// CTest test of each view, and `make references` (--update-references).
//
//   labrun [--labs 01,13] [--views default,wireframe] [--out DIR]
//          [--bin DIR] [--refs DIR] [--env NAME=VALUE]...
//   labrun --update-references     render into reference_images/ + MANIFEST
//   labrun --check-references      every view has a reference, no stray ones
//
// An error view (harness/lab.h View::expect_error; --list-views prints
// "name expect_error") has no reference image: it passes when the render
// exits 1 with an error line, and --update-references skips it.
//
// Exit status: 0 all pass, 1 some view failed, 2 usage or input error.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "process.h"

namespace fs = std::filesystem;

namespace {

// Tolerance written to MANIFEST by --update-references and read back when
// comparing (calibrated in tests/harness/tolerance_test.cpp and README.md):
//  - lighting differs between llvmpipe and softpipe by at most 8 per channel;
//  - softpipe draws one-pixel lines one pixel over (up to 0.4% of a
//    wireframe view's pixels), which a shift radius of 1 excuses;
//  - what remains must be under 0.05% of the pixels (131 of 512x512).
constexpr int kDefaultChannelThreshold = 24;
constexpr int kDefaultShiftRadius = 1;
constexpr double kDefaultMaxDifferingShare = 0.0005;

struct Settings {
  std::vector<std::string> labs;  // empty: all
  std::set<std::string> views;    // empty: all
  fs::path bin, refs, out = "out";
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
    } else if (a == "--out") s.out = value();
    else if (a == "--bin") s.bin = value();
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
          "usage: labrun [--labs 01,13] [--views NAME,...] [--out DIR] [--bin DIR] [--refs DIR]\n"
          "              [--env NAME=VALUE]...\n"
          "       labrun --update-references | --check-references\n\n"
          "Renders every view of every lab with build/bin/<lab>_headless, compares each\n"
          "with reference_images/<lab>__<view>.png using the tolerance in\n"
          "reference_images/MANIFEST, prints a table and writes the renders and diff\n"
          "heat maps to --out (default out/): <lab>__<view>.png, <lab>__<view>.diff.png.\n"
          "An error view (--list-views: 'name expect_error') has no reference and passes\n"
          "when the render exits 1 with an error line.\n\n"
          "  --update-references  render into the reference folder and rewrite MANIFEST\n"
          "  --check-references   fail when a view has no reference or a reference no view\n"
          "  --env NAME=VALUE     set for the renderer, e.g. GALLIUM_DRIVER=softpipe\n\n"
          "Exit status: 0 all passed, 1 some failed, 2 usage or input error.");
      std::exit(0);
    } else throw UsageError("unknown option '" + a + "' (try --help)");
  }
  if (s.labs.empty()) s.labs = all_labs();
  return s;
}

fs::path renderer_of(const Settings& s, const std::string& lab) { return s.bin / (lab + "_headless"); }

// One line of --list-views: "name", or "name expect_error" for an error view
// (harness/lab.h View::expect_error: headless it exits 1, it has no reference).
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
    if (words.size() > 2 || (words.size() == 2 && words[1] != "expect_error"))
      throw UsageError(lab + ": --list-views printed '" + line + "' (expected a name, optionally 'expect_error')");
    if (s.views.empty() || s.views.count(words[0])) views.push_back({words[0], words.size() == 2});
  }
  return views;
}

std::map<std::string, std::string> read_manifest(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read " + path.string() + " (run: make references)");
  std::map<std::string, std::string> m;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon != std::string::npos) m[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return m;
}

gllab::Tolerance tolerance_from(const std::map<std::string, std::string>& m, const fs::path& path) {
  gllab::Tolerance t;
  try {
    t.channel_threshold = std::stoi(m.at("tolerance_channel_threshold"));
    t.max_differing_share = std::stod(m.at("tolerance_max_differing_share"));
    t.shift_radius = std::stoi(m.at("tolerance_shift_radius"));
  } catch (const std::exception&) {
    throw UsageError(path.string() + ": missing or malformed tolerance_channel_threshold, "
                     "tolerance_shift_radius or tolerance_max_differing_share");
  }
  return t;
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

int compare_all(const Settings& s) {
  const fs::path manifest = s.refs / "MANIFEST";
  const gllab::Tolerance tolerance = tolerance_from(read_manifest(manifest), manifest);
  fs::create_directories(s.out);
  std::printf("%-22s %-20s %-6s %10s %20s %9s\n", "lab", "view", "result", "differing", "unexcused (share)",
              "max delta");
  int passed = 0, failed = 0;
  for (const std::string& lab : s.labs) {
    for (const ViewEntry& entry : views_of(s, lab)) {
      const std::string& view = entry.name;
      const std::string name = reference_name(lab, view);
      const fs::path render = s.out / name;
      const fs::path heat = s.out / (lab + "__" + view + ".diff.png");
      std::string failure, note;
      gllab::Comparison c;
      const gllab::ProcessResult r = gllab::run_process(
          {renderer_of(s, lab).string(), "--view", view, "--out", render.string()}, s.env);
      if (entry.expect_error) {
        // Passes when the renderer reports its frame error: exit 1, one line.
        const std::string line = gllab::first_line(r.err);
        if (r.exit_status == 1 && !line.empty()) note = "error view, exits 1 as expected: " + line;
        else if (r.exit_status == 0) failure = "error view rendered without an error (expected exit 1)";
        else failure = "error view: exit status " + std::to_string(r.exit_status) + " (expected 1): " + line;
      } else if (r.exit_status != 0) {
        failure = r.started ? gllab::first_line(r.err) : r.err;
        if (failure.empty()) failure = "renderer exited with status " + std::to_string(r.exit_status);
      } else if (!fs::exists(s.refs / name)) {
        failure = "no reference image " + (s.refs / name).string() + " (run: make references)";
      } else {
        try {
          const gllab::Image reference = gllab::read_png((s.refs / name).string());
          const gllab::Image image = gllab::read_png(render.string());
          c = gllab::compare_images(reference, image, tolerance.channel_threshold, tolerance.shift_radius);
          gllab::write_png(heat.string(), gllab::heat_map(reference, image, tolerance.channel_threshold, tolerance.shift_radius), 1);
          if (!c.passes(tolerance)) failure = "differs beyond tolerance (heat map: " + heat.string() + ")";
        } catch (const std::exception& e) {
          failure = e.what();
        }
      }
      char unexcused[64];
      std::snprintf(unexcused, sizeof unexcused, "%lld (%.3f%%)", c.mismatched_pixels, 100.0 * c.mismatched_share());
      const bool compared = c.total_pixels > 0;
      std::printf("%-22s %-20s %-6s %10s %20s %9s\n", lab.c_str(), view.c_str(), failure.empty() ? "pass" : "FAIL",
                  compared ? std::to_string(c.differing_pixels).c_str() : "-", compared ? unexcused : "-",
                  compared ? std::to_string(c.max_delta).c_str() : "-");
      if (!failure.empty()) std::printf("    %s\n", failure.c_str());
      if (!note.empty()) std::printf("    %s\n", note.c_str());
      (failure.empty() ? passed : failed)++;
    }
  }
  std::printf("%d views: %d passed, %d failed (tolerance: a channel off by >%d, not excused by a "
              "%d-pixel shift, on at most %.3f%% of pixels)\n",
              passed + failed, passed, failed, tolerance.channel_threshold, tolerance.shift_radius,
              100.0 * tolerance.max_differing_share);
  std::printf("renders and heat maps: %s/\n", s.out.c_str());
  return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Settings s = parse(argc, argv);
    if (s.update) return update_references(s);
    if (s.check) return check_references(s);
    return compare_all(s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "labrun: %s\n", e.what());
    return 2;
  }
}
