// common/spline/trim.h — trim loops in the (u, v) domain of a surface:
// flattening to polygons, validation, orientation, and the inside test.
//
// GLU's rule (docs/glu.md, "Trimming keeps the left side"; the Red Book's trim example): the trimmed
// surface keeps what lies to the LEFT of each trim curve. So an outer loop runs
// counter-clockwise, a hole inside it clockwise, an island inside the hole
// counter-clockwise again; every loop is closed and no two curves cross.
// GLU reports a broken rule as a NURBS error number; this core throws
// TrimLoopError (a SplineError, errors.h: a code, the values, and a message
// that names the loop and the point),
// e.g. "trim loop 1: not closed: piece 2 ends at (0.5, 0.9), piece 0 starts at (0.5, 1)".
//
// Notation: a TrimLoop (types.h) is a chain of pieces, each a polyline or a 2D
// B-spline/NURBS curve (x = u, y = v). Flattening turns a loop into a
// TrimPolygon: the closed polygon through its points, first point NOT repeated
// at the end, so edge k runs from point k to point (k + 1) % size.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/errors.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

/// A closed polygon in (u, v); edge k joins points[k] and points[(k + 1) % n].
using TrimPolygon = std::vector<Vec2>;

/// The parameter rectangle [u0, u1] x [v0, v1] of a surface.
struct UvDomain {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
};

/// How far (in u, v units) one piece may end from where the next one starts
/// and still count as joined. GLU wants the ends to meet; a file written with
/// 6 decimals, or a curve end evaluated in floating point, misses by far less.
inline constexpr double kTrimClosureTolerance = 1e-7;

/// How far (in u, v units) a trim point may lie outside the domain and still
/// count as on its edge (round-off of an evaluated curve end).
inline constexpr double kTrimDomainSlack = 1e-12;

/// Default chordal tolerance (u, v units) for flattening curve pieces when no
/// surface is involved (validation, the inside test, drawing in the domain).
inline constexpr double kTrimFlattenTolerance = 1e-4;

/// What the flattening and validation below throw for a bad loop: the
/// message documented at each function (what()), and the same as data, so a
/// program shows the loop and the rule without parsing the text. A SplineError
/// (errors.h): code() is the precondition (kTrimNotClosed, ..., or for a bad
/// piece the piece's own: kTooFewPoints, kNotFinite, kNotPlanar, or whatever
/// its curve broke), values() start with {loop, ...}.
struct TrimLoopError : SplineError {
  enum class Kind {
    kBadPiece,              // a piece without points, not finite, or a broken curve
    kNotClosed,             // a piece ends where the next does not start
    kOutsideDomain,         // a point beyond the surface's (u, v) domain
    kRepeatedPoint,         // a TrimPolygon lists a point twice in a row
    kTooFewPoints,          // fewer than 3 distinct points
    kCrossing,              // two edges cross or touch
    kZeroArea,
    kOuterClockwise,        // an outer loop (even depth) runs clockwise
    kHoleCounterClockwise,  // a hole (odd depth) runs counter-clockwise
  };
  /// The code a kind stands for when no finer one is given (kBadPiece: kTrimBadPiece).
  static ErrorCode code_of(Kind kind);
  /// code_of(kind), values {loop}.
  TrimLoopError(Kind kind, std::size_t loop, const std::string& message, std::string summary,
                std::string rule = "")
      : TrimLoopError(code_of(kind), {{"loop", static_cast<double>(loop)}}, kind, loop, message,
                      std::move(summary), std::move(rule)) {}
  TrimLoopError(ErrorCode code, std::vector<ErrorValue> values, Kind kind, std::size_t loop,
                const std::string& message, std::string summary, std::string rule = "")
      : SplineError(code, message, std::move(values)),
        kind(kind),
        loop(loop),
        summary(std::move(summary)),
        rule(std::move(rule)) {}
  Kind kind;
  std::size_t loop;     // the loop at fault (for a crossing, the later of the two)
  std::string summary;  // a few words without numbers: "runs clockwise", "is not closed"
  std::string rule;     // the rule it breaks, or empty: "outer loops must run counter-clockwise"
};

// ---- flattening ------------------------------------------------------------

/// The closed polygon of one loop: polyline pieces point by point, curve pieces
/// flattened adaptively (flatten_curve, tessellate.h) to the chordal tolerance
/// `tolerance` in (u, v) units, using curve_point (bspline.h). Where one piece
/// ends and the next starts within kTrimClosureTolerance, the start point is
/// dropped; a last point equal to the first is dropped too. Consecutive
/// duplicate points are removed.
/// Throws (naming loop `loop_index`, piece and point) when a piece is empty,
/// a point is not finite, a curve piece is not a valid curve, or the loop is
/// not closed — see validate_trim_loops for the messages.
TrimPolygon flatten_trim_loop(const TrimLoop& loop, double tolerance = kTrimFlattenTolerance,
                              std::size_t loop_index = 0);

/// Flattens one curve piece: its (u, v) points from its start to its end.
using TrimCurveFlattener = std::function<std::vector<Vec2>(const BsplineCurve& curve)>;

/// The same with curve pieces flattened by `flatten_piece` — e.g. the
/// tessellator flattens S(C(t)) on the surface, so the tolerance holds in 3D.
/// The piece is checked (validate, z == 0) before flatten_piece sees it.
TrimPolygon flatten_trim_loop(const TrimLoop& loop, const TrimCurveFlattener& flatten_piece,
                              std::size_t loop_index = 0);

// ---- area and orientation -----------------------------------------------------

/// Signed area by the shoelace formula (Gauss's area formula): positive for a
/// counter-clockwise polygon, negative for a clockwise one, 0 when degenerate.
double signed_area(const TrimPolygon& polygon);

enum class Orientation { CounterClockwise, Clockwise, Degenerate };
/// The sign of signed_area: the orientation GLU's keep-left rule reads.
Orientation orientation(const TrimPolygon& polygon);
const char* to_string(Orientation orientation);

/// The same points in reverse order (a hole becomes an outer loop and back).
TrimPolygon reversed(const TrimPolygon& polygon);

// ---- validation ------------------------------------------------------------------

/// What validate_trim_loops learned about each loop: nesting depth (how many
/// other loops contain it) and the innermost loop that contains it (-1: none).
/// Even depth = outer loop (counter-clockwise), odd depth = hole (clockwise).
struct TrimLoopInfo {
  int depth = 0;
  int parent = -1;
  double area = 0;  // signed area of the flattened polygon
};

/// Checks polygons as GLU would have them, in this order, and throws
/// TrimLoopError (a std::invalid_argument) on the first failure:
///   - a point not finite or outside `domain` (beyond kTrimDomainSlack):
///       "trim loop 0: point 3 (1.5, 0.5) lies outside the domain [0, 1] x [0, 1]"
///   - fewer than 3 distinct points: "trim loop 0: has 2 points (a loop needs at least 3)"
///   - two edges that cross or touch (the same loop, or two loops; edges next to
///     each other in one loop may only share their common point):
///       "trim loop 2: edge 3 (0.2, 0.2)-(0.8, 0.8) crosses edge 7 of loop 0 at (0.5, 0.5)"
///     (the later edge in loop order is named first, and the earliest such pair is reported)
///   - zero area: "trim loop 0: has zero area (signed area 0)"
///   - an outer loop (even depth) that runs clockwise:
///       "trim loop 0 (outer) runs clockwise (signed area -0.25); outer loops must run counter-clockwise"
///   - a hole (odd depth) that runs counter-clockwise:
///       "trim loop 1 (hole in loop 0) runs counter-clockwise (signed area 0.04); holes must run clockwise"
/// A clockwise loop that lies in no other loop has depth 0, so it is reported
/// as an outer loop: a hole must lie inside an outer loop.
std::vector<TrimLoopInfo> validate_trim_polygons(const std::vector<TrimPolygon>& polygons, UvDomain domain);

/// Checks the loops piece by piece, flattens them (flatten_trim_loop) and
/// checks the polygons (validate_trim_polygons). Returns the polygons.
/// Piece-level messages:
///   "trim loop 0: has no pieces"
///   "trim loop 0: piece 1 has 1 point (a polyline piece needs at least 2)"
///   "trim loop 0: piece 1 point 2 (nan, 0) is not finite"
///   "trim loop 0: piece 1 point 2 (1.5, 0.5) lies outside the domain [0, 1] x [0, 1]"
///   "trim loop 0: piece 1 (curve) at t=0.25 (1.5, 0.5) lies outside the domain [0, 1] x [0, 1]"
///   "trim loop 0: piece 1 (curve): <what validate(BsplineCurve) says>"
///   "trim loop 1: not closed: piece 2 ends at (0.5, 0.9), piece 0 starts at (0.5, 1)"
std::vector<TrimPolygon> validate_trim_loops(const std::vector<TrimLoop>& loops, UvDomain domain,
                                             double tolerance = kTrimFlattenTolerance);

// ---- inside test -------------------------------------------------------------

/// Contribution of the directed edge a -> b to the winding number of p, by the
/// crossing rule of Sunday ("Inclusion of a point in a polygon", 2001): an edge
/// crossing the ray from p towards +u upward with p on its left counts +1, one
/// crossing downward with p on its right counts -1. The half-open rule
/// (a.y <= p.y < b.y) counts a vertex on the ray exactly once.
int edge_winding(Vec2 a, Vec2 b, Vec2 p);

/// How many times the polygon winds counter-clockwise around p (negative for
/// clockwise). Undefined for p exactly on the polygon.
int winding_number(const TrimPolygon& polygon, Vec2 p);
/// The sum over all loops.
int winding_number(const std::vector<TrimPolygon>& polygons, Vec2 p);

/// Is p in the trimmed region? With no loops, the whole domain is kept.
/// Otherwise p is kept when the loops wind around it a positive number of times
/// (the nonzero-winding rule, counting orientation). Why this is GLU's
/// keep-left rule: for valid loops (nested, alternating orientation) a point
/// inside an outer loop and inside k of the holes/islands nested in it has
/// winding 1 - 1 + 1 ... = 1 (kept) or 0 (cut away): exactly what "keep the
/// left side of every curve" keeps. Even-odd counting gives the same answer for
/// valid loops but ignores orientation, so a reversed loop would still look
/// right; the winding rule shows the mistake (a lone clockwise loop keeps nothing).
/// Points on a trim edge: either answer may come back.
bool inside_trimmed(const std::vector<TrimPolygon>& polygons, Vec2 p);

/// "[0, 1] x [0, 1]", as used in the messages.
std::string to_string(UvDomain domain);

}  // namespace gllab::spline
