// tools/labrun.cpp — the reference images themselves: `make references`
// renders them (--update-references), the repository test checks that every
// lab view has one and every one a view (--check-references). Grading renders
// against them is labgrade's job (tools/labgrade.cpp, `./lab run`).
//
//   labrun --update-references [--labs 01,15] [--views NAME,...] [--refs DIR] [--env NAME=VALUE]...
//   labrun --check-references  [--bin DIR] [--refs DIR]
//   labrun --compare-builds OTHER_BIN [--bin DIR] [--labs 01,15] [--views NAME,...]
//
// --compare-builds renders every view with DIR's programs and with OTHER_BIN's
// and fails on any byte that differs: CI runs it between the EGL build and an
// OSMesa build (.ci/run), which must draw the same frames (docs/platform.md).
//
// An error view (harness/lab.h View::expect_error; --list-views prints
// "name expect_error") has no reference image: --update-references skips it
// and --check-references expects none.
//
// Exit status: 0 done / all present, 1 a reference missing or stray, 2 usage or input error
// (a failed write, stdout included). Limits: tools/README.md.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "files/files.h"
#include "image/image.h"
#include "image/pam.h"
#include "option_names.h"
#include "process.h"

namespace fs = std::filesystem;

namespace {

// The two grading profiles written to MANIFEST by --update-references and
// read back by labgrade (tools/grading.h; calibrated in tests/grading/, the
// measurements in README.md "Grading" and docs/grading_calibration.md).
struct ProfileLimits {
  const char* name;
  int channel_threshold, shift_radius, edge_contrast;
  double max_unexcused_share, max_shifted_share;
};
// build: the reference renderer on a student's build. Correct code that
// computes the same values another way renders byte-identical, or within 1
// per channel (a rotation split in two): a threshold of 2 sees a shading
// error spread over a surface, and 48 keeps the shift excuse to real edges.
// images: a foreign renderer. softpipe lights up to 8 per channel apart and
// draws one-pixel lines one pixel over (up to 3.5% of a view's pixels); a
// threshold of 12 (edges: a neighbour 13 apart, more than the threshold)
// leaves at most 111 of its pixels unexcused, as 24 left 101.
constexpr ProfileLimits kProfiles[] = {
    {"build", 2, 1, 48, 0.0001, 0.001},
    {"images", 12, 1, 13, 0.001, 0.1},
};
// Text: numbers within this relative difference agree; numbers both under
// the absolute bound (rounding noise such as 3e-17) agree whatever they are.
constexpr double kTextRelative = 1e-6;
constexpr double kTextAbsolute = 1e-9;
// A renderer's --text-out read back: at most 1 MiB (the largest view's text is
// 1.9 KB; labgrade's kMaxTextFileBytes).
constexpr std::uintmax_t kMaxTextBytes = std::uintmax_t{1} << 20;

struct Settings {
  std::vector<std::string> labs;  // empty: all
  std::set<std::string> views;    // empty: all
  fs::path bin, refs;
  fs::path other_bin;  // --compare-builds
  std::vector<std::string> env;
  bool update = false, check = false, compare = false, help = false;
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

std::vector<std::string> names(const std::string& option, const std::string& text) {
  return gllab::option_names<UsageError>(option, text);
}

// A renderer run with the grader's output limit (process.h): a program that
// prints without end is killed, not buffered until memory runs out.
gllab::ProcessResult run_renderer(const std::vector<std::string>& argv,
                                  const std::vector<std::string>& env = {}) {
  gllab::ProcessResult r =
      gllab::run_process(argv, env, gllab::ProcessLimits{0, gllab::kMaxRendererOutputBytes});
  if (r.output_exceeded)
    throw std::runtime_error(argv[0] + ": wrote more than " +
                             std::to_string(gllab::kMaxRendererOutputBytes >> 20) +
                             " MiB to stdout or stderr (killed)");
  return r;
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
      for (const std::string& l : names(a, value())) s.labs.push_back(resolve_lab(l));
    } else if (a == "--views") {
      for (const std::string& v : names(a, value())) s.views.insert(v);
    } else if (a == "--bin") s.bin = value();
    else if (a == "--refs") s.refs = value();
    else if (a == "--env") {
      const std::string e = value();
      if (e.find('=') == std::string::npos || e.front() == '=')
        throw UsageError("malformed --env '" + e + "' (expected NAME=VALUE)");
      s.env.push_back(e);
    } else if (a == "--update-references") s.update = true;
    else if (a == "--check-references") s.check = true;
    else if (a == "--compare-builds") s.compare = true, s.other_bin = value();
    else if (a == "--help" || a == "-h") {
      s.help = true;
      std::puts(
          "usage: labrun --update-references [--labs 01,15] [--views NAME,...] [--refs DIR]\n"
          "              [--env NAME=VALUE]...\n"
          "       labrun --check-references [--bin DIR] [--refs DIR]\n"
          "       labrun --compare-builds OTHER_BIN [--bin DIR] [--labs 01,15] [--views NAME,...]\n\n"
          "  --update-references  render every view of the labs with build/bin/<lab> --headless\n"
          "                       into the reference folder and rewrite its MANIFEST\n"
          "  --check-references   fail when a view has no reference or a reference no view\n"
          "  --compare-builds     render every view with DIR's programs and OTHER_BIN's (say,\n"
          "                       the EGL and the OSMesa build) and fail on any differing byte\n"
          "  --env NAME=VALUE     set for the renderer\n\n"
          "To grade renders against the references: labgrade (./lab run, ./lab grade).\n"
          "Exit status: 0 done, 1 a reference missing or stray, 2 usage or input error.");
      return s;
    } else throw UsageError("unknown option '" + a + "' (try --help)");
  }
  if (s.update + s.check + s.compare != 1)
    throw UsageError("give one of --update-references, --check-references, --compare-builds (try --help)");
  if (s.labs.empty()) s.labs = all_labs();
  return s;
}

fs::path renderer_of(const Settings& s, const std::string& lab) { return s.bin / lab; }

// One line of --list-views: "name", then optionally "expect_error" for an
// error view (harness/lab.h kErrorView: headless it exits 1, it has no
// reference) and "same_as=OTHER" (View::same_as, read by the tests).
struct ViewEntry {
  std::string name;
  bool expect_error = false;
};

std::vector<ViewEntry> views_of(const Settings& s, const std::string& lab) {
  const gllab::ProcessResult r = run_renderer({renderer_of(s, lab).string(), "--list-views"});
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

// Whole or not at all: a temporary file beside it, renamed over it when
// complete and removed on every failure.
void write_file(const fs::path& file, const std::string& text) {
  std::error_code ec;
  if (fs::is_directory(file, ec))
    throw UsageError("cannot write " + file.string() + ": it is a directory");
  const fs::path tmp =
      file.parent_path() / ("." + file.filename().string() + ".tmp-" + std::to_string(getpid()));
  const auto fail = [&](const std::string& why) {
    fs::remove(tmp, ec);
    return UsageError("cannot write " + file.string() + " (" + why + ")");
  };
  {
    errno = 0;
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw fail(errno ? std::strerror(errno) : "write failed");
  }
  fs::rename(tmp, file, ec);
  if (ec) throw fail(ec.message());
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
      const std::string stem = lab + "__" + view.name;
      // An error view: its line (.error), no image; any other: image and text.
      const std::vector<std::string> files =
          view.expect_error ? std::vector<std::string>{stem + ".error"} : std::vector<std::string>{name, stem + ".txt"};
      if (view.expect_error && fs::exists(s.refs / name)) {
        std::printf("reference image for an error view (it exits 1): %s\n", (s.refs / name).c_str());
        ++problems;
      }
      for (const std::string& f : files) {
        expected.insert(f);
        if (!fs::exists(s.refs / f)) {
          std::printf("missing reference: %s\n", (s.refs / f).c_str());
          ++problems;
        }
      }
    }
  if (s.labs == all_labs() && s.views.empty())
    for (const auto& entry : fs::directory_iterator(s.refs)) {
      const std::string name = entry.path().filename().string();
      const std::string ext = entry.path().extension().string();
      if ((ext == ".png" || ext == ".txt" || ext == ".error") && !expected.count(name)) {
        std::printf("reference without a lab view: %s\n", entry.path().c_str());
        ++problems;
      }
    }
  std::printf("%zu reference files, %d problem%s\n", expected.size(), problems, problems == 1 ? "" : "s");
  return problems ? 1 : 0;
}

std::string installed_version(const std::string& package) {
  const gllab::ProcessResult r =
      gllab::run_process({"/usr/bin/dpkg-query", "-W", "-f=${Version}", package});
  return r.exit_status == 0 && !r.out.empty() ? r.out : "unknown";
}

std::string mesa_package(const std::string& renderer_info) {
  const std::string package =
      renderer_info.find("backend: OSMesa") != std::string::npos ? "libosmesa6" : "libgl1-mesa-dri";
  return package + " " + installed_version(package);
}

// What one program draws for the views: the PAM frames of the drawn views
// (one run, --views), and each error view's line.
struct Drawn {
  std::string frames;
  std::vector<std::string> error_lines;
};

Drawn draw_views(const fs::path& program, const std::vector<ViewEntry>& views) {
  Drawn d;
  std::string list;
  for (const ViewEntry& v : views) {
    if (!v.expect_error) {
      list += (list.empty() ? "" : ",") + v.name;
      continue;
    }
    const gllab::ProcessResult r = run_renderer({program.string(), "--headless", "--view", v.name, "--out", "-"});
    if (r.exit_status != 1) throw UsageError(program.string() + " " + v.name + ": an error view must exit 1");
    d.error_lines.push_back(gllab::first_line(r.err));
  }
  if (list.empty()) return d;
  const gllab::ProcessResult r = run_renderer({program.string(), "--headless", "--views", list, "--out", "-"});
  if (r.exit_status != 0) throw UsageError(program.string() + ": " + gllab::first_line(r.err));
  d.frames = r.out;
  return d;
}

// The frames of one PAM stream (image/pam.h), one per drawn view.
std::vector<gllab::Image> split_frames(const std::string& stream, const std::string& source) {
  std::vector<gllab::Image> frames;
  for (std::size_t at = 0; at < stream.size();) frames.push_back(gllab::decode_pam_at(stream, at, source));
  return frames;
}

int compare_builds(const Settings& s) {
  Settings other = s;
  other.bin = s.other_bin;
  const auto backend = [&](const Settings& b) {
    const gllab::ProcessResult info =
        run_renderer({renderer_of(b, s.labs.front()).string(), "--headless", "--info"});
    if (info.exit_status != 0) throw UsageError(b.bin.string() + ": --info failed: " + gllab::first_line(info.err));
    const std::string line = info.out.substr(0, info.out.find('\n'));
    return line.rfind("backend: ", 0) == 0 ? line.substr(9) : line;
  };
  std::printf("comparing %s (%s) with %s (%s)\n", s.bin.c_str(), backend(s).c_str(), other.bin.c_str(),
              backend(other).c_str());
  int views = 0, differ = 0;
  for (const std::string& lab : s.labs) {
    const std::vector<ViewEntry> entries = views_of(s, lab);
    const Drawn a = draw_views(renderer_of(s, lab), entries);
    const Drawn b = draw_views(renderer_of(other, lab), entries);
    const std::vector<gllab::Image> fa = split_frames(a.frames, renderer_of(s, lab).string());
    const std::vector<gllab::Image> fb = split_frames(b.frames, renderer_of(other, lab).string());
    std::size_t frame = 0, error = 0;
    for (const ViewEntry& v : entries) {
      ++views;
      std::string why;
      if (v.expect_error) {
        if (a.error_lines[error] != b.error_lines[error])
          why = "error lines differ: \"" + a.error_lines[error] + "\" and \"" + b.error_lines[error] + "\"";
        ++error;
      } else {
        if (frame >= fa.size() || frame >= fb.size()) why = "a frame is missing";
        else if (fa[frame].width != fb[frame].width || fa[frame].height != fb[frame].height)
          why = "the sizes differ";
        else if (fa[frame].rgba != fb[frame].rgba) {
          const std::vector<std::uint8_t>&x = fa[frame].rgba, &y = fb[frame].rgba;
          std::size_t bytes = 0;
          int most = 0;
          for (std::size_t i = 0; i < x.size(); ++i)
            if (x[i] != y[i]) ++bytes, most = std::max(most, std::abs(int(x[i]) - int(y[i])));
          why = std::to_string(bytes) + " of " + std::to_string(x.size()) + " bytes differ (by up to " +
                std::to_string(most) + ")";
        }
        ++frame;
      }
      if (!why.empty()) {
        ++differ;
        std::printf("DIFFERS %s %s: %s\n", lab.c_str(), v.name.c_str(), why.c_str());
      }
    }
  }
  std::printf("%d views of %zu lab%s: %d byte-identical, %d differ\n", views, s.labs.size(),
              s.labs.size() == 1 ? "" : "s", views - differ, differ);
  return differ ? 1 : 0;
}

int update_references(const Settings& s) {
  fs::create_directories(s.refs);
  std::string renderer_info;
  int count = 0;
  for (const std::string& lab : s.labs) {
    if (renderer_info.empty()) {
      const gllab::ProcessResult info =
          run_renderer({renderer_of(s, lab).string(), "--headless", "--info"}, s.env);
      if (info.exit_status != 0) throw UsageError(lab + ": --info failed: " + gllab::first_line(info.err));
      renderer_info = info.out;
    }
    for (const ViewEntry& entry : views_of(s, lab)) {
      const std::string& view = entry.name;
      if (entry.expect_error) {
        // Its reference is the one line it must refuse with.
        const gllab::ProcessResult r =
            run_renderer({renderer_of(s, lab).string(), "--headless", "--view", view, "--out", "-"}, s.env);
        if (r.exit_status != 1 || !r.out.empty())
          throw UsageError(lab + " " + view + ": an error view must exit 1 and draw nothing (exit " +
                           std::to_string(r.exit_status) + ")");
        const fs::path target = s.refs / (lab + "__" + view + ".error");
        write_file(target, gllab::first_line(r.err) + "\n");
        std::printf("wrote %s\n", target.c_str());
        continue;
      }
      const fs::path target = s.refs / reference_name(lab, view);
      const fs::path text = s.refs / (lab + "__" + view + ".txt");
      const gllab::ProcessResult r =
          run_renderer({renderer_of(s, lab).string(), "--headless", "--view", view, "--out", target.string(),
                        "--text-out", text.string()},
                       s.env);
      if (r.exit_status != 0) throw UsageError(lab + " " + view + ": " + gllab::first_line(r.err));
      // --text-out's one section, "== VIEW N", becomes the N lines alone.
      std::istringstream in(gllab::files::read_input(text.string(), kMaxTextBytes));
      std::string header, body;
      std::getline(in, header);
      for (std::string line; std::getline(in, line);) body += line + "\n";
      write_file(text, body);
      std::printf("wrote %s and .txt\n", target.c_str());
      ++count;
    }
  }
  std::ostringstream m;
  m << "# reference_images/MANIFEST: how the reference images were made.\n"
    << "# Regenerate all of them with: make references\n"
    << "# Two profiles: build (labgrade --build: a student's build on this renderer)\n"
    << "# and images (labgrade --images: renders made elsewhere). In each, a pixel\n"
    << "# differs when a channel (R, G, B or A, 0..255) differs from the reference\n"
    << "# by more than <profile>_channel_threshold. It is excused when a shift of up\n"
    << "# to <profile>_shift_radius pixels explains it and it lies on a thin feature:\n"
    << "# a neighbour differs from it by <profile>_edge_contrast or more (a line or\n"
    << "# an edge moved, not a surface's colour changed). A render passes when at\n"
    << "# most <profile>_max_unexcused_share of its pixels differ unexcused and at\n"
    << "# most <profile>_max_shifted_share are excused. Its text (<view>.txt) must\n"
    << "# agree: words exactly, numbers within text_relative_tolerance (and any two\n"
    << "# under text_absolute_tolerance). An error view has <view>.error: its line.\n"
    << renderer_info
    // The package that holds the renderer: OSMesa's own llvmpipe, or the DRI driver EGL loads.
    << "mesa_package: " << mesa_package(renderer_info) << "\n"
    << "glu_package: libglu1-mesa " << installed_version("libglu1-mesa") << "\n"
    << "size: 512x512\n";
  for (const ProfileLimits& p : kProfiles)
    m << p.name << "_channel_threshold: " << p.channel_threshold << "\n"
      << p.name << "_shift_radius: " << p.shift_radius << "\n"
      << p.name << "_edge_contrast: " << p.edge_contrast << "\n"
      << p.name << "_max_unexcused_share: " << p.max_unexcused_share << "\n"
      << p.name << "_max_shifted_share: " << p.max_shifted_share << "\n";
  m << "text_relative_tolerance: " << kTextRelative << "\n"
    << "text_absolute_tolerance: " << kTextAbsolute << "\n";
  write_file(s.refs / "MANIFEST", m.str());
  std::printf("%d reference images and MANIFEST written to %s\n", count, s.refs.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Settings s = parse(argc, argv);
    const int status = s.help      ? 0
                       : s.update  ? update_references(s)
                       : s.compare ? compare_builds(s)
                                   : check_references(s);
    gllab::files::finish_stdout();
    return status;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "labrun: %s\n", e.what());
    return 2;
  }
}
