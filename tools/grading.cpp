// tools/grading.cpp — grading.h: sources, one view, a whole submission.
#include "grading.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

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

class BuildSource : public Source {
 public:
  BuildSource(fs::path dir, std::vector<std::string> env, double timeout)
      : dir_(std::move(dir)), env_(std::move(env)), timeout_(timeout) {}

  Image obtain(const ViewId& id) const override {
    const fs::path program = renderer(id.lab);
    if (program.empty()) throw SubmissionError("no renderer " + id.lab + "_headless in " + dir_.string());
    const ProcessResult r = run_process({program.string(), "--view", id.view, "--out", "-"}, env_, timeout_);
    if (!r.started) throw SubmissionError(first_line(r.err));
    if (r.timed_out) throw SubmissionError("the render took longer than " + std::to_string(int(timeout_)) + " s (killed)");
    if (r.exit_status != 0) {
      std::string why = first_line(r.err);
      if (r.exit_status > 128) why = "crashed (signal " + std::to_string(r.exit_status - 128) + ")" + (why.empty() ? "" : ": " + why);
      if (why.empty()) why = "exited with status " + std::to_string(r.exit_status);
      throw SubmissionError(why);
    }
    try {
      return decode_pam(r.out, id.lab + "_headless --view " + id.view);
    } catch (const ImageError& e) {
      throw SubmissionError(e.what());
    }
  }

  // <lab>_headless --views a,b,c --out -: one PAM per view, in order, until
  // the first failure; the views after it are rendered one by one for their
  // own reasons.
  std::vector<Obtained> obtain_batch(const std::vector<ViewId>& views) const override {
    if (views.size() < 2) return Source::obtain_batch(views);
    const fs::path program = renderer(views.front().lab);
    if (program.empty()) return Source::obtain_batch(views);
    std::string list;
    for (const ViewId& v : views) list += (list.empty() ? "" : ",") + v.view;
    const ProcessResult r =
        run_process({program.string(), "--views", list, "--out", "-"}, env_, timeout_ * static_cast<double>(views.size()));
    std::vector<Obtained> out;
    std::size_t at = 0;
    while (r.started && !r.timed_out && out.size() < views.size() && at < r.out.size()) {
      try {
        out.push_back({decode_pam_at(r.out, at, views[out.size()].lab + "_headless"), ""});
      } catch (const ImageError&) {
        break;  // a torn or foreign stream: the rest one by one
      }
    }
    for (std::size_t i = out.size(); i < views.size(); ++i) out.push_back(Source::obtain_batch({views[i]}).front());
    return out;
  }

  std::string describe() const override { return dir_.string(); }

 private:
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
  std::string describe() const override { return dir_.string(); }

 private:
  fs::path dir_;
};

}  // namespace

std::vector<Obtained> Source::obtain_batch(const std::vector<ViewId>& views) const {
  std::vector<Obtained> out;
  for (const ViewId& v : views) {
    try {
      out.push_back({obtain(v), ""});
    } catch (const SubmissionError& e) {
      out.push_back({std::nullopt, e.what()});
    } catch (const std::exception& e) {
      out.push_back({std::nullopt, std::string("cannot grade: ") + e.what()});
    }
  }
  return out;
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
  const auto number = [&](const char* key) {
    const auto it = m.fields.find(key);
    if (it == m.fields.end()) throw UsageError(path.string() + ": no " + key);
    try {
      std::size_t used = 0;
      const double v = std::stod(it->second, &used);
      if (used != it->second.size()) throw std::invalid_argument(key);
      return v;
    } catch (const std::exception&) {
      throw UsageError(path.string() + ": malformed " + key + " '" + it->second + "'");
    }
  };
  m.tolerance.channel_threshold = static_cast<int>(number("tolerance_channel_threshold"));
  m.tolerance.shift_radius = static_cast<int>(number("tolerance_shift_radius"));
  m.tolerance.max_differing_share = number("tolerance_max_differing_share");
  return m;
}

std::vector<ViewId> reference_views(const fs::path& refs) {
  if (!fs::is_directory(refs)) throw UsageError("no reference folder " + refs.string());
  std::vector<ViewId> views;
  for (const auto& entry : fs::directory_iterator(refs)) {
    if (entry.path().extension() != ".png") continue;
    const std::string stem = entry.path().stem().string();
    const auto sep = stem.find("__");
    if (sep == std::string::npos || sep == 0 || sep + 2 >= stem.size())
      throw UsageError("reference " + entry.path().string() + " is not named <lab>__<view>.png");
    views.push_back({stem.substr(0, sep), stem.substr(sep + 2)});
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

// The verdict on one render (or on its absence).
ViewResult judge(const ViewId& id, Obtained obtained, const Image& reference, const Tolerance& tolerance,
                 bool keep_image) {
  ViewResult r;
  r.id = id;
  if (!obtained.image) {
    r.reason = obtained.error;
    return r;
  }
  try {
    Image& image = *obtained.image;
    if (image.width != reference.width || image.height != reference.height) {
      r.reason = "render is " + std::to_string(image.width) + "x" + std::to_string(image.height) + ", the reference " +
                 std::to_string(reference.width) + "x" + std::to_string(reference.height);
    } else {
      r.comparison = compare_images(reference, image, tolerance.channel_threshold, tolerance.shift_radius);
      r.passed = r.comparison->passes(tolerance);
      if (!r.passed) r.reason = "differs beyond tolerance";
    }
    if (keep_image || !r.passed) r.submission = std::move(image);
  } catch (const std::exception& e) {
    r.reason = std::string("cannot grade: ") + e.what();
  }
  return r;
}

}  // namespace

ViewResult grade_view(const Source& source, const ViewId& id, const Image& reference, const Tolerance& tolerance,
                      bool keep_image) {
  const auto start = std::chrono::steady_clock::now();
  ViewResult r = judge(id, source.obtain_batch({id}).front(), reference, tolerance, keep_image);
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

Grade grade(const Source& source, const std::vector<ViewId>& views, const fs::path& refs, const Tolerance& tolerance,
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
          const Image reference = read_png((refs / (views[i].name() + ".png")).string());
          r = judge(views[i], std::move(renders[b]), reference, tolerance, keep_images);
          r.seconds = each;
          // From a batch, a failure is confirmed by a render of its own.
          if (!r.passed && r.comparison && batch.size() > 1) r = grade_view(source, views[i], reference, tolerance, keep_images);
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
