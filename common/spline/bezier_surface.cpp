// common/spline/bezier_surface.cpp — tensor-product Bézier surfaces (ch. 1
// §1.7 Surface representations, "Bézier tensor product"): de Casteljau both
// ways, Bernstein form, derivatives, normals, iso-curves, continuation and
// interpolation (see surface.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include "spline/bezier.h"
#include "spline/errors.h"
#include "spline/surface.h"
#include "spline/surface_support.h"

namespace gllab::spline {

using namespace internal;  // surface_support.h: the checks and helpers both surface files use

namespace {

// ---- Bézier helpers --------------------------------------------------------------

void validate_as(const BezierSurface& s, const std::string& what) {
  if (s.n < 0 || s.m < 0)
    fail(ErrorCode::kDegreeTooLow, what + ": degrees (n, m)=" + ij_text(s.n, s.m) + " must not be negative",
         {{"n", s.n}, {"m", s.m}});
  const std::size_t count = (uz(s.n) + 1) * (uz(s.m) + 1);
  if (s.P.size() != count)
    fail(ErrorCode::kSizeMismatch,
         what + ": P.size()=" + std::to_string(s.P.size()) + " != (n+1)*(m+1) = " + std::to_string(s.n + 1) + "*" +
             std::to_string(s.m + 1) + " = " + std::to_string(count),
         {{"P", s.P.size()}, {"n", s.n}, {"m", s.m}});
  require_finite(s.a, what, "a");
  require_finite(s.b, what, "b");
  require_finite(s.c, what, "c");
  require_finite(s.d, what, "d");
  if (!(s.a < s.b))
    fail(ErrorCode::kEmptyDomain,
         what + ": u interval [a, b] = [" + num(s.a) + ", " + num(s.b) + "] is empty (need a < b)",
         {{"a", s.a}, {"b", s.b}});
  if (!(s.c < s.d))
    fail(ErrorCode::kEmptyDomain,
         what + ": v interval [c, d] = [" + num(s.c) + ", " + num(s.d) + "] is empty (need c < d)",
         {{"c", s.c}, {"d", s.d}});
  for (int i = 0; i <= s.n; ++i)
    for (int j = 0; j <= s.m; ++j)
      if (!finite(s.point(i, j))) require_finite(s.point(i, j), what, "P" + ij_text(i, j));
}

/// Row k of the net (P[k][0..m]) as a curve along v on [c, d], or column k
/// (P[0..n][k]) as a curve along u on [a, b].
BezierCurve net_curve(const BezierSurface& s, int k, bool row) {
  BezierCurve curve;
  curve.a = row ? s.c : s.a;
  curve.b = row ? s.d : s.b;
  for (int l = 0; l <= (row ? s.m : s.n); ++l) curve.P.push_back(row ? s.point(k, l) : s.point(l, k));
  return curve;
}
BezierCurve row_curve(const BezierSurface& s, int i) { return net_curve(s, i, true); }
BezierCurve column_curve(const BezierSurface& s, int j) { return net_curve(s, j, false); }

/// One de Casteljau step along the rows (u): rows - 1 rows.
ControlNet step_u(const ControlNet& net, double s) {
  ControlNet next{net.rows - 1, net.cols, {}};
  next.P.reserve(uz(next.rows) * uz(next.cols));
  for (int r = 0; r < next.rows; ++r)
    for (int k = 0; k < net.cols; ++k) next.P.push_back(lerp(net.point(r, k), net.point(r + 1, k), s));
  return next;
}

/// One de Casteljau step along the columns (v): cols - 1 columns.
ControlNet step_v(const ControlNet& net, double t) {
  ControlNet next{net.rows, net.cols - 1, {}};
  next.P.reserve(uz(next.rows) * uz(next.cols));
  for (int r = 0; r < net.rows; ++r)
    for (int k = 0; k < next.cols; ++k) next.P.push_back(lerp(net.point(r, k), net.point(r, k + 1), t));
  return next;
}

Table bezier_derivs_checked(const BezierSurface& s, double u, double v, int d) {
  // Differentiate every row along v (bezier_derivatives), then, for each order
  // l, the column of those points along u: SKL[k][l] = d^k/du^k (d^l/dv^l X).
  std::vector<std::vector<Vec3>> row_ders;  // row_ders[i][l]
  row_ders.reserve(uz(s.n) + 1);
  for (int i = 0; i <= s.n; ++i) row_ders.push_back(bezier_derivatives(row_curve(s, i), v, d));
  Table SKL(uz(d) + 1, std::vector<Vec3>(uz(d) + 1));
  for (int l = 0; l <= d; ++l) {
    BezierCurve column;
    column.a = s.a;
    column.b = s.b;
    for (int i = 0; i <= s.n; ++i) column.P.push_back(row_ders[uz(i)][uz(l)]);
    const std::vector<Vec3> ders = bezier_derivatives(column, u, d - l);
    for (int k = 0; k <= d - l; ++k) SKL[uz(k)][uz(l)] = ders[uz(k)];
  }
  return SKL;
}

}  // namespace

// ==== Bézier surfaces ============================================================

void validate(const BezierSurface& surface) { validate_as(surface, "Bezier surface"); }

BezierSurfaceConstruction de_casteljau(const BezierSurface& surface, double u, double v, SurfaceDirection first) {
  const std::string what = "de_casteljau (surface)";
  validate_as(surface, what);
  const double uc = checked_parameter(u, surface.a, surface.b, what, "u");
  const double vc = checked_parameter(v, surface.c, surface.d, what, "v");
  BezierSurfaceConstruction out;
  out.first = first;
  out.s = (uc - surface.a) / (surface.b - surface.a);
  out.t = (vc - surface.c) / (surface.d - surface.c);
  const int n = surface.n, m = surface.m;
  out.nets.push_back(ControlNet{n + 1, m + 1, surface.P});  // b^{00}
  if (first == SurfaceDirection::U) {
    for (int k = 1; k <= n; ++k) out.nets.push_back(step_u(out.nets.back(), out.s));  // b^{k,0}
    for (int l = 1; l <= m; ++l) out.nets.push_back(step_v(out.nets.back(), out.t));  // b^{n,l}
  } else {
    for (int l = 1; l <= m; ++l) out.nets.push_back(step_v(out.nets.back(), out.t));  // b^{0,l}
    for (int k = 1; k <= n; ++k) out.nets.push_back(step_u(out.nets.back(), out.s));  // b^{k,m}
  }
  out.point = out.nets.back().P.front();  // X(u, v) = b_00^{nm}
  // The net b^{n-1,m-1} (the steps commute, so take it from level 0).
  ControlNet q = out.nets.front();
  for (int k = 1; k < n; ++k) q = step_u(q, out.s);
  for (int l = 1; l < m; ++l) q = step_v(q, out.t);
  out.last_quad = q;
  SurfacePartials& d = out.partials;
  d.S = out.point;
  const double hu = surface.b - surface.a, hv = surface.d - surface.c;
  if (n >= 1 && m >= 1) {
    const Vec3 q00 = q.point(0, 0), q01 = q.point(0, 1), q10 = q.point(1, 0), q11 = q.point(1, 1);
    d.Su = n * ((1 - out.t) * (q10 - q00) + out.t * (q11 - q01)) / hu;
    d.Sv = m * ((1 - out.s) * (q01 - q00) + out.s * (q11 - q10)) / hv;
    d.Suv = (n * m) * (q11 - q10 - q01 + q00) / (hu * hv);
  } else if (n >= 1) {  // m == 0: a curve along u
    d.Su = n * (q.point(1, 0) - q.point(0, 0)) / hu;
  } else if (m >= 1) {  // n == 0: a curve along v
    d.Sv = m * (q.point(0, 1) - q.point(0, 0)) / hv;
  }
  return out;
}

Vec3 surface_point(const BezierSurface& surface, double u, double v) {
  const std::string what = "surface_point (Bezier)";
  validate_as(surface, what);
  const double s = (checked_parameter(u, surface.a, surface.b, what, "u") - surface.a) / (surface.b - surface.a);
  const double t = (checked_parameter(v, surface.c, surface.d, what, "v") - surface.c) / (surface.d - surface.c);
  // All n steps along u in place (one curve per column), then m along v.
  std::vector<Vec3> b = surface.P;
  const std::size_t cols = uz(surface.m) + 1;
  for (int k = 1; k <= surface.n; ++k)
    for (std::size_t r = 0; r + uz(k) <= uz(surface.n); ++r)
      for (std::size_t j = 0; j < cols; ++j) b[r * cols + j] = lerp(b[r * cols + j], b[(r + 1) * cols + j], s);
  for (std::size_t l = 1; l < cols; ++l)
    for (std::size_t j = 0; j + l < cols; ++j) b[j] = lerp(b[j], b[j + 1], t);
  return b[0];
}

Vec3 bernstein_surface_point(const BezierSurface& surface, double u, double v) {
  const std::string what = "bernstein_surface_point";
  validate_as(surface, what);
  const double uc = checked_parameter(u, surface.a, surface.b, what, "u");
  const double vc = checked_parameter(v, surface.c, surface.d, what, "v");
  const std::vector<double> Bu = bernstein_all(surface.n, uc, surface.a, surface.b);
  const std::vector<double> Bv = bernstein_all(surface.m, vc, surface.c, surface.d);
  Vec3 X;
  for (int i = 0; i <= surface.n; ++i) {
    Vec3 row;
    for (int j = 0; j <= surface.m; ++j) row += Bv[uz(j)] * surface.point(i, j);
    X += Bu[uz(i)] * row;
  }
  return X;
}

std::vector<std::vector<Vec3>> surface_derivs(const BezierSurface& surface, double u, double v, int d) {
  const std::string what = "surface_derivs (Bezier)";
  validate_as(surface, what);
  require_order(d, what);
  const double uc = checked_parameter(u, surface.a, surface.b, what, "u");
  const double vc = checked_parameter(v, surface.c, surface.d, what, "v");
  return bezier_derivs_checked(surface, uc, vc, d);
}

SurfacePartials surface_partials(const BezierSurface& surface, double u, double v) {
  const Table D = surface_derivs(surface, u, v, 2);
  return {D[0][0], D[1][0], D[0][1], D[1][1]};
}

Vec3 surface_normal(const BezierSurface& surface, double u, double v) {
  const std::string what = "surface_normal (Bezier)";
  validate_as(surface, what);
  const double uc = checked_parameter(u, surface.a, surface.b, what, "u");
  const double vc = checked_parameter(v, surface.c, surface.d, what, "v");
  const auto derivs2 = [&surface](double uu, double vv) { return bezier_derivs_checked(surface, uu, vv, 2); };
  return unit_normal(derivs2, uc, vc, {surface.a, surface.b}, {surface.c, surface.d});
}

BezierSurface derivative_surface(const BezierSurface& surface, int k, int l) {
  const std::string what = "derivative_surface";
  validate_as(surface, what);
  if (k < 0 || l < 0)
    fail(ErrorCode::kNegativeDerivativeOrder,
         what + ": derivative orders (k, l)=" + ij_text(k, l) + " must not be negative", {{"k", k}, {"l", l}});
  // Along u: every column becomes its k-th derivative curve (bezier_derivative:
  // n!/(n-k)! Delta^k / (b-a)^k); then along v every row its l-th.
  std::vector<BezierCurve> columns;
  for (int j = 0; j <= surface.m; ++j) columns.push_back(bezier_derivative(column_curve(surface, j), k));
  BezierSurface out;
  out.a = surface.a;
  out.b = surface.b;
  out.c = surface.c;
  out.d = surface.d;
  out.n = static_cast<int>(columns.front().P.size()) - 1;
  std::vector<BezierCurve> rows;
  for (int i = 0; i <= out.n; ++i) {
    BezierCurve row;
    row.a = surface.c;
    row.b = surface.d;
    for (const BezierCurve& column : columns) row.P.push_back(column.P[uz(i)]);
    rows.push_back(bezier_derivative(row, l));
  }
  out.m = static_cast<int>(rows.front().P.size()) - 1;
  for (const BezierCurve& row : rows) out.P.insert(out.P.end(), row.P.begin(), row.P.end());
  return out;
}

namespace {
/// An iso-curve of a Bézier surface is a Bézier curve: its control points are
/// the points of the columns (u fixed) or the rows (v fixed) at the parameter.
BezierCurve bezier_iso_curve(const BezierSurface& s, double t, bool u_fixed) {
  const std::string what = u_fixed ? "iso_curve_u (Bezier)" : "iso_curve_v (Bezier)";
  validate_as(s, what);
  const double tc = u_fixed ? checked_parameter(t, s.a, s.b, what, "u0") : checked_parameter(t, s.c, s.d, what, "v0");
  BezierCurve curve;
  curve.a = u_fixed ? s.c : s.a;
  curve.b = u_fixed ? s.d : s.b;
  for (int k = 0; k <= (u_fixed ? s.m : s.n); ++k)
    curve.P.push_back(bezier_point(u_fixed ? column_curve(s, k) : row_curve(s, k), tc));
  return curve;
}
}  // namespace

BezierCurve iso_curve_u(const BezierSurface& surface, double u0) { return bezier_iso_curve(surface, u0, true); }
BezierCurve iso_curve_v(const BezierSurface& surface, double v0) { return bezier_iso_curve(surface, v0, false); }

BsplineSurface to_bspline(const BezierSurface& surface) {
  const std::string what = "to_bspline (Bezier surface)";
  validate_as(surface, what);
  if (surface.n < 1 || surface.m < 1)
    fail(ErrorCode::kDegreeTooLow,
         what + ": degrees (n, m)=" + ij_text(surface.n, surface.m) + " (a B-spline surface needs degree >= 1)",
         {{"n", surface.n}, {"m", surface.m}});
  BsplineSurface out;
  out.p = surface.n;
  out.q = surface.m;
  out.nu = surface.n + 1;
  out.nv = surface.m + 1;
  out.U.assign(uz(surface.n) + 1, surface.a);
  out.U.insert(out.U.end(), uz(surface.n) + 1, surface.b);
  out.V.assign(uz(surface.m) + 1, surface.c);
  out.V.insert(out.V.end(), uz(surface.m) + 1, surface.d);
  out.P = surface.P;
  return out;
}

BezierSurface interpolating_bezier_surface(const std::vector<double>& us, const std::vector<double>& vs,
                                           const std::vector<Vec3>& points) {
  const std::string what = "interpolating_bezier_surface";
  if (us.size() < 2 || vs.size() < 2)
    fail(ErrorCode::kTooFewPoints,
         what + ": " + std::to_string(us.size()) + " u and " + std::to_string(vs.size()) +
             " v parameters (need at least 2 each way)",
         {{"us", us.size()}, {"vs", vs.size()}});
  if (points.size() != us.size() * vs.size())
    fail(ErrorCode::kSizeMismatch,
         what + ": points.size()=" + std::to_string(points.size()) +
             " != us.size()*vs.size() = " + std::to_string(us.size()) + "*" + std::to_string(vs.size()),
         {{"points", points.size()}, {"us", us.size()}, {"vs", vs.size()}});
  require_nodes(us, what, "us");
  require_nodes(vs, what, "vs");
  const std::size_t rows = us.size(), cols = vs.size();
  // Step 1 (ch. 1 §1.7): one curve per column j through points[., j] at us.
  std::vector<Vec3> A(rows * cols);  // a_ij
  BezierCurve first;
  for (std::size_t j = 0; j < cols; ++j) {
    std::vector<Vec3> column;
    for (std::size_t i = 0; i < rows; ++i) column.push_back(points[i * cols + j]);
    first = bezier_interpolate(column, us);
    for (std::size_t i = 0; i < rows; ++i) A[i * cols + j] = first.P[i];
  }
  // Step 2: row-wise through a_i0..a_im at vs gives b_ij.
  BezierSurface out;
  out.n = static_cast<int>(rows) - 1;
  out.m = static_cast<int>(cols) - 1;
  out.a = first.a;
  out.b = first.b;
  for (std::size_t i = 0; i < rows; ++i) {
    const std::vector<Vec3> row(A.begin() + static_cast<std::ptrdiff_t>(i * cols),
                                A.begin() + static_cast<std::ptrdiff_t>((i + 1) * cols));
    const BezierCurve second = bezier_interpolate(row, vs);
    out.c = second.a;
    out.d = second.b;
    out.P.insert(out.P.end(), second.P.begin(), second.P.end());
  }
  return out;
}

std::vector<std::vector<Vec3>> continuation_rows(const BezierSurface& a, int k, double next_length,
                                                 SurfaceDirection direction) {
  const std::string what = "continuation_rows";
  validate_as(a, what);
  const bool along_u = direction == SurfaceDirection::U;
  const int degree = along_u ? a.n : a.m;
  if (k < 0 || k > degree)
    fail(ErrorCode::kOutOfRange,
         what + ": continuity k=" + std::to_string(k) + " must lie in [0, " + std::to_string(degree) +
             "] (the degree across the edge)",
         {{"k", k}, {"degree", degree}});
  require_finite(next_length, what, "next_length");
  if (!(next_length > 0))
    fail(ErrorCode::kOutOfRange, what + ": next_length=" + num(next_length) + " must be > 0",
         {{"next_length", next_length}});
  // The neighbour's far end in a's local parameter: tau = (s2 - s0) / (s1 - s0).
  const double tau = 1 + next_length / (along_u ? a.b - a.a : a.d - a.c);
  const int lines = along_u ? a.m + 1 : a.n + 1;
  std::vector<std::vector<Vec3>> rows(uz(k) + 1, std::vector<Vec3>(uz(lines)));
  for (int line = 0; line < lines; ++line) {
    // The curve across the edge: column `line` (U) or row `line` (V).
    std::vector<Vec3> b;
    for (int r = 0; r <= degree; ++r) b.push_back(along_u ? a.point(r, line) : a.point(line, r));
    // de Casteljau at tau, keeping the last point of each level: b_{n-r}^r.
    for (int r = 0; r <= k; ++r) {
      rows[uz(r)][uz(line)] = b[uz(degree - r)];
      for (int i = 0; i + r < degree; ++i) b[uz(i)] = lerp(b[uz(i)], b[uz(i) + 1], tau);
    }
  }
  return rows;
}

BezierSurface joined_patch(const BezierSurface& a, const BezierSurface& next, int k, SurfaceDirection direction) {
  const std::string what = "joined_patch";
  validate_as(a, what + " (patch a)");
  validate_as(next, what + " (patch next)");
  if (a.n != next.n || a.m != next.m)
    fail(ErrorCode::kPiecesDoNotJoin,
         what + ": degrees " + ij_text(next.n, next.m) + " of next differ from " + ij_text(a.n, a.m) + " of a",
         {{"n", next.n}, {"m", next.m}, {"a.n", a.n}, {"a.m", a.m}});
  const bool along_u = direction == SurfaceDirection::U;
  if (along_u ? (a.c != next.c || a.d != next.d) : (a.a != next.a || a.b != next.b))
    fail(ErrorCode::kPiecesDoNotJoin,
         what + ": the intervals along the shared edge differ: " +
             (along_u ? "[" + num(a.c) + ", " + num(a.d) + "] vs [" + num(next.c) + ", " + num(next.d) + "]"
                      : "[" + num(a.a) + ", " + num(a.b) + "] vs [" + num(next.a) + ", " + num(next.b) + "]"));
  const double length = along_u ? next.b - next.a : next.d - next.c;
  const std::vector<std::vector<Vec3>> rows = continuation_rows(a, k, length, direction);
  BezierSurface out = next;
  if (along_u) {
    out.a = a.b;
    out.b = a.b + length;
  } else {
    out.c = a.d;
    out.d = a.d + length;
  }
  for (int r = 0; r <= k; ++r)
    for (std::size_t line = 0; line < rows[uz(r)].size(); ++line) {
      const int x = static_cast<int>(line);
      (along_u ? out.point(r, x) : out.point(x, r)) = rows[uz(r)][line];
    }
  return out;
}

BezierSurface constant_twist_patch(const BezierCurve& edge_u, const BezierCurve& edge_v, Vec3 twist) {
  const std::string what = "constant_twist_patch";
  validate(edge_u);
  validate(edge_v);
  require_finite(twist, what, "twist");
  BezierSurface out;
  out.n = static_cast<int>(edge_u.P.size()) - 1;
  out.m = static_cast<int>(edge_v.P.size()) - 1;
  if (out.n < 1 || out.m < 1)
    fail(ErrorCode::kTooFewPoints,
         what + ": degrees " + ij_text(out.n, out.m) + " (the edges need at least 2 points each)",
         {{"n", out.n}, {"m", out.m}});
  if (edge_u.P[0] != edge_v.P[0])
    fail(ErrorCode::kPiecesDoNotJoin,
         what + ": the edges start at different corners: edge_u " + num(edge_u.P[0]) + ", edge_v " + num(edge_v.P[0]),
         {{"edge_u.P[0]", edge_u.P[0]}, {"edge_v.P[0]", edge_v.P[0]}});
  out.a = edge_u.a, out.b = edge_u.b, out.c = edge_v.a, out.d = edge_v.b;
  out.P.resize(uz((out.n + 1) * (out.m + 1)));
  // Each cell's share of the twist: X_uv = n m Delta^{11} b / ((b - a)(d - c)).
  const Vec3 cell = (out.b - out.a) * (out.d - out.c) / (out.n * out.m) * twist;
  for (int i = 0; i <= out.n; ++i)
    for (int j = 0; j <= out.m; ++j)
      out.point(i, j) = i == 0   ? edge_v.P[uz(j)]
                        : j == 0 ? edge_u.P[uz(i)]
                                 : edge_u.P[uz(i)] + (edge_v.P[uz(j)] - edge_v.P[0]) + double(i * j) * cell;
  return out;
}

// ==== Lagrange, Hermite, Hermite–Lagrange =========================================

SurfaceEvaluator surface_evaluator(const BezierSurface& surface) { return surface_evaluator(to_bspline(surface)); }

UvDomain uv_domain(const BezierSurface& surface) {
  validate(surface);
  return {surface.a, surface.b, surface.c, surface.d};
}

}  // namespace gllab::spline
