// common/spline/surface_support.h — helpers the surface files share (checks,
// message texts, the unit normal with its fallback). Internal: not part of the
// core's API.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "spline/bezier.h"
#include "spline/errors.h"
#include "spline/internal.h"
#include "spline/surface.h"

namespace gllab::spline::internal {

using Table = std::vector<std::vector<Vec3>>;  // SKL[k][l]

inline std::size_t uz(int i) { return static_cast<std::size_t>(i); }

inline std::string interval_text(const char* name, double lo, double hi) {
  return std::string(name) + " interval [" + num(lo) + ", " + num(hi) + "]";
}

inline std::string ij_text(int i, int j) { return "(" + std::to_string(i) + ", " + std::to_string(j) + ")"; }

/// A parameter of a Bézier-type surface checked against [lo, hi] and snapped
/// onto it when it misses only by round-off (kBezierParameterSlack, bezier.h).
inline double checked_parameter(double x, double lo, double hi, const std::string& what, const char* name) {
  require_finite(x, what, name);
  const double slack = kBezierParameterSlack * std::max({std::fabs(lo), std::fabs(hi), hi - lo});
  if (x < lo - slack || x > hi + slack)
    fail(ErrorCode::kParameterOutsideDomain,
         what + ": " + name + "=" + num(x) + " is outside the " + interval_text(name, lo, hi) +
             (x < lo ? " (below)" : " (above)"),
         {{name, x}, {"a", lo}, {"b", hi}});
  return std::clamp(x, lo, hi);
}

/// A B-spline parameter checked against its domain (no snapping: find_span
/// decides the span exactly).
inline void require_in(double x, ParamInterval dom, const std::string& what, const char* name) {
  require_finite(x, what, name);
  if (x < dom.a || x > dom.b)
    fail(ErrorCode::kParameterOutsideDomain,
         what + ": " + name + "=" + num(x) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) + "]",
         {{name, x}, {"a", dom.a}, {"b", dom.b}});
}

inline void require_nodes(const std::vector<double>& nodes, const std::string& what, const char* name) {
  if (nodes.empty())
    fail(ErrorCode::kEmptyInput, what + ": " + name + " is empty (need at least one node)", {{name, 0}});
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    require_finite(nodes[i], what, at(name, i));
    for (std::size_t k = 0; k < i; ++k)
      if (nodes[k] == nodes[i])
        fail(ErrorCode::kNodesCoincide,
             what + ": " + at(name, k) + "=" + num(nodes[k]) + " and " + at(name, i) + "=" + num(nodes[i]) +
                 " coincide (nodes must be pairwise distinct)",
             {{at(name, k), nodes[k]}, {at(name, i), nodes[i]}});
  }
}

inline void require_order(int d, const std::string& what) {
  if (d < 0)
    fail(ErrorCode::kNegativeDerivativeOrder, what + ": derivative order d=" + std::to_string(d) + " is negative",
         {{"d", d}});
}

// ---- unit normal with fallback (shared by every surface type) ----------------

/// true when |n| is zero at the scale of the vectors it was made of.
inline bool degenerate(Vec3 n, double scale) { return !(norm(n) > kDegenerateNormal * scale * scale); }

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

}  // namespace gllab::spline::internal
