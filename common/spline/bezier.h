// common/spline/bezier.h — Bézier curves (lecture notes ch. 1, §1.6 Spline
// representations, "Bézier segments" to "Interpolating with Bézier segments";
// lecture notes "Geometric Modeling", "Bezier Curves de Casteljau algorithm";
// lecture notes "Higher Order Surfaces", "Bezier Curves").
//
// A BezierCurve (types.h) has control points P[0..n] (degree n = P.size() - 1;
// the notes call them b_0..b_n) and a parameter interval [a, b]. §1.6,
// "Generalization", evaluates it at the local parameter
//     s = (t - a) / (b - a),      X(t) = sum_i b_i B_i^n(s),
// so every function here takes the global t in [a, b], and the k-th derivative
// with respect to t picks up the chain-rule factor 1 / (b - a)^k.
//
// Checks: every function that takes a curve calls validate() (P not empty,
// a < b, everything finite) and rejects a parameter t that is NaN or outside
// [a, b], naming the end it passed. A t that misses [a, b] only by round-off
// (at most kBezierParameterSlack relative to the interval's magnitude, as a
// sampling loop a + i (b - a) / N can produce) is taken as that end.
// Errors throw std::invalid_argument with a message naming the values.
#pragma once

#include <limits>
#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

/// How far (relative to max(|a|, |b|, b - a)) t may lie outside [a, b] and
/// still count as a or b: a few units of round-off, nothing a user would type.
inline constexpr double kBezierParameterSlack = 4 * std::numeric_limits<double>::epsilon();

/// The highest Bézier degree the core takes: 64 (65 control points). The labs
/// go to degree 10; de Casteljau's scheme for drawing (de_casteljau) holds
/// (n + 1)(n + 2)/2 points, 2,145 at the limit. Degree elevation, interpolation
/// and the Bernstein functions check it too.
inline constexpr int kMaxBezierDegree = 64;

/// Throws std::invalid_argument naming the values when the curve has no
/// control points or more than kMaxBezierDegree + 1, a or b is not finite,
/// a >= b, or a control point is not finite.
void validate(const BezierCurve& curve);

/// n = P.size() - 1.
inline int bezier_degree(const BezierCurve& curve) { return static_cast<int>(curve.P.size()) - 1; }

// ---- Bernstein basis (§1.6, "Properties of Bézier segments", property 5;
//      "Higher Order Surfaces", "Bezier Curves") ---------------------------

/// B_i^n(s) = C(n, i) s^i (1 - s)^(n - i) at s = (t - a) / (b - a), computed by
/// A1.2 Bernstein (The NURBS Book, 2nd ed., p. 20): the de Casteljau triangle
/// run on the unit vector e_i, convex combinations only. B_i^n = 0 for i < 0
/// or i > n (the convention of the derivative formula in §1.6, "Properties of
/// Bézier segments", property 11).
/// Throws if n < 0 or t is outside [a, b].
double bernstein(int i, int n, double t, double a = 0, double b = 1);

/// All B_0^n(s) .. B_n^n(s), A1.3 AllBernstein (The NURBS Book, p. 21). They
/// are >= 0 and sum to 1 on [a, b] (§1.6, "Properties of Bézier segments",
/// property 6).
std::vector<double> bernstein_all(int n, double t, double a = 0, double b = 1);

// ---- evaluation: de Casteljau (§1.6, "Bézier segments: the de Casteljau
//      algorithm"; "Geometric Modeling", "De Casteljau Algorithm") ---------

/// Every point of the de Casteljau scheme, for drawing the intermediate polygons.
struct DeCasteljau {
  /// levels[j][i] = b_i^j (§1.6, "de Casteljau algorithm"), j = 0..n,
  /// i = 0..n-j: levels[0] is the control polygon, levels[n] holds the single
  /// point X(t).
  std::vector<std::vector<Vec3>> levels;
  Vec3 point;      // X(t) = b_0^n
  double t = 0;    // the parameter asked for
  double s = 0;    // the local parameter (t - a) / (b - a) the scheme used
};

/// de Casteljau (§1.6, "de Casteljau algorithm"):  b_i^0 = b_i,
///   b_i^j = (1 - s) b_i^{j-1} + s b_{i+1}^{j-1},  j = 1..n, i = 0..n-j,
/// X(t) = b_0^n. Only convex combinations, hence numerically stable. O(n^2).
DeCasteljau de_casteljau(const BezierCurve& curve, double t);

/// X(t), by the same recursion in O(n) memory.
Vec3 bezier_point(const BezierCurve& curve, double t);

// ---- monomial (power) form (§1.6, "Example (n=3): basis transformation (to
//      monomials)"; "Higher Order Surfaces", "Bezier Curves", Matrix Form) -

/// The Bézier matrix in the notes' layout: X(s) = (s^n ... s 1) M (b_0 ...
/// b_n)^T, so row r multiplies s^(n-r). Entry (row for s^j, column i) is
/// (-1)^(j-i) C(n, j) C(j, i) for i <= j, else 0. For n = 3 it is [[-1, 3, -3,
/// 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]].
std::vector<std::vector<double>> bezier_matrix(int n);

/// c_0..c_n with X(t) = sum_j c_j t^j for t in [a, b] (ascending powers of the
/// GLOBAL t, like vandermonde_coefficients; evaluate with monomial_value). On
/// [0, 1] this is the notes' matrix product; otherwise the power form in s is
/// re-expanded in t by substituting s = (t - a) / (b - a). Expect the power
/// form to lose accuracy when |a| or |b| is large compared to b - a.
std::vector<Vec3> monomial_coefficients(const BezierCurve& curve);

/// The inverse: the Bézier points on [a, b] of X(t) = sum_j c_j t^j
/// (degree n = c.size() - 1). In s: b_i = sum_{j <= i} C(i, j) / C(n, j) c_j(s).
BezierCurve bezier_from_monomial(const std::vector<Vec3>& c, double a = 0, double b = 1);

// ---- convex hull (§1.6, "Properties of Bézier segments", property 1) -------

/// The convex hull of the points' projection into the xy plane, as its
/// corners in counter-clockwise order starting at the lowest-leftmost point;
/// points on a hull edge are not corners. Andrew's monotone chain (A. M.
/// Andrew, "Another efficient algorithm for convex hulls in two dimensions",
/// Inf. Proc. Letters 9, 1979): sort by x then y, build the lower and the upper
/// chain, keep only left turns. O(n log n). Every X(t), t in [a, b], of a
/// Bézier curve lies in the hull of its control points (property 1: X(t) is a
/// convex combination with weights B_i^n >= 0 that sum to 1). One distinct
/// point gives one corner, collinear points the two ends. Throws if P is empty
/// or a point is not finite. z is kept from the input points.
std::vector<Vec3> convex_hull_xy(const std::vector<Vec3>& P);

// ---- subdivision and degree elevation ---------------------------------------

/// The two halves of a curve split at a parameter.
struct BezierSplit {
  BezierCurve left;   // the piece over [a, t]
  BezierCurve right;  // the piece over [t, b]
};

/// Subdivision (§1.6, "Properties of Bézier segments", property 10; "Higher
/// Order Surfaces", "Rendering Bezier Curves": "De Casteljau actually
/// subdivides the curve in 2"): the de Casteljau scheme at t gives the left
/// points b_0^j and the right points b_j^(n-j), j = 0..n. Each piece keeps its
/// part of the parameter interval, so left(u) = X(u) for u in [a, t] and
/// right(u) = X(u) for u in [t, b]. Needs a < t < b.
BezierSplit subdivide(const BezierCurve& curve, double t);

/// The same curve written with degree n + times (same interval). times = 1:
/// §1.6, "Properties of Bézier segments", property 9 (degree increase),
///   b'_i = i/(n+1) b_{i-1} + (1 - i/(n+1)) b_i,  i = 0..n+1.
/// times > 1: all steps at once, The NURBS Book eq. (5.36), p. 205:
///   b'_i = sum_{j} C(n, j) C(times, i-j) / C(n+times, i) b_j.
/// times = 0 returns the curve unchanged. Throws if times < 0.
BezierCurve degree_elevate(const BezierCurve& curve, int times = 1);

// ---- joining segments (§1.6, "Bézier splines"; "Higher Order Surfaces",
//      "Joining of Bezier Curves") -----------------------------------------

/// What continuation_points returns: the next segment's first points and the
/// part of the de Casteljau scheme they come from.
struct BezierContinuation {
  /// b_0..b_k of the next segment: points[r] = b_{n-r}^r(tau).
  std::vector<Vec3> points;
  /// levels[r] = b_{n-k}^r(tau) .. b_{n-r}^r(tau), r = 0..k (k - r + 1 points):
  /// levels[r][j] lies on the line through levels[r-1][j] and levels[r-1][j+1],
  /// beyond the second (tau > 1), so these are the notes' construction lines.
  /// For a cubic and k = 2: levels[1][0] is the de Boor point d of the joint.
  std::vector<std::vector<Vec3>> levels;
  double tau = 0;  // the next segment's far end in a's local parameter
};

/// The first k + 1 Bézier points of the segment that follows `a` over [a.b,
/// a.b + next_length] with C^k continuity at a.b (§1.6, "Bézier splines", with
/// Delta_i = b - a and Delta_{i+1} = next_length): the polynomial of `a`
/// continued, i.e. de Casteljau at tau = 1 + next_length / (b - a), outside [0,
/// 1] (§1.7 Surface representations, "Spline surfaces": "evaluating ... outside
/// of the interval"; the curve case of continuation_rows in surface.h). The
/// points satisfy the notes' conditions, for a cubic (m = 3) at the joint
/// t_{i+1}:
///   C0: b_0 = a_n
///   C1: (a_n - a_{n-1}) / Delta_i = (b_1 - b_0) / Delta_{i+1}   (notes' eq. 1)
///   C2: d = a_{n-1} + Delta_{i+1}/Delta_i (a_{n-1} - a_{n-2})   (notes' eq. 2)
///       b_2 = b_1 + Delta_{i+1}/Delta_i (b_1 - d)               (notes' eq. 3)
/// G1 ("Higher Order Surfaces", "Joining of Bezier Curves": a_n - a_{n-1} =
/// k (b_1 - b_0)) is the C1 point for a
/// next_length of Delta_i / k: same direction, another speed.
/// Needs 0 <= k <= n and next_length > 0 and finite.
BezierContinuation continuation_points(const BezierCurve& a, int k, double next_length);

// ---- derivatives (§1.6, "Properties of Bézier segments", property 11, and
//      "Derivatives") ------------------------------------------------------

/// The k-th derivative as a Bézier curve (the hodograph for k = 1) of degree
/// n - k on the same [a, b]:
///   d^k/dt^k X(t) = n!/(n-k)! / (b-a)^k  sum_i Delta^k b_i B_i^(n-k)(s),
///   Delta^k b_i = Delta^(k-1) b_{i+1} - Delta^(k-1) b_i,  Delta^0 b_i = b_i.
/// For k = 1 the points are n (b_{i+1} - b_i) / (b - a). k = 0 returns the curve;
/// k > n returns the zero curve (one point at the origin). Throws if k < 0.
BezierCurve bezier_derivative(const BezierCurve& curve, int k = 1);

/// X^(k)(t): the hodograph of order k evaluated at t.
Vec3 bezier_derivative_at(const BezierCurve& curve, double t, int k = 1);

/// X(t), X'(t), ..., X^(d)(t) from ONE de Casteljau scheme (§1.6,
/// "Derivatives": "The derivatives ... can also be calculated using the de
/// Casteljau algorithm"):
///   X^(k)(t) = n!/(n-k)! / (b-a)^k  Delta^k b_0^(n-k),
/// e.g. X'(t) = n (b_1^(n-1) - b_0^(n-1)), X''(t) = n (n-1) (b_2^(n-2) - 2 b_1^(n-2) + b_0^(n-2)).
/// Orders above n are zero. Throws if d < 0.
std::vector<Vec3> bezier_derivatives(const BezierCurve& curve, double t, int d);

/// X^(k)(a) from the first k + 1 points only (§1.6, "Derivatives at end
/// points"):
///   X^(k)(a) = n!/(n-k)! / (b-a)^k  sum_{j=0}^{k} (-1)^(k-j) C(k, j) b_j,
/// e.g. X'(a) = n (b_1 - b_0) / (b - a). Zero for k > n. Throws if k < 0.
Vec3 bezier_start_derivative(const BezierCurve& curve, int k);
/// X^(k)(b) from the last k + 1 points:
///   X^(k)(b) = n!/(n-k)! / (b-a)^k  sum_{j=0}^{k} (-1)^j C(k, j) b_{n-j}.
Vec3 bezier_end_derivative(const BezierCurve& curve, int k);

// ---- integral (§1.6, "Integrating a Bézier segment") ---------------------

/// The integral of X over [a, b], componentwise:
///   int_a^b X(t) dt = (b - a) / (n + 1) (b_0 + b_1 + ... + b_n),
/// because every B_i^n integrates to 1 / (n + 1) over [0, 1].
Vec3 bezier_integral(const BezierCurve& curve);

/// The antiderivative Y(t) = start + int_a^t X(u) du as a Bézier curve of
/// degree n + 1 on [a, b]: Y_0 = start, Y_{i+1} = Y_i + (b - a) / (n + 1) b_i.
/// (Differentiating Y with property 11 gives back b_i.) Y(b) - Y(a) equals
/// bezier_integral.
BezierCurve bezier_antiderivative(const BezierCurve& curve, Vec3 start = {});

// ---- interpolation (§1.6, "Interpolating with Bézier segments") ----------

/// The Bézier curve of degree r = Q.size() - 1 on [a, b] through the points,
/// X(t_j) = Q_j, j = 0..r: the notes' system sum_i b_i B_i^r(s_j) = Q_j,
/// s_j = (t_j - a) / (b - a), solved by gauss_solve (interpolation.h). The
/// parameters must be finite, pairwise distinct and inside [a, b]; they need
/// not be sorted. Throws if Q is empty or the sizes differ.
BezierCurve bezier_interpolate(const std::vector<Vec3>& Q, const std::vector<double>& t, double a, double b);

/// The same on [a, b] = [min t_j, max t_j] (the notes' example: [t_0, t_3]).
/// Needs at least two points (one point has no interval; give a and b).
BezierCurve bezier_interpolate(const std::vector<Vec3>& Q, const std::vector<double>& t);

}  // namespace gllab::spline
