// common/spline/bezier.cpp — Bézier curves (ch. 1 §1.6). See bezier.h for
// what each function returns and where its formula comes from.
#include "spline/bezier.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include "spline/errors.h"
#include "spline/interpolation.h"

namespace gllab::spline {

namespace {

/// C(n, k) as a double; 0 outside 0 <= k <= n. The multiplicative form
/// r = r (n - k + j) / j stays exact while the values fit in 53 bits.
double binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  k = std::min(k, n - k);
  double r = 1;
  for (int j = 1; j <= k; ++j) r = r * (n - k + j) / j;
  return r;
}

/// n! / (n - k)! = n (n - 1) ... (n - k + 1), the factor in every derivative formula.
double falling_factorial(int n, int k) {
  double r = 1;
  for (int j = 0; j < k; ++j) r *= n - j;
  return r;
}

std::string interval_text(double a, double b) { return "[a, b] = [" + num(a) + ", " + num(b) + "]"; }

void check_bezier_degree(long long n, const std::string& what) {
  if (n > kMaxBezierDegree)
    fail(ErrorCode::kDegreeTooHigh,
         what + ": degree n=" + std::to_string(n) + " is above the limit of " + std::to_string(kMaxBezierDegree) +
             " (kMaxBezierDegree)",
         {{"n", static_cast<double>(n)}});
}

void validate_as(const BezierCurve& curve, const std::string& what) {
  if (curve.P.empty()) fail(ErrorCode::kEmptyInput, what + ": no control points (P is empty)", {{"points", 0}});
  check_bezier_degree(static_cast<long long>(curve.P.size()) - 1, what);
  require_finite(curve.a, what, "a");
  require_finite(curve.b, what, "b");
  if (!(curve.a < curve.b))
    fail(ErrorCode::kEmptyDomain, what + ": interval " + interval_text(curve.a, curve.b) + " is empty (need a < b)",
         {{"a", curve.a}, {"b", curve.b}});
  for (std::size_t i = 0; i < curve.P.size(); ++i) require_finite(curve.P[i], what, at("P", i));
}

void validate_interval(double a, double b, const std::string& what) {
  require_finite(a, what, "a");
  require_finite(b, what, "b");
  if (!(a < b))
    fail(ErrorCode::kEmptyDomain, what + ": interval " + interval_text(a, b) + " is empty (need a < b)",
         {{"a", a}, {"b", b}});
}

/// t checked against [a, b] and snapped onto it when it misses only by
/// round-off (kBezierParameterSlack). The message says which end t passed.
double checked_parameter(double t, double a, double b, const std::string& what) {
  require_finite(t, what, "t");
  const double slack = kBezierParameterSlack * std::max({std::fabs(a), std::fabs(b), b - a});
  if (t < a - slack)
    fail(ErrorCode::kParameterOutsideDomain, what + ": t=" + num(t) + " is outside " + interval_text(a, b) +
         " (below a)", {{"t", t}, {"a", a}, {"b", b}});
  if (t > b + slack)
    fail(ErrorCode::kParameterOutsideDomain, what + ": t=" + num(t) + " is outside " + interval_text(a, b) +
         " (above b)", {{"t", t}, {"a", a}, {"b", b}});
  return std::clamp(t, a, b);
}

/// The local parameter s = (t - a) / (b - a) in [0, 1] (ch. 1 §1.6, "Generalization").
double local_parameter(double t, double a, double b) { return (t - a) / (b - a); }

void require_order(int k, const std::string& what, const char* name) {
  if (k < 0)
    fail(ErrorCode::kNegativeDerivativeOrder, what + ": derivative order " + name + "=" + std::to_string(k) +
         " is negative", {{name, k}});
}

/// Forward differences Delta^k of the points, applied in place k times:
/// afterwards pts[i] = Delta^k b_i, i = 0..size-1-k (ch. 1 §1.6).
void forward_differences(std::vector<Vec3>& pts, int k) {
  for (int r = 0; r < k; ++r) {
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) pts[i] = pts[i + 1] - pts[i];
    pts.pop_back();
  }
}

/// One de Casteljau step at s: level j -> level j + 1 (one point fewer).
std::vector<Vec3> de_casteljau_step(const std::vector<Vec3>& level, double s) {
  std::vector<Vec3> next(level.size() - 1);
  for (std::size_t i = 0; i + 1 < level.size(); ++i) next[i] = lerp(level[i], level[i + 1], s);
  return next;
}

DeCasteljau de_casteljau_as(const BezierCurve& curve, double t, const std::string& what) {
  validate_as(curve, what);
  const double tc = checked_parameter(t, curve.a, curve.b, what);
  DeCasteljau scheme;
  scheme.t = t;
  scheme.s = local_parameter(tc, curve.a, curve.b);
  scheme.levels.reserve(curve.P.size());
  scheme.levels.push_back(curve.P);  // b_i^0 = b_i
  while (scheme.levels.back().size() > 1) scheme.levels.push_back(de_casteljau_step(scheme.levels.back(), scheme.s));
  scheme.point = scheme.levels.back().front();  // X(t) = b_0^n
  return scheme;
}

/// The curve over [a, b] with points P, keeping the source's dimension.
BezierCurve with_points(const BezierCurve& source, std::vector<Vec3> P, double a, double b) {
  BezierCurve out;
  out.P = std::move(P);
  out.a = a;
  out.b = b;
  out.dimension = source.dimension;
  return out;
}

}  // namespace

void validate(const BezierCurve& curve) { validate_as(curve, "Bezier curve"); }

// ---- Bernstein basis ------------------------------------------------------------

double bernstein(int i, int n, double t, double a, double b) {
  const std::string what = "bernstein";
  if (n < 0) fail(ErrorCode::kDegreeTooLow, what + ": degree n=" + std::to_string(n) + " is negative", {{"n", n}});
  check_bezier_degree(n, what);
  validate_interval(a, b, what);
  const double s = local_parameter(checked_parameter(t, a, b, what), a, b);
  if (i < 0 || i > n) return 0;
  // A1.2 Bernstein (The NURBS Book, p. 20): de Casteljau on the unit vector e_i.
  std::vector<double> temp(static_cast<std::size_t>(n) + 1, 0.0);
  temp[static_cast<std::size_t>(n - i)] = 1;
  const double s1 = 1 - s;
  for (int k = 1; k <= n; ++k)
    for (int j = n; j >= k; --j)
      temp[static_cast<std::size_t>(j)] = s1 * temp[static_cast<std::size_t>(j)] + s * temp[static_cast<std::size_t>(j - 1)];
  return temp[static_cast<std::size_t>(n)];
}

std::vector<double> bernstein_all(int n, double t, double a, double b) {
  const std::string what = "bernstein_all";
  if (n < 0) fail(ErrorCode::kDegreeTooLow, what + ": degree n=" + std::to_string(n) + " is negative", {{"n", n}});
  check_bezier_degree(n, what);
  validate_interval(a, b, what);
  const double s = local_parameter(checked_parameter(t, a, b, what), a, b);
  // A1.3 AllBernstein (The NURBS Book, p. 21): degree j from degree j - 1,
  // B_k^j = (1 - s) B_k^{j-1} + s B_{k-1}^{j-1}.
  std::vector<double> B(static_cast<std::size_t>(n) + 1, 0.0);
  B[0] = 1;
  const double s1 = 1 - s;
  for (std::size_t j = 1; j <= static_cast<std::size_t>(n); ++j) {
    double saved = 0;
    for (std::size_t k = 0; k < j; ++k) {
      const double temp = B[k];
      B[k] = saved + s1 * temp;
      saved = s * temp;
    }
    B[j] = saved;
  }
  return B;
}

// ---- evaluation ------------------------------------------------------------------

DeCasteljau de_casteljau(const BezierCurve& curve, double t) { return de_casteljau_as(curve, t, "de_casteljau"); }

Vec3 bezier_point(const BezierCurve& curve, double t) {
  const std::string what = "bezier_point";
  validate_as(curve, what);
  const double s = local_parameter(checked_parameter(t, curve.a, curve.b, what), curve.a, curve.b);
  // de Casteljau in one array: after step j, b[i] holds b_i^j.
  std::vector<Vec3> b = curve.P;
  for (std::size_t j = 1; j < b.size(); ++j)
    for (std::size_t i = 0; i + j < b.size(); ++i) b[i] = lerp(b[i], b[i + 1], s);
  return b[0];
}

// ---- monomial form -------------------------------------------------------------

std::vector<std::vector<double>> bezier_matrix(int n) {
  if (n < 0)
    fail(ErrorCode::kDegreeTooLow, "bezier_matrix: degree n=" + std::to_string(n) + " is negative", {{"n", n}});
  check_bezier_degree(n, "bezier_matrix");
  const std::size_t size = static_cast<std::size_t>(n) + 1;
  std::vector<std::vector<double>> M(size, std::vector<double>(size, 0.0));
  for (int j = 0; j <= n; ++j) {  // power s^j sits in row n - j (the lecture's layout)
    for (int i = 0; i <= j; ++i) {
      const double sign = (j - i) % 2 == 0 ? 1.0 : -1.0;
      M[static_cast<std::size_t>(n - j)][static_cast<std::size_t>(i)] = sign * binomial(n, j) * binomial(j, i);
    }
  }
  return M;
}

std::vector<Vec3> monomial_coefficients(const BezierCurve& curve) {
  validate_as(curve, "monomial_coefficients");
  const int n = bezier_degree(curve);
  const std::size_t size = curve.P.size();
  // 1. Power form in s: c_j(s) = sum_{i <= j} (-1)^(j-i) C(n, j) C(j, i) b_i
  //    (the lecture's matrix M, read bottom row first).
  const std::vector<std::vector<double>> M = bezier_matrix(n);
  std::vector<Vec3> cs(size);
  for (std::size_t j = 0; j < size; ++j)
    for (std::size_t i = 0; i < size; ++i) cs[j] += M[size - 1 - j][i] * curve.P[i];
  // 2. Substitute s = alpha + beta t with alpha = -a / h, beta = 1 / h, by
  //    Horner's rule on polynomials: c <- c (alpha + beta t) + cs_j.
  const double h = curve.b - curve.a, alpha = -curve.a / h, beta = 1 / h;
  std::vector<Vec3> c{cs[size - 1]};
  for (std::size_t j = size - 1; j-- > 0;) {
    std::vector<Vec3> next(c.size() + 1);
    for (std::size_t k = 0; k < c.size(); ++k) {
      next[k] += alpha * c[k];
      next[k + 1] += beta * c[k];
    }
    next[0] += cs[j];
    c = std::move(next);
  }
  return c;
}

BezierCurve bezier_from_monomial(const std::vector<Vec3>& c, double a, double b) {
  const std::string what = "bezier_from_monomial";
  if (c.empty()) fail(ErrorCode::kEmptyInput, what + ": no coefficients (c is empty)", {{"coefficients", 0}});
  validate_interval(a, b, what);
  for (std::size_t j = 0; j < c.size(); ++j) require_finite(c[j], what, at("c", j));
  const std::size_t size = c.size();
  const int n = static_cast<int>(size) - 1;
  // 1. Substitute t = a + h s: coefficients in s, Horner's rule on polynomials.
  const double h = b - a;
  std::vector<Vec3> cs{c[size - 1]};
  for (std::size_t j = size - 1; j-- > 0;) {
    std::vector<Vec3> next(cs.size() + 1);
    for (std::size_t k = 0; k < cs.size(); ++k) {
      next[k] += a * cs[k];
      next[k + 1] += h * cs[k];
    }
    next[0] += c[j];
    cs = std::move(next);
  }
  // 2. s^j = sum_{i >= j} C(i, j) / C(n, j) B_i^n(s), so b_i = sum_{j <= i} C(i, j) / C(n, j) c_j(s).
  BezierCurve out;
  out.a = a;
  out.b = b;
  out.P.assign(size, Vec3{});
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= i; ++j)
      out.P[static_cast<std::size_t>(i)] += binomial(i, j) / binomial(n, j) * cs[static_cast<std::size_t>(j)];
  return out;
}

// ---- subdivision and degree elevation ------------------------------------------

std::vector<Vec3> convex_hull_xy(const std::vector<Vec3>& P) {
  if (P.empty()) fail(ErrorCode::kEmptyInput, "convex_hull_xy: no points (P is empty)", {{"points", 0}});
  for (std::size_t i = 0; i < P.size(); ++i) require_finite(P[i], "convex_hull_xy", at("P", i));
  std::vector<Vec3> q = P;
  std::sort(q.begin(), q.end(), [](Vec3 u, Vec3 v) { return u.x < v.x || (u.x == v.x && u.y < v.y); });
  q.erase(std::unique(q.begin(), q.end(), [](Vec3 u, Vec3 v) { return u.x == v.x && u.y == v.y; }), q.end());
  if (q.size() < 3) return q;
  // > 0 when o -> a -> b turns left (counter-clockwise).
  const auto turn = [](Vec3 o, Vec3 a, Vec3 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<Vec3> hull;
  // Lower chain left to right, then upper chain right to left; each pops the
  // corners that would make a right turn or a straight line.
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (std::size_t k = 0; k < q.size(); ++k) {
      const Vec3 p = pass == 0 ? q[k] : q[q.size() - 1 - k];
      while (hull.size() >= start + 2 && turn(hull[hull.size() - 2], hull.back(), p) <= 0) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // the chain's last point starts the other chain
  }
  return hull;
}

BezierSplit subdivide(const BezierCurve& curve, double t) {
  const std::string what = "subdivide";
  const DeCasteljau scheme = de_casteljau_as(curve, t, what);
  const double tc = checked_parameter(t, curve.a, curve.b, what);
  if (tc == curve.a || tc == curve.b)
    fail(ErrorCode::kParameterOutsideDomain,
         what + ": t=" + num(t) + " is an end of " + interval_text(curve.a, curve.b) +
             " (one piece would be empty; need a < t < b)",
         {{"t", t}, {"a", curve.a}, {"b", curve.b}});
  const std::size_t n = curve.P.size() - 1;
  std::vector<Vec3> left(n + 1), right(n + 1);
  for (std::size_t j = 0; j <= n; ++j) {
    left[j] = scheme.levels[j][0];       // b_0^j: the upper edge of the scheme
    right[j] = scheme.levels[n - j][j];  // b_j^(n-j): the lower edge
  }
  return {with_points(curve, std::move(left), curve.a, tc), with_points(curve, std::move(right), tc, curve.b)};
}

BezierCurve degree_elevate(const BezierCurve& curve, int times) {
  const std::string what = "degree_elevate";
  validate_as(curve, what);
  if (times < 0)
    fail(ErrorCode::kOutOfRange, what + ": times=" + std::to_string(times) + " is negative", {{"times", times}});
  if (times == 0) return curve;
  check_bezier_degree(static_cast<long long>(bezier_degree(curve)) + times, what + " (the result)");
  const int n = bezier_degree(curve);
  const auto& b = curve.P;
  std::vector<Vec3> e(curve.P.size() + static_cast<std::size_t>(times));
  if (times == 1) {
    // ch. 1 §1.6 property 9: b'_i = i/(n+1) b_{i-1} + (1 - i/(n+1)) b_i.
    e.front() = b.front();
    e.back() = b.back();
    for (int i = 1; i <= n; ++i) {
      const double alpha = static_cast<double>(i) / (n + 1);
      e[static_cast<std::size_t>(i)] = alpha * b[static_cast<std::size_t>(i - 1)] + (1 - alpha) * b[static_cast<std::size_t>(i)];
    }
  } else {
    // The NURBS Book eq. (5.36): b'_i = sum_j C(n, j) C(times, i - j) / C(n + times, i) b_j,
    // j from max(0, i - times) to min(n, i).
    for (int i = 0; i <= n + times; ++i) {
      Vec3 sum;
      for (int j = std::max(0, i - times); j <= std::min(n, i); ++j)
        sum += binomial(n, j) * binomial(times, i - j) / binomial(n + times, i) * b[static_cast<std::size_t>(j)];
      e[static_cast<std::size_t>(i)] = sum;
    }
  }
  return with_points(curve, std::move(e), curve.a, curve.b);
}

// ---- derivatives ---------------------------------------------------------------

BezierCurve bezier_derivative(const BezierCurve& curve, int k) {
  const std::string what = "bezier_derivative";
  validate_as(curve, what);
  require_order(k, what, "k");
  const int n = bezier_degree(curve);
  if (k == 0) return curve;
  if (k > n) return with_points(curve, {Vec3{}}, curve.a, curve.b);  // differentiated away
  // ch. 1 §1.6 "Derivatives": n!/(n-k)! Delta^k b_i, scaled by 1/(b-a)^k.
  std::vector<Vec3> d = curve.P;
  forward_differences(d, k);
  const double factor = falling_factorial(n, k) / std::pow(curve.b - curve.a, k);
  for (Vec3& p : d) p *= factor;
  return with_points(curve, std::move(d), curve.a, curve.b);
}

Vec3 bezier_derivative_at(const BezierCurve& curve, double t, int k) {
  const std::string what = "bezier_derivative_at";
  validate_as(curve, what);
  require_order(k, what, "k");
  checked_parameter(t, curve.a, curve.b, what);
  return bezier_point(bezier_derivative(curve, k), t);
}

std::vector<Vec3> bezier_derivatives(const BezierCurve& curve, double t, int d) {
  const std::string what = "bezier_derivatives";
  require_order(d, what, "d");
  const DeCasteljau scheme = de_casteljau_as(curve, t, what);
  const int n = bezier_degree(curve);
  const double h = curve.b - curve.a;
  std::vector<Vec3> ders(static_cast<std::size_t>(d) + 1);  // orders above n stay zero
  for (int k = 0; k <= std::min(d, n); ++k) {
    // Level n - k of the scheme has the k + 1 points b_0^(n-k) .. b_k^(n-k).
    std::vector<Vec3> pts = scheme.levels[static_cast<std::size_t>(n - k)];
    forward_differences(pts, k);
    ders[static_cast<std::size_t>(k)] = falling_factorial(n, k) / std::pow(h, k) * pts.front();
  }
  return ders;
}

Vec3 bezier_start_derivative(const BezierCurve& curve, int k) {
  const std::string what = "bezier_start_derivative";
  validate_as(curve, what);
  require_order(k, what, "k");
  const int n = bezier_degree(curve);
  if (k > n) return {};
  // X^(k)(a) = n!/(n-k)! / h^k sum_j (-1)^(k-j) C(k, j) b_j   (ch. 1 §1.6)
  Vec3 sum;
  for (int j = 0; j <= k; ++j)
    sum += ((k - j) % 2 == 0 ? 1.0 : -1.0) * binomial(k, j) * curve.P[static_cast<std::size_t>(j)];
  return falling_factorial(n, k) / std::pow(curve.b - curve.a, k) * sum;
}

Vec3 bezier_end_derivative(const BezierCurve& curve, int k) {
  const std::string what = "bezier_end_derivative";
  validate_as(curve, what);
  require_order(k, what, "k");
  const int n = bezier_degree(curve);
  if (k > n) return {};
  // X^(k)(b) = n!/(n-k)! / h^k sum_j (-1)^j C(k, j) b_{n-j}   (ch. 1 §1.6)
  Vec3 sum;
  for (int j = 0; j <= k; ++j)
    sum += (j % 2 == 0 ? 1.0 : -1.0) * binomial(k, j) * curve.P[static_cast<std::size_t>(n - j)];
  return falling_factorial(n, k) / std::pow(curve.b - curve.a, k) * sum;
}

// ---- joining segments ----------------------------------------------------------

BezierContinuation continuation_points(const BezierCurve& a, int k, double next_length) {
  const std::string what = "continuation_points";
  validate_as(a, what);
  const int n = bezier_degree(a);
  if (k < 0 || k > n)
    fail(ErrorCode::kOutOfRange,
         what + ": continuity k=" + std::to_string(k) + " must lie in [0, " + std::to_string(n) + "] (the degree)",
         {{"k", k}, {"n", n}});
  require_finite(next_length, what, "next_length");
  if (!(next_length > 0))
    fail(ErrorCode::kOutOfRange, what + ": next_length=" + num(next_length) + " must be > 0",
         {{"next_length", next_length}});
  BezierContinuation out;
  out.tau = 1 + next_length / (a.b - a.a);
  // de Casteljau at tau on the last k + 1 points only: b_{n-k}^r .. b_{n-r}^r
  // need nothing to their left.
  std::vector<Vec3> level(a.P.end() - (k + 1), a.P.end());
  for (int r = 0; r <= k; ++r) {
    out.levels.push_back(level);
    out.points.push_back(level.back());
    if (r < k) level = de_casteljau_step(level, out.tau);
  }
  return out;
}

// ---- integral --------------------------------------------------------------------

Vec3 bezier_integral(const BezierCurve& curve) {
  validate_as(curve, "bezier_integral");
  // int_a^b X = (b - a) / (n + 1) (b_0 + ... + b_n)   (ch. 1 §1.6)
  Vec3 sum;
  for (const Vec3& p : curve.P) sum += p;
  return (curve.b - curve.a) / static_cast<double>(curve.P.size()) * sum;
}

BezierCurve bezier_antiderivative(const BezierCurve& curve, Vec3 start) {
  const std::string what = "bezier_antiderivative";
  validate_as(curve, what);
  require_finite(start, what, "start");
  const double step = (curve.b - curve.a) / static_cast<double>(curve.P.size());  // (b - a) / (n + 1)
  std::vector<Vec3> Y{start};
  for (const Vec3& p : curve.P) Y.push_back(Y.back() + step * p);
  return with_points(curve, std::move(Y), curve.a, curve.b);
}

// ---- interpolation -----------------------------------------------------------------

BezierCurve bezier_interpolate(const std::vector<Vec3>& Q, const std::vector<double>& t, double a, double b) {
  const std::string what = "bezier_interpolate";
  if (Q.empty()) fail(ErrorCode::kEmptyInput, what + ": no points to interpolate (Q is empty)", {{"points", 0}});
  if (t.size() != Q.size())
    fail(ErrorCode::kSizeMismatch,
         what + ": " + std::to_string(Q.size()) + " points but " + std::to_string(t.size()) +
             " parameters (need one t_j per Q_j)",
         {{"points", Q.size()}, {"parameters", t.size()}});
  check_bezier_degree(static_cast<long long>(Q.size()) - 1, what);
  validate_interval(a, b, what);
  for (std::size_t j = 0; j < Q.size(); ++j) require_finite(Q[j], what, at("Q", j));
  std::vector<double> s(t.size());
  for (std::size_t j = 0; j < t.size(); ++j) {
    require_finite(t[j], what, at("t", j));
    if (t[j] < a || t[j] > b)
      fail(ErrorCode::kParameterOutsideDomain,
           what + ": " + at("t", j) + "=" + num(t[j]) + " is outside " + interval_text(a, b) +
               (t[j] < a ? " (below a)" : " (above b)"),
           {{"j", j}, {at("t", j), t[j]}, {"a", a}, {"b", b}});
    for (std::size_t k = 0; k < j; ++k)
      if (t[k] == t[j])
        fail(ErrorCode::kNodesCoincide,
             what + ": " + at("t", k) + "=" + num(t[k]) + " and " + at("t", j) + "=" + num(t[j]) +
                 " coincide (parameters must be pairwise distinct)",
             {{"k", k}, {"j", j}, {at("t", k), t[k]}});
    s[j] = local_parameter(t[j], a, b);
  }
  // ch. 1 §1.6: row j of the system is sum_i b_i B_i^r(s_j) = Q_j.
  const int r = static_cast<int>(Q.size()) - 1;
  std::vector<std::vector<double>> A;
  A.reserve(Q.size());
  for (double sj : s) A.push_back(bernstein_all(r, sj));
  BezierCurve out;
  out.P = gauss_solve(std::move(A), Q);
  out.a = a;
  out.b = b;
  return out;
}

BezierCurve bezier_interpolate(const std::vector<Vec3>& Q, const std::vector<double>& t) {
  const std::string what = "bezier_interpolate";
  if (Q.size() < 2 || t.size() < 2)
    fail(ErrorCode::kTooFewPoints,
         what + ": " + std::to_string(Q.size()) + " point(s) and " + std::to_string(t.size()) +
             " parameter(s) give no interval [min t, max t] (pass a and b explicitly)",
         {{"points", Q.size()}, {"parameters", t.size()}});
  for (std::size_t j = 0; j < t.size(); ++j) require_finite(t[j], what, at("t", j));
  const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
  return bezier_interpolate(Q, t, *lo, *hi);
}

}  // namespace gllab::spline
