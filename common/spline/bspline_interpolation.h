// common/spline/bspline_interpolation.h — cubic B-spline interpolation set up as in
// the lecture notes "Higher Order Surfaces", "Interpolation": data X_0..X_{n-2} at the
// breakpoints, Q(t_{i+3}) = X_i, closed by the two extra constraints p_0 = p_1 and
// p_n = p_{n-1}.
//
// With these end conditions the curve starts and ends with zero velocity
// (Q'(t_3) = 3 (p_1 - p_0) / (t_4 - t_1) = 0 on end-clamped knots). So on the
// clamped knot vector this is the clamped cubic spline of cubic_spline.h with both
// end tangents zero, and it differs from any clamped spline with non-zero end
// tangents; the natural spline differs as well (S'' = 0 instead of S' = 0).
#pragma once

#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

/// Control points p_0..p_n of the cubic B-spline on the knot vector U (n + 5 knots,
/// non-decreasing, the breakpoints U[3..n+1] strictly increasing) that passes
/// through X_i at U[i + 3], i = 0..n-2, with p_0 = p_1 and p_n = p_{n-1}.
/// Each row is X_i = alpha_i p_i + beta_i p_{i+1} + Gamma_i p_{i+2} with the notes'
/// alpha_i = N_{i,4}(t_{i+3}), beta_i = N_{i+1,4}(t_{i+3}), Gamma_i = N_{i+2,4}(t_{i+3})
/// from the notes' closed forms (a 0/0 term counts as 0). Substituting the end
/// constraints leaves a tridiagonal system in p_1..p_{n-1} (tridiagonal.h).
/// Needs X.size() >= 2 and U.size() == X.size() + 6; else std::invalid_argument.
BsplineCurve notes_interpolating_bspline(const std::vector<double>& U, const std::vector<Vec3>& X);

/// The notes' knot vector for data at parameters t_0 < ... < t_m: the breakpoints are
/// the parameters, each end knot repeated four times (clamped).
std::vector<double> notes_clamped_knots(const std::vector<double>& params);

}  // namespace gllab::spline
