// common/spline/bspline.h — B-spline curves: knot vectors, basis functions,
// evaluation (de Boor, derivatives, NURBS), knot insertion and refinement,
// Bézier decomposition, splitting, degree elevation, periodic curves and the
// uniform cubic matrix form.
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

/// The knot-vector part of validate(), for curves and for each direction of a
/// surface: `what` starts the messages ("knot vector", "V knot vector", ...) and
/// `symbol` names the array in them ("U[5]=0.4", "V[2]=2").
void validate_knots(int p, int num_points, const std::vector<double>& U, const char* what = "knot vector",
                    const char* symbol = "U");

/// A closed parameter interval [a, b].
struct ParamInterval {
  double a = 0, b = 1;
};

/// [U[p], U[n+1]], the parameters where the curve is defined (ch. 1 §1.6:
/// X(u) for u_{m-1} <= u <= u_{n+1} with order m = p + 1).
ParamInterval domain(const BsplineCurve& curve);
/// The same for raw (p, U): [U[p], U[U.size() - p - 1]]. Checks nothing.
ParamInterval domain(int p, const std::vector<double>& U);

/// Throws "u=1.5 is outside the domain [0, 1]" (also for NaN).
void require_in_domain(double u, ParamInterval dom);

/// How many times the value u appears in U (exact comparison).
int knot_multiplicity(const std::vector<double>& U, double u);

// ---- knot vectors -----------------------------------------------------------

/// Clamped ("nonperiodic", notes "Higher Order Surfaces") uniform knots for P[0..n] of degree p:
/// p + 1 zeros, the interior knots j / (n - p + 1), j = 1..n-p, p + 1 ones.
/// Domain [0, 1]; the curve interpolates P[0] and P[n]. Needs 1 <= p <= n.
std::vector<double> clamped_uniform_knots(int n, int p);

/// Unclamped uniform knots 0, 1, 2, ..., n + p + 1 (notes "Higher Order Surfaces", "knots = 0, 1, 2,
/// ..., n"). Domain [p, n + 1]; segment i (0-based) is u in [p + i, p + i + 1].
/// Needs 1 <= p <= n.
std::vector<double> uniform_knots(int n, int p);

/// A closed C^{p-1} curve: the points followed by their first p points again
/// (notes "B-Spline Polynomials", "closed cubic B-splines: make the last 3 control points coincide
/// with the first 3"), on uniform_knots. Domain [p, p + points.size()]; the
/// curve ends where it starts, with equal derivatives up to order p - 1.
/// Needs points.size() >= 2 and p >= 1.
BsplineCurve periodic_curve(const std::vector<Vec3>& points, int p, int dimension = 3);

/// A polynomial curve from points on clamped_uniform_knots(n, p).
BsplineCurve clamped_curve(const std::vector<Vec3>& points, int p, int dimension = 3);

// ---- basis functions (chapter 2 of The NURBS Book) ------------------------

/// A2.1 FindSpan (The NURBS Book, 2nd ed., p. 68). Returns i with
/// U[i] <= u < U[i+1], p <= i <= n. At the end of the domain, u == U[n+1],
/// returns the last non-empty span (n for a clamped curve).
/// Throws if u is outside [U[p], U[n+1]] or U.size() != n + p + 2.
int find_span(int n, int p, double u, const std::vector<double>& U);

/// The span seen from the left: i with U[i] < u <= U[i+1]. At u == U[p] returns
/// the first non-empty span. Used for left limits at a knot (Side::Left).
int find_span_left(int n, int p, double u, const std::vector<double>& U);

/// A2.2 BasisFuns (p. 70). N[j] = N_{i-p+j,p}(u), j = 0..p, for the span i
/// returned by find_span. The p + 1 values are >= 0 and sum to 1.
std::vector<double> basis_funs(int i, double u, int p, const std::vector<double>& U);
/// The same, writing p + 1 values to N (no allocation). Needs p <= kMaxDegree.
void basis_funs(int i, double u, int p, const std::vector<double>& U, double* N);

/// A2.3 DersBasisFuns (p. 72). ders[k][j] = k-th derivative of N_{i-p+j,p} at
/// u, k = 0..d, j = 0..p. Rows k > p are zero.
std::vector<std::vector<double>> ders_basis_funs(int i, double u, int p, int d, const std::vector<double>& U);

/// A2.4 OneBasisFun (p. 74): the single function N_{i,p}(u), 0 <= i <= m-p-1.
/// (Arguments ordered like basis_funs, not like the book's (p, m, U, i, u).)
/// At u == U[m] the last function is 1 (the book's special case).
double one_basis_fun(int i, double u, int p, const std::vector<double>& U);

/// The Cox–de Boor recursion exactly as the lecture write it (ch. 1 §1.6,
/// notes "Higher Order Surfaces"), with 0/0 := 0 and half-open N_{i,0} = 1 on [U[i], U[i+1]), plus
/// the right end: at u == U[m] the last non-empty interval counts as closed.
/// Exponential time; for teaching and plotting. Equals one_basis_fun.
double cox_de_boor(int i, double u, int p, const std::vector<double>& U);

/// All N_{0..n,p}(u) for n = U.size() - p - 2: a row to plot every basis
/// function of a knot vector, by the Cox–de Boor table (O(m p)). u may be
/// anywhere in [U[0], U[m]] (zeros outside); only on the domain do they sum to 1.
std::vector<double> all_basis_funs(double u, int p, const std::vector<double>& U);

/// The largest degree the allocation-free paths support (GLU stops at order 24).
inline constexpr int kMaxDegree = 31;

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

/// Batched evaluation at non-decreasing parameters inside the domain: out[k] =
/// C(sorted_u[k]). Walks the spans forward (no binary search per point) and
/// checks the curve once. Throws if sorted_u decreases or leaves the domain.
/// Agrees with curve_point() to rounding, not bit for bit (it multiplies by
/// per-span reciprocals where A2.2 divides), and gives the same bits on every
/// CPU; how it is made fast is explained in bspline.cpp ("batched evaluation").
void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out);
/// The same with first derivatives: derivs[k] = C'(sorted_u[k]).
void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out,
                  std::vector<Vec3>& derivs);

/// count >= 2 evenly spaced parameters from the start to the end of the domain
/// (the last is exactly U[n+1]).
std::vector<double> uniform_params(const BsplineCurve& curve, int count);

/// The Greville abscissae (knot averages) xi_i = (U[i+1] + ... + U[i+p]) / p,
/// i = 0..n, for n = U.size() - p - 2. A B-spline with the control values xi_i
/// is the parameter itself on the domain: sum_i xi_i N_{i,p}(u) = u (linear
/// precision, from Marsden's identity; de Boor, "A Practical Guide to
/// Splines", rev. ed. 2001, ch. IX). common/gl/glu_nurbs.cpp feeds them to
/// GLU as a texture-coordinate map so that every GLU vertex tells its u.
/// Throws for p < 1 or U.size() < p + 2 (no control point).
std::vector<double> greville_abscissae(int p, const std::vector<double>& U);

// ---- knot insertion, refinement, decomposition -------------------------------

/// One insertion of the knot t by the lecture's formula (ch. 1 §1.6, Boehm):
/// t in [U[k], U[k+1]), q_i = (1 - a_i) P[i-1] + a_i P[i] with
/// a_i = (t - U[i]) / (U[i+p] - U[i]) for k - p + 1 <= i <= k.
/// a[j] is a_{first + j}, first = k - p + 1 (so a.size() == p). k is
/// find_span(t) (at the end of the domain, t == U[k+1]). Needs the same as
/// knot_insert with r = 1.
struct KnotInsertStep {
  BsplineCurve curve;
  int k = 0;
  int first = 0;
  std::vector<double> a;
};
KnotInsertStep knot_insert_step(const BsplineCurve& curve, double t);

/// A5.1 CurveKnotIns (p. 151): insert u r times. Needs U[p] <= u <= U[n+1] and
/// s + r <= p where s is the multiplicity u already has. The curve is unchanged.
BsplineCurve knot_insert(const BsplineCurve& curve, double u, int r = 1);

/// A5.4 RefineKnotVectCurve (p. 164): insert all knots X (non-decreasing,
/// inside the domain; final multiplicities <= p).
BsplineCurve knot_refine(const BsplineCurve& curve, const std::vector<double>& X);

/// The Bézier pieces of a polynomial curve, one per non-empty knot span of the
/// domain, each with its parameter interval [a, b]. Made by raising every knot
/// of the domain to multiplicity p with one knot refinement (A5.4), as ch. 1
/// §1.6 "Displaying B-spline curves" describes; the result is that of A5.6
/// DecomposeCurve, and it works for unclamped curves too. Throws for a rational
/// curve (BezierCurve has no weights; use bezier_segments).
std::vector<BezierCurve> bezier_decompose(const BsplineCurve& curve);

/// The same decomposition for any curve (rational too): each piece is a
/// single-span curve with knots {a x (p+1), b x (p+1)}.
std::vector<BsplineCurve> bezier_segments(const BsplineCurve& curve);

/// The inverse of bezier_decompose: Bézier segments of one degree p >= 1,
/// each starting where the previous one ends (same point, same parameter),
/// as one B-spline curve. The knots are a x (p+1), every joint x p, b x (p+1),
/// and the control points are the segments' points with each joint once
/// (ch. 1 §1.6, "B-splines": a B-spline whose knots all have multiplicity
/// m - 1, m the order, has the Bézier points as its control points). The
/// curve is only C0 at the joints, unless the points make it smoother.
/// Throws for no segments, a degree < 1 or different degrees, a gap between
/// intervals, or a segment that does not start at the previous one's end.
BsplineCurve from_bezier_segments(const std::vector<BezierCurve>& segments);

/// Splits at u strictly inside the domain (by inserting u up to multiplicity p):
/// first covers [U[p], u], second [u, U[n+1]]. Each keeps the original
/// parameters and the end knots it inherits (clamped at u).
std::pair<BsplineCurve, BsplineCurve> split(const BsplineCurve& curve, double u);

/// A5.9 DegreeElevateCurve (p. 206): the same curve at degree p + t (t >= 0).
/// Rational curves are elevated in homogeneous space. A5.9 needs clamped ends,
/// so an unclamped curve is first clamped (same curve on the same domain, end
/// knots of multiplicity p + 1); the result is always clamped. A break (an
/// interior knot of multiplicity p + 1) is kept: the pieces between breaks are
/// elevated separately and joined. Interior knots gain t in multiplicity.
BsplineCurve degree_elevate(const BsplineCurve& curve, int t = 1);

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
