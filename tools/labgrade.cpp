// tools/labgrade.cpp — grade lab renders against reference_images/ (instructors).
//
//   labgrade --build DIR    render every view with DIR's headless programs and grade them
//   labgrade --images DIR   grade a folder of <lab>__<view>.png
//   labgrade --class DIR    grade every submission (build or image folder) in DIR: one CSV
//   options: --labs 15,22  --views a,b  --jobs N  --report DIR  --out DIR  --refs DIR
//            --env NAME=VALUE  --timeout SECONDS  --csv FILE  --profile build|images  --quiet
//
// Exit status: 0 every view passed, 1 some failed, 2 usage or input error
// (among them a reference or MANIFEST that is unreadable or out of range,
// checked before any grading, and a failed write, stdout included).
// The metric and its calibration: grading.h and README.md ("Grading");
// the limits: tools/README.md.
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
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "files/files.h"
#include "grading.h"
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
    "  --class DIR        every folder in DIR is one student's build or image folder;\n"
    "                     writes one CSV: a row per student, a column per lab\n"
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

void write_report(const Grade& g, const fs::path& dir, const fs::path& refs,
                  const References& references, const Judgement& judge) {
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
       << "limit. Heat map: grey = equal, blue = excused by the shift, yellow to red = differs.</p>\n<table>\n"
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

int run_single(const Settings& s, const std::vector<ViewId>& all, const Manifest& m,
               const References& references) {
  const bool build = s.mode == Settings::Mode::kBuild;
  const std::vector<ViewId> views = gradable(all, build, s.quiet);
  const Judgement j = judgement_for(s, m, build);
  const std::unique_ptr<Source> source = build ? build_source(s.input, s.env, s.timeout) : image_source(s.input);
  const Grade g = grade_one(*source, views, references, s, j, !s.report.empty());
  if (!s.quiet) print_table(g);
  print_summary(g, j);
  write_failures(g, s, j.tolerance, references);
  if (!s.report.empty()) write_report(g, s.report, s.refs, references, j);
  return g.passed() == static_cast<int>(g.views.size()) ? 0 : 1;
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
  std::string csv = "student,kind,views,passed,score";
  for (const std::string& lab : labs) csv += "," + lab;
  csv += "\n";
  bool all_passed = true;
  for (const fs::path& student : students) {
    const bool build = looks_like_build(student);
    const std::vector<ViewId> views = gradable(all, build, true);
    const Judgement j = judgement_for(s, m, build);
    const std::unique_ptr<Source> source = build ? build_source(student, s.env, s.timeout) : image_source(student);
    const Grade g = grade_one(*source, views, references, s, j, !s.report.empty());
    all_passed = all_passed && g.passed() == static_cast<int>(g.views.size());
    std::printf("%-24s %-6s %3d/%zu views  score %5.1f%%  (%s)\n", student.filename().c_str(), build ? "build" : "images",
                g.passed(), g.views.size(), g.score(), lab_summary(g).c_str());
    char score[16];
    std::snprintf(score, sizeof score, "%.1f", g.score());
    csv += csv_field(student.filename().string()) + "," + (build ? "build" : "images") + "," +
           std::to_string(g.views.size()) + "," + std::to_string(g.passed()) + "," + score;
    const auto by_lab = g.by_lab();
    for (const std::string& lab : labs) {
      const auto it = by_lab.find(lab);  // absent: only error views, not graded from images
      if (it != by_lab.end()) std::snprintf(score, sizeof score, "%.1f", 100.0 * it->second.first / it->second.second);
      csv += std::string(",") + (it != by_lab.end() ? score : "-");
    }
    csv += "\n";
    if (!s.report.empty()) write_report(g, s.report / student.filename(), s.refs, references, j);
  }
  write_text(s.csv, csv);
  std::printf("%zu submissions; one row each, one column per lab (percent of its views passed): %s\n",
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
