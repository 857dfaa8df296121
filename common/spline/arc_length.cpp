// common/spline/arc_length.cpp — arc length, its inverse, equal-length steps (arc_length.h).
#include "spline/arc_length.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/internal.h"

namespace gllab::spline {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr int kMaxDepth = 50;  // a panel 2^-50 of its span: far below any useful u

}  // namespace

ArcLength::ArcLength(const BsplineCurve& curve, double tolerance)
    : curve_(curve), rule_(gauss_legendre(kArcLengthGaussPoints)) {
  require_finite(tolerance, "arc length", "tolerance");
  if (tolerance < 1e-15 || tolerance > 0.1)
    fail(tolerance > 0 ? ErrorCode::kOutOfRange : ErrorCode::kToleranceNotPositive,
         "arc length: tolerance=" + num(tolerance) + " must lie in [1e-15, 0.1] (relative)",
         {{"tolerance", tolerance}});
  const ParamInterval dom = curve_.domain();
  breaks_ = {dom.a};
  cumulative_ = {0.0};
  // Cut at every distinct knot inside the domain: X' may have a kink there.
  double a = dom.a;
  for (double knot : curve_.curve().U) {
    if (knot <= a || knot >= dom.b) continue;
    add_span(a, knot, tolerance, 0);
    a = knot;
  }
  add_span(a, dom.b, tolerance, 0);
}

double ArcLength::speed(double u) const { return norm(curve_.derivs(u, 1)[1]); }

// The Gauss rule on [a, b]: the nodes map from [-1, 1] by u = m + h x.
double ArcLength::panel_integral(double a, double b) const {
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  double sum = 0;
  for (std::size_t i = 0; i < rule_.x.size(); ++i) sum += rule_.w[i] * speed(m + h * rule_.x[i]);
  return h * sum;
}

// Accepts the two halves of [a, b] as panels when the rule on [a, b] agrees
// with the sum over them; else splits each half in turn.
void ArcLength::add_span(double a, double b, double tolerance, int depth) {
  const double m = 0.5 * (a + b);
  const double whole = panel_integral(a, b);
  const double left = panel_integral(a, m), right = panel_integral(m, b);
  const double difference = std::fabs(whole - (left + right));
  const bool full = panels() + 2 > kArcLengthMaxPanels;
  if (difference <= tolerance * (left + right) || depth >= kMaxDepth || full || m <= a || m >= b) {
    breaks_.push_back(m);
    cumulative_.push_back(cumulative_.back() + left);
    breaks_.push_back(b);
    cumulative_.push_back(cumulative_.back() + right);
    error_ += difference;
    return;
  }
  add_span(a, m, tolerance, depth + 1);
  add_span(m, b, tolerance, depth + 1);
}

double ArcLength::s(double u) const {
  internal::check_param(u, {breaks_.front(), breaks_.back()});
  // The panel [breaks_[j], breaks_[j+1]] that holds u (the last one for u at the end).
  const auto it = std::upper_bound(breaks_.begin(), breaks_.end(), u);
  const std::size_t j = std::min<std::size_t>(it - breaks_.begin(), panels()) - 1;
  if (u == breaks_[j]) return cumulative_[j];
  if (u == breaks_[j + 1]) return cumulative_[j + 1];
  return cumulative_[j] + panel_integral(breaks_[j], u);
}

double ArcLength::u(double s) const {
  require_finite(s, "arc length inverse", "s");
  const double L = length();
  if (s < 0 || s > L)
    fail(ErrorCode::kParameterOutsideDomain,
         "arc length inverse: s=" + num(s) + " is outside [0, " + num(L) + "] (the curve's length)",
         {{"s", s}, {"L", L}});
  // The panel that holds s; s(u) is non-decreasing, so the bracket [lo, hi] is that panel.
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const std::size_t j = std::min<std::size_t>(it - cumulative_.begin(), panels()) - 1;
  double lo = breaks_[j], hi = breaks_[j + 1];
  const double s_lo = cumulative_[j], s_hi = cumulative_[j + 1];
  if (s == s_lo) return lo;
  if (s == s_hi) return hi;
  // Start where the chord of s over the panel says; then Newton, guarded.
  double u = lo + (hi - lo) * (s - s_lo) / (s_hi - s_lo);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double f = s_lo + panel_integral(breaks_[j], u) - s;
    if (std::fabs(f) <= 4 * kEps * L) return u;
    (f < 0 ? lo : hi) = u;
    if (hi - lo <= 4 * kEps * std::max(std::fabs(lo), std::fabs(hi))) return u;
    const double v = speed(u);
    const double newton = v > 0 ? u - f / v : lo - 1;  // lo - 1: outside, so bisect
    u = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
  }
  return u;  // not reached for a panel of width >= 2^-50 of a span: 200 bisections
}

std::vector<double> ArcLength::equal_steps(int count) const {
  if (count < 2)
    fail(ErrorCode::kTooFewPoints, "arc length steps: count=" + std::to_string(count) + " must be >= 2",
         {{"count", count}});
  std::vector<double> out(count);
  const double L = length();
  for (int k = 0; k < count; ++k) {
    out[k] = k == count - 1 ? breaks_.back() : u(L * k / (count - 1));
  }
  return out;
}

}  // namespace gllab::spline
