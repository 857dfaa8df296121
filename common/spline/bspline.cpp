// common/spline/bspline.cpp — B-spline curves (see bspline.h for the sources).
#include "spline/bspline.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "spline/errors.h"

namespace gllab::spline {

namespace {

// ---- small helpers ----------------------------------------------------------

int size_of(const std::vector<double>& U) { return static_cast<int>(U.size()); }

/// The cheap checks every raw (p, U) routine makes.
void check_degree_and_knots(const char* fn, int n, int p, const std::vector<double>& U) {
  if (p < 0) fail(std::string(fn) + ": degree p=" + std::to_string(p) + " must be >= 0");
  if (p > kMaxDegree)
    fail(std::string(fn) + ": degree p=" + std::to_string(p) + " exceeds kMaxDegree=" + std::to_string(kMaxDegree));
  if (n < p)
    fail(std::string(fn) + ": n=" + std::to_string(n) + " < p=" + std::to_string(p) +
         " (needs at least p + 1 control points)");
  if (size_of(U) != n + p + 2)
    fail(std::string(fn) + ": knot vector has " + std::to_string(U.size()) + " knots, needs n + p + 2 = " +
         std::to_string(n + p + 2) + " (n=" + std::to_string(n) + ", p=" + std::to_string(p) + ")");
}

/// U[i] <= u < U[i+1] by binary search, for U[p] <= u < U[n+1] (A2.1's loop).
int span_right(int n, int p, double u, const std::vector<double>& U) {
  int low = p;
  int high = n + 1;
  int mid = (low + high) / 2;
  while (u < U[mid] || u >= U[mid + 1]) {
    if (u < U[mid]) {
      high = mid;
    } else {
      low = mid;
    }
    mid = (low + high) / 2;
  }
  return mid;
}

/// The last non-empty span at or below n: where u == U[n+1] is evaluated.
int last_span(int n, int p, const std::vector<double>& U) {
  int i = n;
  while (i > p && U[i] == U[i + 1]) --i;
  return i;
}

/// The degree-0 function that is 1 at u: find_span's rule extended to the
/// whole knot range [U[0], U[m]] (for plotting), -1 outside it.
int active_interval(double u, int p, const std::vector<double>& U) {
  const int m = size_of(U) - 1;
  const int n = m - p - 1;
  if (!(u >= U[0] && u <= U[m])) return -1;
  auto last_nonempty_below = [&](int top) {
    for (int j = top; j >= 0; --j)
      if (U[j] < U[j + 1]) return j;
    return -1;
  };
  if (n >= 0 && u == U[n + 1]) {
    const int j = last_nonempty_below(n);
    if (j >= 0) return j;
  }
  if (u == U[m]) return last_nonempty_below(m - 1);
  return static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
}

/// A2.2 on raw arrays; N gets p + 1 values. left/right hold p + 1 entries.
inline void basis_funs_raw(int i, double u, int p, const double* U, double* N) {
  double left[kMaxDegree + 1];
  double right[kMaxDegree + 1];
  N[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

std::vector<Vec4> weighted_points(const BsplineCurve& c) {
  std::vector<Vec4> Pw(c.P.size());
  for (std::size_t i = 0; i < c.P.size(); ++i) Pw[i] = homogeneous(c.P[i], c.rational() ? c.w[i] : 1.0);
  return Pw;
}

double binomial(int n, int k) {
  double b = 1.0;
  for (int j = 1; j <= k; ++j) b = b * (n - k + j) / j;
  return b;
}

bool finite(Vec3 q) { return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z); }

/// The span used to evaluate at u from the given side; u must be in the domain.
int span_at(const BsplineCurve& c, double u, Side side) {
  return side == Side::Right ? find_span(c.n(), c.p, u, c.U) : find_span_left(c.n(), c.p, u, c.U);
}

void check_param(double u, ParamInterval dom) {
  require_finite(u, "parameter", "u");
  require_in_domain(u, dom);
}

// ---- control points as a template: Vec3 for polynomial, Vec4 (Pw) for NURBS ----

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

/// The index k of the last knot <= u (so U[k] <= u < U[k+1] when u < U[m]).
int last_knot_at_or_below(const std::vector<double>& U, double u) {
  return static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
}

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

/// A5.9 DegreeElevateCurve (The NURBS Book, p. 206) for a clamped curve whose
/// interior knots have multiplicity <= p.
template <class Pt>
Ctl<Pt> degree_elevate_impl(const Ctl<Pt>& c, int t) {
  const int p = c.p;
  const int n = static_cast<int>(c.P.size()) - 1;
  const int m = n + p + 1;
  const int ph = p + t;
  const int ph2 = ph / 2;
  const std::vector<double>& U = c.U;
  const std::vector<Pt>& Pw = c.P;
  // Bézier degree elevation coefficients.
  std::vector<std::vector<double>> bezalfs(ph + 1, std::vector<double>(p + 1, 0.0));
  bezalfs[0][0] = bezalfs[ph][p] = 1.0;
  for (int i = 1; i <= ph2; ++i) {
    const double inv = 1.0 / binomial(ph, i);
    const int mpi = std::min(p, i);
    for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = inv * binomial(p, j) * binomial(t, i - j);
  }
  for (int i = ph2 + 1; i <= ph - 1; ++i) {
    const int mpi = std::min(p, i);
    for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = bezalfs[ph - i][p - j];
  }
  // Upper bounds on the result's size: every distinct interior knot gains t.
  int distinct = 0;
  for (int i = 1; i <= m; ++i)
    if (U[i] != U[i - 1]) ++distinct;
  std::vector<double> Uh(m + 1 + (distinct + 2) * t + 1);
  std::vector<Pt> Qw(n + 1 + (distinct + 2) * t + 1);
  std::vector<Pt> bpts(p + 1), ebpts(ph + 1), Nextbpts(std::max(p - 1, 1));
  std::vector<double> alfs(std::max(p - 1, 1));

  int mh = ph;
  int kind = ph + 1;
  int r = -1;
  int a = p;
  int b = p + 1;
  int cind = 1;
  double ua = U[0];
  Qw[0] = Pw[0];
  for (int i = 0; i <= ph; ++i) Uh[i] = ua;
  for (int i = 0; i <= p; ++i) bpts[i] = Pw[i];  // the first Bézier segment
  while (b < m) {                                 // big loop through the knot vector
    int i = b;
    while (b < m && U[b] == U[b + 1]) ++b;
    const int mul = b - i + 1;
    mh = mh + mul + t;
    const double ub = U[b];
    const int oldr = r;
    r = p - mul;
    // Insert the knot U[b] r times.
    const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
    const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
    if (r > 0) {
      const double numer = ub - ua;
      for (int k = p; k > mul; --k) alfs[k - mul - 1] = numer / (U[a + k] - ua);
      for (int j = 1; j <= r; ++j) {
        const int save = r - j;
        const int s = mul + j;
        for (int k = p; k >= s; --k) bpts[k] = alfs[k - s] * bpts[k] + (1.0 - alfs[k - s]) * bpts[k - 1];
        Nextbpts[save] = bpts[p];
      }
    }
    // Degree-elevate the Bézier segment (only points lbz..ph are used below).
    for (int e = lbz; e <= ph; ++e) {
      ebpts[e] = Pt{};
      const int mpi = std::min(p, e);
      for (int j = std::max(0, e - t); j <= mpi; ++j) ebpts[e] = ebpts[e] + bezalfs[e][j] * bpts[j];
    }
    if (oldr > 1) {  // remove the knot u = U[a] oldr - 1 times
      int first = kind - 2;
      int last = kind;
      const double den = ub - ua;
      const double bet = (ub - Uh[kind - 1]) / den;
      for (int tr = 1; tr < oldr; ++tr) {
        int ii = first;
        int j = last;
        int kj = j - kind + 1;
        while (j - ii > tr) {  // new control points for one removal step
          if (ii < cind) {
            const double alf = (ub - Uh[ii]) / (ua - Uh[ii]);
            Qw[ii] = alf * Qw[ii] + (1.0 - alf) * Qw[ii - 1];
          }
          if (j >= lbz) {
            if (j - tr <= kind - ph + oldr) {
              const double gam = (ub - Uh[j - tr]) / den;
              ebpts[kj] = gam * ebpts[kj] + (1.0 - gam) * ebpts[kj + 1];
            } else {
              ebpts[kj] = bet * ebpts[kj] + (1.0 - bet) * ebpts[kj + 1];
            }
          }
          ++ii;
          --j;
          --kj;
        }
        --first;
        ++last;
      }
    }
    if (a != p)  // load the knot ua
      for (int e = 0; e < ph - oldr; ++e) Uh[kind++] = ua;
    for (int j = lbz; j <= rbz; ++j) Qw[cind++] = ebpts[j];  // load control points
    if (b < m) {  // set up for the next pass
      for (int j = 0; j < r; ++j) bpts[j] = Nextbpts[j];
      for (int j = r; j <= p; ++j) bpts[j] = Pw[b - p + j];
      a = b;
      ++b;
      ua = ub;
    } else {
      for (int e = 0; e <= ph; ++e) Uh[kind + e] = ub;  // the end knot
    }
  }
  const int nh = mh - ph - 1;
  Ctl<Pt> q;
  q.p = ph;
  q.U.assign(Uh.begin(), Uh.begin() + (nh + ph + 2));
  q.P.assign(Qw.begin(), Qw.begin() + (nh + 1));
  return q;
}

/// Joins two clamped curves of equal degree where the first ends and the
/// second starts (the same parameter): the knot there gets multiplicity p + 1.
BsplineCurve join_clamped(const BsplineCurve& left, const BsplineCurve& right) {
  BsplineCurve out = left;
  const int p = left.p;
  out.U.resize(left.U.size() - (p + 1));
  for (int i = 0; i <= p; ++i) out.U.push_back(right.U.front());
  out.U.insert(out.U.end(), right.U.begin() + (p + 1), right.U.end());
  out.P.insert(out.P.end(), right.P.begin(), right.P.end());
  out.w.insert(out.w.end(), right.w.begin(), right.w.end());
  return out;
}

bool is_clamped(const BsplineCurve& c) {
  const int p = c.p;
  const int m = size_of(c.U) - 1;
  return knot_multiplicity(c.U, c.U[p]) >= p + 1 && c.U[0] == c.U[p] && c.U[m - p] == c.U[m] &&
         knot_multiplicity(c.U, c.U[m]) >= p + 1;
}

}  // namespace

// ---- checks -----------------------------------------------------------------

void validate_knots(int p, int num_points, const std::vector<double>& U, const char* what, const char* symbol) {
  const std::string S = symbol;  // "U" or "V": the array the messages name
  const std::string w = what;  // short: no allocation (SSO)
  if (num_points < 1) fail(w + ": no control points (empty input)");
  if (p < 1) fail(w + ": degree p=" + std::to_string(p) + " must be >= 1");
  if (p >= num_points)
    fail(w + ": degree p=" + std::to_string(p) + " needs at least p + 1 = " + std::to_string(p + 1) +
         " control points, has " + std::to_string(num_points));
  if (p > kMaxDegree)
    fail(w + ": degree p=" + std::to_string(p) + " exceeds kMaxDegree=" + std::to_string(kMaxDegree));
  const int needed = num_points + p + 1;
  if (size_of(U) != needed)
    fail(w + " has " + std::to_string(U.size()) + " knots, needs n + p + 2 = " + std::to_string(needed) + " (" +
         std::to_string(num_points) + " points, degree " + std::to_string(p) + ")");
  // (Messages are built only on failure: validate runs on every evaluation.)
  for (std::size_t i = 0; i < U.size(); ++i)
    if (!std::isfinite(U[i])) require_finite(U[i], w, at(symbol, i));
  for (std::size_t i = 1; i < U.size(); ++i)
    if (U[i] < U[i - 1])
      fail(w + ": " + at(symbol, i) + "=" + num(U[i]) + " < " + at(symbol, i - 1) + "=" + num(U[i - 1]) +
           " (must be non-decreasing)");
  for (std::size_t i = 0; i < U.size();) {
    std::size_t j = i;
    while (j < U.size() && U[j] == U[i]) ++j;
    if (static_cast<int>(j - i) > p + 1)
      fail(w + ": knot " + num(U[i]) + " has multiplicity " + std::to_string(j - i) + " (" + S + "[" + std::to_string(i) +
           ".." + std::to_string(j - 1) + "]), more than p + 1 = " + std::to_string(p + 1));
    i = j;
  }
  const int n = num_points - 1;
  if (!(U[p] < U[n + 1]))
    fail(w + ": the domain [" + S + "[" + std::to_string(p) + "], " + S + "[" + std::to_string(n + 1) + "]] = [" + num(U[p]) + ", " +
         num(U[n + 1]) + "] is empty");
}

void validate(const BsplineCurve& curve) {
  if (curve.P.empty()) fail("curve: no control points (empty input)");
  if (curve.dimension != 2 && curve.dimension != 3)
    fail("curve: dimension=" + std::to_string(curve.dimension) + " must be 2 or 3");
  validate_knots(curve.p, static_cast<int>(curve.P.size()), curve.U, "knot vector");
  for (std::size_t i = 0; i < curve.P.size(); ++i) {
    if (!finite(curve.P[i])) require_finite(curve.P[i], "control points", at("P", i));
    if (curve.dimension == 2 && curve.P[i].z != 0)
      fail("control points: " + at("P", i) + "=" + num(curve.P[i]) + " has z != 0 in a 2D curve");
  }
  if (curve.rational()) {
    if (curve.w.size() != curve.P.size())
      fail("weights: " + std::to_string(curve.w.size()) + " weights for " + std::to_string(curve.P.size()) +
           " control points (need one per point, or none)");
    for (std::size_t i = 0; i < curve.w.size(); ++i) {
      if (!std::isfinite(curve.w[i])) require_finite(curve.w[i], "weights", at("w", i));
      if (!(curve.w[i] > 0)) fail("weights: " + at("w", i) + "=" + num(curve.w[i]) + " must be > 0");
    }
  }
}

ParamInterval domain(int p, const std::vector<double>& U) { return {U[p], U[U.size() - p - 1]}; }

ParamInterval domain(const BsplineCurve& curve) {
  validate(curve);
  return domain(curve.p, curve.U);
}

void require_in_domain(double u, ParamInterval dom) {
  if (!(u >= dom.a && u <= dom.b))
    fail("u=" + num(u) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) + "]");
}

int knot_multiplicity(const std::vector<double>& U, double u) {
  return static_cast<int>(std::count(U.begin(), U.end(), u));
}

// ---- knot vectors -----------------------------------------------------------

std::vector<double> clamped_uniform_knots(int n, int p) {
  if (p < 1 || p > n)
    fail("clamped_uniform_knots: needs 1 <= p <= n, got p=" + std::to_string(p) + ", n=" + std::to_string(n));
  std::vector<double> U(n + p + 2);
  const int segments = n - p + 1;
  for (int i = 0; i <= p; ++i) {
    U[i] = 0.0;
    U[n + 1 + i] = 1.0;
  }
  for (int j = 1; j <= n - p; ++j) U[p + j] = static_cast<double>(j) / segments;
  return U;
}

std::vector<double> uniform_knots(int n, int p) {
  if (p < 1 || p > n)
    fail("uniform_knots: needs 1 <= p <= n, got p=" + std::to_string(p) + ", n=" + std::to_string(n));
  std::vector<double> U(n + p + 2);
  for (int i = 0; i < n + p + 2; ++i) U[i] = i;
  return U;
}

BsplineCurve periodic_curve(const std::vector<Vec3>& points, int p, int dimension) {
  if (points.size() < 2)
    fail("periodic_curve: needs at least 2 points, got " + std::to_string(points.size()));
  if (p < 1) fail("periodic_curve: degree p=" + std::to_string(p) + " must be >= 1");
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
  if (points.empty()) fail("clamped_curve: no control points (empty input)");
  if (p < 1 || p >= static_cast<int>(points.size()))
    fail("clamped_curve: degree p=" + std::to_string(p) + " needs 1 <= p < number of points (" +
         std::to_string(points.size()) + ")");
  c.U = clamped_uniform_knots(c.n(), p);
  validate(c);
  return c;
}

// ---- basis functions --------------------------------------------------------

int find_span(int n, int p, double u, const std::vector<double>& U) {
  check_degree_and_knots("find_span", n, p, U);
  require_finite(u, "find_span", "u");
  if (!(U[p] < U[n + 1]))
    fail("find_span: the domain [U[p], U[n+1]] = [" + num(U[p]) + ", " + num(U[n + 1]) + "] is empty");
  require_in_domain(u, domain(p, U));
  if (u == U[n + 1]) return last_span(n, p, U);  // the special case of A2.1
  return span_right(n, p, u, U);
}

int find_span_left(int n, int p, double u, const std::vector<double>& U) {
  check_degree_and_knots("find_span_left", n, p, U);
  require_finite(u, "find_span_left", "u");
  require_in_domain(u, domain(p, U));
  if (u == U[p]) return find_span(n, p, u, U);
  // First j in [p+1, n+1] with U[j] >= u; then U[j-1] < u <= U[j].
  const auto first = U.begin() + (p + 1);
  const auto last = U.begin() + (n + 2);
  const int j = static_cast<int>(std::lower_bound(first, last, u) - U.begin());
  return j - 1;
}

void basis_funs(int i, double u, int p, const std::vector<double>& U, double* N) {
  const int m = size_of(U) - 1;
  if (p < 0 || p > kMaxDegree) fail("basis_funs: degree p=" + std::to_string(p) + " out of [0, kMaxDegree]");
  if (i < p || i + p + 1 > m)
    fail("basis_funs: span i=" + std::to_string(i) + " out of range [p, m - p - 1] = [" + std::to_string(p) + ", " +
         std::to_string(m - p - 1) + "]");
  basis_funs_raw(i, u, p, U.data(), N);
}

std::vector<double> basis_funs(int i, double u, int p, const std::vector<double>& U) {
  std::vector<double> N(std::max(p, 0) + 1);
  basis_funs(i, u, p, U, N.data());
  return N;
}

std::vector<std::vector<double>> ders_basis_funs(int i, double u, int p, int d, const std::vector<double>& U) {
  const int m = size_of(U) - 1;
  if (p < 0) fail("ders_basis_funs: degree p=" + std::to_string(p) + " must be >= 0");
  if (d < 0) fail("ders_basis_funs: derivative order d=" + std::to_string(d) + " must be >= 0");
  if (i < p || i + p + 1 > m)
    fail("ders_basis_funs: span i=" + std::to_string(i) + " out of range [p, m - p - 1] = [" + std::to_string(p) +
         ", " + std::to_string(m - p - 1) + "]");
  std::vector<std::vector<double>> ders(d + 1, std::vector<double>(p + 1, 0.0));
  const int nd = std::min(d, p);  // derivatives above p vanish
  // ndu: basis functions (upper triangle) and knot differences (lower).
  std::vector<std::vector<double>> ndu(p + 1, std::vector<double>(p + 1, 0.0));
  std::vector<double> left(p + 1), right(p + 1);
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;  // upper triangle
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  // The derivatives (The NURBS Book §2.3), two rows of coefficients a alternating.
  std::vector<std::vector<double>> a(2, std::vector<double>(p + 1, 0.0));
  for (int r = 0; r <= p; ++r) {
    int s1 = 0;
    int s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= nd; ++k) {
      double dk = 0.0;
      const int rk = r - k;
      const int pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        dk = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        dk += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        dk += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = dk;
      std::swap(s1, s2);
    }
  }
  // Multiply by p! / (p - k)!.
  double factor = p;
  for (int k = 1; k <= nd; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] *= factor;
    factor *= (p - k);
  }
  return ders;
}

double one_basis_fun(int i, double u, int p, const std::vector<double>& U) {
  const int m = size_of(U) - 1;
  if (p < 0) fail("one_basis_fun: degree p=" + std::to_string(p) + " must be >= 0");
  if (i < 0 || i > m - p - 1)
    fail("one_basis_fun: index i=" + std::to_string(i) + " out of range [0, m - p - 1] = [0, " +
         std::to_string(m - p - 1) + "]");
  require_finite(u, "one_basis_fun", "u");
  // The book special-cases u == U[0] and u == U[m]; the active interval rule
  // (find_span's, extended to [U[0], U[m]]) covers both.
  const int s = active_interval(u, p, U);
  if (s < i || s > i + p) return 0.0;  // local support: N_{i,p} lives on [U[i], U[i+p+1])
  std::vector<double> N(p + 1);
  for (int j = 0; j <= p; ++j) N[j] = (i + j == s) ? 1.0 : 0.0;  // degree 0
  for (int k = 1; k <= p; ++k) {                                  // the triangular table
    double saved = (N[0] == 0.0) ? 0.0 : ((u - U[i]) * N[0]) / (U[i + k] - U[i]);
    for (int j = 0; j < p - k + 1; ++j) {
      const double Uleft = U[i + j + 1];
      const double Uright = U[i + j + k + 1];
      if (N[j + 1] == 0.0) {
        N[j] = saved;
        saved = 0.0;
      } else {
        const double temp = N[j + 1] / (Uright - Uleft);
        N[j] = saved + (Uright - u) * temp;
        saved = (u - Uleft) * temp;
      }
    }
  }
  return N[0];
}

namespace {
double cox_de_boor_rec(int i, int k, double u, const std::vector<double>& U, int s) {
  if (k == 0) return i == s ? 1.0 : 0.0;
  // 0/0 := 0 (notes "Higher Order Surfaces"): a zero-length support contributes nothing.
  const double d1 = U[i + k] - U[i];
  const double d2 = U[i + k + 1] - U[i + 1];
  const double a = d1 == 0.0 ? 0.0 : (u - U[i]) / d1 * cox_de_boor_rec(i, k - 1, u, U, s);
  const double b = d2 == 0.0 ? 0.0 : (U[i + k + 1] - u) / d2 * cox_de_boor_rec(i + 1, k - 1, u, U, s);
  return a + b;
}
}  // namespace

double cox_de_boor(int i, double u, int p, const std::vector<double>& U) {
  const int m = size_of(U) - 1;
  if (p < 0) fail("cox_de_boor: degree p=" + std::to_string(p) + " must be >= 0");
  if (i < 0 || i > m - p - 1)
    fail("cox_de_boor: index i=" + std::to_string(i) + " out of range [0, m - p - 1] = [0, " +
         std::to_string(m - p - 1) + "]");
  require_finite(u, "cox_de_boor", "u");
  return cox_de_boor_rec(i, p, u, U, active_interval(u, p, U));
}

std::vector<double> all_basis_funs(double u, int p, const std::vector<double>& U) {
  const int m = size_of(U) - 1;
  if (p < 0 || m - p - 1 < 0)
    fail("all_basis_funs: degree p=" + std::to_string(p) + " does not fit " + std::to_string(U.size()) + " knots");
  require_finite(u, "all_basis_funs", "u");
  // The Cox–de Boor table, one degree at a time (ch. 1 §1.6).
  std::vector<double> N(m, 0.0);
  const int s = active_interval(u, p, U);
  if (s >= 0) N[s] = 1.0;
  for (int k = 1; k <= p; ++k) {
    for (int j = 0; j + k < m; ++j) {
      const double d1 = U[j + k] - U[j];
      const double d2 = U[j + k + 1] - U[j + 1];
      const double a = d1 == 0.0 ? 0.0 : (u - U[j]) / d1 * N[j];
      const double b = d2 == 0.0 ? 0.0 : (U[j + k + 1] - u) / d2 * N[j + 1];
      N[j] = a + b;
    }
  }
  N.resize(m - p);
  return N;
}

// ---- evaluation ----------------------------------------------------------------

Vec4 homogeneous_curve_point(const BsplineCurve& curve, double u, Side side) {
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  const int p = curve.p;
  const int span = span_at(curve, u, side);
  double N[kMaxDegree + 1];
  basis_funs_raw(span, u, p, curve.U.data(), N);
  Vec4 Cw;
  for (int j = 0; j <= p; ++j) {
    const int i = span - p + j;
    Cw += N[j] * homogeneous(curve.P[i], curve.rational() ? curve.w[i] : 1.0);
  }
  return Cw;
}

Vec3 rational_curve_point(const BsplineCurve& curve, double u, Side side) {
  return project(homogeneous_curve_point(curve, u, side));
}

Vec3 curve_point(const BsplineCurve& curve, double u, Side side) {
  if (curve.rational()) return rational_curve_point(curve, u, side);
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  // A3.1: find the span, the p + 1 non-zero basis functions, and sum.
  const int p = curve.p;
  const int span = span_at(curve, u, side);
  double N[kMaxDegree + 1];
  basis_funs_raw(span, u, p, curve.U.data(), N);
  Vec3 C;
  for (int j = 0; j <= p; ++j) C += N[j] * curve.P[span - p + j];
  return C;
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

std::vector<Vec3> rational_curve_derivs(const BsplineCurve& curve, double u, int d, Side side) {
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  if (d < 0) fail("curve_derivs: derivative order d=" + std::to_string(d) + " must be >= 0");
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

std::vector<Vec3> curve_derivs(const BsplineCurve& curve, double u, int d, Side side) {
  if (curve.rational()) return rational_curve_derivs(curve, u, d, side);
  validate(curve);
  check_param(u, domain(curve.p, curve.U));
  if (d < 0) fail("curve_derivs: derivative order d=" + std::to_string(d) + " must be >= 0");
  return derivs_impl<Vec3>(curve, u, d, side, [&](int i) { return curve.P[i]; });
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

// ---- batched evaluation ------------------------------------------------------------
//
// curve_points() computes what curve_point() and curve_derivs(u, 1) compute --
// A2.1 FindSpan, A2.2 BasisFuns, the sums of A3.1 / A4.1 and A4.2 -- for many
// sorted parameters at once. The per-point functions above (curve_point,
// homogeneous_curve_point, basis_funs_raw) stay the reference implementation:
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
//    for the CPU -- no -march=native, the binary runs anywhere. Every variant
//    performs the same IEEE operations in the same order on each point: no
//    FMA contraction (-ffp-contract=off in CMakeLists.txt: GCC would contract
//    in the AVX2 / AVX-512 variants only) and no reassociation (no
//    -ffast-math), so all variants give bit-identical results; a vector lane
//    does exactly what the scalar code does.
//
// GLLAB_SPLINE_NO_CLONES (a compile definition) turns the clones off: then the
// kernels are compiled for whatever -march the build uses. That is how the
// variants are compared with each other (bench/README.md).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__ELF__) && !defined(GLLAB_SPLINE_NO_CLONES)
#define GLLAB_SPLINE_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define GLLAB_SPLINE_CLONES
#endif

namespace {
/// Checks the parameters of a batch: finite, non-decreasing, in the domain,
/// and throws naming the first bad one.
void check_sorted_params_detailed(const std::vector<double>& us, ParamInterval dom) {
  for (std::size_t k = 0; k < us.size(); ++k) {
    if (!std::isfinite(us[k])) require_finite(us[k], "curve_points", at("u", k));
    if (k > 0 && us[k] < us[k - 1])
      fail("curve_points: " + at("u", k) + "=" + num(us[k]) + " < " + at("u", k - 1) + "=" + num(us[k - 1]) +
           " (parameters must be non-decreasing)");
  }
  if (!us.empty() && (us.front() < dom.a || us.back() > dom.b)) {
    const double bad = us.front() < dom.a ? us.front() : us.back();
    fail("curve_points: u=" + num(bad) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) + "]");
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
  fail("curve_points: invalid parameters");  // not reached: the detailed check throws
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

/// Walks the runs of sorted parameters span by span and evaluates each run
/// with the kernel for the curve's degree.
template <class Pt, bool kDerivs>
[[gnu::always_inline]] inline void eval_runs(const BsplineCurve& c, const double* u, std::size_t count, Vec3* out,
                                             Vec3* der) {
  const int p = c.p;
  const int n = c.n();
  const double* U = c.U.data();
  const int last = last_span(n, p, c.U);  // u == U[n+1] is evaluated here
  int span = find_span(n, p, u[0], c.U);
  SpanData<Pt> s;
  std::size_t k = 0;
  while (true) {
    // U[span] <= u[k] < U[span+1] (or span == last): the run ends at the
    // first parameter >= U[span+1].
    const std::size_t end =
        span == last ? count : static_cast<std::size_t>(std::lower_bound(u + k, u + count, U[span + 1]) - u);
    prepare_span(c, span, kDerivs, s);
    const double* run_u = u + k;
    Vec3* run_out = out + k;
    Vec3* run_der = kDerivs ? der + k : nullptr;
    const std::size_t m = end - k;
    switch (p) {
      case 1: eval_run<1, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 2: eval_run<2, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 3: eval_run<3, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 4: eval_run<4, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      case 5: eval_run<5, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
      default: eval_run<0, Pt, kDerivs>(s, p, run_u, run_out, run_der, m); break;
    }
    k = end;
    if (k == count) break;
    // The next non-empty span that holds u[k]: the last i <= last with U[i] <= u[k].
    span = static_cast<int>(std::upper_bound(U + span + 1, U + last + 1, u[k]) - U) - 1;
  }
}

// One function per kind of curve, compiled once per instruction set (the
// templates above are inlined into each, always_inline: a call to a separate
// function would run that function's baseline code).
GLLAB_SPLINE_CLONES void eval_polynomial(const BsplineCurve& c, const double* u, std::size_t count, Vec3* out,
                                         Vec3* der) {
  if (der)
    eval_runs<Vec3, true>(c, u, count, out, der);
  else
    eval_runs<Vec3, false>(c, u, count, out, nullptr);
}
GLLAB_SPLINE_CLONES void eval_rational(const BsplineCurve& c, const double* u, std::size_t count, Vec3* out,
                                       Vec3* der) {
  if (der)
    eval_runs<Vec4, true>(c, u, count, out, der);
  else
    eval_runs<Vec4, false>(c, u, count, out, nullptr);
}

void curve_points_impl(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out,
                       std::vector<Vec3>* derivs) {
  validate(curve);
  check_sorted_params(sorted_u, domain(curve.p, curve.U));
  out.resize(sorted_u.size());
  if (derivs) derivs->resize(sorted_u.size());
  if (sorted_u.empty()) return;
  Vec3* der = derivs ? derivs->data() : nullptr;
  if (curve.rational())
    eval_rational(curve, sorted_u.data(), sorted_u.size(), out.data(), der);
  else
    eval_polynomial(curve, sorted_u.data(), sorted_u.size(), out.data(), der);
}
}  // namespace

void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out) {
  curve_points_impl(curve, sorted_u, out, nullptr);
}

void curve_points(const BsplineCurve& curve, const std::vector<double>& sorted_u, std::vector<Vec3>& out,
                  std::vector<Vec3>& derivs) {
  curve_points_impl(curve, sorted_u, out, &derivs);
}

std::vector<double> uniform_params(const BsplineCurve& curve, int count) {
  const ParamInterval dom = domain(curve);
  if (count < 2) fail("uniform_params: count=" + std::to_string(count) + " must be >= 2");
  std::vector<double> us(count);
  for (int k = 0; k < count; ++k) us[k] = dom.a + (dom.b - dom.a) * k / (count - 1);
  us.back() = dom.b;
  return us;
}

std::vector<double> greville_abscissae(int p, const std::vector<double>& U) {
  if (p < 1) fail("greville_abscissae: p=" + std::to_string(p) + " must be >= 1");
  if (U.size() < static_cast<std::size_t>(p) + 2)
    fail("greville_abscissae: " + std::to_string(U.size()) + " knots for degree " + std::to_string(p) +
         " leave no control point (at least p + 2 = " + std::to_string(p + 2) + " needed)");
  const std::size_t count = U.size() - static_cast<std::size_t>(p) - 1;
  std::vector<double> xi(count);
  for (std::size_t i = 0; i < count; ++i) {
    double sum = 0;
    for (int k = 1; k <= p; ++k) sum += U[i + static_cast<std::size_t>(k)];
    xi[i] = sum / p;
  }
  return xi;
}

// ---- knot insertion, refinement, decomposition -------------------------------

namespace {
/// The checks knot insertion makes: u in the domain and s + r <= p.
void check_insertion(const BsplineCurve& c, double u, int r) {
  validate(c);
  check_param(u, domain(c.p, c.U));
  if (r < 0) fail("knot_insert: r=" + std::to_string(r) + " must be >= 0");
  const int s = knot_multiplicity(c.U, u);
  if (s + r > c.p)
    fail("knot_insert: inserting u=" + num(u) + " " + std::to_string(r) + " time(s) onto multiplicity " +
         std::to_string(s) + " gives " + std::to_string(s + r) + " > p=" + std::to_string(c.p));
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
  for (std::size_t j = 0; j < X.size(); ++j) {
    if (!std::isfinite(X[j])) require_finite(X[j], "knot_refine", at("X", j));
    if (j > 0 && X[j] < X[j - 1])
      fail("knot_refine: " + at("X", j) + "=" + num(X[j]) + " < " + at("X", j - 1) + "=" + num(X[j - 1]) +
           " (must be non-decreasing)");
    if (X[j] < dom.a || X[j] > dom.b)
      fail("knot_refine: " + at("X", j) + "=" + num(X[j]) + " is outside the domain [" + num(dom.a) + ", " +
           num(dom.b) + "]");
  }
  for (std::size_t j = 0; j < X.size();) {
    std::size_t e = j;
    while (e < X.size() && X[e] == X[j]) ++e;
    const int s = knot_multiplicity(curve.U, X[j]);
    if (s + static_cast<int>(e - j) > curve.p)
      fail("knot_refine: knot " + num(X[j]) + " would get multiplicity " + std::to_string(s + (e - j)) +
           " > p=" + std::to_string(curve.p));
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
    fail("bezier_decompose: the curve is rational (" + std::to_string(curve.w.size()) +
         " weights); BezierCurve has no weights, use bezier_segments");
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
  if (segments.empty()) fail(what + ": no segments");
  BsplineCurve out;
  out.p = static_cast<int>(segments.front().P.size()) - 1;
  out.dimension = 2;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const BezierCurve& s = segments[i];
    const std::string name = what + ": " + at("segment", i);
    const int p = static_cast<int>(s.P.size()) - 1;
    if (p < 1) fail(name + " has degree " + std::to_string(p) + " (need >= 1)");
    if (p != out.p) fail(name + " has degree " + std::to_string(p) + ", segment[0] degree " + std::to_string(out.p));
    if (!(s.a < s.b) || !std::isfinite(s.a) || !std::isfinite(s.b))
      fail(name + ": interval [" + num(s.a) + ", " + num(s.b) + "] is not a finite a < b");
    for (std::size_t j = 0; j < s.P.size(); ++j) require_finite(s.P[j], name, at("P", j));
    if (i > 0) {
      const BezierCurve& prev = segments[i - 1];
      if (s.a != prev.b)
        fail(name + " starts at t=" + num(s.a) + ", segment[" + std::to_string(i - 1) + "] ends at t=" + num(prev.b));
      if (s.P.front() != prev.P.back())
        fail(name + " starts at " + num(s.P.front()) + ", segment[" + std::to_string(i - 1) + "] ends at " +
             num(prev.P.back()));
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
    fail("split: u=" + num(u) + " must lie strictly inside the domain (" + num(dom.a) + ", " + num(dom.b) + ")");
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

namespace {
/// The same curve on the same domain with end knots of multiplicity p + 1.
BsplineCurve clamped_copy(const BsplineCurve& curve) {
  if (is_clamped(curve)) return curve;
  const int p = curve.p;
  const ParamInterval dom = domain(curve.p, curve.U);
  BsplineCurve c = curve;
  for (const double e : {dom.a, dom.b}) {
    const int s = knot_multiplicity(c.U, e);
    if (s < p) c = knot_insert(c, e, p - s);
  }
  // Now a and b have multiplicity >= p; the points outside go.
  const int la = last_knot_at_or_below(c.U, dom.a);
  const int fb = static_cast<int>(std::lower_bound(c.U.begin(), c.U.end(), dom.b) - c.U.begin());
  // Start: with a at U[fa..la], multiplicity >= p, the first point is P[la-p].
  const int first_point = la - p;
  // End: with b at U[fb..], the last point is P[fb-1].
  const int last_point = fb - 1;
  BsplineCurve out;
  out.p = p;
  out.dimension = c.dimension;
  out.U.assign(p + 1, dom.a);
  out.U.insert(out.U.end(), c.U.begin() + (la + 1), c.U.begin() + fb);
  out.U.insert(out.U.end(), p + 1, dom.b);
  out.P.assign(c.P.begin() + first_point, c.P.begin() + (last_point + 1));
  if (c.rational()) out.w.assign(c.w.begin() + first_point, c.w.begin() + (last_point + 1));
  return out;
}
}  // namespace

BsplineCurve degree_elevate(const BsplineCurve& curve, int t) {
  validate(curve);
  if (t < 0) fail("degree_elevate: t=" + std::to_string(t) + " must be >= 0");
  if (curve.p + t > kMaxDegree)
    fail("degree_elevate: p + t = " + std::to_string(curve.p + t) + " exceeds kMaxDegree=" +
         std::to_string(kMaxDegree));
  if (t == 0) return curve;
  // A5.9 needs clamped ends and interior multiplicities <= p: clamp first,
  // and elevate the pieces between breaks (multiplicity p + 1) separately.
  const BsplineCurve c = clamped_copy(curve);
  const ParamInterval dom = domain(c.p, c.U);
  for (int i = c.p + 1; i < c.n() + 1; ++i) {
    if (c.U[i] > dom.a && c.U[i] < dom.b && knot_multiplicity(c.U, c.U[i]) == c.p + 1) {
      auto [left, right] = split(c, c.U[i]);
      return join_clamped(degree_elevate(left, t), degree_elevate(right, t));
    }
  }
  BsplineCurve out = apply_to_points(c, [&](const auto& q) { return degree_elevate_impl(q, t); });
  validate(out);
  return out;
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
    fail("uniform_cubic_point: segment i=" + std::to_string(i) + " needs P[i..i+3], but there are " +
         std::to_string(P.size()) + " points");
  require_finite(t, "uniform_cubic_point", "t");
  if (t < 0 || t > 1) fail("uniform_cubic_point: t=" + num(t) + " is outside [0, 1]");
  // Q(t) = [t^3 t^2 t 1] M [P_i .. P_{i+3}], by Horner on (a, b, c, d).
  const auto [a, b, c, d] = uniform_cubic_coefficients(P[i], P[i + 1], P[i + 2], P[i + 3]);
  return ((a * t + b) * t + c) * t + d;
}

}  // namespace gllab::spline
