// bench/prototype_eval.h — PROTOTYPE batched evaluators, NOT the own core.
//
// They exist to measure what common/spline/bspline.cpp curve_points() and
// surface.cpp surface_grid() could reach (bench/README.md, "What limits the
// own core"). The benchmark labels their rows "prototype"; no own-core figure
// or ratio uses them. Cubic / bicubic rational only; they throw otherwise.
// Compiled with -ffp-contract=fast and function multiversioning
// (target_clones: x86-64-v4, x86-64-v3, baseline), no -march=native.
#pragma once

#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::bench::prototype {

/// Variant R, the minimal change to A2.2: per-span reciprocals of the six knot
/// differences (A2.2's denominators do not depend on u), degree fixed at 3,
/// points of one span in a vectorisable loop. One division per point (1/w).
void curve_points_reciprocal(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                             std::vector<spline::Vec3>& out);
void curve_points_reciprocal(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                             std::vector<spline::Vec3>& out, std::vector<spline::Vec3>& derivs);

/// Variant T: per span, the homogeneous curve Cw as a cubic in t = u - U[i]
/// (Taylor coefficients, found once per span from the basis polynomials);
/// per point a Horner step per component: 12 FMAs and one division.
void curve_points_taylor(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                         std::vector<spline::Vec3>& out);
void curve_points_taylor(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                         std::vector<spline::Vec3>& out, std::vector<spline::Vec3>& derivs);

/// Grid of points and unit normals (Su x Sv, normalised), row-major over
/// (us, vs): basis values and derivatives once per u and once per v, the 4 x nv
/// control net contracted along u once per row, then per point 3 x 16 FMAs,
/// one division and one square root.
void surface_grid(const spline::BsplineSurface& surface, const std::vector<double>& us,
                  const std::vector<double>& vs, std::vector<spline::Vec3>& points,
                  std::vector<spline::Vec3>& normals);

}  // namespace gllab::bench::prototype

namespace gllab::bench::prototype {

/// Variant P ("plain"): the own core's curve_points loop as it is (A2.1 span
/// walk, A2.2 BasisFuns with its p(p+1)/2 divisions, A4.1 projection with three
/// divisions, any degree), but with the parameter check done by comparisons
/// instead of building a std::string per parameter. Compiled with the
/// project's flags (prototype_plain.cpp): it isolates the cost of the check.
void curve_points_plain(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                        std::vector<spline::Vec3>& out);
void curve_points_plain(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                        std::vector<spline::Vec3>& out, std::vector<spline::Vec3>& derivs);

}  // namespace gllab::bench::prototype
