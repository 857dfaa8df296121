// common/spline/forward_differences.h — plotting a cubic by forward differences:
// three additions per point instead of a polynomial evaluation, and the price,
// an error that grows with the number of steps.
//
// Lecture notes "B-Spline Polynomials", "Plotting Uniform Cubic B-Splines":
// the brute-force loop evaluates x = ax t^3 + bx t^2 + cx t + dx at t = 0, δ,
// 2δ, ... and ends "to increase performance, use forward differences" (Foley,
// van Dam, Feiner and Hughes, "Computer Graphics: Principles and Practice",
// 2nd ed., §11.2.9). With δ = 1 / steps and Q(t) = a t^3 + b t^2 + c t + d:
//   Q(0) = d,  Δ1 = a δ^3 + b δ^2 + c δ,  Δ2 = 6 a δ^3 + 2 b δ^2,  Δ3 = 6 a δ^3,
// and each step is Q += Δ1; Δ1 += Δ2; Δ2 += Δ3 (exact in real numbers).
// In floating point each addition rounds, and a rounding error made in Δ2 at
// step k is added into Δ1 and Q at every later step: the error grows with the
// number of steps n (like n times the unit roundoff when the increments are
// tiny against Q), while Horner's rule evaluates every point afresh with an
// error of a few units of roundoff whatever n is.
#pragma once

#include <array>
#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

/// At most this many steps per call, and points per plot (each step makes one point).
inline constexpr int kMaxForwardDifferenceSteps = 1 << 24;

/// Q(k / steps), k = 0..steps, of the cubic with coefficients abcd = (a, b, c, d)
/// (bspline.h uniform_cubic_coefficients gives them), by forward differences
/// carried out in Real (float or double): the coefficients are rounded to Real
/// first, and every operation is done in Real. steps in [1, kMaxForwardDifferenceSteps].
template <class Real>
std::vector<Vec3> cubic_by_forward_differences(const std::array<Vec3, 4>& abcd, int steps);

/// The same points by Horner's rule ((a t + b) t + c) t + d, each point from
/// scratch, t = k / steps, in Real.
template <class Real>
std::vector<Vec3> cubic_by_horner(const std::array<Vec3, 4>& abcd, int steps);

/// The largest distance of a method's points from the exact values (Horner in
/// long double, whose error is far below double's) over k = 0..steps.
enum class CubicMethod { kForwardFloat, kForwardDouble, kHornerFloat, kHornerDouble };
double cubic_plot_error(const std::array<Vec3, 4>& abcd, int steps, CubicMethod method);

/// The notes' plot of a uniform cubic B-spline, one segment per four
/// consecutive points P[i-3..i], i = 3..m, each drawn with `steps` steps by
/// `method` (forward differences in double by default; Horner for comparison):
/// a polyline of (m - 2) steps + 1 points (each segment starts where the
/// previous one ends, so the joints are not repeated). At least 4 finite points;
/// steps as above.
std::vector<Vec3> plot_uniform_cubic_bspline(const std::vector<Vec3>& P, int steps,
                                             CubicMethod method = CubicMethod::kForwardDouble);

}  // namespace gllab::spline
