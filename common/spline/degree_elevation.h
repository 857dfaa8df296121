// common/spline/degree_elevation.h — degree elevation of a B-spline or NURBS
// curve, A5.9 DegreeElevateCurve (The NURBS Book, 2nd ed., p. 206).
#pragma once

#include "spline/types.h"

namespace gllab::spline {

/// A5.9 DegreeElevateCurve (p. 206): the same curve at degree p + t (t >= 0).
/// Rational curves are elevated in homogeneous space. A5.9 needs clamped ends,
/// so an unclamped curve is first clamped (same curve on the same domain, end
/// knots of multiplicity p + 1); the result is always clamped. A break (an
/// interior knot of multiplicity p + 1) is kept: the pieces between breaks are
/// elevated separately and joined. Interior knots gain t in multiplicity.
BsplineCurve degree_elevate(const BsplineCurve& curve, int t = 1);

}  // namespace gllab::spline
