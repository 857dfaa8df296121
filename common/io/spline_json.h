// common/io/spline_json.h — curves and surfaces in JSON files.
//
// The format is fixed (other tools read these files); common/io/README.md
// documents every key. In short:
//   {"type": "bspline_curve", "degree": 3, "knots": [...], "points": [[x, y, z], ...],
//    "weights": [...]}                        weights optional: present = NURBS
//   {"type": "bezier_curve", "points": [...], "interval": [a, b]}   interval optional
//   {"type": "bspline_surface", "degree_u": 3, "degree_v": 3, "knots_u": [...],
//    "knots_v": [...], "points": [[[x, y, z], ...], ...], "weights": [[...]],
//    "trims": [loop, ...]}                    points[i][j]: i along u, j along v
// Points in files are NOT premultiplied by their weights (the core's Pw is).
//
// A bad file throws FileError with ONE line naming the file and the JSON path:
//   "circle.json: knots[5]: 0.4 < knots[4] = 0.6 (knots must be non-decreasing)"
// Writing prints every double so that it reads back bit-identical, and
// replaces the file atomically (temporary file + rename).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "spline/types.h"

namespace gllab::io {

/// Objects keep their keys in the order written ("type" first).
using Json = nlohmann::ordered_json;

/// A file (or text) that cannot be read or written. what() is one line:
/// "<file>: <json path>: <problem>", or "<file>: <problem>" when the problem
/// is the file itself (missing, empty, a syntax error at line L, column C).
class FileError : public std::runtime_error {
 public:
  FileError(std::string file, std::string json_path, std::string problem);
  const std::string& file() const { return file_; }
  const std::string& json_path() const { return json_path_; }  // "" for the file as a whole
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, json_path_, problem_;
};

/// What a spline file holds: its "type" picks the alternative.
using SplineFile = std::variant<spline::BsplineCurve, spline::BezierCurve, spline::BsplineSurface>;

/// The points file `splinetool interpolate` reads:
/// {"points": [[x, y], ...], "start_tangent": [...], "end_tangent": [...]}.
struct PointsFile {
  std::vector<spline::Vec3> points;  // at least 2, all of one dimension
  int dimension = 3;                 // 2 or 3 (2D points have z = 0)
  std::optional<spline::Vec3> start_tangent, end_tangent;  // same dimension as the points
};

// --- reading a file ------------------------------------------------------------
SplineFile read_any(const std::filesystem::path& file);
/// A "bspline_curve", or a "bezier_curve" as the same curve written as a
/// B-spline (knots a repeated p + 1 times, then b repeated p + 1 times).
spline::BsplineCurve read_curve(const std::filesystem::path& file);
spline::BezierCurve read_bezier(const std::filesystem::path& file);
spline::BsplineSurface read_surface(const std::filesystem::path& file);
PointsFile read_points(const std::filesystem::path& file);

// --- reading text (source names the text in messages) -------------------------
SplineFile parse_any(const std::string& text, const std::string& source = "<string>");
spline::BsplineCurve parse_curve(const std::string& text, const std::string& source = "<string>");
spline::BezierCurve parse_bezier(const std::string& text, const std::string& source = "<string>");
spline::BsplineSurface parse_surface(const std::string& text, const std::string& source = "<string>");
PointsFile parse_points(const std::string& text, const std::string& source = "<string>");

/// The Bézier curve over [a, b] written as a B-spline: the same points, knots
/// a repeated p + 1 times then b repeated p + 1 times (The NURBS Book §2.2:
/// on that knot vector the B-splines are the Bernstein polynomials).
spline::BsplineCurve as_bspline(const spline::BezierCurve& bezier);

// --- limits (common/io/README.md lists them) -----------------------------------

/// The deepest nesting of arrays and objects a JSON file may have. A spline
/// file nests 4 levels (the file, "points", a row of a surface, a point); a
/// CSG tree up to two per node ({"op": ..., "children": [...]}), so its own
/// limit of kCsgMaxDepth = 64 nodes (csg_json.h) needs about 130; the deepest
/// example (examples/csg/classic.json) has 10. Checked while parsing, at the
/// opening bracket, so nothing deeper is ever built (nor copied, nor freed by
/// recursion).
inline constexpr int kMaxJsonDepth = 256;
/// The largest JSON file read: 8 MiB (the examples are under 2 KB; a file at
/// the limit holds about a million numbers and parses in well under a second).
inline constexpr std::uintmax_t kMaxJsonBytes = std::uintmax_t{8} << 20;

/// The JSON text of a file, parsed with this format's rules: an empty file, a
/// NUL byte, a syntax error (line and column), a number that overflows to
/// inf, a key given twice in one object, nesting deeper than kMaxJsonDepth
/// and text longer than kMaxJsonBytes are FileErrors naming source.
/// Other JSON formats of common/io (field_json.h, csg_json.h) share it.
Json parse_json_text(const std::string& text, const std::string& source);
/// A file's bytes: FileError naming it when it is not a regular file (a
/// directory, a FIFO, a device: files/files.h), is larger than kMaxJsonBytes,
/// or cannot be read.
std::string read_text_file(const std::filesystem::path& file);

/// Checks an already parsed JSON value as a spline file (same checks and
/// messages as parse_any).
SplineFile from_json(const Json& value, const std::string& source = "<json>");

// --- writing -------------------------------------------------------------------
Json to_json(const spline::BsplineCurve& curve);
Json to_json(const spline::BezierCurve& curve);
Json to_json(const spline::BsplineSurface& surface);
Json to_json(const SplineFile& spline);
Json to_json(const PointsFile& points);

/// The file layout: two-space indent, an array of numbers on one line (so
/// each point is one line), a trailing newline. Doubles are printed in their
/// shortest form that reads back bit-identical. Throws std::invalid_argument
/// for a NaN or infinite number (JSON has none).
std::string to_text(const Json& value);
std::string to_text(const SplineFile& spline);

/// The shortest text that reads back to the same double: 40, 0.4, 1e-07,
/// 0.7071067811865476, inf (std::to_chars). Used in messages and OBJ files.
std::string shortest_text(double x);

/// Writes to_text(spline) to file atomically; throws FileError.
void write_file(const std::filesystem::path& file, const SplineFile& spline);
/// Writes text to file atomically: a temporary file beside it, then rename().
/// A reader never sees half a file. Throws FileError naming the file.
void write_text_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace gllab::io
