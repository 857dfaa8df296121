// common/io/spline_json.cpp — reads and writes the spline file format
// (common/io/README.md). The reader checks every key itself first, so that a
// mistake is reported at its JSON path ("knots[5]: ..."); whatever is left
// is the core's to judge (spline::validate, trim validation).
#include "io/spline_json.h"

#include "files/files.h"
#include "io/json_checks.h"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "spline/bezier.h"
#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/surface.h"
#include "spline/trim.h"

namespace gllab::io {

using spline::BezierCurve;
using spline::BsplineCurve;
using spline::BsplineSurface;
using spline::TrimLoop;
using spline::TrimPiece;
using spline::Vec2;
using spline::Vec3;

namespace {

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

}  // namespace

FileError::FileError(std::string file, std::string json_path, std::string problem)
    : std::runtime_error(one_line(file + ": " + (json_path.empty() ? "" : json_path + ": ") + problem)),
      file_(std::move(file)),
      json_path_(std::move(json_path)),
      problem_(std::move(problem)) {}

std::string shortest_text(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

namespace {

std::string point_text(const Vec3& p) {
  return "(" + shortest_text(p.x) + ", " + shortest_text(p.y) + ", " + shortest_text(p.z) + ")";
}

using detail::describe;
using detail::index_path;
using detail::member_path;

constexpr const char* kSplineTypes = R"("bspline_curve", "bezier_curve" or "bspline_surface")";

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

/// Checks one parsed file (json_checks.h: every failure one FileError).
class Checker : public detail::JsonChecker {
 public:
  using JsonChecker::JsonChecker;

  /// The core's own checks (spline::validate and friends) for whatever the
  /// JSON-path checks above let through; the message keeps the JSON path.
  template <class Check>
  void core_check(const std::string& path, Check check) const {
    try {
      check();
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
  }

  const Json& array(const Json& v, const std::string& path, const std::string& what) const {
    if (!v.is_array()) fail(path, "expected " + what + ", got " + describe(v));
    return v;
  }

  std::vector<double> numbers(const Json& v, const std::string& path) const {
    std::vector<double> out;
    for (std::size_t i = 0; i < array(v, path, "an array of numbers").size(); ++i)
      out.push_back(number(v[i], index_path(path, i)));
    return out;
  }

  /// A degree: a whole number with 1 <= degree < count (count points).
  int degree(const Json& v, const std::string& path, std::size_t count, const std::string& counted) const {
    const double d = number(v, path);
    if (d != std::floor(d)) fail(path, shortest_text(d) + " (must be a whole number)");
    if (d < 1 || d >= static_cast<double>(count))
      fail(path, shortest_text(d) + " (must be >= 1 and < " + counted + " = " + std::to_string(count) + ")");
    if (d > spline::kMaxDegree)
      fail(path, shortest_text(d) + " (the spline core supports degrees up to " +
                     std::to_string(spline::kMaxDegree) + "; GLU stops at order 24, degree 23)");
    return static_cast<int>(d);
  }

  /// One point: [x, y] or [x, y, z]. dims: 0 = either, 2 or 3 = exactly that.
  Vec3 point(const Json& v, const std::string& path, int dims, const std::string& shape) const {
    if (!v.is_array()) fail(path, "expected a point " + shape + ", got " + describe(v));
    const std::size_t k = v.size();
    const bool ok = dims == 0 ? (k == 2 || k == 3) : k == static_cast<std::size_t>(dims);
    if (!ok) {
      std::string hint = k == 4 ? "; weights go in \"weights\", points are not premultiplied" : "";
      fail(path, "has " + plural(k, "coordinate") + " (expected " + shape + hint + ")");
    }
    Vec3 p;
    p.x = number(v[0], index_path(path, 0));
    p.y = number(v[1], index_path(path, 1));
    if (k == 3) p.z = number(v[2], index_path(path, 2));
    return p;
  }

  /// A list of points of one dimension (2 or 3, stored in *dimension).
  std::vector<Vec3> points(const Json& v, const std::string& path, int dims, const std::string& shape,
                           int* dimension) const {
    array(v, path, "an array of points " + shape);
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string here = index_path(path, i);
      if (dims == 0 && i > 0 && v[i].is_array() && v[i].size() != v[0].size())
        fail(here, "has " + plural(v[i].size(), "coordinate") + ", " + index_path(path, 0) + " has " +
                       std::to_string(v[0].size()));
      out.push_back(point(v[i], here, dims, shape));
    }
    if (dimension && !v.empty()) *dimension = static_cast<int>(v[0].size());
    return out;
  }

  /// A knot vector for count control points of degree p: non-decreasing,
  /// count + p + 1 entries, no value more than p + 1 times, a non-empty domain.
  std::vector<double> knots(const Json& v, const std::string& path, int p, std::size_t count,
                            const std::string& count_words, const std::string& degree_name) const {
    std::vector<double> U = numbers(v, path);
    for (std::size_t i = 1; i < U.size(); ++i)
      if (U[i] < U[i - 1])
        fail(index_path(path, i), shortest_text(U[i]) + " < " + index_path(path, i - 1) + " = " +
                                      shortest_text(U[i - 1]) + " (knots must be non-decreasing)");
    const std::size_t need = count + static_cast<std::size_t>(p) + 1;
    if (U.size() != need)
      fail(path, plural(U.size(), "knot") + ", need " + count_words + " + " + degree_name + " + 1 = " +
                     std::to_string(need));
    for (std::size_t i = 0, first = 0; i < U.size(); ++i) {
      if (U[i] != U[first]) first = i;
      if (i - first + 1 > static_cast<std::size_t>(p) + 1)
        fail(index_path(path, i), shortest_text(U[i]) + " appears " + std::to_string(i - first + 1) +
                                      " times from " + index_path(path, first) + " (at most " + degree_name +
                                      " + 1 = " + std::to_string(p + 1) + ")");
    }
    const std::size_t lo = static_cast<std::size_t>(p), hi = count;  // domain [U[p], U[n + 1]]
    if (!(U[lo] < U[hi]))
      fail(path, "domain [" + index_path(path, lo) + ", " + index_path(path, hi) + "] = [" +
                     shortest_text(U[lo]) + ", " + shortest_text(U[hi]) + "] is empty");
    return U;
  }

  double weight(const Json& v, const std::string& path) const {
    const double w = number(v, path);
    if (!(w > 0)) fail(path, shortest_text(w) + " (weights must be > 0)");
    return w;
  }

  std::vector<double> weights(const Json& v, const std::string& path, std::size_t count,
                              const std::string& points_path) const {
    array(v, path, "an array of weights");
    if (v.size() != count)
      fail(path, plural(v.size(), "weight") + ", " + points_path + " has " + plural(count, "point"));
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(weight(v[i], index_path(path, i)));
    return out;
  }

  // --- the three spline types ---------------------------------------------

  /// dims: 0 for a curve of its own (2D or 3D), 2 for a trim curve.
  BsplineCurve bspline_curve(const Json& v, const std::string& path, int dims) const {
    const std::string kind = "bspline_curve";
    only_keys(v, path, {"type", "degree", "knots", "points", "weights", "parameters"}, kind);
    const std::string shape = dims == 2 ? "[u, v] (trim curves live in the (u, v) domain)" : "[x, y] or [x, y, z]";
    const std::string points_path = member_path(path, "points");
    BsplineCurve c;
    c.P = points(member(v, path, "points", kind), points_path, dims, shape, &c.dimension);
    if (c.P.empty()) fail(points_path, "no points (a curve of degree p needs at least p + 1)");
    c.p = degree(member(v, path, "degree", kind), member_path(path, "degree"), c.P.size(), "number of points");
    c.U = knots(member(v, path, "knots", kind), member_path(path, "knots"), c.p, c.P.size(), "points", "degree");
    if (const Json* w = optional_member(v, "weights"))
      c.w = weights(*w, member_path(path, "weights"), c.P.size(), "points");
    if (const Json* t = optional_member(v, "parameters")) numbers(*t, member_path(path, "parameters"));
    core_check(path, [&] { spline::validate(c); });
    return c;
  }

  BezierCurve bezier_curve(const Json& v) const {
    const std::string kind = "bezier_curve";
    only_keys(v, "", {"type", "points", "interval", "parameters"}, kind);
    BezierCurve c;
    c.P = points(member(v, "", "points", kind), "points", 0, "[x, y] or [x, y, z]", &c.dimension);
    if (c.P.size() < 2)
      fail("points", plural(c.P.size(), "point") + " (a Bézier curve needs at least 2: degree = points - 1 >= 1)");
    if (const Json* interval = optional_member(v, "interval")) {
      if (!interval->is_array() || interval->size() != 2)
        fail("interval", "expected [a, b], got " + describe(*interval));
      c.a = number((*interval)[0], "interval[0]");
      c.b = number((*interval)[1], "interval[1]");
      if (!(c.a < c.b)) fail("interval", "[" + shortest_text(c.a) + ", " + shortest_text(c.b) + "] (need a < b)");
    }
    if (const Json* t = optional_member(v, "parameters")) numbers(*t, "parameters");
    core_check("", [&] { spline::validate(c); });
    return c;
  }

  BsplineSurface bspline_surface(const Json& v) const {
    const std::string kind = "bspline_surface";
    only_keys(v, "", {"type", "degree_u", "degree_v", "knots_u", "knots_v", "points", "weights", "trims"}, kind);
    BsplineSurface s;
    const Json& rows = array(member(v, "", "points", kind), "points", "an array of rows points[i][j] (i along u)");
    if (rows.empty()) fail("points", "no rows (need points[i][j], i along u, j along v)");
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const std::string row_path = index_path("points", i);
      array(rows[i], row_path, "a row of points [[x, y, z], ...]");
      if (rows[i].empty()) fail(row_path, "empty row");
      if (rows[i].size() != rows[0].size())
        fail(row_path, plural(rows[i].size(), "point") + ", points[0] has " + std::to_string(rows[0].size()) +
                           " (every row needs the same number of points along v)");
      const std::vector<Vec3> row =
          points(rows[i], row_path, 3, "[x, y, z] (surface points are 3D)", nullptr);
      s.P.insert(s.P.end(), row.begin(), row.end());
    }
    s.nu = static_cast<int>(rows.size());
    s.nv = static_cast<int>(rows[0].size());
    const auto nu = static_cast<std::size_t>(s.nu), nv = static_cast<std::size_t>(s.nv);
    s.p = degree(member(v, "", "degree_u", kind), "degree_u", nu, "number of points along u (rows)");
    s.q = degree(member(v, "", "degree_v", kind), "degree_v", nv, "number of points along v (per row)");
    s.U = knots(member(v, "", "knots_u", kind), "knots_u", s.p, nu, "points along u", "degree_u");
    s.V = knots(member(v, "", "knots_v", kind), "knots_v", s.q, nv, "points along v", "degree_v");
    if (const Json* w = optional_member(v, "weights")) {
      array(*w, "weights", "rows of weights [[w, ...], ...] shaped like points");
      if (w->size() != nu) fail("weights", plural(w->size(), "row") + ", points has " + plural(nu, "row"));
      for (std::size_t i = 0; i < nu; ++i) {
        const std::vector<double> row =
            weights((*w)[i], index_path("weights", i), nv, index_path("points", i));
        s.w.insert(s.w.end(), row.begin(), row.end());
      }
    }
    core_check("knots_u", [&] { spline::validate_knots(s.p, s.nu, s.U, "U knot vector"); });
    core_check("knots_v", [&] { spline::validate_knots(s.q, s.nv, s.V, "V knot vector", "V"); });
    core_check("", [&] { spline::validate(s); });
    if (const Json* trims = optional_member(v, "trims")) {
      s.trims = trim_loops(*trims);
      check_trims(s);
    }
    return s;
  }

  std::vector<TrimLoop> trim_loops(const Json& v) const {
    array(v, "trims", "an array of loops, each an array of pieces");
    std::vector<TrimLoop> loops;
    for (std::size_t l = 0; l < v.size(); ++l) {
      const std::string loop_path = index_path("trims", l);
      array(v[l], loop_path, "a loop: an array of pieces");
      if (v[l].empty()) fail(loop_path, "empty loop (a loop needs at least one piece)");
      TrimLoop loop;
      for (std::size_t k = 0; k < v[l].size(); ++k)
        loop.pieces.push_back(trim_piece(v[l][k], index_path(loop_path, k)));
      loops.push_back(std::move(loop));
    }
    return loops;
  }

  /// The core's trim validation (trim.h): closed loops inside the domain, no
  /// crossings, outer loops counter-clockwise and holes clockwise. An error
  /// whose values name a loop (TrimLoopError and the like: {loop=1, ...})
  /// goes to the JSON path "trims[1]", its "trim loop 1: " said once, by the
  /// path; any other names "trims".
  void check_trims(const BsplineSurface& s) const {
    try {
      spline::validate_trim_loops(s.trims, spline::uv_domain(s));
    } catch (const spline::SplineError& e) {
      const std::optional<double> loop = e.value("loop");
      if (!loop) fail("trims", e.what());
      const auto l = static_cast<std::size_t>(*loop);
      std::string message = e.what();
      const std::string head = "trim loop " + std::to_string(l) + ": ";
      if (message.compare(0, head.size(), head) == 0) message.erase(0, head.size());
      fail(index_path("trims", l), message);
    }
  }

  TrimPiece trim_piece(const Json& v, const std::string& path) const {
    require_object(v, path, R"(a piece {"type": "polyline", ...} or {"type": "bspline_curve", ...})");
    const std::string type = string(member(v, path, "type", "trim piece"), member_path(path, "type"));
    TrimPiece piece;
    if (type == "polyline") {
      only_keys(v, path, {"type", "points"}, "polyline");
      const std::string points_path = member_path(path, "points");
      for (const Vec3& p : points(member(v, path, "points", "polyline"), points_path, 2, "[u, v]", nullptr))
        piece.polyline.push_back({p.x, p.y});
      if (piece.polyline.size() < 2)
        fail(points_path, plural(piece.polyline.size(), "point") + " (a polyline needs at least 2)");
    } else if (type == "bspline_curve") {
      piece.curve = bspline_curve(v, path, 2);
    } else {
      fail(member_path(path, "type"), describe(v["type"]) + R"( (a trim piece is "polyline" or "bspline_curve"))");
    }
    return piece;
  }

  SplineFile any(const Json& root) const {
    require_object(root, "", R"(a JSON object {"type": ...})");
    const auto it = root.find("type");
    if (it == root.end()) fail("type", std::string("missing (one of ") + kSplineTypes + ")");
    const std::string type = string(*it, "type");
    if (type == "bspline_curve") return bspline_curve(root, "", 0);
    if (type == "bezier_curve") return bezier_curve(root);
    if (type == "bspline_surface") return bspline_surface(root);
    fail("type", describe(*it) + " is not a spline type (one of " + kSplineTypes + ")");
  }

  PointsFile points_file(const Json& root) const {
    require_object(root, "", R"(a JSON object {"points": [[x, y], ...]})");
    only_keys(root, "", {"points", "start_tangent", "end_tangent"}, "points file");
    PointsFile f;
    f.points = points(member(root, "", "points", "points file"), "points", 0, "[x, y] or [x, y, z]", &f.dimension);
    if (f.points.size() < 2) fail("points", plural(f.points.size(), "point") + " (need at least 2 to interpolate)");
    for (const char* key : {"start_tangent", "end_tangent"}) {
      const Json* t = optional_member(root, key);
      if (!t) continue;
      const std::string shape = f.dimension == 2 ? "[x, y] like the points" : "[x, y, z] like the points";
      (key[0] == 's' ? f.start_tangent : f.end_tangent) = point(*t, key, f.dimension, shape);
    }
    return f;
  }

};

// --- parsing -----------------------------------------------------------------

/// Tracks where the parser is, to catch a key given twice in one object
/// (JSON allows it; the last one would silently win).
class DuplicateKeyFinder {
 public:
  /// Thrown at the opening bracket of a value nested deeper than kMaxJsonDepth.
  struct TooDeep {
    std::string path;
  };

  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
    using E = Json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        start_child();
        if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) throw TooDeep{path(false)};
        frames_.emplace_back();
        frames_.back().is_array = event == E::array_start;
        break;
      case E::object_end:
      case E::array_end:
        frames_.pop_back();
        break;
      case E::key: {
        Frame& top = frames_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second && duplicate_.empty()) duplicate_ = path(false);
        break;
      }
      case E::value:
        start_child();
        break;
    }
    return true;
  }
  const std::string& duplicate() const { return duplicate_; }
  /// The path of the value being read now (when the parser stopped in it).
  std::string current_path() const { return path(true); }

 private:
  struct Frame {
    bool is_array = false;
    std::size_t next_index = 0;  // arrays: the index of the next element
    std::set<std::string> keys;  // objects: the keys seen so far
    std::string key;             // objects: the key being read
  };
  /// A value starts in the innermost array: it takes the next index.
  void start_child() {
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().next_index;
  }
  /// Built only when needed (building it at every level would cost
  /// O(depth^2) on deeply nested input). pending: the innermost array's next
  /// element has not started yet.
  std::string path(bool pending) const {
    std::string out;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      const bool innermost = i + 1 == frames_.size();
      if (f.is_array)
        out = index_path(out, innermost && pending ? f.next_index : f.next_index - 1);
      else
        out = member_path(out, f.key);
    }
    return out;
  }
  std::vector<Frame> frames_;
  std::string duplicate_;
};

Json parse_json(const std::string& text, const std::string& source) {
  if (text.size() > kMaxJsonBytes)
    throw FileError(source, "",
                    std::to_string(text.size()) + " bytes, larger than the limit of " +
                        std::to_string(kMaxJsonBytes) + " (kMaxJsonBytes)");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw FileError(source, "", "empty file (expected a JSON object)");
  // nlohmann reads a NUL byte as the end of the input: say what it is.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw FileError(source, "", "NUL byte at offset " + std::to_string(nul) + " (not a JSON text file)");
  DuplicateKeyFinder finder;
  Json root;
  try {
    root = Json::parse(text, std::ref(finder), /*allow_exceptions=*/true, /*ignore_comments=*/false);
  } catch (const Json::parse_error& e) {
    // "[json.exception.parse_error.101] parse error at line 2, column 7: ..."
    std::string message = e.what();
    const std::string marker = "parse error at ";
    const std::size_t at = message.find(marker);
    if (at != std::string::npos) message = message.substr(at + marker.size());
    else if (message.find("] ") != std::string::npos) message = message.substr(message.find("] ") + 2);
    throw FileError(source, "", "JSON syntax error at " + message);
  } catch (const Json::out_of_range& e) {
    // 406: "number overflow parsing '1e400'": a number beyond the double range.
    // JSON has no inf; say where it is and what it would become.
    const std::string message = e.what();
    const std::size_t open = message.find('\''), close = message.rfind('\'');
    if (e.id == 406 && open != std::string::npos && close > open) {
      const std::string token = message.substr(open + 1, close - open - 1);
      throw FileError(source, finder.current_path(),
                      token + " overflows to " + (token[0] == '-' ? "-inf" : "inf") +
                          " (numbers must be finite)");
    }
    throw FileError(source, finder.current_path(), std::string("not valid JSON: ") + e.what());
  } catch (const Json::exception& e) {
    throw FileError(source, finder.current_path(), std::string("not valid JSON: ") + e.what());
  } catch (const DuplicateKeyFinder::TooDeep& e) {
    throw FileError(source, e.path,
                    "nested more than " + std::to_string(kMaxJsonDepth) +
                        " arrays or objects deep (the limit, kMaxJsonDepth)");
  }
  if (!finder.duplicate().empty())
    throw FileError(source, finder.duplicate(), "key appears twice in one object (each key once)");
  return root;
}

std::string read_text(const std::filesystem::path& file) {
  try {
    return files::read_input(file.string(), kMaxJsonBytes);
  } catch (const files::FileError& e) {
    // "path: is a FIFO, not a regular file": the file's name, then the problem.
    const std::string what = e.what(), prefix = file.string() + ": ";
    throw FileError(file.string(), "", what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
  }
}

[[noreturn]] void wrong_type(const std::string& source, const SplineFile& got, const std::string& wanted) {
  static const char* names[] = {"\"bspline_curve\"", "\"bezier_curve\"", "\"bspline_surface\""};
  throw FileError(source, "type", std::string(names[got.index()]) + " where " + wanted + " was expected");
}

BsplineCurve curve_of(SplineFile f, const std::string& source) {
  if (auto* c = std::get_if<BsplineCurve>(&f)) return std::move(*c);
  if (auto* b = std::get_if<BezierCurve>(&f)) return as_bspline(*b);
  wrong_type(source, f, R"(a curve ("bspline_curve" or "bezier_curve"))");
}

BezierCurve bezier_of(SplineFile f, const std::string& source) {
  if (auto* b = std::get_if<BezierCurve>(&f)) return std::move(*b);
  wrong_type(source, f, R"("bezier_curve")");
}

BsplineSurface surface_of(SplineFile f, const std::string& source) {
  if (auto* s = std::get_if<BsplineSurface>(&f)) return std::move(*s);
  wrong_type(source, f, R"("bspline_surface")");
}

// --- writing -----------------------------------------------------------------

Json number_json(double x) {
  if (!std::isfinite(x))
    spline::fail(spline::ErrorCode::kNotFinite,
                 "cannot write " + shortest_text(x) + " to a JSON file (numbers must be finite)", {{"value", x}});
  return Json(x);
}

Json numbers_json(const std::vector<double>& xs) {
  Json out = Json::array();
  for (double x : xs) out.push_back(number_json(x));
  return out;
}

Json point_json(const Vec3& p, int dimension, const std::string& name) {
  Json out = Json::array({number_json(p.x), number_json(p.y)});
  if (dimension == 3) out.push_back(number_json(p.z));
  else if (p.z != 0)
    spline::fail(spline::ErrorCode::kNotPlanar, "a 2D spline has " + name + " = " + point_text(p) + " with z != 0",
                 {{name, p}});
  return out;
}

Json points_json(const std::vector<Vec3>& P, int dimension) {
  if (dimension != 2 && dimension != 3)
    spline::fail(spline::ErrorCode::kDimension, "dimension " + std::to_string(dimension) + " (must be 2 or 3)",
                 {{"dimension", dimension}});
  Json out = Json::array();
  for (std::size_t i = 0; i < P.size(); ++i) out.push_back(point_json(P[i], dimension, spline::at("P", i)));
  return out;
}

void print(const Json& v, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  if (v.is_array()) {
    const bool flat = std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_primitive(); });
    if (v.empty() || flat) {
      out += "[";
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) out += ", ";
        print(v[i], indent, out);
      }
      out += "]";
      return;
    }
    out += "[\n";
    for (std::size_t i = 0; i < v.size(); ++i) {
      out += pad;
      print(v[i], indent + 2, out);
      out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else if (v.is_object()) {
    if (v.empty()) {
      out += "{}";
      return;
    }
    out += "{\n";
    std::size_t i = 0;
    for (const auto& item : v.items()) {
      out += pad + Json(item.key()).dump() + ": ";
      print(item.value(), indent + 2, out);
      out += ++i < v.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else {
    // nlohmann prints a double in its shortest form that reads back
    // bit-identical (Grisu2), always with a '.' or an exponent.
    out += v.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
}

}  // namespace

// --- public: reading -----------------------------------------------------------

BsplineCurve as_bspline(const BezierCurve& b) {
  BsplineCurve c;
  c.p = static_cast<int>(b.P.size()) - 1;
  c.P = b.P;
  c.U.assign(b.P.size(), b.a);
  c.U.insert(c.U.end(), b.P.size(), b.b);
  c.dimension = b.dimension;
  return c;
}

SplineFile from_json(const Json& value, const std::string& source) {
  return Checker(source).any(value);
}

SplineFile parse_any(const std::string& text, const std::string& source) {
  return from_json(parse_json(text, source), source);
}
BsplineCurve parse_curve(const std::string& text, const std::string& source) {
  return curve_of(parse_any(text, source), source);
}
BezierCurve parse_bezier(const std::string& text, const std::string& source) {
  return bezier_of(parse_any(text, source), source);
}
BsplineSurface parse_surface(const std::string& text, const std::string& source) {
  return surface_of(parse_any(text, source), source);
}
PointsFile parse_points(const std::string& text, const std::string& source) {
  return Checker(source).points_file(parse_json(text, source));
}

Json parse_json_text(const std::string& text, const std::string& source) { return parse_json(text, source); }
std::string read_text_file(const std::filesystem::path& file) { return read_text(file); }

SplineFile read_any(const std::filesystem::path& file) { return parse_any(read_text(file), file.string()); }
BsplineCurve read_curve(const std::filesystem::path& file) { return parse_curve(read_text(file), file.string()); }
BezierCurve read_bezier(const std::filesystem::path& file) { return parse_bezier(read_text(file), file.string()); }
BsplineSurface read_surface(const std::filesystem::path& file) {
  return parse_surface(read_text(file), file.string());
}
PointsFile read_points(const std::filesystem::path& file) { return parse_points(read_text(file), file.string()); }

// --- public: writing -----------------------------------------------------------

Json to_json(const BsplineCurve& c) {
  Json out = Json::object();
  out["type"] = "bspline_curve";
  out["degree"] = c.p;
  out["knots"] = numbers_json(c.U);
  out["points"] = points_json(c.P, c.dimension);
  if (c.rational()) out["weights"] = numbers_json(c.w);
  return out;
}

Json to_json(const BezierCurve& c) {
  Json out = Json::object();
  out["type"] = "bezier_curve";
  out["points"] = points_json(c.P, c.dimension);
  if (c.a != 0 || c.b != 1) out["interval"] = Json::array({number_json(c.a), number_json(c.b)});
  return out;
}

Json to_json(const BsplineSurface& s) {
  if (s.nu < 1 || s.nv < 1 || s.P.size() != static_cast<std::size_t>(s.nu) * static_cast<std::size_t>(s.nv))
    spline::fail(spline::ErrorCode::kSizeMismatch,
                 "surface: " + std::to_string(s.P.size()) + " points, need nu * nv = " + std::to_string(s.nu) + " * " +
                     std::to_string(s.nv),
                 {{"P", s.P.size()}, {"nu", s.nu}, {"nv", s.nv}});
  if (s.rational() && s.w.size() != s.P.size())
    spline::fail(spline::ErrorCode::kWeightCount,
                 "surface: " + std::to_string(s.w.size()) + " weights, need " + std::to_string(s.P.size()),
                 {{"w", s.w.size()}, {"points", s.P.size()}});
  Json out = Json::object();
  out["type"] = "bspline_surface";
  out["degree_u"] = s.p;
  out["degree_v"] = s.q;
  out["knots_u"] = numbers_json(s.U);
  out["knots_v"] = numbers_json(s.V);
  Json rows = Json::array(), weight_rows = Json::array();
  for (int i = 0; i < s.nu; ++i) {
    Json row = Json::array(), weight_row = Json::array();
    for (int j = 0; j < s.nv; ++j) {
      row.push_back(point_json(s.point(i, j), 3, "P"));
      weight_row.push_back(number_json(s.weight(i, j)));
    }
    rows.push_back(std::move(row));
    weight_rows.push_back(std::move(weight_row));
  }
  out["points"] = std::move(rows);
  if (s.rational()) out["weights"] = std::move(weight_rows);
  if (!s.trims.empty()) {
    Json loops = Json::array();
    for (const TrimLoop& loop : s.trims) {
      Json pieces = Json::array();
      for (const TrimPiece& piece : loop.pieces) {
        if (piece.curve) {
          BsplineCurve uv = *piece.curve;
          uv.dimension = 2;  // trim curves live in the (u, v) domain
          pieces.push_back(to_json(uv));
        } else {
          Json points = Json::array();
          for (const Vec2& q : piece.polyline) points.push_back(Json::array({number_json(q.x), number_json(q.y)}));
          pieces.push_back(Json{{"type", "polyline"}, {"points", std::move(points)}});
        }
      }
      loops.push_back(std::move(pieces));
    }
    out["trims"] = std::move(loops);
  }
  return out;
}

Json to_json(const SplineFile& spline) {
  return std::visit([](const auto& s) { return to_json(s); }, spline);
}

Json to_json(const PointsFile& f) {
  Json out = Json::object();
  out["points"] = points_json(f.points, f.dimension);
  if (f.start_tangent) out["start_tangent"] = point_json(*f.start_tangent, f.dimension, "start_tangent");
  if (f.end_tangent) out["end_tangent"] = point_json(*f.end_tangent, f.dimension, "end_tangent");
  return out;
}

namespace {

/// JSON has no NaN or infinity (nlohmann would print null): refuse them.
void require_finite_numbers(const Json& value) {
  std::vector<const Json*> stack = {&value};
  while (!stack.empty()) {
    const Json* v = stack.back();
    stack.pop_back();
    if (v->is_number_float() && !std::isfinite(v->get<double>()))
      spline::fail(spline::ErrorCode::kNotFinite,
                   "cannot write " + shortest_text(v->get<double>()) + " to JSON (numbers must be finite)",
                   {{"value", v->get<double>()}});
    if (v->is_structured())
      for (const Json& child : *v) stack.push_back(&child);
  }
}

}  // namespace

std::string to_text(const Json& value) {
  require_finite_numbers(value);
  std::string out;
  print(value, 0, out);
  return out + "\n";
}

std::string to_text(const SplineFile& spline) { return to_text(to_json(spline)); }

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  // Through a symlink, the file it names is replaced. A path that names no
  // regular file (/dev/null, a FIFO, /dev/stdout) is written in place: a
  // rename would replace the device itself.
  std::error_code status;
  std::filesystem::path file = path;
  if (std::filesystem::exists(path, status)) file = std::filesystem::canonical(path, status);
  if (status) file = path;
  if (std::filesystem::exists(file, status) && !std::filesystem::is_regular_file(file, status) &&
      !std::filesystem::is_directory(file, status)) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw FileError(path.string(), "", std::string("cannot write (") + std::strerror(errno) + ")");
    return;
  }
  const std::filesystem::path tmp =
      file.parent_path() / ("." + file.filename().string() + ".tmp-" + std::to_string(getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw FileError(path.string(), "", std::string("cannot write (") + std::strerror(errno) + ")");
    out << text;
    out.close();  // a full disk may only show here
    if (!out) {
      const int error = errno;
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw FileError(path.string(), "", std::string("cannot write (") + std::strerror(error) + ")");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw FileError(path.string(), "", "cannot replace (" + ec.message() + ")");
  }
}

void write_file(const std::filesystem::path& file, const SplineFile& spline) {
  write_text_atomically(file, to_text(spline));
}

}  // namespace gllab::io
