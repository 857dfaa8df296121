// bench/prototype_eval.cpp — PROTOTYPE batched evaluators, NOT the own core
// (see prototype_eval.h). Notation of common/spline/README.md: p degree, U
// knots, Pw homogeneous points, span i with U[i] <= u < U[i+1].
#include "prototype_eval.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace gllab::bench::prototype {

using spline::Vec3;
using spline::Vec4;

namespace {

constexpr int kP = 3;  // the only degree these prototypes take

// One kernel per instruction set, chosen at load time (no -march=native).
#define GLLAB_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

// A run of sorted parameters that fall into one knot span.
struct Run {
  int span;
  std::size_t begin, end;
};

// A2.1 FindSpan (The NURBS Book, p. 68) done once per span instead of once per
// point: the parameters are sorted, so each span owns a contiguous run.
std::vector<Run> span_runs(int p, const std::vector<double>& U, int n, const std::vector<double>& u) {
  if (u.empty()) return {};
  if (!std::is_sorted(u.begin(), u.end()) || u.front() < U[std::size_t(p)] || u.back() > U[std::size_t(n) + 1])
    throw std::invalid_argument("prototype: parameters must be sorted and inside the domain");
  int last = n;  // the last non-empty span takes u == U[n+1]
  while (U[std::size_t(last)] == U[std::size_t(last) + 1]) --last;
  std::vector<Run> runs;
  std::size_t k = 0;
  for (int i = p; i <= last && k < u.size(); ++i) {
    if (U[std::size_t(i)] == U[std::size_t(i) + 1]) continue;
    const std::size_t end = i == last ? u.size()
                                      : std::size_t(std::lower_bound(u.begin() + std::ptrdiff_t(k), u.end(),
                                                                     U[std::size_t(i) + 1]) -
                                                    u.begin());
    if (end > k) runs.push_back({i, k, end});
    k = end;
  }
  return runs;
}

void require_cubic_rational(int p, bool rational, const char* what) {
  if (p != kP || !rational)
    throw std::invalid_argument(std::string("prototype ") + what + ": only cubic rational, got p=" +
                                std::to_string(p) + (rational ? "" : " (polynomial)"));
}

// The knots around span i and the reciprocals of A2.2's six denominators
// U[i+r+1] - U[i+1-j+r] (j = 1..3, r < j): they do not depend on u.
struct SpanBasis {
  double u0, u1, u2, u3, um1, um2;  // U[i], U[i+1], U[i+2], U[i+3], U[i-1], U[i-2]
  double inv10, inv20, inv21, inv30, inv31, inv32;
};

SpanBasis span_basis(const std::vector<double>& U, int i) {
  const auto at = [&](int k) { return U[std::size_t(k)]; };
  SpanBasis s{at(i), at(i + 1), at(i + 2), at(i + 3), at(i - 1), at(i - 2), 0, 0, 0, 0, 0, 0};
  s.inv10 = 1 / (s.u1 - s.u0);
  s.inv20 = 1 / (s.u1 - s.um1);
  s.inv21 = 1 / (s.u2 - s.u0);
  s.inv30 = 1 / (s.u1 - s.um2);
  s.inv31 = 1 / (s.u2 - s.um1);
  s.inv32 = 1 / (s.u3 - s.u0);
  return s;
}

// A2.2 BasisFuns (p. 70) unrolled for p = 3 with the reciprocals above, and
// the first derivatives the way A2.3 (p. 72) gets them from the degree-2 step.
struct Basis {
  double N[4], D[4];
};

inline Basis cubic_basis(const SpanBasis& s, double x) {
  const double l1 = x - s.u0, l2 = x - s.um1, l3 = x - s.um2;  // left[j] = u - U[i+1-j]
  const double r1 = s.u1 - x, r2 = s.u2 - x, r3 = s.u3 - x;    // right[j] = U[i+j] - u
  const double a0 = r1 * s.inv10, a1 = l1 * s.inv10;            // degree 1
  const double t0 = a0 * s.inv20, t1 = a1 * s.inv21;
  const double b0 = r1 * t0, b1 = l2 * t0 + r2 * t1, b2 = l1 * t1;  // degree 2
  const double c0 = b0 * s.inv30, c1 = b1 * s.inv31, c2 = b2 * s.inv32;
  Basis out;
  out.N[0] = r1 * c0;
  out.N[1] = l3 * c0 + r2 * c1;
  out.N[2] = l2 * c1 + r3 * c2;
  out.N[3] = l1 * c2;
  out.D[0] = -3 * c0;
  out.D[1] = 3 * (c0 - c1);
  out.D[2] = 3 * (c1 - c2);
  out.D[3] = 3 * c2;
  return out;
}

// ---- curve, variant R: A2.2 with per-span reciprocals ------------------------

struct CurveSpanR {
  SpanBasis s;
  Vec4 P[4];  // Pw[i-3..i]
};

template <bool kDerivs>
inline void kernel_r_body(const CurveSpanR& c, const double* u, Vec3* out, Vec3* der, std::size_t count) {
  const SpanBasis s = c.s;
  const Vec4 P0 = c.P[0], P1 = c.P[1], P2 = c.P[2], P3 = c.P[3];
  for (std::size_t k = 0; k < count; ++k) {
    const Basis b = cubic_basis(s, u[k]);
    const double x = b.N[0] * P0.x + b.N[1] * P1.x + b.N[2] * P2.x + b.N[3] * P3.x;
    const double y = b.N[0] * P0.y + b.N[1] * P1.y + b.N[2] * P2.y + b.N[3] * P3.y;
    const double z = b.N[0] * P0.z + b.N[1] * P1.z + b.N[2] * P2.z + b.N[3] * P3.z;
    const double w = b.N[0] * P0.w + b.N[1] * P1.w + b.N[2] * P2.w + b.N[3] * P3.w;
    const double iw = 1 / w;
    const double px = x * iw, py = y * iw, pz = z * iw;
    out[k] = {px, py, pz};
    if constexpr (kDerivs) {
      // A4.2 for k = 1: C' = (Aw' - w' C) / w.
      const double dx = b.D[0] * P0.x + b.D[1] * P1.x + b.D[2] * P2.x + b.D[3] * P3.x;
      const double dy = b.D[0] * P0.y + b.D[1] * P1.y + b.D[2] * P2.y + b.D[3] * P3.y;
      const double dz = b.D[0] * P0.z + b.D[1] * P1.z + b.D[2] * P2.z + b.D[3] * P3.z;
      const double dw = b.D[0] * P0.w + b.D[1] * P1.w + b.D[2] * P2.w + b.D[3] * P3.w;
      der[k] = {(dx - dw * px) * iw, (dy - dw * py) * iw, (dz - dw * pz) * iw};
    }
  }
}

GLLAB_CLONES void kernel_r_points(const CurveSpanR& c, const double* u, Vec3* out, std::size_t count) {
  kernel_r_body<false>(c, u, out, nullptr, count);
}
GLLAB_CLONES void kernel_r_derivs(const CurveSpanR& c, const double* u, Vec3* out, Vec3* der, std::size_t count) {
  kernel_r_body<true>(c, u, out, der, count);
}

void curve_r(const spline::BsplineCurve& curve, const std::vector<double>& u, std::vector<Vec3>& out,
             std::vector<Vec3>* derivs) {
  require_cubic_rational(curve.p, curve.rational(), "curve_points_reciprocal");
  out.resize(u.size());
  if (derivs) derivs->resize(u.size());
  for (const Run& run : span_runs(curve.p, curve.U, curve.n(), u)) {
    CurveSpanR c{span_basis(curve.U, run.span), {}};
    for (int r = 0; r <= kP; ++r) {
      const std::size_t idx = std::size_t(run.span - kP + r);
      c.P[r] = spline::homogeneous(curve.P[idx], curve.w[idx]);
    }
    const std::size_t count = run.end - run.begin;
    if (derivs)
      kernel_r_derivs(c, u.data() + run.begin, out.data() + run.begin, derivs->data() + run.begin, count);
    else
      kernel_r_points(c, u.data() + run.begin, out.data() + run.begin, count);
  }
}

// ---- curve, variant T: per-span Taylor form of Cw ---------------------------

struct CurveSpanT {
  double u0;
  Vec4 A[4];  // Cw(u) = A0 + A1 t + A2 t^2 + A3 t^3, t = u - U[i]
};

// The basis polynomials of span i in t = u - U[i]: A2.2 run on polynomials
// (left[j] = t + (U[i] - U[i+1-j]), right[j] = (U[i+j] - U[i]) - t).
CurveSpanT span_taylor(const std::vector<double>& U, int i, const Vec4* Pw) {
  using Poly = double[4];
  Poly N[4] = {{1, 0, 0, 0}};
  const double ui = U[std::size_t(i)];
  for (int j = 1; j <= kP; ++j) {
    Poly saved = {0, 0, 0, 0};
    for (int r = 0; r < j; ++r) {
      const double right0 = U[std::size_t(i + r + 1)] - ui;  // right[r+1] = right0 - t
      const double left0 = ui - U[std::size_t(i + 1 - j + r)];  // left[j-r] = left0 + t
      const double inv = 1 / (right0 + left0);
      Poly temp, next;
      for (int k = 0; k < 4; ++k) temp[k] = N[r][k] * inv;
      for (int k = 0; k < 4; ++k) next[k] = saved[k] + right0 * temp[k] - (k > 0 ? temp[k - 1] : 0);
      for (int k = 0; k < 4; ++k) saved[k] = left0 * temp[k] + (k > 0 ? temp[k - 1] : 0);
      std::copy(next, next + 4, N[r]);
    }
    std::copy(saved, saved + 4, N[j]);
  }
  CurveSpanT c{ui, {}};
  for (int k = 0; k < 4; ++k)
    for (int r = 0; r <= kP; ++r) c.A[k] += N[r][k] * Pw[r];
  return c;
}

GLLAB_CLONES void kernel_t_points(const CurveSpanT& c, const double* u, Vec3* out, std::size_t count) {
  const Vec4 A0 = c.A[0], A1 = c.A[1], A2 = c.A[2], A3 = c.A[3];
  for (std::size_t k = 0; k < count; ++k) {
    const double t = u[k] - c.u0;
    const double x = ((A3.x * t + A2.x) * t + A1.x) * t + A0.x;
    const double y = ((A3.y * t + A2.y) * t + A1.y) * t + A0.y;
    const double z = ((A3.z * t + A2.z) * t + A1.z) * t + A0.z;
    const double w = ((A3.w * t + A2.w) * t + A1.w) * t + A0.w;
    const double iw = 1 / w;
    out[k] = {x * iw, y * iw, z * iw};
  }
}

GLLAB_CLONES void kernel_t_derivs(const CurveSpanT& c, const double* u, Vec3* out, Vec3* der, std::size_t count) {
  const Vec4 A0 = c.A[0], A1 = c.A[1], A2 = c.A[2], A3 = c.A[3];
  const Vec4 B2 = 3 * A3, B1 = 2 * A2;  // Cw' = A1 + B1 t + B2 t^2
  for (std::size_t k = 0; k < count; ++k) {
    const double t = u[k] - c.u0;
    const double x = ((A3.x * t + A2.x) * t + A1.x) * t + A0.x;
    const double y = ((A3.y * t + A2.y) * t + A1.y) * t + A0.y;
    const double z = ((A3.z * t + A2.z) * t + A1.z) * t + A0.z;
    const double w = ((A3.w * t + A2.w) * t + A1.w) * t + A0.w;
    const double dx = (B2.x * t + B1.x) * t + A1.x;
    const double dy = (B2.y * t + B1.y) * t + A1.y;
    const double dz = (B2.z * t + B1.z) * t + A1.z;
    const double dw = (B2.w * t + B1.w) * t + A1.w;
    const double iw = 1 / w;
    const double px = x * iw, py = y * iw, pz = z * iw;
    out[k] = {px, py, pz};
    der[k] = {(dx - dw * px) * iw, (dy - dw * py) * iw, (dz - dw * pz) * iw};
  }
}

void curve_t(const spline::BsplineCurve& curve, const std::vector<double>& u, std::vector<Vec3>& out,
             std::vector<Vec3>* derivs) {
  require_cubic_rational(curve.p, curve.rational(), "curve_points_taylor");
  out.resize(u.size());
  if (derivs) derivs->resize(u.size());
  for (const Run& run : span_runs(curve.p, curve.U, curve.n(), u)) {
    Vec4 Pw[4];
    for (int r = 0; r <= kP; ++r) {
      const std::size_t idx = std::size_t(run.span - kP + r);
      Pw[r] = spline::homogeneous(curve.P[idx], curve.w[idx]);
    }
    const CurveSpanT c = span_taylor(curve.U, run.span, Pw);
    const std::size_t count = run.end - run.begin;
    if (derivs)
      kernel_t_derivs(c, u.data() + run.begin, out.data() + run.begin, derivs->data() + run.begin, count);
    else
      kernel_t_points(c, u.data() + run.begin, out.data() + run.begin, count);
  }
}

// ---- surface grid ---------------------------------------------------------------

// Basis values and derivatives along one direction, one entry per parameter,
// stored component-wise so the per-point loop reads them contiguously.
struct DirectionBasis {
  std::vector<Run> runs;
  std::vector<double> N[4], D[4];
};

DirectionBasis direction_basis(int p, const std::vector<double>& U, int count, const std::vector<double>& params) {
  DirectionBasis d;
  d.runs = span_runs(p, U, count - 1, params);
  for (int r = 0; r <= kP; ++r) {
    d.N[r].resize(params.size());
    d.D[r].resize(params.size());
  }
  for (const Run& run : d.runs) {
    const SpanBasis s = span_basis(U, run.span);
    for (std::size_t k = run.begin; k < run.end; ++k) {
      const Basis b = cubic_basis(s, params[k]);
      for (int r = 0; r <= kP; ++r) {
        d.N[r][k] = b.N[r];
        d.D[r][k] = b.D[r];
      }
    }
  }
  return d;
}

// One run of v parameters in one v span, for one u: Q are the four columns of
// the net contracted with the u basis, Qu with its derivative.
struct SurfaceRun {
  Vec4 Q[4], Qu[4];
  const double *M0, *M1, *M2, *M3, *E0, *E1, *E2, *E3;  // v basis and derivatives
};

GLLAB_CLONES void kernel_surface(const SurfaceRun& s, Vec3* __restrict out, Vec3* __restrict nrm, std::size_t count) {
  const Vec4 Q0 = s.Q[0], Q1 = s.Q[1], Q2 = s.Q[2], Q3 = s.Q[3];
  const Vec4 U0 = s.Qu[0], U1 = s.Qu[1], U2 = s.Qu[2], U3 = s.Qu[3];
  // Ten streams are more than GCC checks for overlap at run time (its
  // vect-max-version-for-alias-checks is 10): promise there is none.
  const double *__restrict M0 = s.M0, *__restrict M1 = s.M1, *__restrict M2 = s.M2, *__restrict M3 = s.M3;
  const double *__restrict E0 = s.E0, *__restrict E1 = s.E1, *__restrict E2 = s.E2, *__restrict E3 = s.E3;
  for (std::size_t k = 0; k < count; ++k) {
    const double m0 = M0[k], m1 = M1[k], m2 = M2[k], m3 = M3[k];
    const double e0 = E0[k], e1 = E1[k], e2 = E2[k], e3 = E3[k];
    // S^w, S^w_u, S^w_v (A4.4's homogeneous derivatives, first order).
    const double x = m0 * Q0.x + m1 * Q1.x + m2 * Q2.x + m3 * Q3.x;
    const double y = m0 * Q0.y + m1 * Q1.y + m2 * Q2.y + m3 * Q3.y;
    const double z = m0 * Q0.z + m1 * Q1.z + m2 * Q2.z + m3 * Q3.z;
    const double w = m0 * Q0.w + m1 * Q1.w + m2 * Q2.w + m3 * Q3.w;
    const double ux = m0 * U0.x + m1 * U1.x + m2 * U2.x + m3 * U3.x;
    const double uy = m0 * U0.y + m1 * U1.y + m2 * U2.y + m3 * U3.y;
    const double uz = m0 * U0.z + m1 * U1.z + m2 * U2.z + m3 * U3.z;
    const double uw = m0 * U0.w + m1 * U1.w + m2 * U2.w + m3 * U3.w;
    const double vx = e0 * Q0.x + e1 * Q1.x + e2 * Q2.x + e3 * Q3.x;
    const double vy = e0 * Q0.y + e1 * Q1.y + e2 * Q2.y + e3 * Q3.y;
    const double vz = e0 * Q0.z + e1 * Q1.z + e2 * Q2.z + e3 * Q3.z;
    const double vw = e0 * Q0.w + e1 * Q1.w + e2 * Q2.w + e3 * Q3.w;
    const double iw = 1 / w;
    const double px = x * iw, py = y * iw, pz = z * iw;
    // w S_u = S^w_u - w_u S (and likewise for v): the factor w > 0 does not
    // change the direction of the cross product, so it is never divided out.
    const double ax = ux - uw * px, ay = uy - uw * py, az = uz - uw * pz;
    const double bx = vx - vw * px, by = vy - vw * py, bz = vz - vw * pz;
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    const double il = 1 / std::sqrt(nx * nx + ny * ny + nz * nz);
    out[k] = {px, py, pz};
    nrm[k] = {nx * il, ny * il, nz * il};
  }
}

}  // namespace

void curve_points_reciprocal(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                             std::vector<Vec3>& out) {
  curve_r(curve, sorted_u, out, nullptr);
}
void curve_points_reciprocal(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                             std::vector<Vec3>& out, std::vector<Vec3>& derivs) {
  curve_r(curve, sorted_u, out, &derivs);
}
void curve_points_taylor(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                         std::vector<Vec3>& out) {
  curve_t(curve, sorted_u, out, nullptr);
}
void curve_points_taylor(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                         std::vector<Vec3>& out, std::vector<Vec3>& derivs) {
  curve_t(curve, sorted_u, out, &derivs);
}

void surface_grid(const spline::BsplineSurface& surface, const std::vector<double>& us,
                  const std::vector<double>& vs, std::vector<Vec3>& points, std::vector<Vec3>& normals) {
  require_cubic_rational(surface.p, surface.rational(), "surface_grid");
  require_cubic_rational(surface.q, surface.rational(), "surface_grid");
  const DirectionBasis bu = direction_basis(surface.p, surface.U, surface.nu, us);
  const DirectionBasis bv = direction_basis(surface.q, surface.V, surface.nv, vs);
  points.resize(us.size() * vs.size());
  normals.resize(points.size());

  const std::size_t nv = std::size_t(surface.nv);
  std::vector<Vec4> Pw(surface.P.size());
  for (std::size_t k = 0; k < Pw.size(); ++k) Pw[k] = spline::homogeneous(surface.P[k], surface.w[k]);
  std::vector<Vec4> Q(nv), Qu(nv);  // the net contracted along u, for one u

  for (const Run& urun : bu.runs) {
    for (std::size_t a = urun.begin; a < urun.end; ++a) {
      std::fill(Q.begin(), Q.end(), Vec4{});
      std::fill(Qu.begin(), Qu.end(), Vec4{});
      for (int r = 0; r <= kP; ++r) {
        const Vec4* row = &Pw[std::size_t(urun.span - kP + r) * nv];
        const double n = bu.N[r][a], d = bu.D[r][a];
        for (std::size_t j = 0; j < nv; ++j) {
          Q[j] += n * row[j];
          Qu[j] += d * row[j];
        }
      }
      for (const Run& vrun : bv.runs) {
        SurfaceRun s{};
        for (int l = 0; l <= kP; ++l) {
          s.Q[l] = Q[std::size_t(vrun.span - kP + l)];
          s.Qu[l] = Qu[std::size_t(vrun.span - kP + l)];
        }
        s.M0 = bv.N[0].data() + vrun.begin;
        s.M1 = bv.N[1].data() + vrun.begin;
        s.M2 = bv.N[2].data() + vrun.begin;
        s.M3 = bv.N[3].data() + vrun.begin;
        s.E0 = bv.D[0].data() + vrun.begin;
        s.E1 = bv.D[1].data() + vrun.begin;
        s.E2 = bv.D[2].data() + vrun.begin;
        s.E3 = bv.D[3].data() + vrun.begin;
        const std::size_t at = a * vs.size() + vrun.begin;
        kernel_surface(s, points.data() + at, normals.data() + at, vrun.end - vrun.begin);
      }
    }
  }
}

}  // namespace gllab::bench::prototype
