// common/spline/knot_insertion.cpp — knot insertion (the lecture's formula
// and A5.1), knot refinement (A5.4), Bézier decomposition and its inverse, and
// splitting a curve (see knot_insertion.h).
#include "spline/knot_insertion.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/internal.h"

namespace gllab::spline {

using internal::apply_to_points;
using internal::check_param;
using internal::Ctl;
using internal::last_knot_at_or_below;

namespace {

/// A5.1 CurveKnotIns (The NURBS Book, p. 151) on Pw: insert u r times; k is
/// the last knot <= u and s the multiplicity u already has.
template <class Pt>
Ctl<Pt> knot_insert_impl(const Ctl<Pt>& c, double u, int r) {
  const int p = c.p;
  const int n = static_cast<int>(c.P.size()) - 1;
  const int m = n + p + 1;
  const int k = last_knot_at_or_below(c.U, u);
  const int s = knot_multiplicity(c.U, u);
  Ctl<Pt> q;
  q.p = p;
  q.U.resize(m + r + 1);
  q.P.resize(n + r + 1);
  // Load the new knot vector.
  for (int i = 0; i <= k; ++i) q.U[i] = c.U[i];
  for (int i = 1; i <= r; ++i) q.U[k + i] = u;
  for (int i = k + 1; i <= m; ++i) q.U[i + r] = c.U[i];
  // Save the unaltered control points.
  for (int i = 0; i <= k - p; ++i) q.P[i] = c.P[i];
  for (int i = k - s; i <= n; ++i) q.P[i + r] = c.P[i];
  std::vector<Pt> R(p + 1);
  for (int i = 0; i <= p - s; ++i) R[i] = c.P[k - p + i];
  int L = k - p + 1;
  for (int j = 1; j <= r; ++j) {  // insert the knot r times
    L = k - p + j;
    for (int i = 0; i <= p - j - s; ++i) {
      const double alpha = (u - c.U[L + i]) / (c.U[i + k + 1] - c.U[L + i]);
      R[i] = alpha * R[i + 1] + (1.0 - alpha) * R[i];
    }
    q.P[L] = R[0];
    q.P[k + r - j - s] = R[p - j - s];
  }
  for (int i = L + 1; i < k - s; ++i) q.P[i] = R[i - L];  // load the remaining points
  return q;
}

/// A5.4 RefineKnotVectCurve (The NURBS Book, p. 164): insert all of X.
template <class Pt>
Ctl<Pt> knot_refine_impl(const Ctl<Pt>& c, const std::vector<double>& X) {
  const int p = c.p;
  const int n = static_cast<int>(c.P.size()) - 1;
  const int m = n + p + 1;
  if (X.empty()) return c;
  const int r = static_cast<int>(X.size()) - 1;
  const std::vector<double>& U = c.U;
  // a and b as in the book: FindSpan of the first and last new knot (so the
  // index ranges below stay inside P even when X[r] == U[n+1]).
  const int a = find_span(n, p, X[0], U);
  const int b = find_span(n, p, X[r], U) + 1;
  Ctl<Pt> q;
  q.p = p;
  q.U.resize(m + r + 2);
  q.P.resize(n + r + 2);
  for (int j = 0; j <= a - p; ++j) q.P[j] = c.P[j];
  for (int j = b - 1; j <= n; ++j) q.P[j + r + 1] = c.P[j];
  for (int j = 0; j <= a; ++j) q.U[j] = U[j];
  for (int j = b + p; j <= m; ++j) q.U[j + r + 1] = U[j];
  int i = b + p - 1;
  int k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (X[j] <= U[i] && i > a) {
      q.P[k - p - 1] = c.P[i - p - 1];
      q.U[k] = U[i];
      --k;
      --i;
    }
    q.P[k - p - 1] = q.P[k - p];
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      double alfa = q.U[k + l] - X[j];
      if (alfa == 0.0) {
        q.P[ind - 1] = q.P[ind];
      } else {
        alfa = alfa / (q.U[k + l] - U[i - p + l]);
        q.P[ind - 1] = alfa * q.P[ind - 1] + (1.0 - alfa) * q.P[ind];
      }
    }
    q.U[k] = X[j];
    --k;
  }
  return q;
}

/// The knots to insert so every knot in the domain [U[p], U[n+1]] reaches
/// multiplicity p (ch. 1 §1.6: "inserting knots so that every knot has
/// multiplicity m-1" turns the control polygon into the Bézier points).
std::vector<double> knots_to_bezier(const BsplineCurve& c) {
  const ParamInterval dom = domain(c);
  std::vector<double> X;
  for (std::size_t i = 0; i < c.U.size();) {
    const double v = c.U[i];
    std::size_t j = i;
    while (j < c.U.size() && c.U[j] == v) ++j;
    if (v >= dom.a && v <= dom.b) {
      const int mult = static_cast<int>(j - i);
      for (int k = mult; k < c.p; ++k) X.push_back(v);
    }
    i = j;
  }
  return X;
}

/// The checks knot insertion makes: u in the domain and s + r <= p.
void check_insertion(const BsplineCurve& c, double u, int r) {
  validate(c);
  check_param(u, domain(c.p, c.U));
  if (r < 0) fail(ErrorCode::kOutOfRange, "knot_insert: r=" + std::to_string(r) + " must be >= 0", {{"r", r}});
  const int s = knot_multiplicity(c.U, u);
  if (s + r > c.p)
    fail(ErrorCode::kKnotMultiplicity,
         "knot_insert: inserting u=" + num(u) + " " + std::to_string(r) + " time(s) onto multiplicity " +
             std::to_string(s) + " gives " + std::to_string(s + r) + " > p=" + std::to_string(c.p),
         {{"u", u}, {"r", r}, {"s", s}, {"p", c.p}});
}

}  // namespace

KnotInsertStep knot_insert_step(const BsplineCurve& curve, double t) {
  check_insertion(curve, t, 1);
  const int p = curve.p;
  const int n = curve.n();
  KnotInsertStep step;
  // t in [U[k], U[k+1]); at the end of the domain t == U[n+1] the last span
  // (the formula holds for U[k] <= t <= U[k+1]).
  step.k = find_span(n, p, t, curve.U);
  step.first = step.k - p + 1;
  step.a.resize(p);
  for (int i = step.first; i <= step.k; ++i) step.a[i - step.first] = (t - curve.U[i]) / (curve.U[i + p] - curve.U[i]);
  step.curve = apply_to_points(curve, [&](const auto& c) {
    using Pt = typename std::decay_t<decltype(c.P)>::value_type;
    Ctl<Pt> q;
    q.p = p;
    // New knots: U[0..k], t, U[k+1..m].
    q.U = c.U;
    q.U.insert(q.U.begin() + step.k + 1, t);
    // New points: P[0..k-p], q_{k-p+1..k}, P[k..n] (ch. 1 §1.6).
    q.P.reserve(n + 2);
    for (int i = 0; i <= step.k - p; ++i) q.P.push_back(c.P[i]);
    for (int i = step.first; i <= step.k; ++i) {
      const double a = step.a[i - step.first];
      q.P.push_back((1.0 - a) * c.P[i - 1] + a * c.P[i]);
    }
    for (int i = step.k; i <= n; ++i) q.P.push_back(c.P[i]);
    return q;
  });
  return step;
}

BsplineCurve knot_insert(const BsplineCurve& curve, double u, int r) {
  check_insertion(curve, u, r);
  if (r == 0) return curve;
  return apply_to_points(curve, [&](const auto& c) { return knot_insert_impl(c, u, r); });
}

BsplineCurve knot_refine(const BsplineCurve& curve, const std::vector<double>& X) {
  validate(curve);
  const ParamInterval dom = domain(curve.p, curve.U);
  internal::require_nondecreasing(X, "knot_refine", "X", ErrorCode::kKnotsDecreasing, "must be non-decreasing");
  for (std::size_t j = 0; j < X.size(); ++j) {
    if (X[j] < dom.a || X[j] > dom.b)
      fail(ErrorCode::kParameterOutsideDomain,
           "knot_refine: " + at("X", j) + "=" + num(X[j]) + " is outside the domain [" + num(dom.a) + ", " +
               num(dom.b) + "]",
           {{at("X", j), X[j]}, {"a", dom.a}, {"b", dom.b}});
  }
  for (std::size_t j = 0; j < X.size();) {
    std::size_t e = j;
    while (e < X.size() && X[e] == X[j]) ++e;
    const int s = knot_multiplicity(curve.U, X[j]);
    if (s + static_cast<int>(e - j) > curve.p)
      fail(ErrorCode::kKnotMultiplicity,
           "knot_refine: knot " + num(X[j]) + " would get multiplicity " + std::to_string(s + (e - j)) +
               " > p=" + std::to_string(curve.p),
           {{"knot", X[j]}, {"multiplicity", s + (e - j)}, {"p", curve.p}});
    j = e;
  }
  if (X.empty()) return curve;
  return apply_to_points(curve, [&](const auto& c) { return knot_refine_impl(c, X); });
}

std::vector<BsplineCurve> bezier_segments(const BsplineCurve& curve) {
  validate(curve);
  // Ch. 1 §1.6 (raise every knot to multiplicity p, here with A5.4 in one
  // pass); then span k with U[k] < U[k+1] has the Bézier points P[k-p..k].
  // Inserting up to p (not p + 1) keeps unclamped ends working too.
  const std::vector<double> X = knots_to_bezier(curve);
  const BsplineCurve fine =
      X.empty() ? curve : apply_to_points(curve, [&](const auto& c) { return knot_refine_impl(c, X); });
  const ParamInterval dom = domain(fine.p, fine.U);
  const int p = fine.p;
  std::vector<BsplineCurve> pieces;
  for (int k = p; k <= fine.n(); ++k) {
    if (!(fine.U[k] < fine.U[k + 1]) || fine.U[k] < dom.a || fine.U[k + 1] > dom.b) continue;
    BsplineCurve b;
    b.p = p;
    b.dimension = fine.dimension;
    b.U.assign(p + 1, fine.U[k]);
    b.U.insert(b.U.end(), p + 1, fine.U[k + 1]);
    b.P.assign(fine.P.begin() + (k - p), fine.P.begin() + (k + 1));
    if (fine.rational()) b.w.assign(fine.w.begin() + (k - p), fine.w.begin() + (k + 1));
    pieces.push_back(std::move(b));
  }
  return pieces;
}

std::vector<BezierCurve> bezier_decompose(const BsplineCurve& curve) {
  validate(curve);
  if (curve.rational())
    fail(ErrorCode::kRationalNotSupported,
         "bezier_decompose: the curve is rational (" + std::to_string(curve.w.size()) +
             " weights); BezierCurve has no weights, use bezier_segments",
         {{"weights", curve.w.size()}});
  std::vector<BezierCurve> out;
  for (BsplineCurve& piece : bezier_segments(curve)) {
    BezierCurve b;
    b.P = std::move(piece.P);
    b.a = piece.U.front();
    b.b = piece.U.back();
    b.dimension = piece.dimension;
    out.push_back(std::move(b));
  }
  return out;
}

BsplineCurve from_bezier_segments(const std::vector<BezierCurve>& segments) {
  const std::string what = "from_bezier_segments";
  if (segments.empty()) fail(ErrorCode::kEmptyInput, what + ": no segments", {{"segments", 0}});
  BsplineCurve out;
  out.p = static_cast<int>(segments.front().P.size()) - 1;
  out.dimension = 2;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const BezierCurve& s = segments[i];
    const std::string name = what + ": " + at("segment", i);
    const int p = static_cast<int>(s.P.size()) - 1;
    if (p < 1)
      fail(ErrorCode::kDegreeTooLow, name + " has degree " + std::to_string(p) + " (need >= 1)",
           {{"segment", i}, {"p", p}});
    if (p != out.p)
      fail(ErrorCode::kPiecesDoNotJoin,
           name + " has degree " + std::to_string(p) + ", segment[0] degree " + std::to_string(out.p),
           {{"segment", i}, {"p", p}, {"p0", out.p}});
    if (!(s.a < s.b) || !std::isfinite(s.a) || !std::isfinite(s.b))
      fail(std::isfinite(s.a) && std::isfinite(s.b) ? ErrorCode::kEmptyDomain : ErrorCode::kNotFinite,
           name + ": interval [" + num(s.a) + ", " + num(s.b) + "] is not a finite a < b",
           {{"segment", i}, {"a", s.a}, {"b", s.b}});
    for (std::size_t j = 0; j < s.P.size(); ++j) require_finite(s.P[j], name, at("P", j));
    if (i > 0) {
      const BezierCurve& prev = segments[i - 1];
      if (s.a != prev.b)
        fail(ErrorCode::kPiecesDoNotJoin,
             name + " starts at t=" + num(s.a) + ", segment[" + std::to_string(i - 1) + "] ends at t=" + num(prev.b),
             {{"segment", i}, {"a", s.a}, {"previous b", prev.b}});
      if (s.P.front() != prev.P.back())
        fail(ErrorCode::kPiecesDoNotJoin,
             name + " starts at " + num(s.P.front()) + ", segment[" + std::to_string(i - 1) + "] ends at " +
                 num(prev.P.back()),
             {{"segment", i}, {"start", s.P.front()}, {"previous end", prev.P.back()}});
    }
    out.U.insert(out.U.end(), i == 0 ? p + 1 : p, s.a);
    out.P.insert(out.P.end(), s.P.begin() + (i == 0 ? 0 : 1), s.P.end());
    if (s.dimension != 2) out.dimension = 3;
  }
  out.U.insert(out.U.end(), out.p + 1, segments.back().b);
  return out;
}

std::pair<BsplineCurve, BsplineCurve> split(const BsplineCurve& curve, double u) {
  validate(curve);
  const ParamInterval dom = domain(curve.p, curve.U);
  require_finite(u, "split", "u");
  if (!(u > dom.a && u < dom.b))
    fail(ErrorCode::kParameterOutsideDomain,
         "split: u=" + num(u) + " must lie strictly inside the domain (" + num(dom.a) + ", " + num(dom.b) + ")",
         {{"u", u}, {"a", dom.a}, {"b", dom.b}});
  const int p = curve.p;
  const int s = knot_multiplicity(curve.U, u);
  const BsplineCurve c = s >= p ? curve : knot_insert(curve, u, p - s);
  // u now has multiplicity p or p + 1 at U[f..l].
  const int f = static_cast<int>(std::lower_bound(c.U.begin(), c.U.end(), u) - c.U.begin());
  const int l = last_knot_at_or_below(c.U, u);
  BsplineCurve left;
  BsplineCurve right;
  left.p = right.p = p;
  left.dimension = right.dimension = c.dimension;
  // Left: P[0..f-1] on U[0..f-1] + u x (p+1). Right: P[l-p..n] on u x (p+1) + U[l+1..m].
  left.U.assign(c.U.begin(), c.U.begin() + f);
  left.U.insert(left.U.end(), p + 1, u);
  left.P.assign(c.P.begin(), c.P.begin() + f);
  right.U.assign(p + 1, u);
  right.U.insert(right.U.end(), c.U.begin() + (l + 1), c.U.end());
  right.P.assign(c.P.begin() + (l - p), c.P.end());
  if (c.rational()) {
    left.w.assign(c.w.begin(), c.w.begin() + f);
    right.w.assign(c.w.begin() + (l - p), c.w.end());
  }
  return {left, right};
}

}  // namespace gllab::spline
