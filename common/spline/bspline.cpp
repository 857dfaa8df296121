// common/spline/bspline.cpp — B-spline and NURBS curves: the checks, the
// standard curves, evaluation (A3.1, A3.2, A4.1, A4.2, de Boor), reversal and
// the uniform cubic matrix form (see bspline.h).
#include "spline/bspline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spline/errors.h"
#include "spline/internal.h"

namespace gllab::spline {

using internal::binomial;
using internal::check_param;
using internal::finite;

namespace {
/// The span used to evaluate at u from the given side; u must be in the domain.
int span_at(const BsplineCurve& c, double u, Side side) {
  return side == Side::Right ? find_span(c.n(), c.p, u, c.U) : find_span_left(c.n(), c.p, u, c.U);
}
}  // namespace

// ---- checks -----------------------------------------------------------------

void validate(const BsplineCurve& curve) {
  if (curve.P.empty()) fail(ErrorCode::kEmptyInput, "curve: no control points (empty input)");
  if (curve.P.size() > kMaxControlPoints)
    fail(ErrorCode::kOutOfRange,
         "curve: " + std::to_string(curve.P.size()) + " control points, more than the limit of " +
             std::to_string(kMaxControlPoints) + " (kMaxControlPoints)",
         {{"points", curve.P.size()}});
  if (curve.dimension != 2 && curve.dimension != 3)
    fail(ErrorCode::kDimension, "curve: dimension=" + std::to_string(curve.dimension) + " must be 2 or 3",
         {{"dimension", curve.dimension}});
  validate_knots(curve.p, static_cast<int>(curve.P.size()), curve.U, "knot vector");
  for (std::size_t i = 0; i < curve.P.size(); ++i) {
    if (!finite(curve.P[i])) require_finite(curve.P[i], "control points", at("P", i));
    if (curve.dimension == 2 && curve.P[i].z != 0)
      fail(ErrorCode::kNotPlanar, "control points: " + at("P", i) + "=" + num(curve.P[i]) + " has z != 0 in a 2D curve",
           {{"i", i}, {at("P", i), curve.P[i]}});
  }
  if (curve.rational()) {
    if (curve.w.size() != curve.P.size())
      fail(ErrorCode::kWeightCount,
           "weights: " + std::to_string(curve.w.size()) + " weights for " + std::to_string(curve.P.size()) +
               " control points (need one per point, or none)",
           {{"weights", curve.w.size()}, {"points", curve.P.size()}});
    for (std::size_t i = 0; i < curve.w.size(); ++i) {
      if (!std::isfinite(curve.w[i])) require_finite(curve.w[i], "weights", at("w", i));
      if (!(curve.w[i] > 0))
        fail(ErrorCode::kWeightNotPositive, "weights: " + at("w", i) + "=" + num(curve.w[i]) + " must be > 0",
             {{"i", i}, {at("w", i), curve.w[i]}});
    }
  }
}

ParamInterval domain(const BsplineCurve& curve) {
  validate(curve);
  return domain(curve.p, curve.U);
}

// ---- curves on standard knot vectors ----------------------------------------

BsplineCurve periodic_curve(const std::vector<Vec3>& points, int p, int dimension) {
  if (points.size() < 2)
    fail(ErrorCode::kTooFewPoints, "periodic_curve: needs at least 2 points, got " + std::to_string(points.size()),
         {{"points", points.size()}});
  if (p < 1)
    fail(ErrorCode::kDegreeTooLow, "periodic_curve: degree p=" + std::to_string(p) + " must be >= 1", {{"p", p}});
  BsplineCurve c;
  c.p = p;
  c.dimension = dimension;
  c.P = points;
  // Wrap: P[k + j] = P[j] for the first p points (cyclically if p > k).
  for (std::size_t j = 0; j < static_cast<std::size_t>(p); ++j) c.P.push_back(points[j % points.size()]);
  c.U = uniform_knots(c.n(), p);
  validate(c);
  return c;
}

BsplineCurve clamped_curve(const std::vector<Vec3>& points, int p, int dimension) {
  BsplineCurve c;
  c.p = p;
  c.dimension = dimension;
  c.P = points;
  if (points.empty()) fail(ErrorCode::kEmptyInput, "clamped_curve: no control points (empty input)");
  if (p < 1 || p >= static_cast<int>(points.size()))
    fail(p < 1 ? ErrorCode::kDegreeTooLow : ErrorCode::kTooFewPoints,
         "clamped_curve: degree p=" + std::to_string(p) + " needs 1 <= p < number of points (" +
             std::to_string(points.size()) + ")",
         {{"p", p}, {"points", points.size()}});
  c.U = clamped_uniform_knots(c.n(), p);
  validate(c);
  return c;
}

// ---- evaluation ----------------------------------------------------------------

namespace {
// Cw(u) of a curve and a u already checked (A4.1 before the projection).
Vec4 homogeneous_point_of_checked(const BsplineCurve& curve, double u, Side side) {
  const int p = curve.p;
  const int span = span_at(curve, u, side);
  double N[kMaxDegree + 1];
  basis_funs(span, u, p, curve.U, N);
  Vec4 Cw;
  for (int j = 0; j <= p; ++j) {
    const int i = span - p + j;
    Cw += N[j] * homogeneous(curve.P[i], curve.rational() ? curve.w[i] : 1.0);
  }
  return Cw;
}
}  // namespace

Vec4 homogeneous_curve_point(const BsplineCurve& curve, double u, Side side) {
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  return homogeneous_point_of_checked(curve, u, side);
}

Vec3 rational_curve_point(const BsplineCurve& curve, double u, Side side) {
  return project(homogeneous_curve_point(curve, u, side));
}

namespace {
// C(u) of a curve and a u already checked: A4.1 for a rational curve, else A3.1.
Vec3 point_of_checked(const BsplineCurve& curve, double u, Side side) {
  if (curve.rational()) return project(homogeneous_point_of_checked(curve, u, side));
  // A3.1: find the span, the p + 1 non-zero basis functions, and sum.
  const int p = curve.p;
  const int span = span_at(curve, u, side);
  double N[kMaxDegree + 1];
  basis_funs(span, u, p, curve.U, N);
  Vec3 C;
  for (int j = 0; j <= p; ++j) C += N[j] * curve.P[span - p + j];
  return C;
}
}  // namespace

Vec3 curve_point(const BsplineCurve& curve, double u, Side side) {
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  return point_of_checked(curve, u, side);
}

namespace {
/// A3.2 CurveDerivsAlg1 on any point type: CK[k], k = 0..d.
template <class Pt, class PointAt>
std::vector<Pt> derivs_impl(const BsplineCurve& c, double u, int d, Side side, PointAt point_at) {
  const int p = c.p;
  std::vector<Pt> CK(d + 1);
  const int du = std::min(d, p);
  const int span = span_at(c, u, side);
  const auto nders = ders_basis_funs(span, u, p, du, c.U);
  for (int k = 0; k <= du; ++k)
    for (int j = 0; j <= p; ++j) CK[k] = CK[k] + nders[k][j] * point_at(span - p + j);
  return CK;
}
}  // namespace

namespace {

void check_order(int d) {
  if (d < 0)
    fail(ErrorCode::kNegativeDerivativeOrder, "curve_derivs: derivative order d=" + std::to_string(d) + " must be >= 0",
         {{"d", d}});
}

// A3.2 on the points, or on the homogeneous points and then A4.2; the curve
// and u already checked.
std::vector<Vec3> derivs_of_checked(const BsplineCurve& curve, double u, int d, Side side, bool by_weights) {
  if (!by_weights) return derivs_impl<Vec3>(curve, u, d, side, [&](int i) { return curve.P[i]; });
  // Derivatives of Cw = (A, w) (A3.2 in homogeneous space), then A4.2:
  // C^(k) = (A^(k) - sum_{i=1..k} Bin(k,i) w^(i) C^(k-i)) / w.
  const auto Cw = derivs_impl<Vec4>(curve, u, d, side, [&](int i) {
    return homogeneous(curve.P[i], curve.rational() ? curve.w[i] : 1.0);
  });
  std::vector<Vec3> CK(d + 1);
  for (int k = 0; k <= d; ++k) {
    Vec3 v = xyz(Cw[k]);
    for (int i = 1; i <= k; ++i) v -= binomial(k, i) * Cw[i].w * CK[k - i];
    CK[k] = v / Cw[0].w;
  }
  return CK;
}

}  // namespace

std::vector<Vec3> rational_curve_derivs(const BsplineCurve& curve, double u, int d, Side side) {
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  check_order(d);
  return derivs_of_checked(curve, u, d, side, true);  // weights 1 for a polynomial curve
}

std::vector<Vec3> curve_derivs(const BsplineCurve& curve, double u, int d, Side side) {
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  check_order(d);
  return derivs_of_checked(curve, u, d, side, curve.rational());
}

CurveEvaluator::CurveEvaluator(BsplineCurve curve) : curve_(std::move(curve)) {
  validate(curve_);
  domain_ = spline::domain(curve_.p, curve_.U);
}

Vec3 CurveEvaluator::point(double u, Side side) const {
  check_param(u, domain_);
  return point_of_checked(curve_, u, side);
}

std::vector<Vec3> CurveEvaluator::derivs(double u, int d, Side side) const {
  check_param(u, domain_);
  check_order(d);
  return derivs_of_checked(curve_, u, d, side, curve_.rational());
}

DeBoorConstruction de_boor(const BsplineCurve& curve, double u) {
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  const int p = curve.p;
  const std::vector<double>& U = curve.U;
  DeBoorConstruction out;
  out.span = find_span(curve.n(), p, u, U);
  const int k = out.span;
  // de Boor's algorithm is knot insertion repeated p times (ch. 1 §1.6
  // knot insertion; The NURBS Book §5.2): d_j^r = (1 - a) d_{j-1}^{r-1} + a d_j^{r-1},
  // a = (u - U[j]) / (U[j+p+1-r] - U[j]), j = k-p+r..k.
  std::vector<Vec4> level(p + 1);
  for (int j = 0; j <= p; ++j)
    level[j] = homogeneous(curve.P[k - p + j], curve.rational() ? curve.w[k - p + j] : 1.0);
  auto store = [&](const std::vector<Vec4>& lv, int count) {
    std::vector<Vec3> pts(count);
    for (int j = 0; j < count; ++j) pts[j] = curve.rational() ? project(lv[j]) : xyz(lv[j]);
    out.levels.push_back(std::move(pts));
  };
  out.levels.emplace_back(curve.P.begin() + (k - p), curve.P.begin() + (k + 1));  // exactly P, not P projected
  for (int r = 1; r <= p; ++r) {
    std::vector<double> alphas(p + 1 - r);
    for (int jj = 0; jj <= p - r; ++jj) {
      const int j = k - p + r + jj;
      const double a = (u - U[j]) / (U[j + p + 1 - r] - U[j]);
      alphas[jj] = a;
      level[jj] = (1.0 - a) * level[jj] + a * level[jj + 1];
    }
    out.alphas.push_back(std::move(alphas));
    store(level, p + 1 - r);
  }
  out.point = out.levels.back().front();
  return out;
}

std::vector<double> uniform_params(const BsplineCurve& curve, int count) {
  const ParamInterval dom = domain(curve);
  if (count < 2)
    fail(ErrorCode::kTooFewPoints, "uniform_params: count=" + std::to_string(count) + " must be >= 2",
         {{"count", count}});
  std::vector<double> us(count);
  for (int k = 0; k < count; ++k) us[k] = dom.a + (dom.b - dom.a) * k / (count - 1);
  us.back() = dom.b;
  return us;
}

BsplineCurve reversed(const BsplineCurve& curve) {
  validate(curve);
  const ParamInterval dom = domain(curve.p, curve.U);
  const double a = dom.a;
  const double b = dom.b;
  const double sum = a + b;
  // U'[i] = a + b - U[m-i]. Rounding could move a knot across the domain's
  // ends, so the ends map exactly and the others are kept on their side;
  // both rules are monotone, so U' stays non-decreasing.
  auto mirror = [&](double x) {
    if (x == a) return b;
    if (x == b) return a;
    const double y = sum - x;
    if (x > a && x < b) return std::min(std::max(y, a), b);
    return x < a ? std::max(y, b) : std::min(y, a);
  };
  BsplineCurve r = curve;
  const std::size_t m = curve.U.size() - 1;
  for (std::size_t i = 0; i <= m; ++i) r.U[i] = mirror(curve.U[m - i]);
  std::reverse(r.P.begin(), r.P.end());
  std::reverse(r.w.begin(), r.w.end());
  validate(r);
  return r;
}

// ---- uniform cubic B-spline, matrix form -------------------------------------

std::array<double, 4> uniform_cubic_basis(double t) {
  const double s = 1.0 - t;
  return {s * s * s / 6.0, (3 * t * t * t - 6 * t * t + 4) / 6.0, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0,
          t * t * t / 6.0};
}

std::array<Vec3, 4> uniform_cubic_coefficients(Vec3 P0, Vec3 P1, Vec3 P2, Vec3 P3) {
  const Vec3 P[4] = {P0, P1, P2, P3};
  std::array<Vec3, 4> coef{};
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) coef[row] += kUniformCubicMatrix[row][col] * P[col];
  return coef;
}

Vec3 uniform_cubic_point(const std::vector<Vec3>& P, int i, double t) {
  if (i < 0 || i + 3 >= static_cast<int>(P.size()))
    fail(ErrorCode::kIndexOutOfRange,
         "uniform_cubic_point: segment i=" + std::to_string(i) + " needs P[i..i+3], but there are " +
             std::to_string(P.size()) + " points",
         {{"i", i}, {"points", P.size()}});
  require_finite(t, "uniform_cubic_point", "t");
  if (t < 0 || t > 1)
    fail(ErrorCode::kParameterOutsideDomain, "uniform_cubic_point: t=" + num(t) + " is outside [0, 1]", {{"t", t}});
  // Q(t) = [t^3 t^2 t 1] M [P_i .. P_{i+3}], by Horner on (a, b, c, d).
  const auto [a, b, c, d] = uniform_cubic_coefficients(P[i], P[i + 1], P[i + 2], P[i + 3]);
  return ((a * t + b) * t + c) * t + d;
}

}  // namespace gllab::spline
