// common/spline/surface.cpp — tensor-product surfaces (ch. 1 §1.7). See
// surface.h for what each function returns and where its formula comes from.
#include "spline/surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>

#include "spline/bezier.h"
#include "spline/errors.h"
#include "spline/interpolation.h"
#include "spline/nurbs.h"

namespace gllab::spline {

namespace {

using Table = std::vector<std::vector<Vec3>>;  // SKL[k][l]

std::size_t uz(int i) { return static_cast<std::size_t>(i); }

bool finite(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

/// C(n, k) as a double (small n: derivative orders).
double binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  double r = 1;
  for (int j = 1; j <= k; ++j) r = r * (n - k + j) / j;
  return r;
}

std::string interval_text(const char* name, double lo, double hi) {
  return std::string(name) + " interval [" + num(lo) + ", " + num(hi) + "]";
}

std::string ij_text(int i, int j) { return "(" + std::to_string(i) + ", " + std::to_string(j) + ")"; }

/// A parameter of a Bézier-type surface checked against [lo, hi] and snapped
/// onto it when it misses only by round-off (kBezierParameterSlack, bezier.h).
double checked_parameter(double x, double lo, double hi, const std::string& what, const char* name) {
  require_finite(x, what, name);
  const double slack = kBezierParameterSlack * std::max({std::fabs(lo), std::fabs(hi), hi - lo});
  if (x < lo - slack || x > hi + slack)
    fail(what + ": " + name + "=" + num(x) + " is outside the " + interval_text(name, lo, hi) +
         (x < lo ? " (below)" : " (above)"));
  return std::clamp(x, lo, hi);
}

/// A B-spline parameter checked against its domain (no snapping: find_span
/// decides the span exactly).
void require_in(double x, ParamInterval dom, const std::string& what, const char* name) {
  require_finite(x, what, name);
  if (x < dom.a || x > dom.b)
    fail(what + ": " + name + "=" + num(x) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) + "]");
}

void require_nodes(const std::vector<double>& nodes, const std::string& what, const char* name) {
  if (nodes.empty()) fail(what + ": " + name + " is empty (need at least one node)");
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    require_finite(nodes[i], what, at(name, i));
    for (std::size_t k = 0; k < i; ++k)
      if (nodes[k] == nodes[i])
        fail(what + ": " + at(name, k) + "=" + num(nodes[k]) + " and " + at(name, i) + "=" + num(nodes[i]) +
             " coincide (nodes must be pairwise distinct)");
  }
}

void require_order(int d, const std::string& what) {
  if (d < 0) fail(what + ": derivative order d=" + std::to_string(d) + " is negative");
}

// ---- unit normal with fallback (shared by every surface type) ----------------

/// true when |n| is zero at the scale of the vectors it was made of.
bool degenerate(Vec3 n, double scale) { return !(norm(n) > kDegenerateNormal * scale * scale); }

/// surface.h, surface_normal(const BsplineSurface&, ...): Su x Sv, else the
/// first Taylor term from inside the domain, else neighbouring points, else 0.
/// derivs2(u, v) returns SKL up to order 2 at a point of the domain.
template <class Derivs2>
Vec3 unit_normal(const Derivs2& derivs2, double u, double v, ParamInterval du, ParamInterval dv) {
  const Table D = derivs2(u, v);
  const Vec3 Su = D[1][0], Sv = D[0][1];
  const Vec3 n = cross(Su, Sv);
  if (!degenerate(n, std::max(norm(Su), norm(Sv)))) return normalized(n);
  // 1. Approach (u, v) from inside: d/de (Su x Sv)(u + e eu, v + e ev) at e = 0.
  const double eu = u < du.b ? 1.0 : -1.0, ev = v < dv.b ? 1.0 : -1.0;
  const Vec3 Suu = D[2][0], Suv = D[1][1], Svv = D[0][2];
  const Vec3 n1 = eu * (cross(Suu, Sv) + cross(Su, Suv)) + ev * (cross(Suv, Sv) + cross(Su, Svv));
  const double scale = std::max({norm(Su), norm(Sv), norm(Suu), norm(Suv), norm(Svv)});
  if (!degenerate(n1, scale)) return normalized(n1);
  // 2. Neighbouring points, a little further inside each time.
  for (double h : {1e-6, 1e-4, 1e-2}) {
    const double un = std::clamp(u + eu * h * (du.b - du.a), du.a, du.b);
    const double vn = std::clamp(v + ev * h * (dv.b - dv.a), dv.a, dv.b);
    const Table Dn = derivs2(un, vn);
    const Vec3 nn = cross(Dn[1][0], Dn[0][1]);
    if (!degenerate(nn, std::max(norm(Dn[1][0]), norm(Dn[0][1])))) return normalized(nn);
  }
  return {};  // 3. the surface collapses to a curve or a point here
}

// ---- Bézier helpers --------------------------------------------------------------

void validate_as(const BezierSurface& s, const std::string& what) {
  if (s.n < 0 || s.m < 0)
    fail(what + ": degrees (n, m)=" + ij_text(s.n, s.m) + " must not be negative");
  const std::size_t count = (uz(s.n) + 1) * (uz(s.m) + 1);
  if (s.P.size() != count)
    fail(what + ": P.size()=" + std::to_string(s.P.size()) + " != (n+1)*(m+1) = " + std::to_string(s.n + 1) + "*" +
         std::to_string(s.m + 1) + " = " + std::to_string(count));
  require_finite(s.a, what, "a");
  require_finite(s.b, what, "b");
  require_finite(s.c, what, "c");
  require_finite(s.d, what, "d");
  if (!(s.a < s.b)) fail(what + ": u interval [a, b] = [" + num(s.a) + ", " + num(s.b) + "] is empty (need a < b)");
  if (!(s.c < s.d)) fail(what + ": v interval [c, d] = [" + num(s.c) + ", " + num(s.d) + "] is empty (need c < d)");
  for (int i = 0; i <= s.n; ++i)
    for (int j = 0; j <= s.m; ++j)
      if (!finite(s.point(i, j))) require_finite(s.point(i, j), what, "P" + ij_text(i, j));
}

/// Row i of the net (j = 0..m) as a curve along v on [c, d].
BezierCurve row_curve(const BezierSurface& s, int i) {
  BezierCurve curve;
  curve.a = s.c;
  curve.b = s.d;
  for (int j = 0; j <= s.m; ++j) curve.P.push_back(s.point(i, j));
  return curve;
}

/// Column j of the net (i = 0..n) as a curve along u on [a, b].
BezierCurve column_curve(const BezierSurface& s, int j) {
  BezierCurve curve;
  curve.a = s.a;
  curve.b = s.b;
  for (int i = 0; i <= s.n; ++i) curve.P.push_back(s.point(i, j));
  return curve;
}

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

// ---- B-spline helpers --------------------------------------------------------------

Vec4 pw(const BsplineSurface& s, int i, int j) { return homogeneous(s.point(i, j), s.weight(i, j)); }

/// Sw(u, v): A3.5 SurfacePoint (p. 103) on the homogeneous points (A4.3, p. 134).
Vec4 homogeneous_point_unchecked(const BsplineSurface& s, double u, double v) {
  const int uspan = find_span(s.nu - 1, s.p, u, s.U);
  const int vspan = find_span(s.nv - 1, s.q, v, s.V);
  std::array<double, kMaxDegree + 1> Nu{}, Nv{};
  basis_funs(uspan, u, s.p, s.U, Nu.data());
  basis_funs(vspan, v, s.q, s.V, Nv.data());
  Vec4 Sw;
  for (int l = 0; l <= s.q; ++l) {
    Vec4 temp;
    for (int k = 0; k <= s.p; ++k) temp += Nu[uz(k)] * pw(s, uspan - s.p + k, vspan - s.q + l);
    Sw += Nv[uz(l)] * temp;
  }
  return Sw;
}

/// A3.6 SurfaceDerivsAlg1 (p. 111) on Pw, then A4.4 RatSurfaceDerivs (p. 137).
Table derivs_unchecked(const BsplineSurface& s, double u, double v, int d) {
  const int p = s.p, q = s.q;
  const int du = std::min(d, p), dv = std::min(d, q);
  const int uspan = find_span(s.nu - 1, p, u, s.U);
  const int vspan = find_span(s.nv - 1, q, v, s.V);
  const std::vector<std::vector<double>> Nu = ders_basis_funs(uspan, u, p, du, s.U);
  const std::vector<std::vector<double>> Nv = ders_basis_funs(vspan, v, q, dv, s.V);
  // Aders[k][l] = d^{k+l} Sw / du^k dv^l (zero beyond the degrees).
  std::vector<std::vector<Vec4>> Aders(uz(d) + 1, std::vector<Vec4>(uz(d) + 1));
  std::vector<Vec4> temp(uz(q) + 1);
  for (int k = 0; k <= du; ++k) {
    for (int r = 0; r <= q; ++r) {
      temp[uz(r)] = Vec4{};
      for (int c = 0; c <= p; ++c) temp[uz(r)] += Nu[uz(k)][uz(c)] * pw(s, uspan - p + c, vspan - q + r);
    }
    for (int l = 0; l <= std::min(d - k, dv); ++l)
      for (int r = 0; r <= q; ++r) Aders[uz(k)][uz(l)] += Nv[uz(l)][uz(r)] * temp[uz(r)];
  }
  Table SKL(uz(d) + 1, std::vector<Vec3>(uz(d) + 1));
  if (!s.rational()) {
    for (int k = 0; k <= d; ++k)
      for (int l = 0; l <= d - k; ++l) SKL[uz(k)][uz(l)] = xyz(Aders[uz(k)][uz(l)]);
    return SKL;
  }
  for (int k = 0; k <= d; ++k) {
    for (int l = 0; l <= d - k; ++l) {
      Vec3 val = xyz(Aders[uz(k)][uz(l)]);
      for (int j = 1; j <= l; ++j) val -= binomial(l, j) * Aders[0][uz(j)].w * SKL[uz(k)][uz(l - j)];
      for (int i = 1; i <= k; ++i) {
        val -= binomial(k, i) * Aders[uz(i)][0].w * SKL[uz(k - i)][uz(l)];
        Vec3 v2;
        for (int j = 1; j <= l; ++j) v2 += binomial(l, j) * Aders[uz(i)][uz(j)].w * SKL[uz(k - i)][uz(l - j)];
        val -= binomial(k, i) * v2;
      }
      SKL[uz(k)][uz(l)] = val / Aders[0][0].w;
    }
  }
  return SKL;
}

Vec3 normal_unchecked(const BsplineSurface& s, double u, double v) {
  const auto derivs2 = [&s](double uu, double vv) { return derivs_unchecked(s, uu, vv, 2); };
  return unit_normal(derivs2, u, v, domain(s.p, s.U), domain(s.q, s.V));
}

void check_uv(const BsplineSurface& s, double u, double v, const std::string& what) {
  require_in(u, domain(s.p, s.U), what, "u");
  require_in(v, domain(s.q, s.V), what, "v");
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
  if (k < 0 || l < 0) fail(what + ": derivative orders (k, l)=" + ij_text(k, l) + " must not be negative");
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

BezierCurve iso_curve_u(const BezierSurface& surface, double u0) {
  const std::string what = "iso_curve_u (Bezier)";
  validate_as(surface, what);
  const double uc = checked_parameter(u0, surface.a, surface.b, what, "u0");
  BezierCurve curve;
  curve.a = surface.c;
  curve.b = surface.d;
  for (int j = 0; j <= surface.m; ++j) curve.P.push_back(bezier_point(column_curve(surface, j), uc));
  return curve;
}

BezierCurve iso_curve_v(const BezierSurface& surface, double v0) {
  const std::string what = "iso_curve_v (Bezier)";
  validate_as(surface, what);
  const double vc = checked_parameter(v0, surface.c, surface.d, what, "v0");
  BezierCurve curve;
  curve.a = surface.a;
  curve.b = surface.b;
  for (int i = 0; i <= surface.n; ++i) curve.P.push_back(bezier_point(row_curve(surface, i), vc));
  return curve;
}

BsplineSurface to_bspline(const BezierSurface& surface) {
  const std::string what = "to_bspline (Bezier surface)";
  validate_as(surface, what);
  if (surface.n < 1 || surface.m < 1)
    fail(what + ": degrees (n, m)=" + ij_text(surface.n, surface.m) + " (a B-spline surface needs degree >= 1)");
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
    fail(what + ": " + std::to_string(us.size()) + " u and " + std::to_string(vs.size()) +
         " v parameters (need at least 2 each way)");
  if (points.size() != us.size() * vs.size())
    fail(what + ": points.size()=" + std::to_string(points.size()) + " != us.size()*vs.size() = " +
         std::to_string(us.size()) + "*" + std::to_string(vs.size()));
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
    fail(what + ": continuity k=" + std::to_string(k) + " must lie in [0, " + std::to_string(degree) +
         "] (the degree across the edge)");
  require_finite(next_length, what, "next_length");
  if (!(next_length > 0)) fail(what + ": next_length=" + num(next_length) + " must be > 0");
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
    fail(what + ": degrees " + ij_text(next.n, next.m) + " of next differ from " + ij_text(a.n, a.m) + " of a");
  const bool along_u = direction == SurfaceDirection::U;
  if (along_u ? (a.c != next.c || a.d != next.d) : (a.a != next.a || a.b != next.b))
    fail(what + ": the intervals along the shared edge differ: " +
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
    fail(what + ": degrees " + ij_text(out.n, out.m) + " (the edges need at least 2 points each)");
  if (edge_u.P[0] != edge_v.P[0])
    fail(what + ": the edges start at different corners: edge_u " + num(edge_u.P[0]) + ", edge_v " +
         num(edge_v.P[0]));
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

namespace {

/// {H0, H0bar, H1, H1bar} (or their derivatives) as an array indexed like the
/// patch: [0] value basis at 0, [1] slope basis at 0, [2] value at 1, [3] slope at 1.
std::array<double, 4> hermite4(const HermiteBasis& h) { return {h.H0, h.H0bar, h.H1, h.H1bar}; }

Vec3 hermite_sum(const HermitePatch& patch, const std::array<double, 4>& hu, const std::array<double, 4>& hv) {
  Vec3 X;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double Hu = hu[uz(2 * a)], Hbu = hu[uz(2 * a + 1)], Hv = hv[uz(2 * b)], Hbv = hv[uz(2 * b + 1)];
      X += Hu * Hv * patch.point[a][b] + Hbu * Hv * patch.du[a][b] + Hu * Hbv * patch.dv[a][b] +
           Hbu * Hbv * patch.twist[a][b];
    }
  return X;
}

}  // namespace

void validate(const LagrangeSurface& surface) {
  const std::string what = "Lagrange surface";
  require_nodes(surface.u_nodes, what, "u_nodes");
  require_nodes(surface.v_nodes, what, "v_nodes");
  const std::size_t count = surface.u_nodes.size() * surface.v_nodes.size();
  if (surface.c.size() != count)
    fail(what + ": c.size()=" + std::to_string(surface.c.size()) + " != u_nodes.size()*v_nodes.size() = " +
         std::to_string(surface.u_nodes.size()) + "*" + std::to_string(surface.v_nodes.size()));
  for (std::size_t i = 0; i < count; ++i) require_finite(surface.c[i], what, at("c", i));
}

Vec3 surface_point(const LagrangeSurface& surface, double u, double v) {
  validate(surface);
  require_finite(u, "surface_point (Lagrange)", "u");
  require_finite(v, "surface_point (Lagrange)", "v");
  const std::vector<double> Lu = lagrange_basis_all(surface.u_nodes, u);
  const std::vector<double> Lv = lagrange_basis_all(surface.v_nodes, v);
  const std::size_t cols = Lv.size();
  Vec3 f;
  for (std::size_t i = 0; i < Lu.size(); ++i) {
    Vec3 ci;  // c_i(v) = sum_j c_ij L_j(v), the lecture's curve c-bar_i(t)
    for (std::size_t j = 0; j < cols; ++j) ci += Lv[j] * surface.c[i * cols + j];
    f += Lu[i] * ci;
  }
  return f;
}

void validate(const HermitePatch& patch) {
  const std::string what = "Hermite patch";
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      require_finite(patch.point[a][b], what, "point" + ij_text(a, b));
      require_finite(patch.du[a][b], what, "du" + ij_text(a, b));
      require_finite(patch.dv[a][b], what, "dv" + ij_text(a, b));
      require_finite(patch.twist[a][b], what, "twist" + ij_text(a, b));
    }
}

Vec3 surface_point(const HermitePatch& patch, double u, double v) {
  const std::string what = "surface_point (Hermite)";
  validate(patch);
  const double uc = checked_parameter(u, 0, 1, what, "u"), vc = checked_parameter(v, 0, 1, what, "v");
  return hermite_sum(patch, hermite4(cubic_hermite_basis(uc)), hermite4(cubic_hermite_basis(vc)));
}

SurfacePartials surface_partials(const HermitePatch& patch, double u, double v) {
  const std::string what = "surface_partials (Hermite)";
  validate(patch);
  const double uc = checked_parameter(u, 0, 1, what, "u"), vc = checked_parameter(v, 0, 1, what, "v");
  const auto hu = hermite4(cubic_hermite_basis(uc)), hv = hermite4(cubic_hermite_basis(vc));
  const auto dhu = hermite4(cubic_hermite_basis_derivative(uc)), dhv = hermite4(cubic_hermite_basis_derivative(vc));
  return {hermite_sum(patch, hu, hv), hermite_sum(patch, dhu, hv), hermite_sum(patch, hu, dhv),
          hermite_sum(patch, dhu, dhv)};
}

Vec3 surface_normal(const HermitePatch& patch, double u, double v) {
  validate(patch);
  return surface_normal(to_bezier(patch), u, v);
}

BezierSurface to_bezier(const HermitePatch& patch) {
  validate(patch);
  BezierSurface out;
  out.n = out.m = 3;
  out.P.assign(16, Vec3{});
  // Corner (a, b): b at (i0, j0) is the point; one step inwards along u (v)
  // adds du/3 (dv/3) with the sign of the step; the inner point adds twist/9
  // (ch. 1 §1.7: Xu(0,0) = 3 (b_10 - b_00), Xuv(0,0) = 9 (b_11 - b_10 - b_01 + b_00)).
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const int i0 = 3 * a, j0 = 3 * b;
      const double su = a == 0 ? 1.0 : -1.0, sv = b == 0 ? 1.0 : -1.0;
      const int i1 = i0 + static_cast<int>(su), j1 = j0 + static_cast<int>(sv);
      const Vec3 P = patch.point[a][b], Pu = su / 3 * patch.du[a][b], Pv = sv / 3 * patch.dv[a][b];
      out.point(i0, j0) = P;
      out.point(i1, j0) = P + Pu;
      out.point(i0, j1) = P + Pv;
      out.point(i1, j1) = P + Pu + Pv + su * sv / 9 * patch.twist[a][b];
    }
  return out;
}

void validate(const HermiteLagrangeSurface& surface) {
  const std::string what = "Hermite-Lagrange surface";
  require_nodes(surface.v_nodes, what, "v_nodes");
  const std::size_t count = surface.v_nodes.size();
  const std::pair<const char*, const std::vector<Vec3>*> lists[] = {
      {"p0", &surface.p0}, {"p1", &surface.p1}, {"du0", &surface.du0}, {"du1", &surface.du1}};
  for (const auto& [name, list] : lists) {
    if (list->size() != count)
      fail(what + ": " + name + ".size()=" + std::to_string(list->size()) + " != v_nodes.size()=" +
           std::to_string(count));
    for (std::size_t j = 0; j < count; ++j) require_finite((*list)[j], what, at(name, j));
  }
}

Vec3 surface_point(const HermiteLagrangeSurface& surface, double u, double v) {
  const std::string what = "surface_point (Hermite-Lagrange)";
  validate(surface);
  const double uc = checked_parameter(u, 0, 1, what, "u");
  require_finite(v, what, "v");
  const HermiteBasis h = cubic_hermite_basis(uc);
  const std::vector<double> L = lagrange_basis_all(surface.v_nodes, v);
  Vec3 X;
  for (std::size_t j = 0; j < L.size(); ++j)
    X += L[j] * (h.H0 * surface.p0[j] + h.H0bar * surface.du0[j] + h.H1 * surface.p1[j] + h.H1bar * surface.du1[j]);
  return X;
}

// ==== B-spline and NURBS surfaces ====================================================

void validate(const BsplineSurface& surface) {
  const std::string what = "B-spline surface";
  if (surface.nu < 1 || surface.nv < 1)
    fail(what + ": (nu, nv)=" + ij_text(surface.nu, surface.nv) + " (need at least one control point each way)");
  validate_knots(surface.p, surface.nu, surface.U, "U knot vector");
  validate_knots(surface.q, surface.nv, surface.V, "V knot vector", "V");
  const std::size_t count = uz(surface.nu) * uz(surface.nv);
  if (surface.P.size() != count)
    fail(what + ": P.size()=" + std::to_string(surface.P.size()) + " != nu*nv = " + std::to_string(surface.nu) + "*" +
         std::to_string(surface.nv) + " = " + std::to_string(count));
  for (int i = 0; i < surface.nu; ++i)
    for (int j = 0; j < surface.nv; ++j)
      if (!finite(surface.point(i, j))) require_finite(surface.point(i, j), what, "P" + ij_text(i, j));
  if (surface.w.empty()) return;
  if (surface.w.size() != count)
    fail(what + ": w.size()=" + std::to_string(surface.w.size()) + " != nu*nv = " + std::to_string(count) +
         " (one weight per control point, or none)");
  for (int i = 0; i < surface.nu; ++i)
    for (int j = 0; j < surface.nv; ++j) {
      const double wij = surface.weight(i, j);
      if (!std::isfinite(wij)) require_finite(wij, what, "weight w" + ij_text(i, j));
      if (!(wij > 0)) fail(what + ": weight w" + ij_text(i, j) + "=" + num(wij) + " must be > 0");
    }
}

ParamInterval domain_u(const BsplineSurface& surface) {
  validate(surface);
  return domain(surface.p, surface.U);
}

ParamInterval domain_v(const BsplineSurface& surface) {
  validate(surface);
  return domain(surface.q, surface.V);
}

Vec3 surface_point(const BsplineSurface& surface, double u, double v) {
  const std::string what = "surface_point";
  validate(surface);
  check_uv(surface, u, v, what);
  const Vec4 Sw = homogeneous_point_unchecked(surface, u, v);
  return surface.rational() ? project(Sw) : xyz(Sw);
}

Vec4 homogeneous_surface_point(const BsplineSurface& surface, double u, double v) {
  validate(surface);
  check_uv(surface, u, v, "homogeneous_surface_point");
  return homogeneous_point_unchecked(surface, u, v);
}

std::vector<std::vector<Vec3>> surface_derivs(const BsplineSurface& surface, double u, double v, int d) {
  const std::string what = "surface_derivs";
  validate(surface);
  require_order(d, what);
  check_uv(surface, u, v, what);
  return derivs_unchecked(surface, u, v, d);
}

SurfacePartials surface_partials(const BsplineSurface& surface, double u, double v) {
  const Table D = surface_derivs(surface, u, v, 2);
  return {D[0][0], D[1][0], D[0][1], D[1][1]};
}

Vec3 surface_twist(const BsplineSurface& surface, double u, double v) { return surface_partials(surface, u, v).Suv; }

Vec3 surface_normal(const BsplineSurface& surface, double u, double v) {
  validate(surface);
  check_uv(surface, u, v, "surface_normal");
  return normal_unchecked(surface, u, v);
}

namespace {

/// The iso-curve through one parameter: blend the control lines across
/// `direction` with the basis functions at x (homogeneous for NURBS).
BsplineCurve iso_curve(const BsplineSurface& s, double x, bool fixed_u, const std::string& what) {
  validate(s);
  require_in(x, fixed_u ? domain(s.p, s.U) : domain(s.q, s.V), what, fixed_u ? "u0" : "v0");
  const int deg = fixed_u ? s.p : s.q;
  const int count = fixed_u ? s.nu : s.nv;  // control lines blended
  const int along = fixed_u ? s.nv : s.nu;  // points of the result
  const std::vector<double>& knots = fixed_u ? s.U : s.V;
  const int span = find_span(count - 1, deg, x, knots);
  const std::vector<double> N = basis_funs(span, x, deg, knots);
  BsplineCurve curve;
  curve.p = fixed_u ? s.q : s.p;
  curve.U = fixed_u ? s.V : s.U;
  for (int k = 0; k < along; ++k) {
    Vec4 Qw;
    for (int r = 0; r <= deg; ++r) {
      const int line = span - deg + r;
      Qw += N[uz(r)] * (fixed_u ? pw(s, line, k) : pw(s, k, line));
    }
    curve.P.push_back(project(Qw));
    if (s.rational()) curve.w.push_back(Qw.w);
  }
  return curve;
}

}  // namespace

BsplineCurve iso_curve_u(const BsplineSurface& surface, double u0) { return iso_curve(surface, u0, true, "iso_curve_u"); }
BsplineCurve iso_curve_v(const BsplineSurface& surface, double v0) {
  return iso_curve(surface, v0, false, "iso_curve_v");
}

std::vector<Vec4> to_homogeneous(const BsplineSurface& surface) {
  validate(surface);
  std::vector<Vec4> Pw;
  Pw.reserve(surface.P.size());
  for (int i = 0; i < surface.nu; ++i)
    for (int j = 0; j < surface.nv; ++j) Pw.push_back(pw(surface, i, j));
  return Pw;
}

BsplineSurface revolved_surface(const BsplineCurve& profile) {
  validate(profile);
  // A8.1 MakeRevolvedSurf (The NURBS Book, p. 346) for a full turn about the
  // z-axis: the unit circle's points scaled by the distance x_i from the axis.
  const BsplineCurve unit = circle(Vec3{}, 1);
  BsplineSurface out;
  out.p = profile.p;
  out.q = unit.p;
  out.U = profile.U;
  out.V = unit.U;
  out.nu = static_cast<int>(profile.P.size());
  out.nv = static_cast<int>(unit.P.size());
  for (int i = 0; i < out.nu; ++i) {
    const Vec3 Pi = profile.P[uz(i)];
    const double wi = profile.rational() ? profile.w[uz(i)] : 1.0;
    for (int j = 0; j < out.nv; ++j) {
      const Vec3 C = unit.P[uz(j)];
      out.P.push_back({Pi.x * C.x, Pi.x * C.y, Pi.z});
      out.w.push_back(wi * (unit.rational() ? unit.w[uz(j)] : 1.0));
    }
  }
  return out;
}

// ==== batched grid evaluation ==========================================================
//
// surface_grid() computes what surface_point() and surface_normal() compute
// (A3.5/A4.3 for the point, A3.6/A4.4 to first order for Su x Sv), for a
// whole grid at once, in the order that shares the most work:
//
// 1. The basis functions and their first derivatives (A2.3) once per us[a]
//    and once per vs[b], not once per point.
// 2. Per row a, the control net blended along u once: Q[j] = sum_k N_k(u_a)
//    Pw[k][j] and Qu[j] = sum_k N'_k(u_a) Pw[k][j] for every control column j
//    (a tensor-product surface is a curve of curves, ch. 1 §1.7). Every
//    point of the row is then a short sum along v over q + 1 of them.
// 3. The points of a row whose v lie in one knot span form a run; the run's
//    q + 1 blended points are loaded once and grid_run<Qd> evaluates the run
//    with the degree fixed at compile time (q = 1..5; grid_run<0> reads it
//    at run time). The v basis is stored component-wise (one array per l) so
//    that the loop reads contiguous arrays, and the loop body has no branch:
//    GCC vectorises it, and target_clones (as in bspline.cpp) compiles it for
//    AVX-512, AVX2 and baseline x86-64, which give bit-identical results (no
//    FMA contraction: -ffp-contract=off; no reassociation).
// 4. The degenerate-normal fallback (surface_normal's, with second
//    derivatives) is kept out of that loop: the loop normalises every normal
//    and notes where |Su x Sv| last failed the test; only for a run that has
//    such points does a second pass find them (grid_point, the same
//    arithmetic) and give them normal_unchecked().
// std::sqrt must not set errno for the loop to vectorise: this file is
// compiled with -fno-math-errno (CMakeLists.txt); that changes no result.
#if defined(__GNUC__) && defined(__x86_64__) && defined(__ELF__) && !defined(GLLAB_SPLINE_NO_CLONES)
#define GLLAB_SPLINE_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define GLLAB_SPLINE_CLONES
#endif

namespace {

/// The non-zero basis functions (and first derivatives) at each parameter,
/// stored component-wise: N[l * count + k] = N_{span[k]-degree+l}(params[k]),
/// l = 0..degree, so the values of one l for consecutive k are contiguous.
struct BasisTable {
  int degree = 0;
  std::size_t count = 0;
  std::vector<int> span;
  std::vector<double> N, dN;
  double value(int l, std::size_t k) const { return N[uz(l) * count + k]; }
  double deriv(int l, std::size_t k) const { return dN[uz(l) * count + k]; }
};

/// A2.3 DersBasisFuns (The NURBS Book, p. 72) to first order, without the
/// allocations of ders_basis_funs(i, u, p, 1, U) but with its operations in
/// its order, so the values are the same bits: N[r] = N_{i-p+r,p}(u) by A2.2
/// (with its divisions), and dN[r] = p (N_{i-p+r,p-1} / (U[i+r] - U[i+r-p])
/// - N_{i-p+r+1,p-1} / (U[i+r+1] - U[i+r+1-p])), from the degree p - 1
/// values of the step before last. Needs 1 <= p <= kMaxDegree.
void first_ders_basis_funs(int i, double u, int p, const double* U, double* N, double* dN) {
  double left[kMaxDegree + 1], right[kMaxDegree + 1];
  double Nlow[kMaxDegree + 1];   // degree p - 1
  double diff[kMaxDegree + 1];   // right[r+1] + left[p-r] of the last step (A2.3's ndu[p][r])
  N[0] = 1.0;
  Nlow[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double d = right[r + 1] + left[j - r];
      if (j == p) diff[r] = d;
      const double temp = N[r] / d;
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
    if (j == p - 1)
      for (int r = 0; r <= j; ++r) Nlow[r] = N[r];
  }
  for (int r = 0; r <= p; ++r) {
    double dk = 0.0;
    if (r >= 1) dk = (1.0 / diff[r - 1]) * Nlow[r - 1];
    if (r <= p - 1) dk += (-(1.0 / diff[r])) * Nlow[r];
    dN[r] = dk * p;
  }
}

BasisTable basis_table(int num_points, int degree, const std::vector<double>& knots, const std::vector<double>& params,
                       bool derivatives, const std::string& what, const char* name) {
  const ParamInterval dom = domain(degree, knots);
  BasisTable t;
  t.degree = degree;
  t.count = params.size();
  const std::size_t w = uz(degree) + 1;
  t.span.resize(params.size());
  t.N.resize(params.size() * w);
  if (derivatives) t.dN.resize(params.size() * w);
  std::array<double, kMaxDegree + 1> N{}, dN{};
  for (std::size_t k = 0; k < params.size(); ++k) {
    const double x = params[k];
    if (!(x >= dom.a && x <= dom.b))
      fail(what + ": " + at(name, k) + "=" + num(x) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) +
           "]");
    t.span[k] = find_span(num_points - 1, degree, x, knots);
    if (derivatives) {
      first_ders_basis_funs(t.span[k], x, degree, knots.data(), N.data(), dN.data());
      for (std::size_t l = 0; l < w; ++l) {
        t.N[l * t.count + k] = N[l];
        t.dN[l * t.count + k] = dN[l];
      }
    } else {
      basis_funs(t.span[k], x, degree, knots, N.data());
      for (std::size_t l = 0; l < w; ++l) t.N[l * t.count + k] = N[l];
    }
  }
  return t;
}

/// Consecutive parameters in one knot span: [begin, end).
struct Run {
  int span;
  std::size_t begin, end;
};

std::vector<Run> span_runs(const std::vector<int>& span) {
  std::vector<Run> runs;
  for (std::size_t k = 0; k < span.size();) {
    std::size_t e = k + 1;
    while (e < span.size() && span[e] == span[k]) ++e;
    runs.push_back({span[k], k, e});
    k = e;
  }
  return runs;
}

/// One run of a row: the q + 1 blended points the run needs, and where its v
/// basis starts. Q[l] = Q[first + l], Qu[l] likewise, first = span - q.
struct GridRun {
  int q = 0;
  const Vec4* Q = nullptr;
  const Vec4* Qu = nullptr;
  const double* M[kMaxDegree + 1] = {};   // M[l][b]: N_{first+l}(v_b) for the run's b
  const double* dM[kMaxDegree + 1] = {};  // dM[l][b]: its derivative
  std::size_t count = 0;
};

/// A point S and, with normals, the normal direction n = (w Su) x (w Sv),
/// |n|^2 and the degenerate test's bound.
struct GridPoint {
  Vec3 S, n;
  double nn = 0, limit = 0;
  bool ok() const { return nn > limit; }  // false for NaN too
};

/// The run's b-th point. Qd > 0: the degree along v, fixed at compile time;
/// Qd == 0: r.q. Both give the same bits (the same operations in the same
/// order), and so does every instruction set.
template <int Qd, bool kNormals>
[[gnu::always_inline]] inline GridPoint grid_point(const GridRun& r, std::size_t b) {
  const int q = Qd > 0 ? Qd : r.q;
  // Sw and its first derivatives in one pass over the q + 1 blended points.
  Vec4 Sw, Swu, Swv;
#pragma GCC unroll 8
  for (int l = 0; l <= q; ++l) {
    const double m = r.M[l][b];
    const Vec4 Ql = r.Q[l];
    Sw += m * Ql;
    if constexpr (kNormals) {
      Swv += r.dM[l][b] * Ql;
      Swu += m * r.Qu[l];
    }
  }
  GridPoint g;
  const double iw = 1 / Sw.w;
  g.S = {iw * Sw.x, iw * Sw.y, iw * Sw.z};
  if constexpr (kNormals) {
    // Derivatives of the projection (A4.4 to first order): Su = (Sw_u - w_u S) / w.
    // The common factor 1 / w does not change the direction, so it is left out.
    const Vec3 su = xyz(Swu) - Swu.w * g.S, sv = xyz(Swv) - Swv.w * g.S;
    g.n = cross(su, sv);
    g.nn = dot(g.n, g.n);
    const double su2 = dot(su, su), sv2 = dot(sv, sv);
    const double ss = su2 < sv2 ? sv2 : su2;  // std::max, without references
    g.limit = kDegenerateNormal * kDegenerateNormal * ss * ss;
  }
  return g;
}

/// Evaluates the run's points b = first .. first + count - 1: out[b] = S and,
/// if kNormals, nrm[b] = n / |n|. Returns 1 + the last b whose normal failed
/// the degenerate test (0: none did); the nrm[b] of those is meaningless
/// (0 * inf, NaN, ...) and the caller replaces it. The loop has no branch (a
/// normal computed only "if ok" would be one, and a branch keeps GCC from
/// vectorising the loop), and it does not count the failures: GCC 12 cannot
/// vectorise a count of double comparisons for SSE2, but it can this "last
/// index where" reduction.
template <int Qd, bool kNormals>
[[gnu::always_inline]] inline std::size_t grid_points(const GridRun& r, std::size_t first, std::size_t count,
                                                      Vec3* __restrict out, Vec3* __restrict nrm) {
  std::size_t degenerate_end = 0;
  for (std::size_t b = first; b < first + count; ++b) {
    const GridPoint g = grid_point<Qd, kNormals>(r, b);
    out[b] = {g.S.x, g.S.y, g.S.z};
    if constexpr (kNormals) {
      const double il = 1 / std::sqrt(g.nn);
      nrm[b] = {il * g.n.x, il * g.n.y, il * g.n.z};
      if (!g.ok()) degenerate_end = b + 1;
    }
  }
  return degenerate_end;
}

/// The whole run. Runs are short (the bench grid has ~18 points per v span),
/// and a plain vectorised loop leaves the last count % 8 (AVX-512) or
/// count % 4 (AVX2) points to a loop that takes one point at a time, which
/// cost up to a sixth of the time. So the vectorised loop takes a multiple of
/// kBlock = 4 points -- which it finishes without that scalar loop: AVX-512
/// takes 8 at a time and then 4 in its vectorised epilogue -- and the rest is
/// one more block of 4 moved back to end at the run's end: a loop of 4
/// iterations known at compile time is one 256-bit step (two with SSE2). The
/// points this block shares with the loop are computed again, to the same
/// bits. (Blocks of 8 are faster still with AVX-512 but slower with SSE2 and
/// AVX2; bench/README.md.)
template <int Qd, bool kNormals>
[[gnu::always_inline]] inline std::size_t grid_run(const GridRun& r, Vec3* out, Vec3* nrm) {
  constexpr std::size_t kBlock = 4;
  if (r.count < kBlock) return grid_points<Qd, kNormals>(r, 0, r.count, out, nrm);
  const std::size_t bulk = r.count - r.count % kBlock;
  std::size_t degenerate_end = grid_points<Qd, kNormals>(r, 0, bulk, out, nrm);
  if (bulk < r.count)
    degenerate_end = std::max(degenerate_end, grid_points<Qd, kNormals>(r, r.count - kBlock, kBlock, out, nrm));
  return degenerate_end;
}

template <bool kNormals>
[[gnu::always_inline]] inline std::size_t grid_run_any(const GridRun& r, Vec3* out, Vec3* nrm) {
  switch (r.q) {
    case 1: return grid_run<1, kNormals>(r, out, nrm);
    case 2: return grid_run<2, kNormals>(r, out, nrm);
    case 3: return grid_run<3, kNormals>(r, out, nrm);
    case 4: return grid_run<4, kNormals>(r, out, nrm);
    case 5: return grid_run<5, kNormals>(r, out, nrm);
    default: return grid_run<0, kNormals>(r, out, nrm);
  }
}

// Compiled once per instruction set (see bspline.cpp).
GLLAB_SPLINE_CLONES std::size_t grid_run_points(const GridRun& r, Vec3* out) {
  return grid_run_any<false>(r, out, nullptr);
}
GLLAB_SPLINE_CLONES std::size_t grid_run_normals(const GridRun& r, Vec3* out, Vec3* nrm) {
  return grid_run_any<true>(r, out, nrm);
}

}  // namespace

void surface_grid(const BsplineSurface& surface, const std::vector<double>& us, const std::vector<double>& vs,
                  std::vector<Vec3>& points, std::vector<Vec3>* normals) {
  const std::string what = "surface_grid";
  validate(surface);
  const bool want_normals = normals != nullptr;
  const BasisTable tu = basis_table(surface.nu, surface.p, surface.U, us, want_normals, what, "us");
  const BasisTable tv = basis_table(surface.nv, surface.q, surface.V, vs, want_normals, what, "vs");
  const std::vector<Run> vruns = span_runs(tv.span);
  const std::vector<Vec4> Pw = to_homogeneous(surface);
  const std::size_t nv = uz(surface.nv), pu = uz(surface.p) + 1;
  const int q = surface.q;
  points.resize(us.size() * vs.size());
  if (want_normals) normals->resize(points.size());

  std::vector<Vec4> Q(nv), Qu(nv);  // row a blended along u: S(u_a, .) and dS/du(u_a, .) per control column
  for (std::size_t a = 0; a < us.size(); ++a) {
    const Vec4* rows = &Pw[uz(tu.span[a] - surface.p) * nv];
    // Q[j] = sum_k N_k Pw[k][j] (k ascending, as A3.5 sums), column j innermost.
    std::fill(Q.begin(), Q.end(), Vec4{});
    if (want_normals) std::fill(Qu.begin(), Qu.end(), Vec4{});
    for (std::size_t k = 0; k < pu; ++k) {
      const double n = tu.value(static_cast<int>(k), a);
      for (std::size_t j = 0; j < nv; ++j) Q[j] += n * rows[k * nv + j];
      if (want_normals) {
        const double dn = tu.deriv(static_cast<int>(k), a);
        for (std::size_t j = 0; j < nv; ++j) Qu[j] += dn * rows[k * nv + j];
      }
    }
    Vec3* out = &points[a * vs.size()];
    Vec3* out_n = want_normals ? &(*normals)[a * vs.size()] : nullptr;
    for (const Run& run : vruns) {
      GridRun r;
      r.q = q;
      r.Q = &Q[uz(run.span - q)];
      r.Qu = &Qu[uz(run.span - q)];
      for (int l = 0; l <= q; ++l) {
        r.M[l] = &tv.N[uz(l) * tv.count + run.begin];
        if (want_normals) r.dM[l] = &tv.dN[uz(l) * tv.count + run.begin];
      }
      r.count = run.end - run.begin;
      if (!want_normals) {
        grid_run_points(r, out + run.begin);
        continue;
      }
      const std::size_t degenerate_end = grid_run_normals(r, out + run.begin, out_n + run.begin);
      // Some normals of the run failed the test: find them (the same
      // arithmetic, so the same verdicts) and give them surface_normal's fallback.
      for (std::size_t b = 0; b < degenerate_end; ++b)
        if (!grid_point<0, true>(r, b).ok()) out_n[run.begin + b] = normal_unchecked(surface, us[a], vs[run.begin + b]);
    }
  }
}

SurfaceEvaluator surface_evaluator(const BsplineSurface& surface) {
  validate(surface);
  auto shared = std::make_shared<const BsplineSurface>(surface);
  return [shared](double u, double v) {
    const BsplineSurface& s = *shared;
    check_uv(s, u, v, "surface_evaluator");
    // A3.6 to first order on Pw (the grid evaluator's sums for one point),
    // then A4.4 to first order: Su = (Sw_u - w_u S) / w.
    const int uspan = find_span(s.nu - 1, s.p, u, s.U), vspan = find_span(s.nv - 1, s.q, v, s.V);
    const std::vector<std::vector<double>> Nu = ders_basis_funs(uspan, u, s.p, 1, s.U);
    const std::vector<std::vector<double>> Nv = ders_basis_funs(vspan, v, s.q, 1, s.V);
    Vec4 Sw, Swu, Swv;
    for (int l = 0; l <= s.q; ++l) {
      Vec4 q, qu;
      for (int k = 0; k <= s.p; ++k) {
        const Vec4 P = pw(s, uspan - s.p + k, vspan - s.q + l);
        q += Nu[0][uz(k)] * P;
        qu += Nu[1][uz(k)] * P;
      }
      Sw += Nv[0][uz(l)] * q;
      Swu += Nv[0][uz(l)] * qu;
      Swv += Nv[1][uz(l)] * q;
    }
    SurfaceSample out;
    out.point = (1 / Sw.w) * xyz(Sw);
    out.du = (1 / Sw.w) * (xyz(Swu) - Swu.w * out.point);
    out.dv = (1 / Sw.w) * (xyz(Swv) - Swv.w * out.point);
    const Vec3 n = cross(out.du, out.dv);
    out.normal = degenerate(n, std::max(norm(out.du), norm(out.dv))) ? normal_unchecked(s, u, v) : normalized(n);
    return out;
  };
}

SurfaceEvaluator surface_evaluator(const BezierSurface& surface) { return surface_evaluator(to_bspline(surface)); }

UvDomain uv_domain(const BsplineSurface& surface) {
  const ParamInterval du = domain_u(surface), dv = domain_v(surface);
  return {du.a, du.b, dv.a, dv.b};
}

UvDomain uv_domain(const BezierSurface& surface) {
  validate(surface);
  return {surface.a, surface.b, surface.c, surface.d};
}

}  // namespace gllab::spline
