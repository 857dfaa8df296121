// common/spline/tessellate_curve.cpp — curve flattening: flatten_curve
// (tessellate.h), adaptive to a chordal (or parametric) tolerance.
//
// Recursive bisection, as the notes "Higher Order Surfaces" subdivide a
// patch: an interval is split at its midpoint until its chord is within the
// tolerance of the curve at three interior samples (1/4, 1/2, 3/4), or until
// max_depth. tessellate.h says why three samples and why the factor 0.9
// (kFlattenSafety). Parameters are lattice positions (tessellate_detail.h),
// so two calls on the same curve and interval give bit-identical samples.
#include "spline/tessellate.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "spline/errors.h"
#include "spline/tessellate_detail.h"

namespace gllab::spline {

using detail::bisect;
using detail::Index;
using detail::lattice_param;

namespace {

/// The error of the curve point q against the chord p0-p1 (f: q's fraction of the interval).
double chord_error(Vec3 q, Vec3 p0, Vec3 p1, double f, ChordError kind) {
  if (kind == ChordError::Parametric) return norm(q - lerp(p0, p1, f));
  const Vec3 d = p1 - p0;
  const double len2 = dot(d, d);
  const double s = len2 > 0 ? std::clamp(dot(q - p0, d) / len2, 0.0, 1.0) : 0.0;
  return norm(q - (p0 + s * d));
}

}  // namespace

std::vector<CurveSample> flatten_curve(const std::function<Vec3(double)>& curve, double a, double b,
                                       const FlattenOptions& options) {
  const std::string what = "flatten_curve";
  if (!curve) fail(ErrorCode::kEmptyInput, what + ": no curve given");
  require_finite(a, what, "a");
  require_finite(b, what, "b");
  if (a > b) fail(ErrorCode::kEmptyDomain, what + ": a=" + num(a) + " > b=" + num(b), {{"a", a}, {"b", b}});
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    fail(ErrorCode::kToleranceNotPositive, what + ": tolerance=" + num(options.tolerance) + " must be > 0",
         {{"tolerance", options.tolerance}});
  if (options.min_depth < 0 || options.min_depth > options.max_depth || options.max_depth > 30)
    fail(ErrorCode::kOutOfRange,
         what + ": need 0 <= min_depth=" + std::to_string(options.min_depth) +
             " <= max_depth=" + std::to_string(options.max_depth) + " <= 30",
         {{"min_depth", options.min_depth}, {"max_depth", options.max_depth}});

  const auto evaluate = [&](double t) {
    const Vec3 p = curve(t);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) require_finite(p, what, "C(" + num(t) + ")");
    return p;
  };
  if (a == b) return {{a, evaluate(a)}, {b, evaluate(b)}};

  // Points at lattice positions k / 2^max_depth, each evaluated once: the three
  // test samples of an interval become breakpoints when it is split.
  const Index n = Index{1} << options.max_depth;
  std::unordered_map<Index, Vec3> cache;
  const auto at = [&](Index k) {
    const auto it = cache.find(k);
    if (it != cache.end()) return it->second;
    const Vec3 p = evaluate(lattice_param(a, b, k, n));
    cache.emplace(k, p);
    return p;
  };
  const double accept = kFlattenSafety * options.tolerance;
  auto needs_split = [&](Index k0, Index k1) {
    const Vec3 p0 = at(k0), p1 = at(k1);
    const double t0 = lattice_param(a, b, k0, n), t1 = lattice_param(a, b, k1, n);
    for (int q = 1; q <= 3; ++q) {
      const double f = q / 4.0;
      const Index kq = k0 + (k1 - k0) * q / 4;
      const bool on_lattice = (k1 - k0) * q % 4 == 0;
      const Vec3 s = on_lattice ? at(kq) : evaluate(t0 + (t1 - t0) * f);
      if (chord_error(s, p0, p1, f, options.error) > accept) return true;
    }
    return false;
  };
  std::vector<Index> ks{0};
  bisect(0, n, 0, options.min_depth, options.max_depth, needs_split, ks);
  std::vector<CurveSample> out;
  out.reserve(ks.size());
  for (Index k : ks) out.push_back({lattice_param(a, b, k, n), at(k)});
  return out;
}

}  // namespace gllab::spline
