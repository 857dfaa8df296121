// common/spline/errors.cpp — see errors.h.
#include "spline/errors.h"

#include <string>

namespace gllab::spline {

const char* error_name(ErrorCode code) {
  switch (code) {
    case ErrorCode::kEmptyInput: return "empty_input";
    case ErrorCode::kTooFewPoints: return "too_few_points";
    case ErrorCode::kSizeMismatch: return "size_mismatch";
    case ErrorCode::kWeightCount: return "weight_count";
    case ErrorCode::kDegreeTooLow: return "degree_too_low";
    case ErrorCode::kDegreeTooHigh: return "degree_too_high";
    case ErrorCode::kKnotCount: return "knot_count";
    case ErrorCode::kKnotsDecreasing: return "knots_decreasing";
    case ErrorCode::kKnotMultiplicity: return "knot_multiplicity";
    case ErrorCode::kEmptyDomain: return "empty_domain";
    case ErrorCode::kParameterOutsideDomain: return "parameter_outside_domain";
    case ErrorCode::kParametersNotSorted: return "parameters_not_sorted";
    case ErrorCode::kNodesCoincide: return "nodes_coincide";
    case ErrorCode::kIndexOutOfRange: return "index_out_of_range";
    case ErrorCode::kNegativeDerivativeOrder: return "negative_derivative_order";
    case ErrorCode::kNotFinite: return "not_finite";
    case ErrorCode::kWeightNotPositive: return "weight_not_positive";
    case ErrorCode::kDimension: return "dimension";
    case ErrorCode::kNotPlanar: return "not_planar";
    case ErrorCode::kToleranceNotPositive: return "tolerance_not_positive";
    case ErrorCode::kOutOfRange: return "out_of_range";
    case ErrorCode::kCoincidentPoints: return "coincident_points";
    case ErrorCode::kDegenerate: return "degenerate";
    case ErrorCode::kSingularMatrix: return "singular_matrix";
    case ErrorCode::kRationalNotSupported: return "rational_not_supported";
    case ErrorCode::kPiecesDoNotJoin: return "pieces_do_not_join";
    case ErrorCode::kTrimBadPiece: return "trim_bad_piece";
    case ErrorCode::kTrimNotClosed: return "trim_not_closed";
    case ErrorCode::kTrimOutsideDomain: return "trim_outside_domain";
    case ErrorCode::kTrimRepeatedPoint: return "trim_repeated_point";
    case ErrorCode::kTrimCrossing: return "trim_crossing";
    case ErrorCode::kTrimZeroArea: return "trim_zero_area";
    case ErrorCode::kTrimOuterClockwise: return "trim_outer_clockwise";
    case ErrorCode::kTrimHoleCounterClockwise:
      return "trim_hole_counter_clockwise";
  }
  return "unknown";  // a value cast from outside the enumeration
}

std::string describe(const SplineError& error) {
  std::string s = std::string(error_name(error.code())) + " {";
  for (std::size_t k = 0; k < error.values().size(); ++k)
    s += (k ? ", " : "") + error.values()[k].name + "=" + num(error.values()[k].value);
  return s + "}";
}

}  // namespace gllab::spline
