// tools/grading.cpp — grading.h: sources, one view, a whole submission.
#include "grading.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "image/pam.h"
#include "process.h"

namespace fs = std::filesystem;

namespace gllab::grading {

namespace {

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// A temporary file for a renderer's --text-out, removed when done.
class TextFile {
 public:
  TextFile() {
    std::string name = (fs::temp_directory_path() / "gllab-text-XXXXXX").string();
    const int fd = mkstemp(name.data());
    if (fd < 0) throw std::runtime_error("cannot create a temporary file in " + fs::temp_directory_path().string());
    close(fd);
    path_ = name;
  }
  ~TextFile() {
    std::error_code ec;
    fs::remove(path_, ec);
  }
  TextFile(const TextFile&) = delete;
  TextFile& operator=(const TextFile&) = delete;
  const fs::path& path() const { return path_; }

  // The sections "== VIEW N" + N lines, by view.
  std::map<std::string, std::vector<std::string>> sections() const {
    std::map<std::string, std::vector<std::string>> out;
    std::ifstream in(path_, std::ios::binary);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("== ", 0) != 0) break;  // not our format: no text
      const auto space = line.rfind(' ');
      if (space <= 3) break;
      std::vector<std::string>& lines = out[line.substr(3, space - 3)];
      const long count = std::strtol(line.c_str() + space + 1, nullptr, 10);
      for (long k = 0; k < count && std::getline(in, line); ++k) lines.push_back(line);
    }
    return out;
  }

 private:
  fs::path path_;
};

class BuildSource : public Source {
 public:
  BuildSource(fs::path dir, std::vector<std::string> env, double timeout)
      : dir_(std::move(dir)), env_(std::move(env)), timeout_(timeout) {}

  Image obtain(const ViewId& id) const override {
    Obtained o = render({id}).front();
    if (!o.image) throw SubmissionError(o.error);
    return std::move(*o.image);
  }

  // Error views one by one (they exit 1); the others of the lab in one run,
  // <lab>_headless --views a,b,c --out - --text-out FILE: one PAM per view,
  // in order, until the first failure; the views after it are rendered one
  // by one for their own reasons.
  std::vector<Obtained> obtain_batch(const std::vector<ViewId>& views) const override {
    std::vector<Obtained> out(views.size());
    std::vector<ViewId> drawn;
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (views[i].error_view) out[i] = render({views[i]}).front();
      else drawn.push_back(views[i]), at.push_back(i);
    }
    std::vector<Obtained> got = render(drawn);
    for (std::size_t k = 0; k < got.size(); ++k) out[at[k]] = std::move(got[k]);
    return out;
  }

  std::string describe() const override { return dir_.string(); }

 private:
  std::vector<Obtained> render(const std::vector<ViewId>& views) const {
    std::vector<Obtained> out;
    if (views.empty()) return out;
    const fs::path program = renderer(views.front().lab);
    if (program.empty()) {
      for (std::size_t i = 0; i < views.size(); ++i)
        out.push_back(Obtained::failed("no renderer " + views.front().lab + "_headless in " + dir_.string()));
      return out;
    }
    std::string list;
    for (const ViewId& v : views) list += (list.empty() ? "" : ",") + v.view;
    const TextFile text;
    std::vector<std::string> argv = {program.string(), views.size() == 1 ? "--view" : "--views", list,
                                     "--out", "-", "--text-out", text.path().string()};
    const ProcessResult r = run_process(argv, env_, timeout_ * static_cast<double>(views.size()));
    // A batch that failed anywhere: every view on its own, for its own reason
    // (the text file is written only when all views were drawn).
    if (views.size() > 1 && (!r.started || r.timed_out || r.exit_status != 0)) {
      for (const ViewId& v : views) out.push_back(render({v}).front());
      return out;
    }
    if (r.started && !r.timed_out && r.exit_status == 0) {
      std::size_t at = 0;
      try {
        while (out.size() < views.size())
          out.push_back(Obtained::drawn(decode_pam_at(r.out, at, views[out.size()].lab + "_headless")));
      } catch (const ImageError& e) {
        if (views.size() == 1) out.push_back(Obtained::failed(e.what()));
        else out.clear();  // a torn or foreign stream: every view on its own
      }
      if (views.size() > 1 && out.size() < views.size()) {
        out.clear();
        for (const ViewId& v : views) out.push_back(render({v}).front());
        return out;
      }
      const auto sections = text.sections();
      for (std::size_t i = 0; i < out.size(); ++i) {
        const auto it = sections.find(views[i].view);
        if (it != sections.end() && out[i].image) out[i].text = it->second;
      }
      return out;
    }
    out.push_back(Obtained::failed(why_not(r), r.exit_status));  // one view, and it gave no image
    return out;
  }

  // One line: why a render gave no image.
  std::string why_not(const ProcessResult& r) const {
    if (!r.started) return first_line(r.err);
    if (r.timed_out) return "the render took longer than " + std::to_string(int(timeout_)) + " s (killed)";
    std::string why = first_line(r.err);
    if (r.exit_status > 128)
      why = "crashed (signal " + std::to_string(r.exit_status - 128) + ")" + (why.empty() ? "" : ": " + why);
    if (why.empty() && r.exit_status != 0) why = "exited with status " + std::to_string(r.exit_status);
    return why;
  }

  fs::path renderer(const std::string& lab) const {
    for (const fs::path& p : {dir_ / (lab + "_headless"), dir_ / "bin" / (lab + "_headless")})
      if (fs::is_regular_file(p)) return p;
    return {};
  }
  fs::path dir_;
  std::vector<std::string> env_;
  double timeout_;
};

class ImageSource : public Source {
 public:
  explicit ImageSource(fs::path dir) : dir_(std::move(dir)) {}
  Image obtain(const ViewId& id) const override {
    const fs::path file = dir_ / (id.name() + ".png");
    if (!fs::exists(file)) throw SubmissionError("no render " + file.string());
    try {
      return read_png(file.string());
    } catch (const std::exception& e) {
      throw SubmissionError(e.what());
    }
  }
  std::vector<Obtained> obtain_batch(const std::vector<ViewId>& views) const override {
    std::vector<Obtained> out = Source::obtain_batch(views);
    for (std::size_t i = 0; i < views.size(); ++i) {
      std::ifstream in(dir_ / (views[i].name() + ".txt"), std::ios::binary);
      if (!in) continue;
      std::vector<std::string> lines;
      for (std::string line; std::getline(in, line);) lines.push_back(line);
      out[i].text = std::move(lines);
    }
    return out;
  }
  std::string describe() const override { return dir_.string(); }

 private:
  fs::path dir_;
};

}  // namespace

std::vector<Obtained> Source::obtain_batch(const std::vector<ViewId>& views) const {
  std::vector<Obtained> out;
  for (const ViewId& v : views) {
    try {
      out.push_back(Obtained::drawn(obtain(v)));
    } catch (const SubmissionError& e) {
      out.push_back(Obtained::failed(e.what()));
    } catch (const std::exception& e) {
      out.push_back(Obtained::failed(std::string("cannot grade: ") + e.what()));
    }
  }
  return out;
}

const char* profile_name(Profile p) { return p == Profile::kBuild ? "build" : "images"; }

Profile parse_profile(const std::string& name) {
  if (name == "build") return Profile::kBuild;
  if (name == "images") return Profile::kImages;
  throw UsageError("unknown profile '" + name + "' (profiles: build, images)");
}

Manifest read_manifest(const fs::path& refs) {
  const fs::path path = refs / "MANIFEST";
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read " + path.string() + " (run: make references)");
  Manifest m;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon != std::string::npos) m.fields[line.substr(0, colon)] = line.substr(colon + 2);
  }
  const auto number = [&](const std::string& key) {
    const auto it = m.fields.find(key);
    if (it == m.fields.end()) throw UsageError(path.string() + ": no " + key);
    try {
      std::size_t used = 0;
      const double v = std::stod(it->second, &used);
      if (used != it->second.size() || !std::isfinite(v) || v < 0) throw std::invalid_argument(key);
      return v;
    } catch (const std::exception&) {
      throw UsageError(path.string() + ": malformed " + key + " '" + it->second + "'");
    }
  };
  for (Profile p : {Profile::kBuild, Profile::kImages}) {
    Tolerance& t = p == Profile::kBuild ? m.build : m.images;
    const std::string prefix = std::string(profile_name(p)) + "_";
    t.channel_threshold = static_cast<int>(number(prefix + "channel_threshold"));
    t.shift_radius = static_cast<int>(number(prefix + "shift_radius"));
    t.edge_contrast = static_cast<int>(number(prefix + "edge_contrast"));
    t.max_differing_share = number(prefix + "max_unexcused_share");
    t.max_shifted_share = number(prefix + "max_shifted_share");
  }
  m.text_relative = number("text_relative_tolerance");
  m.text_absolute = number("text_absolute_tolerance");
  return m;
}

std::vector<ViewId> reference_views(const fs::path& refs) {
  if (!fs::is_directory(refs)) throw UsageError("no reference folder " + refs.string());
  std::vector<ViewId> views;
  for (const auto& entry : fs::directory_iterator(refs)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".png" && ext != ".error") continue;
    const std::string stem = entry.path().stem().string();
    const auto sep = stem.find("__");
    if (sep == std::string::npos || sep == 0 || sep + 2 >= stem.size())
      throw UsageError("reference " + entry.path().string() + " is not named <lab>__<view>" + ext);
    views.push_back({stem.substr(0, sep), stem.substr(sep + 2), ext == ".error"});
  }
  if (views.empty()) throw UsageError("no reference images in " + refs.string() + " (run: make references)");
  std::sort(views.begin(), views.end());
  return views;
}

std::vector<ViewId> select_views(const std::vector<ViewId>& all, const std::vector<std::string>& labs,
                                 const std::vector<std::string>& views) {
  std::set<std::string> lab_names, view_names;
  for (const ViewId& v : all) lab_names.insert(v.lab), view_names.insert(v.view);
  const auto lab_matches = [](const std::string& lab, const std::string& asked) {
    return lab == asked || lab.substr(0, lab.find('_')) == asked;
  };
  for (const std::string& asked : labs)
    if (std::none_of(lab_names.begin(), lab_names.end(), [&](const std::string& l) { return lab_matches(l, asked); }))
      throw UsageError("unknown lab '" + asked + "' (labs: " + joined(lab_names) + ")");
  for (const std::string& asked : views)
    if (!view_names.count(asked)) throw UsageError("unknown view '" + asked + "' (views: " + joined(view_names) + ")");
  std::vector<ViewId> out;
  for (const ViewId& v : all) {
    const bool lab_ok = labs.empty() || std::any_of(labs.begin(), labs.end(), [&](const std::string& a) { return lab_matches(v.lab, a); });
    const bool view_ok = views.empty() || std::find(views.begin(), views.end(), v.view) != views.end();
    if (lab_ok && view_ok) out.push_back(v);
  }
  if (out.empty()) throw UsageError("no view matches the --labs and --views given");
  return out;
}

std::unique_ptr<Source> build_source(const fs::path& dir, std::vector<std::string> env, double timeout_seconds) {
  if (!fs::is_directory(dir)) throw UsageError("no build folder " + dir.string());
  return std::make_unique<BuildSource>(dir, std::move(env), timeout_seconds);
}

std::unique_ptr<Source> image_source(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw UsageError("no image folder " + dir.string());
  return std::make_unique<ImageSource>(dir);
}

bool looks_like_build(const fs::path& dir) {
  for (const fs::path& d : {dir, dir / "bin"}) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(d, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > 9 && name.compare(name.size() - 9, 9, "_headless") == 0) return true;
    }
  }
  return false;
}

namespace {

// A line cut into words and numbers: numbers are compared by value, the
// rest exactly. A number starts at a digit (or ".5", or a sign before
// either) that does not continue a word: "P3" and "x2" stay words; strtod
// reads it, exponent included.
struct Token {
  bool number = false;
  std::string text;
  double value = 0;
};

std::vector<Token> tokens(const std::string& line) {
  const auto digit = [&](std::size_t k) { return k < line.size() && std::isdigit(static_cast<unsigned char>(line[k])); };
  const auto word = [&](std::size_t k) { return std::isalnum(static_cast<unsigned char>(line[k])) || line[k] == '_'; };
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < line.size()) {
    std::size_t k = i + ((line[i] == '-' || line[i] == '+') ? 1 : 0);
    const bool starts = (digit(k) || (k < line.size() && line[k] == '.' && digit(k + 1))) && (i == 0 || !word(i - 1));
    if (starts) {
      char* end = nullptr;
      const double v = std::strtod(line.c_str() + i, &end);
      const auto stop = static_cast<std::size_t>(end - line.c_str());
      if (stop > i) {
        out.push_back({true, line.substr(i, stop - i), v});
        i = stop;
        continue;
      }
    }
    if (out.empty() || out.back().number) out.push_back({false, "", 0});
    out.back().text += line[i++];
  }
  return out;
}

bool numbers_agree(double a, double b, double relative, double absolute) {
  if (a == b) return true;
  if (std::fabs(a) <= absolute && std::fabs(b) <= absolute) return true;
  return std::fabs(a - b) <= relative * std::max(std::fabs(a), std::fabs(b));
}

// The verdict on one render (or on its absence).
ViewResult judge(const ViewId& id, Obtained obtained, const Reference& reference, const Judgement& j,
                 bool keep_image) {
  ViewResult r;
  r.id = id;
  if (id.error_view) {
    // It must refuse to draw: exit 1 with its error line.
    if (obtained.image) r.reason = "drew a picture; it must exit 1 with \"" + reference.error_line + "\"";
    else if (obtained.exit_status != 1) r.reason = "expected exit 1 with \"" + reference.error_line + "\", got: " + obtained.error;
    else if (obtained.error != reference.error_line)
      r.reason = "exit 1 with \"" + obtained.error + "\", the reference \"" + reference.error_line + "\"";
    else r.passed = true;
    return r;
  }
  if (!obtained.image) {
    r.reason = obtained.error;
    return r;
  }
  try {
    Image& image = *obtained.image;
    const Image& ref = reference.image;
    if (image.width != ref.width || image.height != ref.height) {
      r.reason = "render is " + std::to_string(image.width) + "x" + std::to_string(image.height) + ", the reference " +
                 std::to_string(ref.width) + "x" + std::to_string(ref.height);
    } else {
      r.comparison = compare_images(ref, image, j.tolerance);
      r.score = r.comparison->score(j.tolerance);
      r.passed = r.comparison->passes(j.tolerance);
      if (!r.passed) r.reason = "differs beyond tolerance";
      if (reference.text) {
        if (!obtained.text) r.text_reason = "no text from the render";
        else r.text_reason = text_difference(*reference.text, *obtained.text, j.text_relative, j.text_absolute);
        if (!r.text_reason.empty()) {
          r.passed = false;
          r.reason += (r.reason.empty() ? "" : "; ") + ("text differs: " + r.text_reason);
        }
      }
    }
    if (keep_image || !r.passed) r.submission = std::move(image);
  } catch (const std::exception& e) {
    r.reason = std::string("cannot grade: ") + e.what();
  }
  return r;
}

}  // namespace

std::string text_difference(const std::vector<std::string>& reference, const std::vector<std::string>& got,
                            double relative, double absolute) {
  const std::size_t n = std::max(reference.size(), got.size());
  for (std::size_t i = 0; i < n; ++i) {
    const std::string where = "line " + std::to_string(i + 1) + ": ";
    if (i >= got.size()) return where + "missing, the reference \"" + reference[i] + "\"";
    if (i >= reference.size()) return where + "\"" + got[i] + "\", not in the reference";
    const std::vector<Token> a = tokens(reference[i]), b = tokens(got[i]);
    bool same = a.size() == b.size();
    for (std::size_t k = 0; same && k < a.size(); ++k)
      same = a[k].number == b[k].number &&
             (a[k].number ? numbers_agree(a[k].value, b[k].value, relative, absolute) : a[k].text == b[k].text);
    if (!same) return where + "\"" + got[i] + "\", the reference \"" + reference[i] + "\"";
  }
  return "";
}

Reference read_reference(const fs::path& refs, const ViewId& id) {
  Reference r;
  if (id.error_view) {
    std::ifstream in(refs / (id.name() + ".error"), std::ios::binary);
    if (!in || !std::getline(in, r.error_line)) throw std::runtime_error("cannot read " + (refs / (id.name() + ".error")).string());
    return r;
  }
  r.image = read_png((refs / (id.name() + ".png")).string());
  std::ifstream in(refs / (id.name() + ".txt"), std::ios::binary);
  if (in) {
    r.text.emplace();
    for (std::string line; std::getline(in, line);) r.text->push_back(line);
  }
  return r;
}

Judgement judgement(const Manifest& m, Profile p) { return {p, m.tolerance(p), m.text_relative, m.text_absolute}; }

ViewResult grade_view(const Source& source, const ViewId& id, const Reference& reference, const Judgement& j,
                      bool keep_image) {
  const auto start = std::chrono::steady_clock::now();
  ViewResult r = judge(id, source.obtain_batch({id}).front(), reference, j, keep_image);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

int Grade::passed() const {
  return static_cast<int>(std::count_if(views.begin(), views.end(), [](const ViewResult& v) { return v.passed; }));
}

double Grade::score() const { return views.empty() ? 0.0 : 100.0 * passed() / static_cast<double>(views.size()); }

std::map<std::string, std::pair<int, int>> Grade::by_lab() const {
  std::map<std::string, std::pair<int, int>> labs;
  for (const ViewResult& v : views) {
    auto& [passed, total] = labs[v.id.lab];
    passed += v.passed ? 1 : 0;
    ++total;
  }
  return labs;
}

Grade grade(const Source& source, const std::vector<ViewId>& views, const fs::path& refs, const Judgement& j,
            int jobs, bool keep_images, const Progress& progress) {
  Grade g;
  g.submission = source.describe();
  g.views.resize(views.size());
  // Work items: the views of one lab (indices into views), in order.
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (groups.empty() || views[groups.back().front()].lab != views[i].lab) groups.emplace_back();
    groups.back().push_back(i);
  }
  std::atomic<std::size_t> next{0};
  std::mutex report;
  int done = 0;
  auto worker = [&] {
    for (std::size_t k = next++; k < groups.size(); k = next++) {
      const std::vector<std::size_t>& group = groups[k];
      std::vector<ViewId> batch;
      for (std::size_t i : group) batch.push_back(views[i]);
      if (progress) {
        std::lock_guard<std::mutex> lock(report);
        progress({done, static_cast<int>(views.size()), &batch.front(), nullptr});
      }
      const auto start = std::chrono::steady_clock::now();
      std::vector<Obtained> renders = source.obtain_batch(batch);
      const double each = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                          static_cast<double>(batch.size());
      for (std::size_t b = 0; b < batch.size(); ++b) {
        const std::size_t i = group[b];
        ViewResult r;
        try {
          const Reference reference = read_reference(refs, views[i]);
          r = judge(views[i], std::move(renders[b]), reference, j, keep_images);
          r.seconds = each;
          // From a batch, a failure is confirmed by a render of its own.
          if (!r.passed && r.comparison && batch.size() > 1) r = grade_view(source, views[i], reference, j, keep_images);
        } catch (const std::exception& e) {
          r.id = views[i];
          r.reason = std::string("cannot read the reference: ") + e.what();
        }
        g.views[i] = std::move(r);
        std::lock_guard<std::mutex> lock(report);
        ++done;
        if (progress) progress({done, static_cast<int>(views.size()), &views[i], &g.views[i]});
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::max(1, jobs); ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  return g;
}

}  // namespace gllab::grading
