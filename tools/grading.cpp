// tools/grading.cpp — grading.h: sources, one view, a whole submission.
#include "grading.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <exception>
#include <mutex>
#include <numeric>
#include <set>
#include <sstream>
#include <system_error>
#include <thread>

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "files/files.h"
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

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

// The lines of a text as std::getline reads them: no line after a final newline.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return lines;
}

// The width and height a PNG's header (IHDR) declares, read before decoding,
// so that a file that would decode to gigabytes is refused first. Nothing
// when the bytes do not start like a PNG (the decoder then says why).
std::optional<std::pair<long long, long long>> png_header_size(const std::string& bytes) {
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
      bytes.compare(12, 4, "IHDR") != 0)
    return std::nullopt;
  const auto be32 = [&](std::size_t at) {
    long long v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = v * 256 + static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  return std::make_pair(be32(16), be32(20));
}

// A PNG's bytes decoded, no side above kMaxImageSide. `name` starts every
// message ("reference x.png", "read_png: 'x.png'"). Throws ImageError.
Image decode_checked_png(const std::string& bytes, const std::string& name) {
  if (const auto size = png_header_size(bytes))
    if (size->first > kMaxImageSide || size->second > kMaxImageSide)
      throw ImageError(name + ": a PNG of " + std::to_string(size->first) + "x" +
                       std::to_string(size->second) + " pixels, larger than the limit of " +
                       std::to_string(kMaxImageSide) + " per side");
  return decode_png(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), name);
}

std::string mib(std::uintmax_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// A temporary file for a renderer's --text-out, removed when done.
class TextFile {
 public:
  // Throws std::runtime_error when there is no usable temporary folder (the
  // grading stops: it is not the student's fault).
  explicit TextFile(const fs::path& scratch = {}) {
    std::error_code ec;
    const fs::path dir = scratch.empty() ? fs::temp_directory_path(ec) : scratch;
    if (ec)
      throw std::runtime_error("no temporary folder for a renderer's text (" + ec.message() + ")");
    std::string name = (dir / "gllab-text-XXXXXX").string();
    const int fd = mkstemp(name.data());
    if (fd < 0)
      throw std::runtime_error("cannot create a temporary file in " + dir.string() + " (" +
                               std::strerror(errno) + ")");
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

  // The sections "== VIEW N" + N lines, by view. Throws files::FileError
  // when the renderer left no regular file or one over kMaxTextFileBytes.
  std::map<std::string, std::vector<std::string>> sections() const {
    std::map<std::string, std::vector<std::string>> out;
    // A sandboxed renderer may have swapped its file for a link to one of the
    // grader's: the text read is the file the renderer wrote, or nothing.
    std::error_code ec;
    if (fs::is_symlink(path_, ec))
      throw files::FileError(path_.string() + " is a symbolic link, not the renderer's text");
    std::istringstream in(files::read_input(path_.string(), kMaxTextFileBytes));
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
  BuildSource(fs::path dir, RenderSettings settings)
      : dir_(std::move(dir)), settings_(std::move(settings)), timeout_(settings_.timeout_seconds) {}

  Image obtain(const ViewId& id) const override {
    Obtained o = render({id}).front();
    if (!o.image) throw SubmissionError(o.error);
    return std::move(*o.image);
  }

  // Error views one by one (they exit 1); the others of the lab in one run,
  // <lab> --headless --views a,b,c --out - --text-out FILE: one PAM per view,
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
        out.push_back(Obtained::failed("no program " + views.front().lab + " in " + dir_.string()));
      return out;
    }
    std::string list;
    for (const ViewId& v : views) list += (list.empty() ? "" : ",") + v.view;
    const TextFile text(settings_.scratch);
    std::vector<std::string> argv = {program.string(), "--headless", views.size() == 1 ? "--view" : "--views", list,
                                     "--out", "-", "--text-out", text.path().string()};
    const auto sets = settings_.sets.find(views.front().lab);
    if (sets != settings_.sets.end())
      for (const std::string& set : sets->second) argv.insert(argv.end(), {"--set", set});
    const ProcessLimits limits{timeout_ * static_cast<double>(views.size()), kMaxRendererOutputBytes};
    const ProcessResult r = settings_.launch ? settings_.launch(argv, settings_.env, limits)
                                             : run_process(argv, settings_.env, limits);
    // A batch that failed anywhere: every view on its own, for its own reason
    // (the text file is written only when all views were drawn).
    const bool ran = r.started && !r.timed_out && !r.output_exceeded && r.exit_status == 0;
    if (views.size() > 1 && !ran) {
      for (const ViewId& v : views) out.push_back(render({v}).front());
      return out;
    }
    if (ran) {
      std::size_t at = 0;
      try {
        while (out.size() < views.size())
          out.push_back(Obtained::drawn(decode_pam_at(r.out, at, views[out.size()].lab)));
      } catch (const ImageError& e) {
        if (views.size() == 1) out.push_back(Obtained::failed(e.what()));
        else out.clear();  // a torn or foreign stream: every view on its own
      }
      if (views.size() > 1 && out.size() < views.size()) {
        out.clear();
        for (const ViewId& v : views) out.push_back(render({v}).front());
        return out;
      }
      try {
        const auto sections = text.sections();
        for (std::size_t i = 0; i < out.size(); ++i) {
          const auto it = sections.find(views[i].view);
          if (it != sections.end() && out[i].image) out[i].text = it->second;
        }
      } catch (const files::FileError& e) {
        for (Obtained& o : out)
          o = Obtained::failed(std::string("the renderer's text (--text-out) ") + e.what());
      }
      return out;
    }
    out.push_back(Obtained::failed(why_not(r), r.exit_status));  // one view, and it gave no image
    return out;
  }

  // One line: why a render gave no image.
  std::string why_not(const ProcessResult& r) const {
    if (!r.started) return first_line(r.err);
    if (!r.limit_hit.empty()) {
      const std::string said = first_line(r.err);
      return "stopped by the sandbox: " + r.limit_hit + (said.empty() ? "" : " (it said: " + said + ")");
    }
    if (r.timed_out) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", timeout_);
      return std::string("the render took longer than ") + seconds + " s (killed)";
    }
    if (r.output_exceeded)
      return "the renderer wrote more than " + mib(kMaxRendererOutputBytes) +
             " to stdout or stderr (killed)";
    std::string why = first_line(r.err);
    if (r.exit_status > 128)
      why = "crashed (signal " + std::to_string(r.exit_status - 128) + ")" + (why.empty() ? "" : ": " + why);
    if (why.empty() && r.exit_status != 0) why = "exited with status " + std::to_string(r.exit_status);
    return why;
  }

  fs::path renderer(const std::string& lab) const {
    for (const fs::path& p : {dir_ / lab, dir_ / "bin" / lab})
      if (fs::is_regular_file(p)) return p;
    return {};
  }
  fs::path dir_;
  RenderSettings settings_;
  double timeout_;
};

class ImageSource : public Source {
 public:
  explicit ImageSource(fs::path dir) : dir_(std::move(dir)) {}
  Image obtain(const ViewId& id) const override {
    const fs::path file = dir_ / (id.name() + ".png");
    std::error_code ec;
    if (!fs::exists(file, ec)) throw SubmissionError("no render " + file.string());
    try {
      // A regular file within the limit: a FIFO is refused, not waited on.
      return decode_checked_png(files::read_input(file.string(), kMaxImageFileBytes),
                                "read_png: '" + file.string() + "'");
    } catch (const std::exception& e) {
      throw SubmissionError(e.what());
    }
  }
  std::vector<Obtained> obtain_batch(const std::vector<ViewId>& views) const override {
    std::vector<Obtained> out = Source::obtain_batch(views);
    for (std::size_t i = 0; i < views.size(); ++i) {
      const fs::path file = dir_ / (views[i].name() + ".txt");
      std::error_code ec;
      if (!fs::exists(file, ec)) continue;
      try {
        out[i].text = lines_of(files::read_input(file.string(), kMaxTextFileBytes));
      } catch (const files::FileError& e) {
        out[i] = Obtained::failed(e.what());
      }
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

std::optional<double> parse_number(const std::string& text, double lo, double hi) {
  // Decimal only: from_chars reads no spaces and no '+', and this leaves out "0x1p3".
  if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string::npos)
    return std::nullopt;
  double v = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, v);
  if (error != std::errc() || stop != end || !std::isfinite(v) || v < lo || v > hi)
    return std::nullopt;
  return v;
}

std::optional<long long> parse_integer(const std::string& text, long long lo, long long hi) {
  long long v = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, v);
  if (text.empty() || error != std::errc() || stop != end || v < lo || v > hi) return std::nullopt;
  return v;
}

Manifest read_manifest(const fs::path& refs) {
  const fs::path path = refs / "MANIFEST";
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw UsageError("cannot read " + path.string() + " (run: make references)");
  try {
    return parse_manifest(files::read_input(path.string(), kMaxTextFileBytes), path.string());
  } catch (const files::FileError& e) {
    throw UsageError(e.what());
  }
}

Manifest parse_manifest(const std::string& text, const std::string& name) {
  Manifest m;
  int line_number = 0;
  for (std::string line : lines_of(text)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon == std::string::npos || colon == 0)
      throw UsageError(name + ": line " + std::to_string(line_number) +
                       " is not 'key: value' or a # comment");
    const std::string key = line.substr(0, colon);
    if (!m.fields.emplace(key, line.substr(colon + 2)).second)
      throw UsageError(name + ": line " + std::to_string(line_number) + ": " + key +
                       " is given twice");
  }
  const auto value = [&](const std::string& key) -> const std::string& {
    const auto it = m.fields.find(key);
    if (it == m.fields.end()) throw UsageError(name + ": no " + key);
    return it->second;
  };
  const auto bad = [&](const std::string& key, const std::string& what) {
    return UsageError(name + ": " + key + " '" + value(key) + "' is not " + what);
  };
  const auto integer = [&](const std::string& key, int hi) {
    const auto v = parse_integer(value(key), 0, hi);
    if (!v) throw bad(key, "an integer from 0 to " + std::to_string(hi));
    return static_cast<int>(*v);
  };
  const auto share = [&](const std::string& key) {
    const auto v = parse_number(value(key), 0, 1);
    if (!v) throw bad(key, "a number from 0 to 1");
    return *v;
  };
  for (Profile p : {Profile::kBuild, Profile::kImages}) {
    Tolerance& t = p == Profile::kBuild ? m.build : m.images;
    const std::string prefix = std::string(profile_name(p)) + "_";
    t.channel_threshold = integer(prefix + "channel_threshold", 255);
    t.shift_radius = integer(prefix + "shift_radius", kMaxShiftRadius);
    t.edge_contrast = integer(prefix + "edge_contrast", 255);
    t.max_differing_share = share(prefix + "max_unexcused_share");
    t.max_shifted_share = share(prefix + "max_shifted_share");
  }
  m.text_relative = share("text_relative_tolerance");
  m.text_absolute = share("text_absolute_tolerance");
  if (m.fields.count("size")) {
    const std::string& size = value("size");
    const auto x = size.find('x');
    const auto w = parse_integer(size.substr(0, x), 1, kMaxImageSide);
    const auto h =
        x == std::string::npos ? std::nullopt : parse_integer(size.substr(x + 1), 1, kMaxImageSide);
    if (!w || !h)
      throw bad("size", "WIDTHxHEIGHT, each from 1 to " + std::to_string(kMaxImageSide));
    m.width = static_cast<int>(*w);
    m.height = static_cast<int>(*h);
  }
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

std::unique_ptr<Source> build_source(const fs::path& dir, RenderSettings settings) {
  const double timeout_seconds = settings.timeout_seconds;
  if (!(timeout_seconds > 0 && timeout_seconds <= kMaxTimeoutSeconds)) {
    char text[64];
    std::snprintf(text, sizeof text, "a timeout of %g s is not in (0, %g]", timeout_seconds,
                  kMaxTimeoutSeconds);
    throw UsageError(text);
  }
  if (!fs::is_directory(dir)) throw UsageError("no build folder " + dir.string());
  return std::make_unique<BuildSource>(dir, std::move(settings));
}

std::unique_ptr<Source> build_source(const fs::path& dir, std::vector<std::string> env, double timeout_seconds) {
  RenderSettings settings;
  settings.env = std::move(env);
  settings.timeout_seconds = timeout_seconds;
  return build_source(dir, std::move(settings));
}

std::unique_ptr<Source> image_source(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw UsageError("no image folder " + dir.string());
  return std::make_unique<ImageSource>(dir);
}

bool looks_like_build(const fs::path& dir) {
  for (const fs::path& d : {dir, dir / "bin"}) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(d, ec)) {
      // A lab's program: "NN_topic", no extension (an image folder holds
      // <lab>__<view>.png and .txt files).
      const std::string name = entry.path().filename().string();
      const bool lab_name = name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
                            std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '_' &&
                            name.find('.') == std::string::npos;
      if (lab_name && entry.is_regular_file(ec)) return true;
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
  const auto read = [](const fs::path& file, std::uintmax_t max_bytes) {
    try {
      return files::read_input(file.string(), max_bytes);
    } catch (const files::FileError& e) {
      throw UsageError(std::string("reference ") + e.what());
    }
  };
  Reference r;
  if (id.error_view) {
    const fs::path file = refs / (id.name() + ".error");
    const std::string text = read(file, kMaxTextFileBytes);
    r.error_line = text.substr(0, text.find('\n'));
    if (r.error_line.empty())
      throw UsageError("reference " + file.string() +
                       ": no line (the one line the view must exit 1 with)");
    return r;
  }
  const fs::path png = refs / (id.name() + ".png");
  try {
    r.image = decode_checked_png(read(png, kMaxImageFileBytes), "reference " + png.string());
  } catch (const ImageError& e) {
    throw UsageError(e.what());
  }
  const fs::path txt = refs / (id.name() + ".txt");
  std::error_code ec;
  if (fs::exists(txt, ec)) r.text = lines_of(read(txt, kMaxTextFileBytes));
  return r;
}

References read_references(const fs::path& refs, const std::vector<ViewId>& views,
                           const Manifest* manifest) {
  References out;
  std::map<std::pair<int, int>, int> sizes;  // how many references have each size
  for (const ViewId& v : views) {
    const Reference& r = out[v.name()] = read_reference(refs, v);
    if (!v.error_view) ++sizes[{r.image.width, r.image.height}];
  }
  if (sizes.empty()) return out;
  // The MANIFEST's size, else the size most references have (ties: the first, by size).
  std::pair<int, int> expected =
      std::max_element(sizes.begin(), sizes.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
      })->first;
  std::string whose =
      "the size of " + std::to_string(sizes[expected]) + " of the " +
      std::to_string(std::accumulate(sizes.begin(), sizes.end(), 0,
                                     [](int n, const auto& s) { return n + s.second; })) +
      " references";
  if (manifest && manifest->width > 0) {
    expected = {manifest->width, manifest->height};
    whose = "the MANIFEST's size";
  }
  for (const ViewId& v : views) {
    const Image& image = out[v.name()].image;
    if (!v.error_view && std::make_pair(image.width, image.height) != expected)
      throw UsageError("reference " + (refs / (v.name() + ".png")).string() + " is " +
                       size_text(image.width, image.height) + ", not " +
                       size_text(expected.first, expected.second) + " (" + whose + ")");
  }
  return out;
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
  return grade(source, views, read_references(refs, views), j, jobs, keep_images, progress);
}

Grade grade(const Source& source, const std::vector<ViewId>& views, const References& references,
            const Judgement& j, int jobs, bool keep_images, const Progress& progress) {
  for (const ViewId& v : views)
    if (!references.count(v.name()))
      throw std::invalid_argument("grade: no reference for " + v.name());
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
  std::atomic<bool> stop{false};
  std::mutex report;
  std::exception_ptr failure;  // the first error that stops the grading (under report)
  int done = 0;
  auto work = [&] {
    for (std::size_t k = next++; k < groups.size() && !stop; k = next++) {
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
        const Reference& reference = references.at(views[i].name());
        ViewResult r = judge(views[i], std::move(renders[b]), reference, j, keep_images);
        r.seconds = each;
        // From a batch, a failure is confirmed by a render of its own.
        if (!r.passed && r.comparison && batch.size() > 1)
          r = grade_view(source, views[i], reference, j, keep_images);
        g.views[i] = std::move(r);
        std::lock_guard<std::mutex> lock(report);
        ++done;
        if (progress) progress({done, static_cast<int>(views.size()), &views[i], &g.views[i]});
      }
    }
  };
  // A source throws only when grading cannot go on (no temporary file, no
  // memory): no thread may end the program with it, every one stops.
  auto worker = [&] {
    try {
      work();
    } catch (...) {
      std::lock_guard<std::mutex> lock(report);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  };
  const int wanted = static_cast<int>(
      std::min<std::size_t>(static_cast<std::size_t>(std::clamp(jobs, 1, kMaxJobs)),
                            std::max<std::size_t>(1, groups.size())));
  std::vector<std::thread> threads;
  threads.reserve(static_cast<std::size_t>(wanted - 1));
  for (int t = 1; t < wanted; ++t) {
    try {
      threads.emplace_back(worker);
    } catch (const std::exception&) {  // std::system_error, or std::bad_alloc for its state
      break;  // no more threads (a process or memory limit): those started share the work
    }
  }
  worker();
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  return g;
}

}  // namespace gllab::grading
