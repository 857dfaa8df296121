// common/spline/fast/curve_batch.h — the fast layer for curves: many points
// (and first derivatives) of one curve at once. Computes what curve_point and
// curve_derivs (bspline.h) compute; tested to agree with them to 1e-12 of the
// curve's size (CurvePoints.BatchedEvaluatorEqualsPerPointEvaluator in
// tests/spline/bspline_test.cpp); how it is made fast: fast/curve_batch.cpp.
#pragma once

#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

/// Batched evaluation at non-decreasing parameters inside the domain: out[k] =
/// C(sorted_u[k]). Walks the spans forward (no binary search per point) and
/// checks the curve once. Throws if sorted_u decreases or leaves the domain.
/// Agrees with curve_point() to rounding, not bit for bit (it multiplies by
/// per-span reciprocals where A2.2 divides), and gives the same bits on every
/// CPU; how it is made fast is explained in fast/curve_batch.cpp.
void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out);
/// The same with first derivatives: derivs[k] = C'(sorted_u[k]).
void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out,
                  std::vector<Vec3>& derivs);

}  // namespace gllab::spline
