// common/spline/bspline.h — B-spline and NURBS curves: the checks, periodic
// and clamped curves, evaluation (A3.1, A3.2, A4.1, A4.2, de Boor), reversal
// and the uniform cubic matrix form. The topics around a curve have their own
// headers, included here so that one include gives the whole B-spline toolbox:
//   knots.h             knot vectors, domain, validate_knots, Greville abscissae
//   basis.h             basis functions (A2.1-A2.4, Cox–de Boor)
//   knot_insertion.h    knot insertion and refinement, Bézier decomposition, split
//   degree_elevation.h  degree elevation (A5.9)
//   fast/curve_batch.h  the fast layer: curve_points for many parameters at once
//
// Notation (common/spline/README.md): p degree, n last control index, U knots
// with m + 1 = n + p + 2 entries (knots = control points + order), P points,
// w weights (empty: polynomial). The domain of a curve is [U[p], U[n+1]].
//
// Sources: The NURBS Book (Piegl & Tiller, 2nd ed.) by algorithm number, and
// the lecture notes (docs/lecture_notes.md): ch. 1 §1.6 (B-splines, Cox–de Boor,
// knot insertion, NURBS), notes "B-Spline Polynomials" (uniform cubic B-splines, cases A–D),
// notes "Higher Order Surfaces" (blending functions, matrix form, knot vectors).
//
// Every function that takes a BsplineCurve checks it (validate) and throws
// std::invalid_argument with a message that names the values. The low-level
// basis routines (find_span, basis_funs, ...) take the raw (p, U) and check
// only what is cheap: the degree, the length of U and the parameter's range.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "spline/basis.h"
#include "spline/degree_elevation.h"
#include "spline/fast/curve_batch.h"
#include "spline/knot_insertion.h"
#include "spline/knots.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

// ---- checks -----------------------------------------------------------------

/// Throws std::invalid_argument naming the values when the curve is not a
/// valid B-spline/NURBS curve: no control points, dimension not 2 or 3, degree
/// < 1 or >= number of points, U.size() != P.size() + p + 1, a knot that is NaN
/// or infinite, knots decreasing, a knot of multiplicity > p + 1, an empty
/// domain U[p] == U[n+1], a control point or weight that is not finite, a weight
/// <= 0, w.size() != P.size() (when w is not empty), a 2D curve with z != 0,
/// or p > kMaxDegree.
void validate(const BsplineCurve& curve);

/// [U[p], U[n+1]], the parameters where the curve is defined (ch. 1 §1.6:
/// X(u) for u_{m-1} <= u <= u_{n+1} with order m = p + 1).
ParamInterval domain(const BsplineCurve& curve);

/// A closed C^{p-1} curve: the points followed by their first p points again
/// (notes "B-Spline Polynomials", "closed cubic B-splines: make the last 3 control points coincide
/// with the first 3"), on uniform_knots. Domain [p, p + points.size()]; the
/// curve ends where it starts, with equal derivatives up to order p - 1.
/// Needs points.size() >= 2 and p >= 1.
BsplineCurve periodic_curve(const std::vector<Vec3>& points, int p, int dimension = 3);

/// A polynomial curve from points on clamped_uniform_knots(n, p).
BsplineCurve clamped_curve(const std::vector<Vec3>& points, int p, int dimension = 3);

// ---- evaluation ----------------------------------------------------------------

/// Which one-sided limit to take at a knot: Right uses U[i] <= u < U[i+1]
/// (find_span), Left uses U[i] < u <= U[i+1] (find_span_left). They differ only
/// at an interior knot where the curve is not C^d (notes "B-Spline Polynomials" cases B–D).
enum class Side { Right, Left };

/// C(u). A3.1 CurvePoint (p. 82) for a polynomial curve, A4.1 (p. 124) for a
/// rational one (evaluate Cw(u) in homogeneous space, then project).
/// Checks the whole curve on every call (O(n)); for many points use curve_points.
Vec3 curve_point(const BsplineCurve& curve, double u, Side side = Side::Right);

/// A4.1 CurvePoint for NURBS (The NURBS Book, p. 124) and the homogeneous point
/// Cw(u) = (w x, w y, w z, w) before the projection. Works on polynomial curves
/// too (all weights 1).
Vec3 rational_curve_point(const BsplineCurve& curve, double u, Side side = Side::Right);
Vec4 homogeneous_curve_point(const BsplineCurve& curve, double u, Side side = Side::Right);

/// CK[k] = k-th derivative of C at u, k = 0..d (CK[0] = C(u)). A3.2
/// CurveDerivsAlg1 (p. 93) for a polynomial curve; A4.2 RatCurveDerivs
/// (p. 127) for a rational one. Derivatives of order > p of a polynomial curve
/// are zero.
std::vector<Vec3> curve_derivs(const BsplineCurve& curve, double u, int d, Side side = Side::Right);

/// A4.2 RatCurveDerivs (p. 127): derivatives of the projected NURBS curve from
/// the derivatives of Cw (computed with A3.2 on the homogeneous points).
std::vector<Vec3> rational_curve_derivs(const BsplineCurve& curve, double u, int d, Side side = Side::Right);

/// A curve checked once (validate, in the constructor), then evaluated with
/// only u (and d) checked per call: O(p^2) per point instead of the O(n) check
/// of curve_point and curve_derivs. What tessellation, arc length and the
/// tools use when they evaluate one curve many times.
class CurveEvaluator {
 public:
  explicit CurveEvaluator(BsplineCurve curve);
  const BsplineCurve& curve() const { return curve_; }
  ParamInterval domain() const { return domain_; }
  /// C(u), as curve_point.
  Vec3 point(double u, Side side = Side::Right) const;
  /// C(u), C'(u), ..., C^(d)(u), as curve_derivs.
  std::vector<Vec3> derivs(double u, int d, Side side = Side::Right) const;

 private:
  BsplineCurve curve_;
  ParamInterval domain_;
};

/// de Boor's algorithm with every intermediate point, for drawing the
/// construction. levels[0] are the p + 1 control points P[span-p..span];
/// levels[r] holds p + 1 - r points; levels[p][0] == point == C(u). For a NURBS
/// curve the construction runs on Pw and each intermediate point is projected.
/// alphas[r-1][j] is the blend factor that made levels[r][j].
struct DeBoorConstruction {
  int span = 0;
  std::vector<std::vector<Vec3>> levels;
  std::vector<std::vector<double>> alphas;
  Vec3 point;
};
DeBoorConstruction de_boor(const BsplineCurve& curve, double u);

/// count >= 2 evenly spaced parameters from the start to the end of the domain
/// (the last is exactly U[n+1]).
std::vector<double> uniform_params(const BsplineCurve& curve, int count);

/// The same curve run backwards: C_rev(a + b - u) == C(u) on [a, b].
BsplineCurve reversed(const BsplineCurve& curve);

// ---- uniform cubic B-spline, matrix form (notes "B-Spline Polynomials", "Higher Order Surfaces") ---

/// M = 1/6 [[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 0, 3, 0], [1, 4, 1, 0]] so that
/// Q_i(t) = [t^3 t^2 t 1] M [P_i P_{i+1} P_{i+2} P_{i+3}]^T, t in [0, 1]
/// (notes "Higher Order Surfaces", "Matrix form"; notes "B-Spline Polynomials" writes the last row "-1 4 1 0", a typo:
/// its own d = (P_{i-3} + 4 P_{i-2} + P_{i-1}) / 6 gives 1 4 1 0).
inline constexpr double kUniformCubicMatrix[4][4] = {
    {-1.0 / 6, 3.0 / 6, -3.0 / 6, 1.0 / 6},
    {3.0 / 6, -6.0 / 6, 3.0 / 6, 0.0},
    {-3.0 / 6, 0.0, 3.0 / 6, 0.0},
    {1.0 / 6, 4.0 / 6, 1.0 / 6, 0.0},
};

/// The four blending functions of one segment (notes "Higher Order Surfaces"): B0 = (1-t)^3 / 6,
/// B1 = (3t^3 - 6t^2 + 4) / 6, B2 = (-3t^3 + 3t^2 + 3t + 1) / 6, B3 = t^3 / 6.
std::array<double, 4> uniform_cubic_basis(double t);

/// Polynomial coefficients (a, b, c, d) of Q(t) = a t^3 + b t^2 + c t + d from
/// four control points: M times (P0, P1, P2, P3) (notes "B-Spline Polynomials", "Solution").
std::array<Vec3, 4> uniform_cubic_coefficients(Vec3 P0, Vec3 P1, Vec3 P2, Vec3 P3);

/// Segment i (uses P[i..i+3]) at local t in [0, 1], by the matrix form. Equals
/// curve_point of {p = 3, U = uniform_knots(n, 3), P} at u = 3 + i + t.
Vec3 uniform_cubic_point(const std::vector<Vec3>& P, int i, double t);

}  // namespace gllab::spline
