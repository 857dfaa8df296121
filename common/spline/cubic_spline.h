// common/spline/cubic_spline.h — interpolating cubic splines (ch. 1 §1.6).
//
// Given nodes t_0 < t_1 < ... < t_N and values p_0..p_N, the cubic spline S
// is a cubic on each interval [t_i, t_{i+1}], passes through S(t_i) = p_i and
// is C2 (value, slope and curvature continuous) at every interior node. That
// leaves two degrees of freedom, fixed by the end conditions (ch. 1 §1.6):
//
//   natural    S''(t_0) = S''(t_N) = 0
//   clamped    S'(t_0) and S'(t_N) given (the end derivatives)
//   periodic   a closed curve: S, S', S'' agree at t_0 and t_N. The points are
//              given once, p_0..p_{N-1}, with N + 1 nodes: the last segment
//              runs from p_{N-1} back to p_0 over [t_{N-1}, t_N].
//
// The values are numbers (a function y = S(t)) or points (a parametric curve
// X(t); ch. 1 §1.6, "Algorithm for parametric cubic curves": each of x, y, z
// is a spline over the same nodes). Get the nodes of a curve from
// parameters() in parameterization.h; for a closed curve pass closed = true.
//
// Three forms of the same spline:
//   PiecewiseCubic   the lecture's power form a_i + b_i h + c_i h^2 + d_i h^3,
//   BezierCurve      one cubic Bézier segment per interval (bezier_segments),
//   BsplineCurve     one C2 cubic B-spline (bspline_curve): clamped knots
//                    t_0 t_0 t_0 t_0 t_1 ... t_{N-1} t_N t_N t_N t_N, or a
//                    periodic knot vector for a closed curve.
// and the lecture's own route to the Bézier form through de Boor points
// (bezier_spline_through). The tests check that all of them agree.
//
// A cusp on a closed outline (the trailing edge of a wing section) wants no
// C2 seam: start and end a natural spline at the cusp, p_0 = p_N, instead of
// closing it periodically (ch. 1 §1.6, comment after the parametric
// algorithm).
#pragma once

#include <cstddef>
#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

enum class EndCondition { kNatural, kClamped, kPeriodic };

/// A piecewise cubic in the lecture's power form (ch. 1 §1.6):
///     S(t) = a[i] + b[i] h + c[i] h^2 + d[i] h^3,  h = t - t[i],  t in [t[i], t[i+1]],
/// so a[i] = S(t_i), b[i] = S'(t_i), c[i] = S''(t_i) / 2, d[i] = S'''/6 on segment i.
/// T is double for a function, Vec3 for a curve.
template <class T>
struct PiecewiseCubic {
  std::vector<double> t;      // nodes t[0] < ... < t[N]
  std::vector<T> a, b, c, d;  // N entries each, one per segment
  EndCondition end = EndCondition::kNatural;
  int dimension = 3;  // curves: 2 when every input point (and tangent) had z = 0; functions: 1

  std::size_t segments() const { return a.size(); }
};
using ScalarCubicSpline = PiecewiseCubic<double>;
using CubicSpline = PiecewiseCubic<Vec3>;

// --- construction (the nodes t must increase strictly) ------------------------

/// Natural cubic spline through (t[i], y[i]), i = 0..N: S''(t_0) = S''(t_N) = 0.
/// Ch. 1 §1.6, "Algorithm for a natural cubic spline". Needs N >= 1.
ScalarCubicSpline natural_cubic_spline(const std::vector<double>& t, const std::vector<double>& y);
CubicSpline natural_cubic_spline(const std::vector<double>& t, const std::vector<Vec3>& P);

/// Clamped cubic spline: S'(t_0) = slope_start, S'(t_N) = slope_end (the end
/// derivatives; for a curve the tangent vectors dX/dt).
ScalarCubicSpline clamped_cubic_spline(const std::vector<double>& t, const std::vector<double>& y,
                                       double slope_start, double slope_end);
CubicSpline clamped_cubic_spline(const std::vector<double>& t, const std::vector<Vec3>& P, Vec3 tangent_start,
                                 Vec3 tangent_end);

/// Periodic (closed) cubic spline through y[0..N-1] at t[0..N-1], returning to
/// y[0] at t[N]: t has one entry more than y. Ch. 1 §1.6, "Algorithm for a
/// periodic cubic spline". Needs N >= 2; y[N-1] must not repeat y[0] (curves).
ScalarCubicSpline periodic_cubic_spline(const std::vector<double>& t, const std::vector<double>& y);
CubicSpline periodic_cubic_spline(const std::vector<double>& t, const std::vector<Vec3>& P);

// --- evaluation ------------------------------------------------------------------

/// The segment i with t[i] <= u < t[i+1]; the last segment for u == t[N].
/// Throws when u lies outside [t[0], t[N]] or is not finite.
std::size_t segment_index(const std::vector<double>& t, double u);

/// S(u) and its k-th derivative (k >= 0; zero for k >= 4) for u in [t_0, t_N].
double spline_value(const ScalarCubicSpline& s, double u);
Vec3 spline_point(const CubicSpline& s, double u);
double spline_derivative(const ScalarCubicSpline& s, double u, int k);
Vec3 spline_derivative(const CubicSpline& s, double u, int k);

/// The k-th derivative of segment i's cubic at any u, without a domain check:
/// segment_derivative(s, i - 1, t[i], k) and segment_derivative(s, i, t[i], k)
/// are the left and right limits at node t_i.
double segment_derivative(const ScalarCubicSpline& s, std::size_t i, double u, int k);
Vec3 segment_derivative(const CubicSpline& s, std::size_t i, double u, int k);

// --- other forms -------------------------------------------------------------------

/// One cubic BezierCurve per segment over [a, b] = [t_i, t_{i+1}]: with
/// h = t_{i+1} - t_i, the Bézier points are a, a + b h/3, a + 2b h/3 + c h^2/3,
/// and S(t_{i+1}) (ch. 1 §1.6, Bézier derivatives at the end points).
std::vector<BezierCurve> bezier_segments(const CubicSpline& s);

/// The same curve as one C2 cubic B-spline over [t_0, t_N] (exact, no fitting).
/// Natural and clamped: knots t_0 x4, t_1..t_{N-1}, t_N x4 and N + 3 control
/// points. Periodic: the knots continue periodically beyond both ends
/// (U[3 + j] = t_{j mod N} + (j div N)(t_N - t_0), j = -3..N+3) and the first
/// three control points repeat at the end, so the curve closes C2 by itself.
/// The control points are the de Boor points of the lecture's Bézier-spline
/// construction (ch. 1 §1.6): the inner Bézier points b_{3i+1}, b_{3i+2}
/// of segment i divide the leg d_i d_{i+1} in the ratio D_{i-1} : D_i : D_{i+1}
/// of the neighbouring interval lengths, which is solved for d_i.
BsplineCurve bspline_curve(const CubicSpline& s);

/// The graph (t, S(t), 0) of a function spline as a 2D cubic B-spline with the
/// knots above: control point i is (xi_i, coefficient_i) with the Greville
/// abscissa xi_i = (U[i+1] + U[i+2] + U[i+3]) / 3, so that curve_point(u) = (u, S(u)).
BsplineCurve bspline_curve(const ScalarCubicSpline& s);

// --- interpolating cubic Bézier splines through de Boor points (ch. 1 §1.6) ---
//
// The lecture's three steps, for points p_0..p_N at nodes t_0..t_N, with
// D_i = t_{i+1} - t_i and Bézier points b_0..b_{3N}, b_{3i} = p_i:
//   1) choose the end condition: the inner Bézier points b_1 and b_{3N-1}
//      (equivalently the end tangents, S'(t_0) = 3 (b_1 - b_0) / D_0), or
//      natural ends, or a closed curve;
//   2) solve a tridiagonal system for the de Boor points d_0..d_N, where
//      segment i's inner Bézier points lie on the leg d_i d_{i+1}:
//        (D_{i-1} + D_i + D_{i+1}) b_{3i+1} = (D_i + D_{i+1}) d_i + D_{i-1} d_{i+1}
//        (D_{i-1} + D_i + D_{i+1}) b_{3i+2} = D_{i+1} d_i + (D_{i-1} + D_i) d_{i+1}
//      with D_{-1} = D_N = 0 (so d_0 = b_1 and d_N = b_{3N-1}), and
//        (D_{i-1} + D_i) p_i = D_i b_{3i-1} + D_{i-1} b_{3i+1}   (C1 at p_i);
//   3) place the remaining Bézier points on the legs.
// The d_i are the control points of bspline_curve(). The lecture's equidistant
// example keeps D_{-1} = D_N = 1 instead of 0: that moves d_0 and d_N but not
// b_1, b_{3N-1} or the curve.

/// Step 2 with b_1 and b_{3N-1} given (the lecture's choice): d_0..d_N.
std::vector<Vec3> de_boor_points_through(const std::vector<double>& t, const std::vector<Vec3>& P, Vec3 b1,
                                         Vec3 b_last);
/// Step 2 with natural ends (kNatural: b_1 = (b_0 + b_2) / 2, i.e. S''(t_0) = 0,
/// and likewise at t_N) or a closed curve (kPeriodic: t has one entry more
/// than P, and d_0..d_{N-1} repeat cyclically). kClamped needs b_1 and b_{3N-1}.
std::vector<Vec3> de_boor_points_through(const std::vector<double>& t, const std::vector<Vec3>& P,
                                         EndCondition end);

/// All three steps: the N cubic Bézier segments, segment i over [t_i, t_{i+1}].
std::vector<BezierCurve> bezier_spline_through(const std::vector<double>& t, const std::vector<Vec3>& P, Vec3 b1,
                                               Vec3 b_last);
std::vector<BezierCurve> bezier_spline_through(const std::vector<double>& t, const std::vector<Vec3>& P,
                                               EndCondition end);

}  // namespace gllab::spline
