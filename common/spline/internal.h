// common/spline/internal.h — helpers the core's .cpp files share. Internal:
// not part of the core's API (nothing outside common/spline includes it).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "spline/errors.h"
#include "spline/knots.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline::internal {

/// C(n, k) as a double (small n: derivative orders); 0 outside 0 <= k <= n.
inline double binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  double b = 1.0;
  for (int j = 1; j <= k; ++j) b = b * (n - k + j) / j;
  return b;
}

inline bool finite(Vec3 q) { return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z); }

/// A curve parameter: finite and in the domain.
inline void check_param(double u, ParamInterval dom) {
  require_finite(u, "parameter", "u");
  require_in_domain(u, dom);
}

/// x[0..] finite and non-decreasing, else `code` naming the first pair out of
/// order: "what: X[3]=0.2 < X[2]=0.5 (rule)", {k=3, X[3]=0.2, X[2]=0.5}.
inline void require_nondecreasing(const std::vector<double>& x, const std::string& what, const char* name,
                                  ErrorCode code, const char* rule) {
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!std::isfinite(x[k])) require_finite(x[k], what, at(name, k));
    if (k > 0 && x[k] < x[k - 1])
      fail(code,
           what + ": " + at(name, k) + "=" + num(x[k]) + " < " + at(name, k - 1) + "=" + num(x[k - 1]) + " (" + rule +
               ")",
           {{"k", k}, {at(name, k), x[k]}, {at(name, k - 1), x[k - 1]}});
  }
}

/// The index k of the last knot <= u (so U[k] <= u < U[k+1] when u < U[m]).
inline int last_knot_at_or_below(const std::vector<double>& U, double u) {
  return static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
}

/// (w x, w y, w z, w) of every control point (w = 1 for a polynomial curve).
inline std::vector<Vec4> weighted_points(const BsplineCurve& c) {
  std::vector<Vec4> Pw(c.P.size());
  for (std::size_t i = 0; i < c.P.size(); ++i) Pw[i] = homogeneous(c.P[i], c.rational() ? c.w[i] : 1.0);
  return Pw;
}

// ---- control points as a template: Vec3 for polynomial, Vec4 (Pw) for NURBS ----
// The knot algorithms of chapter 5 (insertion, refinement, degree elevation)
// are written once, on points of type Pt.

template <class Pt>
struct Ctl {
  int p = 0;
  std::vector<double> U;
  std::vector<Pt> P;
};

/// Runs op on the curve's points: P itself for a polynomial curve, Pw for a
/// rational one (the book's algorithms work on Pw). Returns the curve op made.
template <class Op>
BsplineCurve apply_to_points(const BsplineCurve& c, Op op) {
  BsplineCurve out;
  out.dimension = c.dimension;
  if (!c.rational()) {
    Ctl<Vec3> in{c.p, c.U, c.P};
    Ctl<Vec3> r = op(in);
    out.p = r.p;
    out.U = std::move(r.U);
    out.P = std::move(r.P);
  } else {
    Ctl<Vec4> in{c.p, c.U, weighted_points(c)};
    Ctl<Vec4> r = op(in);
    out.p = r.p;
    out.U = std::move(r.U);
    out.P.resize(r.P.size());
    out.w.resize(r.P.size());
    for (std::size_t i = 0; i < r.P.size(); ++i) {
      out.P[i] = project(r.P[i]);
      out.w[i] = r.P[i].w;
    }
  }
  if (out.dimension == 2)
    for (Vec3& q : out.P) q.z = 0.0;  // 0 * x may give -0; keep the plane exact
  return out;
}


}  // namespace gllab::spline::internal
