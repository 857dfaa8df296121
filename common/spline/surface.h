// common/spline/surface.h — tensor-product surfaces: Bézier, Lagrange,
// Hermite, Hermite–Lagrange, B-spline and NURBS; partial derivatives, normals,
// twist vectors, iso-parameter curves, C^k continuation of a Bézier patch,
// interpolating Bézier surfaces; the fast grid evaluator (surface_grid) is
// declared in fast/surface_batch.h, included here.
//
// A tensor-product surface is made of two curve representations (ch. 1
// §1.7, "Surface Representations"):
//     X(u, v) = sum_i sum_j c_ij phi_i(u) psi_j(v) = sum_j c_j(u) psi_j(v),
//     c_j(u) = sum_i c_ij phi_i(u):
// evaluate one curve per column along u, then one curve along v through the
// results (or the other way round; the result is the same).
//
// Notation. The lecture writes (s, t) and put degree m along s, n along t; this
// file follows The NURBS Book and the rest of the core: parameters (u, v),
// degree n (Bézier) or p (B-spline) along u with row index i, degree m or q
// along v with column index j. Control nets are stored row by row,
// P[i * (columns) + j], like BsplineSurface (types.h). The lecture's formulas below are
// rewritten in this notation.
//
// Checks: every function checks its surface and parameters and throws
// std::invalid_argument naming the values (errors.h). Bézier parameters that
// miss their interval only by round-off are snapped onto it, as in bezier.h.
#pragma once

#include <vector>

#include "spline/bspline.h"
#include "spline/fast/surface_batch.h"
#include "spline/tessellate.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

/// A point and its first partial derivatives at one (u, v): S, dS/du, dS/dv
/// and the twist vector d^2S/(du dv) (ch. 1 §1.7, "The twist vector").
struct SurfacePartials {
  Vec3 S, Su, Sv, Suv;
};

/// The two parameter directions of a tensor-product surface.
enum class SurfaceDirection { U, V };

/// |Su x Sv| at or below kDegenerateNormal * max(|Su|, |Sv|)^2 counts as zero:
/// Su and Sv are parallel or one of them vanishes (a pole, a collapsed edge),
/// and the unit normal takes the fallback described at surface_normal().
inline constexpr double kDegenerateNormal = 1e-12;

// ==== Bézier surfaces (ch. 1 §1.7 "Bézier tensor product") ===============

/// X(u, v) = sum_{i=0..n} sum_{j=0..m} b_ij B_i^n(s) B_j^m(t) over the
/// rectangle [a, b] x [c, d], with the local parameters s = (u - a) / (b - a),
/// t = (v - c) / (d - c) (ch. 1 §1.7, "For a more generic interval").
/// The net has (n + 1) x (m + 1) points, b_ij = P[i * (m + 1) + j].
struct BezierSurface {
  int n = 3, m = 3;       // degrees along u and v
  std::vector<Vec3> P;    // (n + 1) * (m + 1) points, row i along u
  double a = 0, b = 1;    // u interval
  double c = 0, d = 1;    // v interval

  const Vec3& point(int i, int j) const { return P[static_cast<std::size_t>(i) * (m + 1) + j]; }
  Vec3& point(int i, int j) { return P[static_cast<std::size_t>(i) * (m + 1) + j]; }
};

/// Throws naming the values when n or m is negative, P.size() != (n+1)(m+1),
/// an interval is empty or not finite, or a control point is not finite.
void validate(const BezierSurface& surface);

/// A control net of rows x cols points, row-major (P[r * cols + k]): one level
/// of the surface de Casteljau scheme.
struct ControlNet {
  int rows = 0, cols = 0;
  std::vector<Vec3> P;
  const Vec3& point(int r, int k) const { return P[static_cast<std::size_t>(r) * cols + k]; }
};

/// Every net of the surface de Casteljau scheme, for drawing (ch. 1 §1.7,
/// "De Casteljau algorithm for surfaces"):
///   b_ij^{00} = b_ij,
///   b_ij^{k+1,l} = (1 - s) b_ij^{kl} + s b_{i+1,j}^{kl}    (a step along u)
///   b_ij^{k,l+1} = (1 - t) b_ij^{kl} + t b_{i,j+1}^{kl}    (a step along v)
/// until X(u, v) = b_00^{nm}. first == U runs all n steps along u, then the m
/// steps along v (the lecture's order: one curve per column, then the curve
/// through their points); first == V the other way round. Either order gives
/// the same point.
struct BezierSurfaceConstruction {
  SurfaceDirection first = SurfaceDirection::U;
  /// first == U: nets[k] = b^{k,0}, (n + 1 - k) x (m + 1), k = 0..n; then
  /// nets[n + l] = b^{n,l}, 1 x (m + 1 - l), l = 1..m. nets[0] is the control
  /// net, nets.back() the single point. (first == V: b^{0,l} then b^{k,m}.)
  std::vector<ControlNet> nets;
  /// The 2 x 2 net b^{n-1,m-1} (rows along u) that gives the derivatives
  /// (empty when n == 0 or m == 0).
  ControlNet last_quad;
  Vec3 point;      // X(u, v) = b_00^{nm}
  SurfacePartials partials;  // from the scheme, see bezier_surface_partials
  double s = 0, t = 0;       // the local parameters used
};

/// The whole scheme at (u, v). The partials come out of it too (ch. 1
/// §1.7): with the 2 x 2 net q_kl = b_kl^{n-1,m-1},
///   Xu  = n [(1 - t)(q_10 - q_00) + t (q_11 - q_01)] / (b - a)
///   Xv  = m [(1 - s)(q_01 - q_00) + s (q_11 - q_10)] / (d - c)
///   Xuv = n m (q_11 - q_10 - q_01 + q_00) / ((b - a)(d - c)),
/// the lecture's X_s = m (b_10^{m-1,n} - b_00^{m-1,n}) after the last v step.
/// A degree 0 direction has zero derivatives along it.
BezierSurfaceConstruction de_casteljau(const BezierSurface& surface, double u, double v,
                                       SurfaceDirection first = SurfaceDirection::U);

/// X(u, v) by the surface de Casteljau algorithm (convex combinations only).
Vec3 surface_point(const BezierSurface& surface, double u, double v);

/// X(u, v) = sum_i sum_j b_ij B_i^n(s) B_j^m(t), Bernstein values from
/// bernstein_all (bezier.h). The same point as surface_point.
Vec3 bernstein_surface_point(const BezierSurface& surface, double u, double v);

/// SKL[k][l] = d^{k+l} X / du^k dv^l at (u, v), k + l <= d (other entries are
/// zero): the rows are differentiated as Bézier curves along v
/// (bezier_derivatives), then the resulting points along u (ch. 1 §1.7,
/// "partial derivatives"). Orders above the degree are zero.
std::vector<std::vector<Vec3>> surface_derivs(const BezierSurface& surface, double u, double v, int d);

/// X, Xu, Xv, Xuv at (u, v) (from surface_derivs).
SurfacePartials surface_partials(const BezierSurface& surface, double u, double v);

/// The unit normal (Xu x Xv) / |Xu x Xv| (ch. 1 §1.7), with the fallback of
/// surface_normal(const BsplineSurface&, ...) at degenerate points.
Vec3 surface_normal(const BezierSurface& surface, double u, double v);

/// The derivative d^{k+l}X / du^k dv^l as a Bézier surface of degrees
/// (n - k, m - l) on the same rectangle (ch. 1 §1.7):
///   A_kl sum_i sum_j Delta^{kl} b_ij B_i^{n-k}(s) B_j^{m-l}(t),
///   A_kl = n!/(n-k)! / (b-a)^k * m!/(m-l)! / (d-c)^l,
/// e.g. the points n (b_{i+1,j} - b_ij) / (b - a) for Xu. Orders above the
/// degree give the zero surface (one point). Throws if k or l is negative.
BezierSurface derivative_surface(const BezierSurface& surface, int k, int l);

/// The iso-parameter curves (ch. 1 §1.7): v -> X(u0, v), a Bézier curve of
/// degree m on [c, d], and u -> X(u, v0), of degree n on [a, b]. Their points
/// come from de Casteljau on each column (or row) of the net.
BezierCurve iso_curve_u(const BezierSurface& surface, double u0);
BezierCurve iso_curve_v(const BezierSurface& surface, double v0);

/// The same patch as a clamped B-spline surface: knots a^(n+1) b^(n+1) along
/// u and c^(m+1) d^(m+1) along v, the same net. Needs n, m >= 1.
BsplineSurface to_bspline(const BezierSurface& surface);

/// The interpolating Bézier surface (ch. 1 §1.7, "Interpolating using
/// Bézier surfaces"): degrees n = us.size() - 1, m = vs.size() - 1 on
/// [min us, max us] x [min vs, max vs], with X(us[i], vs[j]) = points[i *
/// vs.size() + j]. First one curve per column j through points[., j] at us
/// (bezier_interpolate: the same matrix for each j), then one curve per row i
/// through those Bézier points at vs. Needs at least 2 parameters each way,
/// pairwise distinct.
BezierSurface interpolating_bezier_surface(const std::vector<double>& us, const std::vector<double>& vs,
                                           const std::vector<Vec3>& points);

/// C^k continuation across an edge (ch. 1 §1.7, "Spline surfaces"). Patch
/// `a` covers [a, b] x [c, d]; its neighbour covers [b, b + next_length] x
/// [c, d] (direction U) or [a, b] x [d, d + next_length] (direction V), with
/// the same degrees. Every column of a's net (direction U) is a Bézier curve
/// along u; evaluating it by de Casteljau at the neighbour's far end,
/// tau = 1 + next_length / (b - a), outside [0, 1], gives the neighbour's
/// points b_r = b_{n-r}^r(tau), r = 0..k (the polynomial continued). They
/// satisfy the lecture's conditions
///   C0: b_0 = a_n,
///   C1: (a_n - a_{n-1}) / ds0 = (b_1 - b_0) / ds1,
///   C2: (a_n - 2 a_{n-1} + a_{n-2}) / ds0^2 = (b_2 - 2 b_1 + b_0) / ds1^2.
/// Returns rows[r], r = 0..k: direction U rows[r][j] = b_{r,j} (m + 1 points),
/// direction V rows[r][i] = b_{i,r} (n + 1 points). Needs 0 <= k <= degree
/// across the edge and next_length > 0. (For the opposite edges, reverse the
/// net first.)
std::vector<std::vector<Vec3>> continuation_rows(const BezierSurface& a, int k, double next_length,
                                                 SurfaceDirection direction = SurfaceDirection::U);

/// The patch `next` moved to start at a's edge (u = a.b for U, v = a.d for V),
/// keeping its interval length, with its first k + 1 rows (columns for V)
/// replaced by continuation_rows: the two patches join with C^k. `next` must
/// have a's degrees and a's interval along the edge.
BezierSurface joined_patch(const BezierSurface& a, const BezierSurface& next, int k,
                           SurfaceDirection direction = SurfaceDirection::U);

/// The patch whose twist vector is the same everywhere (ch. 1 §1.7, "The
/// twist vector": surfaces with zero and with constant twist). Its boundary
/// curves through the corner (a, c) are given, X(u, c) = edge_u over [a, b]
/// and X(a, v) = edge_v over [c, d], and
///   b_ij = b_i0 + (b_0j - b_00) + i j (b - a)(d - c) / (n m) * twist,
/// so every cell of the net has Delta^{11} b_ij = (b - a)(d - c) twist / (n m)
/// and X_uv = n m Delta^{11} b_ij / ((b - a)(d - c)) = twist at every (u, v)
/// (the lecture's X_st(0,0) = 9 (b_11 - b_10 - b_01 + b_00) on every cell).
/// twist = 0: the translational surface X(u, c) + X(a, v) - X(a, c), every
/// v-curve the same curve moved along edge_u. The rows j = 0 and i = 0 are
/// copied exactly. Needs degrees n, m >= 1 and edge_u.P[0] == edge_v.P[0].
BezierSurface constant_twist_patch(const BezierCurve& edge_u, const BezierCurve& edge_v, Vec3 twist);

// ==== Lagrange, Hermite and Hermite–Lagrange surfaces (ch. 1 §1.7) =======

/// f(u, v) = sum_i sum_j c_ij L_i(u) L_j(v), the tensor product of the Lagrange
/// polynomials on the nodes u_nodes[i], v_nodes[j] (ch. 1 §1.7, "Lagrange
/// surfaces"). It interpolates: f(u_i, v_j) = c_ij = c[i * v_nodes.size() + j],
/// and the curves through each row and column of c lie on the surface.
/// (Its Bézier form, for derivatives and normals, is
/// interpolating_bezier_surface(u_nodes, v_nodes, c): the same polynomial.)
struct LagrangeSurface {
  std::vector<double> u_nodes, v_nodes;  // pairwise distinct, finite
  std::vector<Vec3> c;                   // u_nodes.size() * v_nodes.size() points
};
void validate(const LagrangeSurface& surface);
/// f(u, v) with lagrange_basis_all (interpolation.h) in each direction; any
/// finite (u, v) (outside the nodes' box it extrapolates).
Vec3 surface_point(const LagrangeSurface& surface, double u, double v);

/// The bicubic Hermite patch on [0, 1]^2 (ch. 1 §1.7, "Hermite surfaces"):
/// the tensor product of the cubic Hermite polynomials H0, H0bar, H1, H1bar
/// (interpolation.h). Index [a][b] is the corner (u, v) = (a, b):
///   X(u, v) = sum_{a,b in {0,1}}  H_a(u) H_b(v) point[a][b]
///           + Hbar_a(u) H_b(v) du[a][b] + H_a(u) Hbar_b(v) dv[a][b]
///           + Hbar_a(u) Hbar_b(v) twist[a][b].
/// It interpolates the corner points, the partials Xu, Xv and the twist
/// vectors Xuv at the four corners.
struct HermitePatch {
  Vec3 point[2][2];  // X(a, b)
  Vec3 du[2][2];     // dX/du (a, b)
  Vec3 dv[2][2];     // dX/dv (a, b)
  Vec3 twist[2][2];  // d^2X/(du dv) (a, b)
};
void validate(const HermitePatch& patch);
/// X(u, v), u and v in [0, 1].
Vec3 surface_point(const HermitePatch& patch, double u, double v);
/// X, Xu, Xv, Xuv (with the derivatives of the Hermite basis).
SurfacePartials surface_partials(const HermitePatch& patch, double u, double v);
/// Unit normal with the fallback of surface_normal(const BsplineSurface&, ...).
Vec3 surface_normal(const HermitePatch& patch, double u, double v);
/// The same patch as a bicubic Bézier surface on [0, 1]^2: the corner formulas
/// of ch. 1 §1.7 (Xu(0,0) = 3 (b_10 - b_00), Xuv(0,0) = 9 (b_11 - b_10 -
/// b_01 + b_00), ...) solved for the 16 points.
BezierSurface to_bezier(const HermitePatch& patch);

/// Hermite along u, Lagrange along v (ch. 1 §1.7, "Hermite–Lagrange tensor
/// product": the derivatives are known in one direction only). For each node
/// v_j the values and u-derivatives at u = 0 and u = 1 are given:
///   X(u, v) = sum_j [H0(u) p0_j + H0bar(u) du0_j + H1(u) p1_j + H1bar(u) du1_j] L_j(v),
/// u in [0, 1]. X(u, v_j) is the Hermite segment of node j; X(0, v) and X(1, v)
/// are the Lagrange curves through p0 and p1.
struct HermiteLagrangeSurface {
  std::vector<double> v_nodes;  // the Lagrange nodes v_j
  std::vector<Vec3> p0, p1;     // X(0, v_j), X(1, v_j)
  std::vector<Vec3> du0, du1;   // dX/du (0, v_j), dX/du (1, v_j)
};
void validate(const HermiteLagrangeSurface& surface);
/// X(u, v), u in [0, 1], v any finite value.
Vec3 surface_point(const HermiteLagrangeSurface& surface, double u, double v);

// ==== B-spline and NURBS surfaces ===========================================

/// Throws naming the values when the surface is not a valid B-spline/NURBS
/// surface: the knot vectors (validate_knots with "U knot vector" and
/// "V knot vector": degrees, lengths nu + p + 1 and nv + q + 1, order,
/// multiplicities), P.size() != nu * nv, a control point that is not finite,
/// w.size() != nu * nv (when w is not empty), a weight that is NaN, infinite or
/// <= 0 (named by (i, j)). Trim loops are not checked here (trim.h).
void validate(const BsplineSurface& surface);

/// [U[p], U[nu]] and [V[q], V[nv]], where the surface is defined.
ParamInterval domain_u(const BsplineSurface& surface);
ParamInterval domain_v(const BsplineSurface& surface);

/// S(u, v). A3.5 SurfacePoint (The NURBS Book, 2nd ed., p. 103) for a
/// polynomial surface; A4.3 SurfacePoint (p. 134) for a rational one: the same
/// sum on Pw = (w x, w y, w z, w), then the projection. Spans are taken with
/// find_span: right limits at interior knots, the last span at u == U[nu].
Vec3 surface_point(const BsplineSurface& surface, double u, double v);
/// Sw(u, v) = sum N_i(u) N_j(v) Pw_ij, before the projection (w = 1 for a
/// polynomial surface).
Vec4 homogeneous_surface_point(const BsplineSurface& surface, double u, double v);

/// SKL[k][l] = d^{k+l} S / du^k dv^l at (u, v), 0 <= k + l <= d; entries with
/// k + l > d are zero. A3.6 SurfaceDerivsAlg1 (p. 111) on the homogeneous
/// points, then A4.4 RatSurfaceDerivs (p. 137) for a rational surface:
///   SKL = (Aders_kl - sum_{j=1..l} C(l,j) w_0j SKL_{k,l-j}
///                   - sum_{i=1..k} C(k,i) w_i0 SKL_{k-i,l}
///                   - sum_{i=1..k} C(k,i) sum_{j=1..l} C(l,j) w_ij SKL_{k-i,l-j}) / w_00.
/// Polynomial derivatives of order > p along u (> q along v) are zero.
std::vector<std::vector<Vec3>> surface_derivs(const BsplineSurface& surface, double u, double v, int d);

/// S, Su, Sv and the twist Suv at (u, v) (surface_derivs with d = 2).
SurfacePartials surface_partials(const BsplineSurface& surface, double u, double v);
/// The twist vector d^2S / (du dv) (ch. 1 §1.7, "The twist vector").
Vec3 surface_twist(const BsplineSurface& surface, double u, double v);

/// The unit normal N = (Su x Sv) / |Su x Sv| (ch. 1 §1.7).
/// Fallback where Su x Sv vanishes (|Su x Sv| <= kDegenerateNormal *
/// max(|Su|, |Sv|)^2: a pole such as the tip of a revolved profile, a
/// collapsed edge, or Su parallel to Sv):
///   1. the limit of the normal approached from inside the domain along the
///      direction (du, dv) = (+1 or -1, +1 or -1), +1 except at the end of the
///      domain (the side whose derivatives find_span used): the first Taylor
///      term du (Suu x Sv + Su x Suv) + dv (Suv x Sv + Su x Svv), normalized;
///   2. if that vanishes too, Su x Sv at neighbouring points (u + h du,
///      v + h dv), h = 1e-6, 1e-4, 1e-2 times the domain's widths;
///   3. if every one vanishes (the surface collapses to a curve or a point
///      there), the zero vector.
Vec3 surface_normal(const BsplineSurface& surface, double u, double v);

/// The iso-parameter curves (ch. 1 §1.7), exactly: v -> S(u0, v) has
/// degree q, knots V and the control points Q_j = sum_i N_i,p(u0) P_ij
/// (rational: in homogeneous space, weight sum_i N_i,p(u0) w_ij); u -> S(u, v0)
/// has degree p, knots U and R_i = sum_j N_j,q(v0) P_ij.
BsplineCurve iso_curve_u(const BsplineSurface& surface, double u0);
BsplineCurve iso_curve_v(const BsplineSurface& surface, double v0);

/// Pw_ij = (w x, w y, w z, w) in the layout of P (w = 1 when polynomial): the
/// premultiplied form GLU's GL_MAP2_VERTEX_4 takes.
std::vector<Vec4> to_homogeneous(const BsplineSurface& surface);

/// The surface of revolution of a profile curve in the xz-plane (its y is
/// ignored: x is the distance from the axis, z the height) about the z-axis,
/// a full turn: A8.1 MakeRevolvedSurf (The NURBS Book, p. 346) with the
/// 9-point circle of nurbs.h. Degree p and knots U of the profile along u,
/// degree 2 and the circle's knots along v; P_ij = (x_i cx_j, x_i cy_j, z_i),
/// w_ij = w_i wc_j with (cx_j, cy_j, wc_j) the unit circle's points and weights.
/// Revolving nurbs.h's circle (turned into the xz-plane) gives an exact sphere.
BsplineSurface revolved_surface(const BsplineCurve& profile);

/// The surface as tessellate.h's SurfaceEvaluator: (u, v) -> point, unit
/// normal (surface_normal's fallback at degenerate points) and the partials
/// du = Su, dv = Sv. Checks the surface once and keeps its own copy (the
/// caller's surface may go away); parameters outside the domain throw.
///   Mesh mesh = tessellate_surface(surface_evaluator(s), uv_domain(s),
///                                  TessellationOptions::adaptive(1e-3), s.trims);
SurfaceEvaluator surface_evaluator(const BsplineSurface& surface);
/// The same for a Bézier patch (through to_bspline: needs n, m >= 1).
SurfaceEvaluator surface_evaluator(const BezierSurface& surface);

/// The parameter rectangle tessellate_surface takes: domain_u x domain_v, or
/// [a, b] x [c, d] for a Bézier patch.
UvDomain uv_domain(const BsplineSurface& surface);
UvDomain uv_domain(const BezierSurface& surface);

}  // namespace gllab::spline
