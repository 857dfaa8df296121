// common/spline/surface.cpp — tensor-product surfaces (ch. 1 §1.7). Lagrange,
// Hermite and Hermite–Lagrange patches, then B-spline and NURBS surfaces
// (A3.5, A3.6, A4.3, A4.4, A8.1). Bézier surfaces are in bezier_surface.cpp,
// the batched grid evaluator in fast/surface_batch.cpp. See surface.h for what
// each function returns and where its formula comes from.
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
#include "spline/surface_support.h"

namespace gllab::spline {

using namespace internal;  // surface_support.h: the checks and helpers both surface files use

namespace {

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
    fail(ErrorCode::kSizeMismatch,
         what + ": c.size()=" + std::to_string(surface.c.size()) + " != u_nodes.size()*v_nodes.size() = " +
             std::to_string(surface.u_nodes.size()) + "*" + std::to_string(surface.v_nodes.size()),
         {{"c", surface.c.size()}, {"u_nodes", surface.u_nodes.size()}, {"v_nodes", surface.v_nodes.size()}});
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
      fail(ErrorCode::kSizeMismatch,
           what + ": " + name + ".size()=" + std::to_string(list->size()) +
               " != v_nodes.size()=" + std::to_string(count),
           {{name, list->size()}, {"v_nodes", count}});
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
    fail(ErrorCode::kTooFewPoints,
         what + ": (nu, nv)=" + ij_text(surface.nu, surface.nv) + " (need at least one control point each way)",
         {{"nu", surface.nu}, {"nv", surface.nv}});
  if (static_cast<double>(surface.nu) * surface.nv > static_cast<double>(kMaxControlPoints))
    fail(ErrorCode::kOutOfRange,
         what + ": (nu, nv)=" + ij_text(surface.nu, surface.nv) + ", more than " +
             std::to_string(kMaxControlPoints) + " control points (kMaxControlPoints)",
         {{"nu", surface.nu}, {"nv", surface.nv}});
  validate_knots(surface.p, surface.nu, surface.U, "U knot vector");
  validate_knots(surface.q, surface.nv, surface.V, "V knot vector", "V");
  const std::size_t count = uz(surface.nu) * uz(surface.nv);
  if (surface.P.size() != count)
    fail(ErrorCode::kSizeMismatch,
         what + ": P.size()=" + std::to_string(surface.P.size()) + " != nu*nv = " + std::to_string(surface.nu) + "*" +
             std::to_string(surface.nv) + " = " + std::to_string(count),
         {{"P", surface.P.size()}, {"nu", surface.nu}, {"nv", surface.nv}});
  for (int i = 0; i < surface.nu; ++i)
    for (int j = 0; j < surface.nv; ++j)
      if (!finite(surface.point(i, j))) require_finite(surface.point(i, j), what, "P" + ij_text(i, j));
  if (surface.w.empty()) return;
  if (surface.w.size() != count)
    fail(ErrorCode::kWeightCount,
         what + ": w.size()=" + std::to_string(surface.w.size()) + " != nu*nv = " + std::to_string(count) +
             " (one weight per control point, or none)",
         {{"w", surface.w.size()}, {"nu", surface.nu}, {"nv", surface.nv}});
  for (int i = 0; i < surface.nu; ++i)
    for (int j = 0; j < surface.nv; ++j) {
      const double wij = surface.weight(i, j);
      if (!std::isfinite(wij)) require_finite(wij, what, "weight w" + ij_text(i, j));
      if (!(wij > 0))
        fail(ErrorCode::kWeightNotPositive, what + ": weight w" + ij_text(i, j) + "=" + num(wij) + " must be > 0",
             {{"i", i}, {"j", j}, {"w", wij}});
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

UvDomain uv_domain(const BsplineSurface& surface) {
  const ParamInterval du = domain_u(surface), dv = domain_v(surface);
  return {du.a, du.b, dv.a, dv.b};
}

}  // namespace gllab::spline
