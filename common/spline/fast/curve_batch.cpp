// common/spline/fast/curve_batch.cpp — curve_points(): many points (and first
// derivatives) of one B-spline or NURBS curve at once (see curve_batch.h).
#include "spline/fast/curve_batch.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "spline/basis.h"
#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/fast/kernels.h"
#include "spline/internal.h"

namespace gllab::spline {

using fast::span_runs;
using fast::SpanRun;

// ---- batched evaluation ------------------------------------------------------------
//
// curve_points() computes what curve_point() and curve_derivs(u, 1) compute --
// A2.1 FindSpan, A2.2 BasisFuns, the sums of A3.1 / A4.1 and A4.2 -- for many
// sorted parameters at once. The per-point functions of the textbook layer (curve_point,
// homogeneous_curve_point in bspline.cpp, basis_funs in basis.cpp) stay the reference:
// they are the book's algorithms as printed, one point at a time. Here the
// same arithmetic is rearranged so that the machine can go fast
// (bench/README.md has the measurements):
//
// 1. Span runs instead of a span search per point. The parameters are sorted,
//    so each knot span i owns a contiguous run u[begin..end) of them: A2.1 is
//    done once per run (std::lower_bound finds where the run ends), and
//    nothing in the per-point loop tests which span it is in.
// 2. Per-span reciprocals. A2.2 divides by right[r+1] + left[j-r] =
//    U[i+r+1] - U[i+1-j+r]: the knots of span i, not u. The p(p+1)/2
//    reciprocals are computed once per run; per point A2.2 only multiplies.
//    (x * (1/d) can differ from x / d in the last bit: the batched results
//    agree with curve_point() to rounding, not bit for bit.)
// 3. One division per point. A4.1 projects C = (x/w, y/w, z/w); here
//    iw = 1/w and C = (x iw, y iw, z iw): one division, not three. The
//    derivative (A4.2 with k = 1) C' = (A' - w' C) / w reuses iw.
// 4. A fixed degree. eval_run<P> is A2.2 with the degree P known to the
//    compiler: the loops over j and r have constant trip counts, they are
//    unrolled completely ("#pragma GCC unroll"), and N[], left[], right[]
//    live in registers instead of memory. curve_points() switches on p for
//    p = 1..5; eval_run<0> is the same code with the degree read at run time,
//    for every other degree.
// 5. Vectorisation. After 1-4 the loop over the points of a run is
//    straight-line arithmetic from u[k] to out[k], with no branch and nothing
//    carried from one point to the next: GCC computes 2 (SSE2), 4 (AVX2) or
//    8 (AVX-512) points at once. target_clones (GLLAB_SPLINE_CLONES) compiles
//    the kernels once per instruction set and the loader picks the best one
//    (GLLAB_SPLINE_CLONES is defined in fast/kernels.h.)

namespace {
/// Checks the parameters of a batch: finite, non-decreasing, in the domain,
/// and throws naming the first bad one.
void check_sorted_params_detailed(const std::vector<double>& us, ParamInterval dom) {
  internal::require_nondecreasing(us, "curve_points", "u", ErrorCode::kParametersNotSorted,
                                  "parameters must be non-decreasing");
  if (!us.empty() && (us.front() < dom.a || us.back() > dom.b)) {
    const double bad = us.front() < dom.a ? us.front() : us.back();
    fail(ErrorCode::kParameterOutsideDomain,
         "curve_points: u=" + num(bad) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) + "]",
         {{"u", bad}, {"a", dom.a}, {"b", dom.b}});
  }
}

/// How many k have !(u[k] >= u[k-1]): a count without a branch, which GCC
/// vectorises (a loop that stops at the first bad parameter cannot be
/// vectorised, and the detailed loop above cost as much as evaluating the
/// points); compiled once per instruction set like the kernels below.
GLLAB_SPLINE_CLONES std::size_t count_unsorted(const double* u, std::size_t count) {
  std::size_t bad = 0;
  for (std::size_t k = 1; k < count; ++k) bad += !(u[k] >= u[k - 1]);
  return bad;
}

/// The check in one fast pass. u[k] >= u[k-1] is false when either is NaN,
/// and a sorted list whose ends lie in the (finite) domain has every value in
/// it: so this accepts exactly what the detailed check accepts, and the
/// detailed check names the culprit.
void check_sorted_params(const std::vector<double>& us, ParamInterval dom) {
  if (us.empty()) return;
  if (count_unsorted(us.data(), us.size()) == 0 && us.front() >= dom.a && us.back() <= dom.b) return;
  check_sorted_params_detailed(us, dom);
  fail(ErrorCode::kParametersNotSorted, "curve_points: invalid parameters");  // not reached: the detailed check throws
}

/// What the kernels need to know about one knot span i, computed once per
/// run of parameters in it. Pt is Vec3 for a polynomial curve and Vec4
/// (w x, w y, w z, w) for a rational one.
template <class Pt>
struct SpanData {
  double left_knot[kMaxDegree + 1];   // U[i+1-j]: A2.2's left[j] = u - left_knot[j], j = 1..p
  double right_knot[kMaxDegree + 1];  // U[i+j]: A2.2's right[j] = right_knot[j] - u
  double inv[(kMaxDegree + 1) * (kMaxDegree + 2) / 2];  // 1 / (U[i+r+1] - U[i+1-j+r]) at j(j-1)/2 + r
  Pt P[kMaxDegree + 1];  // P[i-p..i] (Pw for a rational curve)
  Pt Q[kMaxDegree];      // Q[i-p..i-1], the control points of C' (only with derivatives)
};

template <class Pt>
Pt control_point(const BsplineCurve& c, int i) {
  if constexpr (std::is_same_v<Pt, Vec4>) {
    return homogeneous(c.P[i], c.w[i]);
  } else {
    return c.P[i];
  }
}

template <class Pt>
void prepare_span(const BsplineCurve& c, int i, bool derivs, SpanData<Pt>& s) {
  const int p = c.p;
  const double* U = c.U.data();
  for (int j = 1; j <= p; ++j) {
    s.left_knot[j] = U[i + 1 - j];
    s.right_knot[j] = U[i + j];
    for (int r = 0; r < j; ++r) s.inv[j * (j - 1) / 2 + r] = 1.0 / (U[i + r + 1] - U[i + 1 - j + r]);
  }
  for (int j = 0; j <= p; ++j) s.P[j] = control_point<Pt>(c, i - p + j);
  if (!derivs) return;
  // The derivative's control points (The NURBS Book, eq. 3.8; in homogeneous
  // space for NURBS): Q_l = p (P_{l+1} - P_l) / (U[l+p+1] - U[l+1]), l = i-p..i-1,
  // so C'(u) = sum_j N_{i-p+1+j,p-1}(u) Q_{i-p+j}. Each denominator is at least
  // U[i+1] - U[i] > 0.
  for (int j = 0; j < p; ++j) {
    const int l = i - p + j;
    s.Q[j] = (p / (U[l + p + 1] - U[l + 1])) * (s.P[j + 1] - s.P[j]);
  }
}

/// Evaluates the points u[0..count) of one span (and, if kDerivs, C' there).
/// P > 0: the degree is P, fixed at compile time; P == 0: the degree is p.
/// The loop body is A2.2 with the span's reciprocals, then A3.1 (Vec3) or
/// A4.1 (Vec4, one reciprocal of w), then A4.2 for C'.
template <int P, class Pt, bool kDerivs>
[[gnu::always_inline]] inline void eval_run(const SpanData<Pt>& s, int p_runtime, const double* __restrict u,
                                            Vec3* __restrict out, Vec3* __restrict der, std::size_t count) {
  constexpr int W = P > 0 ? P : kMaxDegree;  // array sizes
  const int p = P > 0 ? P : p_runtime;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = u[k];
    // A2.2 BasisFuns. N: degree p; Nlow: degree p - 1 (the step before last).
    double N[W + 1], Nlow[W + 1], left[W + 1], right[W + 1];
    N[0] = 1.0;
    Nlow[0] = 1.0;
#pragma GCC unroll 8
    for (int j = 1; j <= p; ++j) {
      left[j] = x - s.left_knot[j];
      right[j] = s.right_knot[j] - x;
      const double* inv_j = s.inv + j * (j - 1) / 2;
      double saved = 0.0;
#pragma GCC unroll 8
      for (int r = 0; r < j; ++r) {
        const double temp = N[r] * inv_j[r];  // N[r] / (right[r+1] + left[j-r]) in A2.2
        N[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      N[j] = saved;
      if (kDerivs && j == p - 1) {
#pragma GCC unroll 8
        for (int r = 0; r <= j; ++r) Nlow[r] = N[r];
      }
    }
    // A3.1 / A4.1: the sum over the p + 1 control points of the span.
    Pt A{};
#pragma GCC unroll 8
    for (int j = 0; j <= p; ++j) A += N[j] * s.P[j];
    Pt dA{};
    if constexpr (kDerivs) {
#pragma GCC unroll 8
      for (int j = 0; j < p; ++j) dA += Nlow[j] * s.Q[j];
    }
    if constexpr (std::is_same_v<Pt, Vec4>) {
      const double iw = 1.0 / A.w;
      const Vec3 C{A.x * iw, A.y * iw, A.z * iw};
      out[k] = C;
      // A4.2 with k = 1: C' = (A' - w' C) / w.
      if constexpr (kDerivs)
        der[k] = {(dA.x - dA.w * C.x) * iw, (dA.y - dA.w * C.y) * iw, (dA.z - dA.w * C.z) * iw};
    } else {
      out[k] = A;
      if constexpr (kDerivs) der[k] = dA;
    }
  }
}

/// Evaluates each run of sorted parameters with the kernel for the curve's
/// degree (the runs come from the span walk, fast/kernels.h).
template <class Pt, bool kDerivs>
[[gnu::always_inline]] inline void eval_runs(const BsplineCurve& c, const SpanRun* runs, std::size_t run_count,
                                             const double* u, Vec3* out, Vec3* der) {
  const int p = c.p;
  SpanData<Pt> s;
  for (std::size_t r = 0; r < run_count; ++r) {
    const SpanRun& run = runs[r];
    prepare_span(c, run.span, kDerivs, s);
    const double* run_u = u + run.begin;
    Vec3* run_out = out + run.begin;
    Vec3* run_der = kDerivs ? der + run.begin : nullptr;
    const std::size_t m = run.end - run.begin;
    switch (p) {
      case 1: eval_run<1, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 2: eval_run<2, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 3: eval_run<3, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 4: eval_run<4, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 5: eval_run<5, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      default: eval_run<0, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
    }
  }
}

// One function per kind of curve, compiled once per instruction set (the
// templates above are inlined into each, always_inline: a call to a separate
// function would run that function's baseline code).
GLLAB_SPLINE_CLONES void eval_polynomial(const BsplineCurve& c, const SpanRun* runs, std::size_t run_count,
                                         const double* u, Vec3* out, Vec3* der) {
  der ? eval_runs<Vec3, true>(c, runs, run_count, u, out, der)
      : eval_runs<Vec3, false>(c, runs, run_count, u, out, der);
}
GLLAB_SPLINE_CLONES void eval_rational(const BsplineCurve& c, const SpanRun* runs, std::size_t run_count,
                                       const double* u, Vec3* out, Vec3* der) {
  der ? eval_runs<Vec4, true>(c, runs, run_count, u, out, der)
      : eval_runs<Vec4, false>(c, runs, run_count, u, out, der);
}

void curve_points_impl(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out,
                       std::vector<Vec3>* derivs) {
  validate(curve);
  check_sorted_params(sorted_u, domain(curve.p, curve.U));
  out.resize(sorted_u.size());
  if (derivs) derivs->resize(sorted_u.size());
  if (sorted_u.empty()) return;
  Vec3* der = derivs ? derivs->data() : nullptr;
  const std::vector<SpanRun> runs = span_runs(curve.n(), curve.p, curve.U, sorted_u.data(), sorted_u.size(), true);
  if (curve.rational())
    eval_rational(curve, runs.data(), runs.size(), sorted_u.data(), out.data(), der);
  else
    eval_polynomial(curve, runs.data(), runs.size(), sorted_u.data(), out.data(), der);
}
}  // namespace

void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out) {
  curve_points_impl(curve, sorted_u, out, nullptr);
}

void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out,
                  std::vector<Vec3>& derivs) {
  curve_points_impl(curve, sorted_u, out, &derivs);
}

}  // namespace gllab::spline
