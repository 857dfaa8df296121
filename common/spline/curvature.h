// common/spline/curvature.h — how sharply a curve bends, from its derivatives.
//
// For a regular curve X(u) (X'(u) != 0) with d1 = X'(u) and d2 = X''(u)
// (do Carmo, "Differential Geometry of Curves and Surfaces", 1976, §1-5):
//   curvature          k   = |d1 x d2| / |d1|^3
//   signed curvature   k_s = (x' y'' - y' x'') / |d1|^3   (in the xy plane;
//                      > 0 where the curve turns left, counter-clockwise)
//   curvature vector   k N = ((d1 x d2) x d1) / |d1|^4    (towards the centre
//                      of the osculating circle, length k)
// None depends on the parameterization: a curve run faster or slower, or
// backwards, bends the same (the sign of k_s follows the direction). That is
// why a curvature comb (a tooth of length k along N at each sample) shows a
// curve's shape, e.g. a spline's overshoot, and not how it is parameterized.
// The derivatives come from the curve's own evaluator (bezier_derivatives,
// spline_derivative, curve_derivatives).
#pragma once

#include "spline/vec.h"

namespace gllab::spline {

/// k = |d1 x d2| / |d1|^3 >= 0. Throws std::invalid_argument naming d1 when
/// d1 is zero (no tangent: the curve is not regular there) or anything is not finite.
double curvature(Vec3 d1, Vec3 d2);

/// k_s = (d1.x d2.y - d1.y d2.x) / |d1|^3, the curvature of the curve's
/// projection into the xy plane with its sign (> 0: turning left). Throws
/// when (d1.x, d1.y) is zero or anything is not finite.
double signed_curvature(Vec3 d1, Vec3 d2);

/// k N = ((d1 x d2) x d1) / |d1|^4: the principal normal scaled by the
/// curvature, pointing to the centre of curvature (zero on a straight piece).
/// Throws like curvature().
Vec3 curvature_vector(Vec3 d1, Vec3 d2);

}  // namespace gllab::spline
