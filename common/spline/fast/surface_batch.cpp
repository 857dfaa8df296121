// common/spline/fast/surface_batch.cpp — surface_grid(): the points and unit
// normals of a B-spline or NURBS surface on a whole grid (see
// fast/surface_batch.h).
#include "spline/fast/surface_batch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include "spline/basis.h"
#include "spline/errors.h"
#include "spline/fast/kernels.h"
#include "spline/surface.h"

namespace gllab::spline {

using fast::span_runs;
using fast::SpanRun;

namespace {
std::size_t uz(int i) { return static_cast<std::size_t>(i); }
}  // namespace

// ==== batched grid evaluation ==========================================================
//
// surface_grid() computes what surface_point() and surface_normal() compute
// (A3.5/A4.3 for the point, A3.6/A4.4 to first order for Su x Sv), for a
// whole grid at once, in the order that shares the most work:
//
// 1. The basis functions and their first derivatives (A2.3) once per us[a]
//    and once per vs[b], not once per point; the spans by the span walk.
// 2. Per row a, the control net blended along u once: Q[j] = sum_k N_k(u_a)
//    Pw[k][j] and Qu[j] = sum_k N'_k(u_a) Pw[k][j] for every control column j
//    (a tensor-product surface is a curve of curves, ch. 1 §1.7). Every
//    point of the row is then a short sum along v over q + 1 of them.
// 3. The points of a row whose v lie in one knot span form a run; the run's
//    q + 1 blended points are loaded once and grid_run<Qd> evaluates the run
//    with the degree fixed at compile time (q = 1..5; grid_run<0> reads it
//    at run time). The v basis is stored component-wise (one array per l) so
//    that the loop reads contiguous arrays, and the loop body has no branch:
//    GCC vectorises it, and target_clones (fast/kernels.h) compiles it for
//    AVX-512, AVX2 and baseline x86-64, which give bit-identical results (no
//    FMA contraction: -ffp-contract=off; no reassociation).
// 4. The degenerate-normal fallback (surface_normal's, with second
//    derivatives) is kept out of that loop: the loop normalises every normal
//    and notes where |Su x Sv| last failed the test; only for a run that has
//    such points does a second pass find them (grid_point, the same
//    arithmetic) and give them surface_normal()'s value.
// std::sqrt must not set errno for the loop to vectorise: this file is

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

/// The basis functions (and first derivatives) of every parameter, by the
/// textbook's A2.2 (basis_funs) and A2.3 (ders_basis_funs to first order, its
/// allocation-free form: allocating cost 15 % of surface_grid), the
/// parameters walked span by span (fast/kernels.h).
BasisTable basis_table(int num_points, int degree, const std::vector<double>& knots, const std::vector<double>& params,
                       bool derivatives, const std::string& what, const char* name, std::vector<SpanRun>& runs) {
  const ParamInterval dom = domain(degree, knots);
  for (std::size_t k = 0; k < params.size(); ++k) {
    const double x = params[k];
    if (!(x >= dom.a && x <= dom.b))
      fail(std::isnan(x) ? ErrorCode::kNotFinite : ErrorCode::kParameterOutsideDomain,
           what + ": " + at(name, k) + "=" + num(x) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) + "]",
           {{at(name, k), x}, {"a", dom.a}, {"b", dom.b}});
  }
  const bool sorted = std::is_sorted(params.begin(), params.end());
  runs = span_runs(num_points - 1, degree, knots, params.data(), params.size(), sorted);
  BasisTable t;
  t.degree = degree;
  t.count = params.size();
  const std::size_t w = uz(degree) + 1;
  t.span.resize(params.size());
  t.N.resize(params.size() * w);
  if (derivatives) t.dN.resize(params.size() * w);
  std::array<double, kMaxDegree + 1> N{};
  std::array<double, 2 * (kMaxDegree + 1)> D{};
  for (const SpanRun& run : runs) {
    for (std::size_t k = run.begin; k < run.end; ++k) {
      t.span[k] = run.span;
      if (derivatives) {
        ders_basis_funs(run.span, params[k], degree, 1, knots, D.data());  // row 0: N, row 1: N'
        for (std::size_t l = 0; l < w; ++l) {
          t.N[l * t.count + k] = D[l];
          t.dN[l * t.count + k] = D[w + l];
        }
      } else {
        basis_funs(run.span, params[k], degree, knots, N.data());
        for (std::size_t l = 0; l < w; ++l) t.N[l * t.count + k] = N[l];
      }
    }
  }
  return t;
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
  std::vector<SpanRun> uruns, vruns;
  const BasisTable tu = basis_table(surface.nu, surface.p, surface.U, us, want_normals, what, "us", uruns);
  const BasisTable tv = basis_table(surface.nv, surface.q, surface.V, vs, want_normals, what, "vs", vruns);
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
    for (const SpanRun& run : vruns) {
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
        if (!grid_point<0, true>(r, b).ok()) out_n[run.begin + b] = surface_normal(surface, us[a], vs[run.begin + b]);
    }
  }
}

}  // namespace gllab::spline
