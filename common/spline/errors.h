// common/spline/errors.h — how the spline core says no.
//
// Bad input throws SplineError, a std::invalid_argument, as text and as data:
//   what()   one line naming the values, for people:
//            "knot vector: U[5]=0.4 < U[4]=0.6 (must be non-decreasing)"
//   code()   the precondition it broke, for programs: ErrorCode::kKnotsDecreasing
//   values() the numbers involved, by name: {i=5, U[5]=0.4, U[4]=0.6}
// A lab or tool that needs the reason reads code() (error_name() spells it
// "knots_decreasing" for printing or files), never the text. The model is
// tinyspline's status codes (tsError: TS_KNOTS_DECR, ...) and GLU's NURBS
// error numbers (GLU_NURBS_ERROR1..37; docs/glu.md): each code below names
// its counterpart where there is one. The helpers keep the messages uniform.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

/// The precondition a call found broken. "TS_" names are tinyspline's tsError,
/// "GLU n" is GLU_NURBS_ERRORn with gluErrorString's text.
enum class ErrorCode {
  // ---- how much input
  /// Nothing given where needed: no points, nodes, segments, evaluator. GLU 36 'null control point reference'
  kEmptyInput = 1,
  /// Fewer points, nodes or samples than needed (degree >= points too). TS_DEG_GE_NCTRLP, TS_NUM_POINTS
  kTooFewPoints,
  /// Sizes that must agree do not (points vs parameters, P vs (n+1)(m+1)). GLU 8 'missing or extra geometric data'
  kSizeMismatch,
  /// Weights given, but not one per control point.
  kWeightCount,
  // ---- degree
  /// Degree < 0, or < 1 where a B-spline needs it.
  kDegreeTooLow,
  /// Degree > kMaxDegree (31). GLU 1 'spline order un-supported' (GLU's order goes to 24)
  kDegreeTooHigh,
  // ---- knots and domain
  /// Knot count != n + p + 2 (or too few for the degree). TS_NUM_KNOTS, GLU 2 'too few knots'
  kKnotCount,
  /// U[i] < U[i-1]. TS_KNOTS_DECR, GLU 4 'decreasing knot sequence knot'
  kKnotsDecreasing,
  /// A knot more than p + 1 times (p after insertion). TS_MULTIPLICITY, GLU 5 'knot multiplicity greater than
  /// order of spline'
  kKnotMultiplicity,
  /// An empty domain or interval: U[p] == U[n+1], a >= b. GLU 3 'valid knot range is empty'
  kEmptyDomain,
  // ---- parameters and indices
  /// A parameter outside the domain (or on its end where an inner one is needed). TS_U_UNDEFINED
  kParameterOutsideDomain,
  /// Parameters not non-decreasing, or nodes not strictly increasing.
  kParametersNotSorted,
  /// Nodes or parameters that must be pairwise distinct coincide.
  kNodesCoincide,
  /// An index, knot span or segment number outside its range. TS_INDEX_ERROR
  kIndexOutOfRange,
  /// A derivative order < 0.
  kNegativeDerivativeOrder,
  // ---- values
  /// A number or point is NaN or infinite.
  kNotFinite,
  /// A weight <= 0.
  kWeightNotPositive,
  /// A dimension other than 2 or 3. TS_DIM_ZERO
  kDimension,
  /// A point of a 2D curve or of a trim curve has z != 0.
  kNotPlanar,
  /// A tolerance <= 0 (< 0 where 0 is allowed) or not finite.
  kToleranceNotPositive,
  /// Another number outside its documented range (r, radius, continuity k, depths, steps).
  kOutOfRange,
  // ---- geometry and numerics
  /// Points that must differ coincide (a zero chord, all points at one spot, P[n] == P[0]).
  kCoincidentPoints,
  /// A vector or step that must not vanish does (zero tangent, zero direction).
  kDegenerate,
  /// The linear system has no unique solution (a zero pivot).
  kSingularMatrix,
  /// A rational curve where the call takes polynomial ones only.
  kRationalNotSupported,
  /// Pieces to join differ in degree or do not meet (parameter, end point, shared edge).
  kPiecesDoNotJoin,
  // ---- trim loops (trim.h, TrimLoopError; GLU's keep-left rule)
  /// A loop without pieces (other piece problems carry their own code). GLU 18 'invalid or missing trim curve'
  kTrimBadPiece,
  /// A piece ends where the next does not start. GLU 31 'unconnected trim curves'
  kTrimNotClosed,
  /// A trim point beyond the surface's (u, v) domain (GLU draws it).
  kTrimOutsideDomain,
  /// A polygon lists a point twice in a row. GLU 37 'duplicate point on piecewise linear trimming curve'
  kTrimRepeatedPoint,
  /// Two trim edges cross or touch. GLU 28, GLU 29 'intersecting trim curves'
  kTrimCrossing,
  /// A loop of zero signed area.
  kTrimZeroArea,
  /// An outer loop runs clockwise. GLU 28 'intersecting or misoriented trim curves'
  kTrimOuterClockwise,
  /// A hole runs counter-clockwise. GLU 28
  kTrimHoleCounterClockwise,  // the last code (errors_test walks them all up to it)
};

/// The code in snake case without the k: "knots_decreasing" (stable, for printing and files).
const char* error_name(ErrorCode code);

/// One number an error names: {"U[5]", 0.4}. Indices and counts are stored as doubles (exact below 2^53).
struct ErrorValue {
  std::string name;
  double value = 0;
};
/// Same name and value; a NaN equals a NaN here (a "not finite" error names one).
inline bool operator==(const ErrorValue& a, const ErrorValue& b) {
  return a.name == b.name && (a.value == b.value || (std::isnan(a.value) && std::isnan(b.value)));
}
inline bool operator!=(const ErrorValue& a, const ErrorValue& b) { return !(a == b); }

/// What the core throws. what() is the message; code() and values() the same as data.
class SplineError : public std::invalid_argument {
 public:
  SplineError(ErrorCode code, const std::string& message, std::vector<ErrorValue> values = {})
      : std::invalid_argument(message),
        code_(code),
        values_(std::make_shared<const std::vector<ErrorValue>>(std::move(values))) {}
  ErrorCode code() const noexcept { return code_; }
  const std::vector<ErrorValue>& values() const noexcept { return *values_; }
  /// The value called `name` (the first, if several are), or nothing.
  std::optional<double> value(std::string_view name) const {
    for (const ErrorValue& v : *values_)
      if (v.name == name) return v.value;
    return std::nullopt;
  }

 private:
  ErrorCode code_;
  std::shared_ptr<const std::vector<ErrorValue>> values_;  // shared: copying an exception must not throw
};

/// "knots_decreasing {i=5, U[5]=0.4, U[4]=0.6}": the data of an error on one line.
std::string describe(const SplineError& error);

/// Shortest text that reads back as the same double: 40, 0.4, 1e-07, nan, inf.
inline std::string num(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);  // shortest round trip
  return std::string(buffer, result.ptr);
}

inline std::string num(Vec3 p) { return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")"; }
inline std::string num(Vec2 p) { return "(" + num(p.x) + ", " + num(p.y) + ")"; }

/// One entry of fail()'s value list: a number ({"i", 5}), or a point, which
/// becomes name.x, name.y (and name.z): {"P[3]", p}.
class ErrorArg {
 public:
  template <class T, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
  ErrorArg(std::string name, T value) : name_(std::move(name)), count_(1), v_{static_cast<double>(value), 0, 0} {}
  ErrorArg(std::string name, Vec2 p) : name_(std::move(name)), count_(2), v_{p.x, p.y, 0} {}
  ErrorArg(std::string name, Vec3 p) : name_(std::move(name)), count_(3), v_{p.x, p.y, p.z} {}
  void append_to(std::vector<ErrorValue>& out) const {
    if (count_ == 1) {
      out.push_back({name_, v_[0]});
      return;
    }
    static constexpr const char* kAxis[] = {".x", ".y", ".z"};
    for (int k = 0; k < count_; ++k) out.push_back({name_ + kAxis[k], v_[k]});
  }

 private:
  std::string name_;
  int count_;
  double v_[3];
};

inline std::vector<ErrorValue> error_values(std::initializer_list<ErrorArg> args) {
  std::vector<ErrorValue> out;
  for (const ErrorArg& a : args) a.append_to(out);
  return out;
}

/// Throws SplineError(code, message, values). Every check in the core ends here.
[[noreturn]] inline void fail(ErrorCode code, const std::string& message, std::initializer_list<ErrorArg> values = {}) {
  throw SplineError(code, message, error_values(values));
}

/// The same error with `prefix` before its message and `context` before its
/// values, the code kept: "patch 3: " + what(), {patch=3, ...}.
inline SplineError with_context(const SplineError& e, const std::string& prefix,
                                std::initializer_list<ErrorArg> context) {
  std::vector<ErrorValue> values = error_values(context);
  values.insert(values.end(), e.values().begin(), e.values().end());
  return SplineError(e.code(), prefix + e.what(), std::move(values));
}

/// Throws "<what>: <name>=<value> is not finite" (kNotFinite, {name: value}) for NaN or infinity.
inline void require_finite(double v, const std::string& what, const std::string& name) {
  if (!std::isfinite(v)) fail(ErrorCode::kNotFinite, what + ": " + name + "=" + num(v) + " is not finite", {{name, v}});
}
inline void require_finite(Vec3 p, const std::string& what, const std::string& name) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    fail(ErrorCode::kNotFinite, what + ": " + name + "=" + num(p) + " is not finite", {{name, p}});
}
inline void require_finite(Vec2 p, const std::string& what, const std::string& name) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    fail(ErrorCode::kNotFinite, what + ": " + name + "=" + num(p) + " is not finite", {{name, p}});
}

/// "P[3]" style names for messages.
inline std::string at(const std::string& array, std::size_t i) { return array + "[" + std::to_string(i) + "]"; }

}  // namespace gllab::spline
