// tools/labgrade.cpp — grade lab renders against reference_images/ (instructors).
//
//   labgrade --build DIR    render every view with DIR's headless programs and grade them
//   labgrade --images DIR   grade a folder of <lab>__<view>.png
//   labgrade --class DIR    grade every submission in DIR (a source tree, a build or an
//                           image folder): one CSV, and with --report a page per student
//   options: --labs 15,22  --views a,b  --jobs N  --report DIR  --out DIR  --refs DIR
//            --env NAME=VALUE  --timeout SECONDS  --csv FILE  --profile build|images  --quiet
//            --hidden N  --seed S  --reference-build DIR  --work DIR  --no-sandbox
//
// A source tree is built in the sandbox with the class's compiler cache
// (class_build.h, sandbox.h), and every program of a student runs in the
// sandbox too. Hidden inputs (--hidden) render every view N more times with
// parameters and points drawn from the lab's ranges (hidden_inputs.h); their
// references are rendered by the instructor's build in the same run.
//
// Exit status: 0 every view passed, 1 some failed, 2 usage or input error
// (among them a reference or MANIFEST that is unreadable or out of range,
// checked before any grading, and a failed write, stdout included).
// The metric and its calibration: grading.h and README.md ("Grading");
// the limits: tools/README.md.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "class_build.h"
#include "files/files.h"
#include "grading.h"
#include "hidden_inputs.h"
#include "image/compare.h"
#include "image/image.h"
#include "option_names.h"

namespace fs = std::filesystem;
using namespace gllab::grading;
using gllab::Tolerance;

namespace {

struct Settings {
  enum class Mode { kNone, kBuild, kImages, kClass } mode = Mode::kNone;
  fs::path input, refs = GLLAB_REFERENCE_DIR, report, out = "out", csv;
  std::vector<std::string> labs, views, env;
  int jobs =
      static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, unsigned(kMaxJobs)));
  double timeout = kDefaultTimeoutSeconds;
  std::optional<Profile> profile;  // --profile; else build for a build, images for images
  bool quiet = false, help = false;
  int hidden = 0;                  // --hidden N: renders per view with drawn inputs
  std::uint64_t seed = 1;          // --seed S
  bool seed_given = false;
  fs::path reference_build;        // --reference-build DIR (default: labgrade's own build)
  fs::path work = "labgrade-work"; // --work DIR: builds, compiler caches, hidden references
  bool sandbox = true;             // --no-sandbox: student code runs with the grader's rights
};

/// --hidden: at most this many hidden inputs per view.
constexpr int kMaxHidden = 100;

// A render of a hidden input: the verdict, which pass, the inputs.
struct HiddenResult {
  ViewResult result;
  int pass = 0;          // 1..N
  std::string sets;      // "--set t=0.412 --set P[0]=1,2"
  fs::path refs;         // the pass's references (WORK/hidden/<pass>/)
};

const char kUsage[] =
    "usage: labgrade --build DIR | --images DIR | --class DIR [options]\n\n"
    "Grades renders of the labs against reference_images/<lab>__<view>.png, every\n"
    "view the references define, with the tolerances in reference_images/MANIFEST,\n"
    "and the text each view draws against <lab>__<view>.txt.\n\n"
    "  --build DIR        a build of this repository: DIR/bin/<lab> --headless (or\n"
    "                     DIR/<lab>) renders each view; error views must\n"
    "                     exit 1 with their line (<lab>__<view>.error)\n"
    "  --images DIR       a folder of PNGs named <lab>__<view>.png, each with its\n"
    "                     text: <lab>__<view>.txt (the headless --print-text output)\n"
    "  --class DIR        every folder in DIR is one student's: a source tree (a\n"
    "                     gllab CMakeLists.txt: built in the sandbox, then graded),\n"
    "                     a build or an image folder; writes one CSV (a row per\n"
    "                     student, a column per lab) and with --report a page per\n"
    "                     student and DIR/index.html\n"
    "  --hidden N         render every view N more times (0 to 100) with parameters\n"
    "                     and control points drawn from the lab's ranges; the\n"
    "                     references are the reference build's renders of the same\n"
    "                     inputs (builds and source trees only)\n"
    "  --seed S           the draw of the hidden inputs (default 1; keep it secret)\n"
    "  --reference-build DIR  the instructor's build that renders the hidden\n"
    "                     references (default: the build labgrade is in)\n"
    "  --work DIR         --class: where source trees are built, with the compiler\n"
    "                     cache (default labgrade-work/; keep it for a warm cache)\n"
    "  --no-sandbox       build and run student code without bubblewrap, with your\n"
    "                     own rights (only where bubblewrap cannot run)\n"
    "  --labs 15,22       only these labs (number or folder name)\n"
    "  --views a,b        only these views\n"
    "  --jobs N           renders at once, 1 to 256 (default: the number of cores)\n"
    "  --report DIR       write DIR/index.html (reference, submission, heat map per\n"
    "                     view, failures first), DIR/results.json, DIR/results.csv\n"
    "  --out DIR          where failing renders and their heat maps go (default out/)\n"
    "  --refs DIR         the references (default: this repository's reference_images/)\n"
    "  --env NAME=VALUE   environment for the renderers, e.g. GALLIUM_DRIVER=softpipe\n"
    "  --timeout SECONDS  a render running longer fails (default 60, at most 3600)\n"
    "  --csv FILE         --class: the CSV to write (default class.csv)\n"
    "  --profile NAME     the limits to judge by: build (the same renderer, tight)\n"
    "                     or images (another renderer); default: build for a build,\n"
    "                     images for a folder of images\n"
    "  --quiet            no progress and no per-view table, only the summary\n\n"
    "Exit status: 0 all views passed, 1 some failed, 2 usage or input error.\n";

std::vector<std::string> names(const std::string& option, const std::string& text) {
  return gllab::option_names<UsageError>(option, text);
}

Settings parse(int argc, char** argv) {
  Settings s;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    auto mode = [&](Settings::Mode m) {
      if (s.mode != Settings::Mode::kNone) throw UsageError("give one of --build, --images, --class");
      s.mode = m;
      s.input = value();
    };
    if (a == "--build") mode(Settings::Mode::kBuild);
    else if (a == "--images") mode(Settings::Mode::kImages);
    else if (a == "--class") mode(Settings::Mode::kClass);
    else if (a == "--labs")
      for (const std::string& l : names(a, value())) s.labs.push_back(l);
    else if (a == "--views")
      for (const std::string& v : names(a, value())) s.views.push_back(v);
    else if (a == "--report") s.report = value();
    else if (a == "--out") s.out = value();
    else if (a == "--refs") s.refs = value();
    else if (a == "--csv") s.csv = value();
    else if (a == "--quiet") s.quiet = true;
    else if (a == "--no-sandbox") s.sandbox = false;
    else if (a == "--work") s.work = value();
    else if (a == "--reference-build") s.reference_build = value();
    else if (a == "--hidden") {
      const std::string v = value();
      const std::optional<long long> n = parse_integer(v, 0, kMaxHidden);
      if (!n) throw UsageError("--hidden '" + v + "' is not a whole number from 0 to " + std::to_string(kMaxHidden));
      s.hidden = static_cast<int>(*n);
    } else if (a == "--seed") {
      const std::string v = value();
      const bool digits = !v.empty() && v.size() <= 19 &&
                          std::all_of(v.begin(), v.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!digits) throw UsageError("--seed '" + v + "' is not a whole number from 0 to 9999999999999999999");
      s.seed = std::stoull(v);
      s.seed_given = true;
    }
    else if (a == "--profile") s.profile = parse_profile(value());
    else if (a == "--env") {
      const std::string e = value();
      if (e.find('=') == std::string::npos || e.front() == '=')
        throw UsageError("malformed --env '" + e + "' (expected NAME=VALUE)");
      s.env.push_back(e);
    } else if (a == "--jobs") {
      const std::string v = value();
      const std::optional<long long> jobs = parse_integer(v, 1, kMaxJobs);
      if (!jobs)
        throw UsageError("--jobs '" + v + "' is not a whole number from 1 to " +
                         std::to_string(kMaxJobs));
      s.jobs = static_cast<int>(*jobs);
    } else if (a == "--timeout") {
      const std::string v = value();
      const std::optional<double> seconds = parse_number(v, 0, kMaxTimeoutSeconds);
      if (!seconds || !(*seconds > 0))
        throw UsageError("--timeout '" + v + "' is not a number of seconds > 0 and <= " +
                         std::to_string(static_cast<int>(kMaxTimeoutSeconds)));
      s.timeout = *seconds;
    } else if (a == "--help" || a == "-h") {
      s.help = true;
      return s;
    } else {
      throw UsageError("unknown option '" + a + "' (try --help)");
    }
  }
  if (s.mode == Settings::Mode::kNone) throw UsageError("nothing to grade: give --build DIR, --images DIR or --class DIR (try --help)");
  if (s.mode != Settings::Mode::kClass && !s.csv.empty()) throw UsageError("--csv goes with --class");
  if (s.mode == Settings::Mode::kImages && s.hidden > 0)
    throw UsageError("--hidden needs programs to render: a build or a class, not --images");
  if (s.seed_given && s.hidden == 0) throw UsageError("--seed goes with --hidden N");
  if (s.csv.empty()) s.csv = "class.csv";
  return s;
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f%%", 100 * share);
  return text;
}

// ---- progress and the table --------------------------------------------------------

class Console {
 public:
  explicit Console(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO)) {}
  void operator()(const ProgressEvent& e) {
    if (quiet_) return;
    if (tty_) {
      // One line, rewritten: "[ 23/98] 15_bspline_curves__knot_insertion"
      std::fprintf(stderr, "\r\033[K[%3d/%d] %s %s", e.done, e.total, e.finished ? "done" : "rendering",
                   e.view->name().c_str());
      if (e.done == e.total && e.finished) std::fputs("\r\033[K", stderr);
    } else if (e.finished) {
      std::fprintf(stderr, "[%d/%d] %s %s\n", e.done, e.total, e.finished->passed ? "pass" : "FAIL",
                   e.view->name().c_str());
    }
    std::fflush(stderr);
  }

 private:
  bool quiet_, tty_;
};

void print_table(const Grade& g) {
  std::size_t width = 4;
  for (const ViewResult& v : g.views) width = std::max(width, v.id.name().size());
  std::printf("%-*s  %-6s %10s %9s %9s %9s  %s\n", int(width), "view", "result", "differing", "max delta",
              "unexcused", "shifted", "score (pass <= 1)");
  for (const ViewResult& v : g.views) {
    if (v.comparison) {
      const gllab::Comparison& c = *v.comparison;
      std::printf("%-*s  %-6s %10s %9d %9lld %9lld  %.3g\n", int(width), v.id.name().c_str(),
                  v.passed ? "pass" : "FAIL", percent(c.differing_share()).c_str(), c.max_delta,
                  c.mismatched_pixels, c.shifted_pixels(), v.score);
    } else {
      std::printf("%-*s  %-6s %10s %9s %9s %9s  %s\n", int(width), v.id.name().c_str(), v.passed ? "pass" : "FAIL",
                  "-", "-", "-", "-", v.id.error_view ? "error view" : "-");
    }
    if (!v.passed) std::printf("    %s\n", v.reason.c_str());
  }
}

std::string lab_summary(const Grade& g) {
  std::string text;
  for (const auto& [lab, counts] : g.by_lab())
    if (counts.first != counts.second)
      text += (text.empty() ? "" : ", ") + lab + " " + std::to_string(counts.first) + "/" + std::to_string(counts.second);
  return text.empty() ? "every lab complete" : "incomplete: " + text;
}

std::string metric_text(const Judgement& j) {
  const Tolerance& t = j.tolerance;
  char text[600];
  std::snprintf(text, sizeof text,
                "profile %s: a pixel differs when a channel is off by more than %d, unless a %d-pixel shift explains "
                "it on a thin feature (a neighbour %d or more apart); a view passes when at most %s of its pixels "
                "differ unexcused and at most %s are excused, and its text agrees (numbers within %g relative)",
                profile_name(j.profile), t.channel_threshold, t.shift_radius, t.edge_contrast,
                percent(t.max_differing_share).c_str(), percent(t.max_shifted_share).c_str(), j.text_relative);
  return text;
}

void print_summary(const Grade& g, const Judgement& j) {
  const int total = static_cast<int>(g.views.size()), passed = g.passed();
  std::printf("%d views: %d passed, %d failed; score %.1f%% (%s)\n", total, passed, total - passed, g.score(),
              lab_summary(g).c_str());
  std::printf("%s\n", metric_text(j).c_str());
}

// ---- files -------------------------------------------------------------------------

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string reason(int error) { return error ? std::strerror(error) : "an earlier write failed"; }

// Writes a file whole or not at all: into a temporary file beside it, renamed
// over it when complete; the temporary file is removed on every failure.
// Through a symlink, the file it names is replaced; a path that names no
// regular file (/dev/stdout, /dev/null, a FIFO) is written in place, since a
// rename would replace the device; a directory is an error.
void write_text(const fs::path& path, const std::string& text) {
  std::error_code ec;
  fs::path file = path;
  if (fs::exists(path, ec)) {
    const fs::path target = fs::canonical(path, ec);
    if (!ec) file = target;
  }
  if (fs::is_directory(file, ec))
    throw UsageError("cannot write " + path.string() + ": it is a directory");
  if (fs::exists(file, ec) && !fs::is_regular_file(file, ec)) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw UsageError("cannot write " + path.string() + " (" + reason(errno) + ")");
    return;
  }
  const fs::path tmp =
      file.parent_path() / ("." + file.filename().string() + ".tmp-" + std::to_string(getpid()));
  struct Remove {
    const fs::path& tmp;
    bool done = false;
    ~Remove() {
      std::error_code ignored;
      if (!done) fs::remove(tmp, ignored);
    }
  } cleanup{tmp};
  {
    errno = 0;
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw UsageError("cannot write " + path.string() + " (" + reason(errno) + ")");
    out << text;
    out.close();  // a full disk may only show here
    if (!out) throw UsageError("cannot write " + path.string() + " (" + reason(errno) + ")");
  }
  fs::rename(tmp, file, ec);
  if (ec) throw UsageError("cannot write " + path.string() + " (" + ec.message() + ")");
  cleanup.done = true;
}

// A folder to write into: made when missing; an error when something else is there.
void make_folder(const std::string& option, const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw UsageError(option + " " + dir.string() + " is not a folder");
  fs::create_directories(dir, ec);
  if (ec)
    throw UsageError(option + " " + dir.string() + ": cannot make the folder (" + ec.message() +
                     ")");
}

// Where the results go, checked before any grading: a target that cannot be
// written must not cost a whole class's renders.
void check_targets(const Settings& s) {
  std::error_code ec;
  const auto not_a_folder = [&](const char* option, const fs::path& dir) {
    if (!dir.empty() && fs::exists(dir, ec) && !fs::is_directory(dir, ec))
      throw UsageError(std::string(option) + " " + dir.string() + " is not a folder");
  };
  not_a_folder("--out", s.out);
  not_a_folder("--report", s.report);
  if (s.mode == Settings::Mode::kClass) {
    if (fs::is_directory(s.csv, ec))
      throw UsageError("--csv " + s.csv.string() + " is a directory");
    const fs::path parent = s.csv.parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
      throw UsageError("--csv " + s.csv.string() + ": no folder " + parent.string());
  }
}

// Failing renders and their heat maps, for the student to look at.
void write_failures(const Grade& g, const Settings& s, const Tolerance& t,
                    const References& references) {
  bool any = false;
  for (const ViewResult& v : g.views) {
    if (v.passed || !v.submission) continue;
    if (!any) make_folder("--out", s.out), any = true;
    const gllab::Image& reference = references.at(v.id.name()).image;
    gllab::write_png((s.out / (v.id.name() + ".png")).string(), *v.submission, 1);
    if (v.comparison)
      gllab::write_png((s.out / (v.id.name() + ".diff.png")).string(),
                       gllab::heat_map(reference, *v.submission, t.channel_threshold, t.shift_radius,
                                       t.edge_contrast),
                       1);
  }
  if (any) std::printf("failing renders and heat maps (<view>.diff.png): %s/\n", s.out.c_str());
}

nlohmann::ordered_json view_json(const ViewResult& v) {
  nlohmann::ordered_json j;
  j["lab"] = v.id.lab;
  j["view"] = v.id.view;
  j["kind"] = v.id.error_view ? "error" : "image";
  j["result"] = v.passed ? "pass" : "fail";
  j["reason"] = v.reason;
  j["text"] = v.text_reason.empty() ? nullptr : nlohmann::ordered_json(v.text_reason);
  if (v.comparison) {
    j["score"] = v.score;
    j["differing_pixels"] = v.comparison->differing_pixels;
    j["differing_share"] = v.comparison->differing_share();
    j["unexcused_pixels"] = v.comparison->mismatched_pixels;
    j["shifted_pixels"] = v.comparison->shifted_pixels();
    j["max_delta"] = v.comparison->max_delta;
  } else {
    j["score"] = j["differing_pixels"] = j["differing_share"] = j["unexcused_pixels"] = j["shifted_pixels"] =
        j["max_delta"] = nullptr;
  }
  j["seconds"] = std::round(v.seconds * 1000) / 1000;
  return j;
}

void write_report(const Grade& g, const std::vector<HiddenResult>& hidden, const fs::path& dir,
                  const fs::path& refs, const References& references, const Judgement& judge,
                  const std::string& failed_build = "", const std::string& log_tail = "") {
  const Tolerance& t = judge.tolerance;
  for (const char* sub : {"reference", "submission", "heat_map"})
    make_folder("--report", dir / sub);
  // Failures first, then by name.
  std::vector<const ViewResult*> rows;
  for (const ViewResult& v : g.views) rows.push_back(&v);
  std::stable_sort(rows.begin(), rows.end(), [](const ViewResult* a, const ViewResult* b) { return !a->passed && b->passed; });

  nlohmann::ordered_json json;
  json["submission"] = g.submission;
  json["views"] = g.views.size();
  json["passed"] = g.passed();
  json["score"] = g.score();
  json["profile"] = profile_name(judge.profile);
  json["tolerance"] = {{"channel_threshold", t.channel_threshold}, {"shift_radius", t.shift_radius},
                       {"edge_contrast", t.edge_contrast}, {"max_unexcused_share", t.max_differing_share},
                       {"max_shifted_share", t.max_shifted_share}, {"text_relative", judge.text_relative},
                       {"text_absolute", judge.text_absolute}};
  json["results"] = nlohmann::ordered_json::array();
  json["hidden"] = nlohmann::ordered_json::array();
  for (const HiddenResult& h : hidden) {
    nlohmann::ordered_json v = view_json(h.result);
    v["hidden"] = h.pass;
    v["inputs"] = h.sets;
    json["hidden"].push_back(v);
  }
  std::string csv = "lab,view,result,score,differing_share,unexcused_pixels,shifted_pixels,max_delta,reason\n";
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>gllab grade</title>\n"
       << "<style>body{font-family:sans-serif;margin:1.5em;background:#fafafa}"
       << "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px;vertical-align:top}"
       << "tr.fail td.result{background:#f8d0d0;font-weight:bold}tr.pass td.result{background:#d6f0d6}"
       << "img{width:192px;height:192px;image-rendering:pixelated;display:block}"
       << ".none{width:192px;height:192px;display:flex;align-items:center;justify-content:center;background:#eee;color:#555}"
       << "</style></head><body>\n<h1>gllab grade</h1>\n<p>Submission: <code>" << html_escape(g.submission)
       << "</code>. " << g.views.size() << " views, " << g.passed() << " passed, "
       << g.views.size() - g.passed() << " failed; score " << std::round(g.score() * 10) / 10 << "%.</p>\n"
       << "<p>Metric, " << html_escape(metric_text(judge)) << ". The score is the larger share in units of its "
       << "limit. Heat map: grey = equal, blue = excused by the shift, yellow to red = differs.</p>\n";
  if (!failed_build.empty())
    html << "<p class=\"build\"><b>The build failed:</b> " << html_escape(failed_build) << "</p>\n<pre>"
         << html_escape(log_tail) << "</pre>\n";
  if (!hidden.empty()) {
    int passed = 0;
    for (const HiddenResult& h : hidden) passed += h.result.passed ? 1 : 0;
    html << "<h2>Hidden inputs</h2>\n<p>" << hidden.size() << " renders with drawn parameters and points, "
         << passed << " passed; each is judged against the instructor's build rendering the same inputs. "
         << "Render a failing one again with the inputs shown.</p>\n<table>\n<tr><th>view</th><th>hidden</th>"
         << "<th>result</th><th>inputs</th><th>reference</th><th>submission</th><th>heat map</th></tr>\n";
    for (const HiddenResult& h : hidden) {
      if (h.result.passed) continue;
      const std::string folder = "hidden" + std::to_string(h.pass), name = h.result.id.name() + ".png";
      make_folder("--report", dir / folder);
      const bool has_reference = fs::exists(h.refs / name);
      if (has_reference) fs::copy_file(h.refs / name, dir / folder / ("reference_" + name), fs::copy_options::overwrite_existing);
      const bool has_render = h.result.submission.has_value();
      if (has_render) gllab::write_png((dir / folder / name).string(), *h.result.submission, 1);
      if (has_render && h.result.comparison)
        gllab::write_png((dir / folder / ("heat_" + name)).string(),
                         gllab::heat_map(gllab::read_png((h.refs / name).string()), *h.result.submission,
                                         t.channel_threshold, t.shift_radius, t.edge_contrast), 1);
      const auto img = [&](bool present, const std::string& file, const std::string& missing) {
        return present ? "<td><img src=\"" + folder + "/" + file + "\" alt=\"" + file + "\"></td>"
                       : "<td><div class=\"none\">" + missing + "</div></td>";
      };
      html << "<tr class=\"fail\"><td><code>" << html_escape(h.result.id.name()) << "</code><br>"
           << html_escape(h.result.reason) << "</td><td>" << h.pass << "</td><td class=\"result\">FAIL</td><td><code>"
           << html_escape(h.sets) << "</code></td>" << img(has_reference, "reference_" + name, "exit 1")
           << img(has_render, name, "no render") << img(has_render && h.result.comparison.has_value(), "heat_" + name, "not compared")
           << "</tr>\n";
    }
    html << "</table>\n<h2>The views</h2>\n";
  }
  html << "<table>\n"
       << "<tr><th>view</th><th>result</th><th>score (pass &le; 1)</th><th>reference</th><th>submission</th>"
       << "<th>heat map</th></tr>\n";
  for (const ViewResult* v : rows) {
    const std::string name = v->id.name() + ".png";
    const bool has_reference = !v->id.error_view;
    if (has_reference) fs::copy_file(refs / name, dir / "reference" / name, fs::copy_options::overwrite_existing);
    const bool has_render = v->submission.has_value();
    if (has_render) gllab::write_png((dir / "submission" / name).string(), *v->submission, 1);
    if (has_render && v->comparison)
      gllab::write_png((dir / "heat_map" / name).string(),
                       gllab::heat_map(references.at(v->id.name()).image, *v->submission,
                                       t.channel_threshold, t.shift_radius, t.edge_contrast),
                       1);
    const auto cell = [&](bool present, const std::string& folder, const std::string& missing) {
      return present ? "<td><a href=\"" + folder + "/" + name + "\"><img src=\"" + folder + "/" + name + "\" alt=\"" +
                           folder + " " + v->id.name() + "\"></a></td>"
                     : "<td><div class=\"none\">" + missing + "</div></td>";
    };
    char score[32] = "-";
    if (v->comparison) std::snprintf(score, sizeof score, "%.3g", v->score);
    html << "<tr class=\"" << (v->passed ? "pass" : "fail") << "\"><td><code>" << html_escape(v->id.name())
         << "</code>" << (v->reason.empty() ? "" : "<br>" + html_escape(v->reason)) << "</td><td class=\"result\">"
         << (v->passed ? "pass" : "FAIL") << "</td><td>" << (v->id.error_view ? "error view" : score) << "</td>"
         << cell(has_reference, "reference", "no image: it must exit 1")
         << cell(has_render, "submission", v->id.error_view ? "exit 1" : "no render")
         << cell(has_render && v->comparison.has_value(), "heat_map", "not compared") << "</tr>\n";
    json["results"].push_back(view_json(*v));
    const nlohmann::ordered_json& j = json["results"].back();
    const auto number = [](const nlohmann::ordered_json& x) { return x.is_null() ? std::string() : x.dump(); };
    csv += csv_field(v->id.lab) + "," + csv_field(v->id.view) + "," + (v->passed ? "pass" : "fail") + "," +
           number(j["score"]) + "," + number(j["differing_share"]) + "," + number(j["unexcused_pixels"]) + "," +
           number(j["shifted_pixels"]) + "," + number(j["max_delta"]) + "," + csv_field(v->reason) + "\n";
  }
  // The page checks its own images once loaded (the test reads the title).
  html << "</table>\n<script>window.addEventListener('load',function(){var i=document.images,ok=0;"
          "for(var k=0;k<i.length;k++)if(i[k].complete&&i[k].naturalWidth>0)ok++;"
          "document.title='gllab grade: images '+ok+'/'+i.length+' loaded';});</script>\n</body></html>\n";
  write_text(dir / "index.html", html.str());
  write_text(dir / "results.json", json.dump(2) + "\n");
  write_text(dir / "results.csv", csv);
  std::printf("report: %s (results.json, results.csv)\n", (dir / "index.html").c_str());
}

// ---- hidden inputs -------------------------------------------------------------------

// An exclusive lock on a file (flock), held while the object lives: labgrade
// processes sharing a --work folder make its shared parts once.
class Lock {
 public:
  explicit Lock(const fs::path& file) : fd_(open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0 || flock(fd_, LOCK_EX) != 0)
      throw UsageError("cannot lock " + file.string() + " (" + std::strerror(errno) + ")");
  }
  ~Lock() { close(fd_); }
  Lock(const Lock&) = delete;
  Lock& operator=(const Lock&) = delete;

 private:
  int fd_;
};

// One hidden pass: every lab's drawn inputs, and the reference build's renders of them.
struct HiddenPass {
  int index = 0;                                          // 1..N
  std::map<std::string, std::vector<std::string>> sets;   // --set values, per lab
  fs::path refs;                                          // WORK/hidden/<index>/
  std::vector<ViewId> views;                              // what the reference drew or refused
  References references;
};

// "--set t=0.412 --set P[0]=1,2": how a student renders a hidden input again.
std::string sets_text(const std::vector<std::string>& sets) {
  std::string text;
  for (const std::string& v : sets) text += (text.empty() ? "" : " ") + std::string("--set ") + v;
  return text;
}

// The folder of this labgrade program: a build, whose lab programs are the
// default reference for hidden inputs.
fs::path own_build() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

fs::path lab_program(const fs::path& build, const std::string& lab) {
  for (const fs::path& p : {build / lab, build / "bin" / lab})
    if (fs::is_regular_file(p)) return p;
  return {};
}

// Draws the hidden inputs and renders their references with the instructor's
// build (trusted: it runs without the sandbox), into WORK/hidden/<k>/.
std::vector<HiddenPass> prepare_hidden(const Settings& s, const std::vector<ViewId>& views, const Manifest& m) {
  std::vector<HiddenPass> passes;
  if (s.hidden == 0) return passes;
  const fs::path ref = s.reference_build.empty() ? own_build() : s.reference_build;
  if (ref.empty() || !looks_like_build(ref))
    throw UsageError("--reference-build " + ref.string() + " holds no lab programs (give the instructor's build)");
  std::vector<std::string> labs;
  for (const ViewId& v : views)
    if (labs.empty() || labs.back() != v.lab) labs.push_back(v.lab);
  // The references of these inputs are rendered once per --work folder and
  // kept: WORK/hidden/<key>/<k>/, the key naming the seed, N, the labs, the
  // reference programs (path, size, time), the views and --env, so that
  // labgrade processes grading one student each (README "A class on many
  // machines", examples/grade_class_parallel.sh) share them.
  std::string key = std::to_string(s.seed) + " " + std::to_string(s.hidden) + " " + fs::absolute(ref).string();
  for (const ViewId& v : views) key += " " + v.name();
  for (const std::string& e : s.env) key += " env " + e;
  for (const std::string& lab : labs) {
    const fs::path program = lab_program(ref, lab);
    if (program.empty()) throw UsageError("--reference-build " + ref.string() + " has no program " + lab);
    std::error_code ec;
    key += " " + lab + " " + std::to_string(fs::file_size(program, ec)) + " " +
           std::to_string(fs::last_write_time(program, ec).time_since_epoch().count());
  }
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a
  for (unsigned char c : key) hash = (hash ^ c) * 1099511628211ull;
  char name[32];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(hash));
  const fs::path root = s.work / "hidden" / name;
  make_folder("--work", root);
  const Lock lock(root / ".lock");
  const bool made = fs::exists(root / "complete");
  passes.resize(static_cast<std::size_t>(s.hidden));
  for (int k = 0; k < s.hidden; ++k) {
    passes[k].index = k + 1;
    passes[k].refs = root / std::to_string(k + 1);
    if (!made) {
      std::error_code ec;
      fs::remove_all(passes[k].refs, ec);
      make_folder("--work", passes[k].refs);
    }
  }
  for (const std::string& lab : labs) {
    const fs::path program = lab_program(ref, lab);
    if (program.empty()) throw UsageError("--reference-build " + ref.string() + " has no program " + lab);
    const gllab::ProcessResult r = gllab::run_process({program.string(), "--list-params"}, {}, s.timeout);
    if (r.exit_status != 0)
      throw UsageError(program.string() + " --list-params failed: " + gllab::first_line(r.err));
    const auto draws = hidden_sets(parse_lab_inputs(r.out, lab), lab, s.hidden, s.seed);
    for (int k = 0; k < s.hidden; ++k) passes[k].sets[lab] = draws[static_cast<std::size_t>(k)];
  }
  for (HiddenPass& pass : passes) {
    if (made) {
      pass.views = reference_views(pass.refs);
      pass.references = read_references(pass.refs, pass.views, &m);
      continue;
    }
    RenderSettings rs;
    rs.env = s.env;
    rs.timeout_seconds = s.timeout;
    rs.sets = pass.sets;
    const std::unique_ptr<Source> source = build_source(ref, rs);
    for (const std::string& lab : labs) {
      std::vector<ViewId> of_lab;
      for (const ViewId& v : views)
        if (v.lab == lab) of_lab.push_back(v);
      std::vector<Obtained> got = source->obtain_batch(of_lab);
      for (std::size_t i = 0; i < of_lab.size(); ++i) {
        const fs::path base = pass.refs / of_lab[i].name();
        Obtained& o = got[i];
        if (o.image) {
          gllab::write_png(base.string() + ".png", *o.image, 1);
          if (o.text) {
            std::string text;
            for (const std::string& line : *o.text) text += line + "\n";
            write_text(base.string() + ".txt", text);
          }
        } else if (o.exit_status == 1 && !o.error.empty()) {
          write_text(base.string() + ".error", o.error + "\n");  // the lab refuses these inputs
        } else {
          std::fprintf(stderr, "labgrade: hidden %d: the reference build cannot render %s (%s): not graded\n",
                       pass.index, of_lab[i].name().c_str(), o.error.c_str());
        }
      }
    }
    std::error_code ec;
    if (fs::is_empty(pass.refs, ec)) throw UsageError("hidden " + std::to_string(pass.index) + ": the reference build rendered nothing");
    pass.views = reference_views(pass.refs);
    pass.references = read_references(pass.refs, pass.views, &m);
  }
  if (!made) write_text(root / "complete", key + "\n");
  return passes;
}

// ---- modes ---------------------------------------------------------------------------

Grade grade_one(const Source& source, const std::vector<ViewId>& views,
                const References& references, const Settings& s, const Judgement& j,
                bool keep_images) {
  Console console(s.quiet);
  return grade(source, views, references, j, s.jobs, keep_images,
               [&](const ProgressEvent& e) { console(e); });
}

// A folder of images cannot show how a program exits: its error views are
// graded from builds only, and said so.
std::vector<ViewId> gradable(const std::vector<ViewId>& views, bool build, bool quiet) {
  if (build) return views;
  std::vector<ViewId> out;
  for (const ViewId& v : views)
    if (!v.error_view) out.push_back(v);
  if (out.size() != views.size() && !quiet)
    std::printf("%zu error view%s not graded: a folder of images cannot show an exit status (grade a build)\n",
                views.size() - out.size(), views.size() - out.size() == 1 ? "" : "s");
  if (out.empty()) throw UsageError("no view to grade from images: every view selected is an error view");
  return out;
}

Judgement judgement_for(const Settings& s, const Manifest& m, bool build) {
  return judgement(m, s.profile ? *s.profile : build ? Profile::kBuild : Profile::kImages);
}

// A student's renders and hidden renders.
struct Graded {
  Grade visible;
  std::vector<HiddenResult> hidden;
  int hidden_passed() const {
    return static_cast<int>(std::count_if(hidden.begin(), hidden.end(), [](const HiddenResult& h) { return h.result.passed; }));
  }
};

Graded grade_build(const fs::path& dir, const Settings& s, const std::vector<ViewId>& views,
                   const References& references, const Judgement& j,
                   const std::vector<HiddenPass>& passes, const Launcher& launch, const fs::path& scratch) {
  RenderSettings rs;
  rs.env = s.env;
  rs.timeout_seconds = s.timeout;
  rs.launch = launch;
  rs.scratch = scratch;
  Graded out;
  out.visible = grade_one(*build_source(dir, rs), views, references, s, j, !s.report.empty());
  // A lab none of whose views rendered (no program, a crash at start, a
  // sandbox limit) is not rendered again for its hidden inputs: they fail
  // with that reason, and a broken submission costs one pass, not N + 1.
  std::map<std::string, std::string> broken;  // lab: the reason of its first view
  std::set<std::string> drew;
  for (const ViewResult& v : out.visible.views) {
    if (v.comparison || v.passed) drew.insert(v.id.lab);
    else broken.emplace(v.id.lab, v.reason);
  }
  for (const std::string& lab : drew) broken.erase(lab);
  for (const HiddenPass& pass : passes) {
    rs.sets = pass.sets;
    std::vector<ViewId> views;
    for (const ViewId& v : pass.views) {
      if (!broken.count(v.lab)) {
        views.push_back(v);
        continue;
      }
      ViewResult skipped;
      skipped.id = v;
      skipped.reason = "not rendered: " + broken.at(v.lab);
      out.hidden.push_back({skipped, pass.index, sets_text(pass.sets.at(v.lab)), pass.refs});
    }
    if (views.empty()) continue;
    const Grade g = grade_one(*build_source(dir, rs), views, pass.references, s, j, !s.report.empty());
    for (const ViewResult& v : g.views)
      out.hidden.push_back({v, pass.index, sets_text(pass.sets.at(v.id.lab)), pass.refs});
  }
  return out;
}

// program: how the student names the lab programs ("build/bin" for a tree).
void print_hidden(const Graded& g, const std::string& program_dir) {
  if (g.hidden.empty()) return;
  std::printf("hidden inputs: %d of %zu renders passed\n", g.hidden_passed(), g.hidden.size());
  for (const HiddenResult& h : g.hidden) {
    if (h.result.passed) continue;
    std::printf("  hidden %d %s FAIL: %s\n    again: %s/%s --headless --view %s %s\n", h.pass, h.result.id.name().c_str(),
                h.result.reason.c_str(), program_dir.c_str(), h.result.id.lab.c_str(), h.result.id.view.c_str(),
                h.sets.c_str());
  }
}

int run_single(const Settings& s, const std::vector<ViewId>& all, const Manifest& m,
               const References& references) {
  const bool build = s.mode == Settings::Mode::kBuild;
  const std::vector<ViewId> views = gradable(all, build, s.quiet);
  const Judgement j = judgement_for(s, m, build);
  if (!build) {
    const std::unique_ptr<Source> source = image_source(s.input);
    const Grade g = grade_one(*source, views, references, s, j, !s.report.empty());
    if (!s.quiet) print_table(g);
    print_summary(g, j);
    write_failures(g, s, j.tolerance, references);
    if (!s.report.empty()) write_report(g, {}, s.report, s.refs, references, j);
    return g.passed() == static_cast<int>(g.views.size()) ? 0 : 1;
  }
  const std::vector<HiddenPass> passes = prepare_hidden(s, views, m);
  const Graded g = grade_build(s.input, s, views, references, j, passes, nullptr, {});
  if (!s.quiet) print_table(g.visible);
  print_summary(g.visible, j);
  print_hidden(g, s.input.string());
  write_failures(g.visible, s, j.tolerance, references);
  if (!s.report.empty()) write_report(g.visible, g.hidden, s.report, s.refs, references, j);
  const bool all_passed = g.visible.passed() == static_cast<int>(g.visible.views.size()) &&
                          g.hidden_passed() == static_cast<int>(g.hidden.size());
  return all_passed ? 0 : 1;
}

// The sandbox for a student's renders: its build read-only, the scratch
// folder for the text writable; the limits of one render.
Launcher sandboxed_renders(const fs::path& build, const fs::path& scratch) {
  return [build = fs::absolute(build), scratch = fs::absolute(scratch)](
             const std::vector<std::string>& argv, const std::vector<std::string>& env,
             const gllab::ProcessLimits& limits) {
    gllab::Sandbox box;
    box.mounts = {{build, build, false}, {scratch, scratch, true}};
    box.env = env;
    box.chdir = scratch;
    box.limits = gllab::render_limits();
    box.limits.wall_seconds = limits.timeout_seconds;
    box.limits.max_output_bytes = limits.max_output_bytes;
    gllab::SandboxResult r = gllab::run_sandboxed(argv, box);
    r.process.limit_hit = r.limit_hit;
    return r.process;
  };
}

struct Row {
  std::string student, kind, build = "-", reason;
  Graded graded;
  double build_seconds = 0;
  std::optional<CacheStats> cache;
  std::string log_tail;
};

std::string fixed1(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

// DIR/index.html: a row per student, linking to the student's page.
void write_class_index(const std::vector<Row>& rows, std::size_t passes, const fs::path& dir) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>gllab class</title>\n"
       << "<style>body{font-family:sans-serif;margin:1.5em;background:#fafafa}"
       << "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px;vertical-align:top}"
       << "td.full{background:#d6f0d6}td.part{background:#f8d0d0}</style></head><body>\n"
       << "<h1>gllab class</h1>\n<p>" << rows.size() << " submissions" << (passes ? ", " + std::to_string(passes) +
                                                                             " hidden inputs per view" : "")
       << ". A student's page shows every failing render beside its reference.</p>\n<table>\n"
       << "<tr><th>student</th><th>kind</th><th>build</th><th>views passed</th><th>hidden passed</th>"
       << "<th>score</th><th>why</th></tr>\n";
  for (const Row& row : rows) {
    const Graded& g = row.graded;
    const int renders = static_cast<int>(g.visible.views.size() + g.hidden.size());
    const int passed = g.visible.passed() + g.hidden_passed();
    const std::string why = !row.reason.empty() ? row.reason : lab_summary(g.visible);
    html << "<tr><td><a href=\"" << html_escape(row.student) << "/index.html\">" << html_escape(row.student)
         << "</a></td><td>" << row.kind << "</td><td>" << row.build
         << (row.cache ? " (" + fixed1(row.build_seconds) + " s, cache " + fixed1(100 * row.cache->hit_rate()) + "%)" : "")
         << "</td><td>" << g.visible.passed() << "/" << g.visible.views.size() << "</td><td>" << g.hidden_passed()
         << "/" << g.hidden.size() << "</td><td class=\"" << (passed == renders ? "full" : "part") << "\">"
         << fixed1(renders ? 100.0 * passed / renders : 0) << "%</td><td>" << html_escape(why) << "</td></tr>\n";
  }
  html << "</table>\n<script>document.title='gllab class: '+(document.querySelectorAll('tr').length-1)+' students';"
          "</script>\n</body></html>\n";
  make_folder("--report", dir);
  write_text(dir / "index.html", html.str());
  std::printf("class report: %s\n", (dir / "index.html").c_str());
}

int run_class(const Settings& s, const std::vector<ViewId>& all, const Manifest& m,
              const References& references) {
  if (!fs::is_directory(s.input)) throw UsageError("no class folder " + s.input.string());
  std::vector<fs::path> students;
  for (const auto& entry : fs::directory_iterator(s.input))
    if (entry.is_directory()) students.push_back(entry.path());
  std::sort(students.begin(), students.end());
  if (students.empty()) throw UsageError("no submission folders in " + s.input.string());
  std::vector<std::string> labs;
  for (const ViewId& v : all)
    if (labs.empty() || labs.back() != v.lab) labs.push_back(v.lab);

  // Student code runs in the sandbox, or not at all unless --no-sandbox.
  const bool any_code = std::any_of(students.begin(), students.end(), [](const fs::path& p) {
    return looks_like_source(p) || looks_like_build(p);
  });
  if (any_code && s.sandbox) {
    const std::string why = gllab::sandbox_unavailable_reason();
    if (!why.empty())
      throw UsageError("cannot run student code in the sandbox: " + why +
                       " (--no-sandbox runs it with your own rights)");
  }
  const ClassWork work{fs::absolute(s.work)};
  if (any_code) make_folder("--work", work.root);
  const std::vector<HiddenPass> passes = prepare_hidden(s, all, m);

  // The base compiler cache: the instructor's tree built once per --work folder.
  const bool any_source = std::any_of(students.begin(), students.end(), [](const fs::path& p) { return looks_like_source(p); });
  TreeBuildSettings tb;
  tb.labs = labs;
  tb.jobs = std::clamp(s.jobs, 1, 8);  // build_limits() allows 256 processes: 5-6 per job
  tb.sandboxed = s.sandbox;
  tb.limits = gllab::build_limits();
  const fs::path seeded = work.root / "ccache" / "base.seeded";
  std::optional<Lock> seeding;
  if (any_source) {
    make_folder("--work", work.root / "ccache");
    seeding.emplace(work.root / "ccache" / "base.lock");
  }
  if (any_source && !fs::exists(seeded)) {
    const fs::path tree = fs::path(GLLAB_REFERENCE_DIR).parent_path();
    std::printf("compiler cache: building the instructor's tree %s once, into %s\n", tree.c_str(),
                work.base_cache().c_str());
    std::fflush(stdout);
    // A copy in WORK: the sandbox's user (nobody, when labgrade runs as root)
    // may not reach the tree where it is (under /root), and the copy does not
    // change while the class is graded.
    const fs::path copy = work.root / "seed-src";
    std::error_code ec;
    fs::remove_all(copy, ec);
    make_folder("--work", copy);
    for (const auto& e : fs::directory_iterator(tree)) {
      const std::string name = e.path().filename().string();
      if (name == ".git" || name.rfind("build", 0) == 0 || name == "reference_images" || name == "out" ||
          fs::equivalent(e.path(), work.root, ec))
        continue;
      fs::copy(e.path(), copy / name, fs::copy_options::recursive, ec);
      if (ec) throw UsageError("cannot copy the instructor's tree into " + copy.string() + " (" + ec.message() + ")");
    }
    const TreeBuild seed = build_tree(copy, work.root / "seed", work.own_cache(".seed"), work.base_cache(), tb, true);
    if (!seed.ok) throw UsageError("the instructor's tree does not build: " + seed.reason + "\n" + seed.log_tail);
    write_text(seeded, "built in " + fixed1(seed.seconds) + " s\n");
    fs::remove_all(work.root / "seed", ec);  // the objects are in the cache now
    fs::remove_all(copy, ec);
    std::printf("compiler cache: seeded in %.1f s (%lld objects)\n", seed.seconds, seed.cache.misses);
  }
  seeding.reset();

  std::vector<Row> rows;
  bool all_passed = true;
  for (const fs::path& student : students) {
    Row row;
    row.student = student.filename().string();
    const bool source = looks_like_source(student), build = source || looks_like_build(student);
    row.kind = source ? "source" : build ? "build" : "images";
    const std::vector<ViewId> views = gradable(all, build, true);
    const Judgement j = judgement_for(s, m, build);
    fs::path programs = student;
    bool graded = true;
    if (source) {
      const TreeBuild b = build_tree(student, work.builds() / row.student, work.own_cache(row.student),
                                     work.base_cache(), tb);
      make_folder("--work", work.root / "logs");
      write_text(work.root / "logs" / (row.student + ".log"), b.log);
      row.build_seconds = b.seconds;
      row.cache = b.cache;
      row.build = b.ok ? "built" : "failed";
      programs = program_dir(b);
      if (!b.ok) {
        graded = false;
        row.reason = b.reason;
        row.log_tail = b.log_tail;
      }
    }
    if (graded && build) {
      const fs::path scratch = work.root / "scratch" / row.student;
      std::error_code ec;
      fs::remove_all(scratch, ec);
      make_folder("--work", scratch);
      const Launcher launch = s.sandbox ? sandboxed_renders(programs, scratch) : Launcher();
      row.graded = grade_build(programs, s, views, references, j, passes, launch, s.sandbox ? scratch : fs::path());
    } else if (graded) {
      row.graded.visible = grade_one(*image_source(student), views, references, s, j, !s.report.empty());
    } else {
      row.graded.visible.submission = student.string();
      for (const ViewId& v : views) {
        ViewResult failed;
        failed.id = v;
        failed.reason = "not built: " + row.reason;
        row.graded.visible.views.push_back(failed);
      }
      for (const HiddenPass& pass : passes)
        for (const ViewId& v : pass.views) {
          ViewResult failed;
          failed.id = v;
          failed.reason = "not built: " + row.reason;
          row.graded.hidden.push_back({failed, pass.index, sets_text(pass.sets.at(v.lab)), pass.refs});
        }
    }
    if (source) {  // 76 MB of objects and programs a student: only the log and the cache stay
      std::error_code ec;
      fs::remove_all(work.builds() / row.student, ec);
    }
    const Graded& g = row.graded;
    const int renders = static_cast<int>(g.visible.views.size() + g.hidden.size());
    const int passed = g.visible.passed() + g.hidden_passed();
    all_passed = all_passed && passed == renders;
    std::printf("%-24s %-6s %3d/%zu views", row.student.c_str(), row.kind.c_str(), g.visible.passed(),
                g.visible.views.size());
    if (!passes.empty()) std::printf("  hidden %3d/%zu", g.hidden_passed(), g.hidden.size());
    std::printf("  score %5.1f%%", renders ? 100.0 * passed / renders : 0.0);
    if (source && row.cache)
      std::printf("  build %.1f s, cache %.0f%%", row.build_seconds, 100 * row.cache->hit_rate());
    std::printf("  (%s)\n", row.reason.empty() ? lab_summary(g.visible).c_str() : row.reason.c_str());
    if (!row.log_tail.empty() && !s.quiet) std::printf("%s\n", row.log_tail.c_str());
    if (!s.quiet) print_hidden(g, source ? "build/bin" : programs.string());
    std::fflush(stdout);
    if (!s.report.empty())
      write_report(g.visible, g.hidden, s.report / row.student, s.refs, references, j, row.reason, row.log_tail);
    rows.push_back(std::move(row));
  }

  std::string csv = "student,kind,views,passed,score";
  for (const std::string& lab : labs) csv += "," + lab;
  csv += ",hidden,hidden_passed,build,build_seconds,cache_hit_rate,reason\n";
  for (const Row& row : rows) {
    const Graded& g = row.graded;
    const int renders = static_cast<int>(g.visible.views.size() + g.hidden.size());
    const int passed = g.visible.passed() + g.hidden_passed();
    csv += csv_field(row.student) + "," + row.kind + "," + std::to_string(g.visible.views.size()) + "," +
           std::to_string(g.visible.passed()) + "," + fixed1(renders ? 100.0 * passed / renders : 0);
    std::map<std::string, std::pair<int, int>> by_lab = g.visible.by_lab();
    for (const HiddenResult& h : g.hidden) {
      auto& [p, t] = by_lab[h.result.id.lab];
      p += h.result.passed ? 1 : 0;
      ++t;
    }
    for (const std::string& lab : labs) {
      const auto it = by_lab.find(lab);  // absent: only error views, not graded from images
      csv += "," + (it != by_lab.end() ? fixed1(100.0 * it->second.first / it->second.second) : std::string("-"));
    }
    csv += "," + std::to_string(g.hidden.size()) + "," + std::to_string(g.hidden_passed()) + "," + row.build + "," +
           (row.cache ? fixed1(row.build_seconds) : "-") + "," +
           (row.cache ? fixed1(100 * row.cache->hit_rate()) : "-") + "," + csv_field(row.reason) + "\n";
  }
  write_text(s.csv, csv);
  if (!s.report.empty()) write_class_index(rows, passes.size(), s.report);
  std::printf("%zu submissions; one row each, one column per lab (percent of its renders passed): %s\n",
              students.size(), s.csv.c_str());
  return all_passed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Settings s = parse(argc, argv);
    if (s.help) {
      std::fputs(kUsage, stdout);
      gllab::files::finish_stdout();
      return 0;
    }
    // The instructor's files and the targets first: a fault there is not the student's.
    const Manifest manifest = read_manifest(s.refs);
    const std::vector<ViewId> views = select_views(reference_views(s.refs), s.labs, s.views);
    const References references = read_references(s.refs, views, &manifest);
    check_targets(s);
    const int status = s.mode == Settings::Mode::kClass
                           ? run_class(s, views, manifest, references)
                           : run_single(s, views, manifest, references);
    gllab::files::finish_stdout();
    return status;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "labgrade: %s\n", e.what());
    return 2;
  }
}
