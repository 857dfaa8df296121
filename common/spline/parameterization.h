// common/spline/parameterization.h — parameter values t_i for points P_i.
//
// Interpolating points P_0..P_n with a parametric curve X(t) first needs the
// nodes t_0 < t_1 < ... < t_n with X(t_i) = P_i (ch. 1 §1.6, "Algorithm for
// parametric cubic curves", step 1). Read t as time: the choice says how long
// the curve takes from one point to the next, and it shapes the curve.
//
// Every method here starts at t_0 = 0 and lets each step t_{i+1} - t_i be a
// length: the lecture's normalizing factor s is 1 (the lecture's own chordal example
// runs over [0, 8.13] the same way). unit_interval_parameters() rescales to [0, 1].
//
//   kUniform      equidistant: t_{i+1} - t_i = 1
//   kChordal      t_{i+1} - t_i = |P_{i+1} - P_i|                 (chord length)
//   kCentripetal  t_{i+1} - t_i = sqrt|P_{i+1} - P_i|             [Lee 1975]
//   kFoley        chord length corrected by the turning angles at both ends
//                 of the chord, measured in the Nielson metric     [Foley 1989]
//   kNielson      chord length measured in the Nielson metric, which whitens
//                 the point cloud by its covariance: affine invariant
//
// kFoley and kNielson are the "affine invariant angle" and "affine invariant
// chord" of ch. 1 §1.6, figure 3 (d) and (c): an affine map of the points
// (shear, scale, rotation, translation) leaves their parameters unchanged.
//
// closed = true adds the closing chord from P_n back to P_0, so t has n + 2
// entries and t_{n+1} is where a closed curve returns to P_0. Give each point
// once: the first point is not repeated at the end.
#pragma once

#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

enum class Parameterization { kUniform, kChordal, kCentripetal, kFoley, kNielson };

/// "uniform", "chordal", "centripetal", "Foley", "Nielson": for messages and labs.
const char* parameterization_name(Parameterization method);

/// Parameter values t_0 = 0 < t_1 < ... for the points (ch. 1 §1.6,
/// "Parameterizations"); n + 1 values for n + 1 points, n + 2 when closed.
/// Throws for fewer than 2 points, a non-finite coordinate, or (all methods
/// but kUniform) two consecutive points at the same place, naming both indices.
std::vector<double> parameters(const std::vector<Vec3>& points, Parameterization method, bool closed = false);

/// The Nielson metric of the points (ch. 1 §1.6, "Nielson metric"): the
/// squared length |v|_N^2 = v^T M v where M is the inverse of the covariance
/// matrix C = 1/N sum (P_i - mean)(P_i - mean)^T. Returned as the 3 x 3 matrix M,
/// row by row. When the points span only a plane or a line (2D points have
/// z = 0), M is the pseudo-inverse: lengths are measured within that span.
/// Throws when all points coincide.
std::vector<double> nielson_metric(const std::vector<Vec3>& points);

/// sqrt(v^T M v) for a metric M as returned by nielson_metric().
double metric_length(const std::vector<double>& M, Vec3 v);

/// t rescaled affinely so that it runs from 0 to 1 (the lecture's normalizing
/// factor s = t_back - t_front). Throws when t has fewer than 2 entries or
/// t_back == t_front.
std::vector<double> unit_interval_parameters(const std::vector<double>& t);

}  // namespace gllab::spline
