// common/spline/cubic_spline.cpp — natural, clamped and periodic cubic
// splines (ch. 1 §1.6), their Bézier and B-spline forms, and the lecture's
// interpolating Bézier spline through de Boor points.
//
// Functions y = S(t) and curves X(t) share one template: only the type of a
// value changes (double or Vec3); the matrices are the same numbers.
#include "spline/cubic_spline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "spline/errors.h"
#include "spline/tridiagonal.h"

namespace gllab::spline {
namespace {

// --- input checks -------------------------------------------------------------------

/// What messages call the values: y[i] for a function, P[i] for a curve.
const char* values_name(const std::vector<double>&) { return "y"; }
const char* values_name(const std::vector<Vec3>&) { return "P"; }

bool finite(double v) { return std::isfinite(v); }
bool finite(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

/// Checks the values and their nodes: at least 2 values, finite, and
/// t.size() == values + extra_nodes with t strictly increasing.
template <class T>
void check_input(const std::string& what, const std::vector<double>& t, const std::vector<T>& values,
                 std::size_t extra_nodes) {
  if (values.size() < 2)
    fail(ErrorCode::kTooFewPoints,
         what + ": " + std::to_string(values.size()) + (values.size() == 1 ? " point" : " points") +
             " given, at least 2 needed",
         {{"points", values.size()}});
  if (t.size() != values.size() + extra_nodes)
    fail(ErrorCode::kSizeMismatch,
         what + ": " + std::to_string(t.size()) + " nodes t for " + std::to_string(values.size()) + " points (" +
             std::to_string(values.size() + extra_nodes) + " needed" +
             (extra_nodes ? ": a closed spline has one more node than points)" : ")"),
         {{"nodes", t.size()}, {"points", values.size()}, {"needed", values.size() + extra_nodes}});
  // Test first, build the message (a std::string per entry) only on failure.
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!finite(values[i])) require_finite(values[i], what, at(values_name(values), i));
  for (std::size_t i = 0; i < t.size(); ++i)
    if (!std::isfinite(t[i])) require_finite(t[i], what, at("t", i));
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      fail(ErrorCode::kParametersNotSorted,
           what + ": " + at("t", i) + "=" + num(t[i]) + " <= " + at("t", i - 1) + "=" + num(t[i - 1]) +
               " (nodes must increase strictly)",
           {{"i", i}, {at("t", i), t[i]}, {at("t", i - 1), t[i - 1]}});
}

/// A closed curve is given each point once; p_{N-1} == p_0 would draw a
/// spurious loop through p_0.
void check_not_repeated(const std::string&, const std::vector<double>&) {}
void check_not_repeated(const std::string& what, const std::vector<Vec3>& P) {
  if (P.back() == P.front())
    fail(ErrorCode::kCoincidentPoints,
         what + ": " + at(values_name(P), P.size() - 1) + "=" + num(P.back()) +
             " repeats P[0]; a closed spline closes by itself (give each point once)",
         {{"i", P.size() - 1}, {at(values_name(P), P.size() - 1), P.back()}});
}

int dimension_of(const std::vector<double>&) { return 1; }
int dimension_of(const std::vector<Vec3>& P) {
  return std::all_of(P.begin(), P.end(), [](Vec3 p) { return p.z == 0; }) ? 2 : 3;
}

/// The interval lengths D_i = t_{i+1} - t_i with the index conventions of
/// ch. 1 §1.6: an open spline has D_{-1} = D_N = 0 (no interval beyond the
/// ends); a closed one repeats its N intervals cyclically.
struct Intervals {
  const std::vector<double>& t;
  bool periodic;

  long count() const { return static_cast<long>(t.size()) - 1; }
  double operator()(long i) const {
    const long n = count();
    if (periodic) i = ((i % n) + n) % n;
    if (i < 0 || i >= n) return 0.0;
    return t[static_cast<std::size_t>(i + 1)] - t[static_cast<std::size_t>(i)];
  }
};

// --- the power form --------------------------------------------------------------

/// The lecture's remaining coefficients once the c_i are known (ch. 1 §1.6,
/// "Algorithm for a natural cubic spline (continued)"), for i = 0..N-1:
///     d_i = (c_{i+1} - c_i) / (3 D_i)
///     b_i = (a_{i+1} - a_i) / D_i - D_i (c_{i+1} + 2 c_i) / 3
/// a and c have N + 1 entries (a_N = S(t_N), c_N = S''(t_N) / 2).
template <class T>
PiecewiseCubic<T> power_form(const std::vector<double>& t, const std::vector<T>& a, const std::vector<T>& c,
                             EndCondition end) {
  const std::size_t N = t.size() - 1;
  PiecewiseCubic<T> s;
  s.t = t;
  s.end = end;
  s.a.assign(a.begin(), a.begin() + static_cast<long>(N));
  s.c.assign(c.begin(), c.begin() + static_cast<long>(N));
  s.b.resize(N);
  s.d.resize(N);
  for (std::size_t i = 0; i < N; ++i) {
    const double D = t[i + 1] - t[i];
    s.d[i] = (c[i + 1] - c[i]) / (3 * D);
    s.b[i] = (a[i + 1] - a[i]) / D - D * (c[i + 1] + 2.0 * c[i]) / 3.0;
  }
  s.dimension = dimension_of(a);
  return s;
}

/// The right-hand side of row i of the lecture's system for the c_i:
///     3 (a_{i+1} - a_i) / D_i - 3 (a_i - a_{i-1}) / D_{i-1}.
template <class T>
T curvature_rhs(const std::vector<T>& a, const std::vector<double>& t, std::size_t i) {
  return 3.0 * (a[i + 1] - a[i]) / (t[i + 1] - t[i]) - 3.0 * (a[i] - a[i - 1]) / (t[i] - t[i - 1]);
}

/// Ch. 1 §1.6, "Algorithm for a natural cubic spline": a_i = p_i,
/// c_0 = c_N = 0, and for i = 1..N-1
///     D_{i-1} c_{i-1} + 2 (D_{i-1} + D_i) c_i + D_i c_{i+1}
///         = 3 (a_{i+1} - a_i) / D_i - 3 (a_i - a_{i-1}) / D_{i-1},
/// a symmetric, strictly diagonally dominant tridiagonal system for c_1..c_{N-1}.
template <class T>
PiecewiseCubic<T> natural(const std::vector<double>& t, const std::vector<T>& y) {
  check_input("natural_cubic_spline", t, y, 0);
  const std::size_t N = t.size() - 1;
  const std::size_t unknowns = N - 1;
  std::vector<double> lower(unknowns), diag(unknowns), upper(unknowns);
  std::vector<T> rhs(unknowns);
  for (std::size_t k = 0; k < unknowns; ++k) {
    const std::size_t i = k + 1;
    lower[k] = t[i] - t[i - 1];
    diag[k] = 2 * (t[i + 1] - t[i - 1]);
    upper[k] = t[i + 1] - t[i];
    rhs[k] = curvature_rhs(y, t, i);
  }
  const std::vector<T> inner = solve_tridiagonal(lower, diag, upper, rhs);
  std::vector<T> c(N + 1, T{});  // c_0 = c_N = 0: natural ends
  std::copy(inner.begin(), inner.end(), c.begin() + 1);
  return power_form(t, y, c, EndCondition::kNatural);
}

/// Clamped ends S'(t_0) = s0 and S'(t_N) = sN (ch. 1 §1.6 names the
/// conditions g'(t_0) = p'_0, g'(t_N) = p'_n). Two more rows join the natural
/// system, both from the lecture's formula for b_i:
///   b_0 = s0                         gives  2 D_0 c_0 + D_0 c_1 = 3 (a_1 - a_0) / D_0 - 3 s0,
///   S'(t_N) = b_{N-1} + (c_{N-1} + c_N) D_{N-1} = sN
///                                    gives  D_{N-1} c_{N-1} + 2 D_{N-1} c_N = 3 sN - 3 (a_N - a_{N-1}) / D_{N-1}.
template <class T>
PiecewiseCubic<T> clamped(const std::vector<double>& t, const std::vector<T>& y, T s0, T sN) {
  const std::string what = "clamped_cubic_spline";
  check_input(what, t, y, 0);
  require_finite(s0, what, "start derivative");
  require_finite(sN, what, "end derivative");
  const std::size_t N = t.size() - 1;
  std::vector<double> lower(N + 1), diag(N + 1), upper(N + 1);
  std::vector<T> rhs(N + 1);
  const double D0 = t[1] - t[0], DN = t[N] - t[N - 1];
  diag[0] = 2 * D0;
  upper[0] = D0;
  rhs[0] = 3.0 * (y[1] - y[0]) / D0 - 3.0 * s0;
  for (std::size_t i = 1; i < N; ++i) {
    lower[i] = t[i] - t[i - 1];
    diag[i] = 2 * (t[i + 1] - t[i - 1]);
    upper[i] = t[i + 1] - t[i];
    rhs[i] = curvature_rhs(y, t, i);
  }
  lower[N] = DN;
  diag[N] = 2 * DN;
  rhs[N] = 3.0 * sN - 3.0 * (y[N] - y[N - 1]) / DN;
  const std::vector<T> c = solve_tridiagonal(lower, diag, upper, rhs);
  PiecewiseCubic<T> s = power_form(t, y, c, EndCondition::kClamped);
  if (dimension_of(std::vector<T>{s0, sN}) == 3) s.dimension = 3;
  return s;
}

/// Ch. 1 §1.6, "Algorithm for a periodic cubic spline": the natural
/// system's rows for every node i = 0..N-1, with indices taken cyclically
/// (a_N = a_0, a_{-1} = a_{N-1}, D_{-1} = D_{N-1}), so row 0 reaches c_{N-1}
/// and row N-1 reaches c_0: the lecture's cyclic tridiagonal matrix.
template <class T>
PiecewiseCubic<T> periodic(const std::vector<double>& t, const std::vector<T>& y) {
  const std::string what = "periodic_cubic_spline";
  check_input(what, t, y, 1);
  check_not_repeated(what, y);
  const std::size_t N = y.size();  // segments = points
  std::vector<T> a(y);
  a.push_back(y[0]);  // a_N = a_0: the curve closes
  const Intervals D{t, true};
  std::vector<double> lower(N), diag(N), upper(N);
  std::vector<T> rhs(N);
  for (std::size_t i = 0; i < N; ++i) {
    const long k = static_cast<long>(i);
    lower[i] = D(k - 1);
    diag[i] = 2 * (D(k - 1) + D(k));
    upper[i] = D(k);
    const T before = i > 0 ? a[i - 1] : a[N - 1];
    rhs[i] = 3.0 * (a[i + 1] - a[i]) / D(k) - 3.0 * (a[i] - before) / D(k - 1);
  }
  std::vector<T> c = solve_cyclic_tridiagonal(lower, diag, upper, rhs);
  c.push_back(c[0]);  // c_N = c_0: the curvature closes too
  return power_form(t, a, c, EndCondition::kPeriodic);
}

/// Horner's rule for the k-th derivative of a + b h + c h^2 + d h^3.
template <class T>
T derivative_of_segment(const PiecewiseCubic<T>& s, std::size_t i, double u, int k) {
  if (k < 0)
    fail(ErrorCode::kNegativeDerivativeOrder,
         "segment_derivative: derivative order k=" + std::to_string(k) + " (must be >= 0)", {{"k", k}});
  if (i >= s.segments())
    fail(ErrorCode::kIndexOutOfRange,
         "segment_derivative: segment " + std::to_string(i) + " of " + std::to_string(s.segments()),
         {{"segment", i}, {"segments", s.segments()}});
  const double h = u - s.t[i];
  switch (k) {
    case 0: return s.a[i] + h * (s.b[i] + h * (s.c[i] + h * s.d[i]));
    case 1: return s.b[i] + h * (2.0 * s.c[i] + 3.0 * h * s.d[i]);
    case 2: return 2.0 * s.c[i] + 6.0 * h * s.d[i];
    case 3: return 6.0 * s.d[i];
    default: return T{};
  }
}

/// The Bézier ordinates of segment i (ch. 1 §1.6: the derivatives of a
/// Bézier segment over an interval of length D at its start are
/// S' = 3 (b_1 - b_0) / D and S'' = 6 (b_0 - 2 b_1 + b_2) / D^2):
///     b_0 = a, b_1 = a + b D/3, b_2 = a + 2 b D/3 + c D^2/3, b_3 = S(t_{i+1}).
template <class T>
std::array<T, 4> bezier_ordinates(const PiecewiseCubic<T>& s, std::size_t i) {
  const double D = s.t[i + 1] - s.t[i];
  const T b0 = s.a[i];
  const T b1 = s.a[i] + s.b[i] * (D / 3);
  const T b2 = s.a[i] + s.b[i] * (2 * D / 3) + s.c[i] * (D * D / 3);
  // The end point: the next segment's a (exactly the data point), else evaluate.
  const T b3 = i + 1 < s.segments() ? s.a[i + 1]
               : s.end == EndCondition::kPeriodic ? s.a[0]
                                                  : derivative_of_segment(s, i, s.t[i + 1], 0);
  return {b0, b1, b2, b3};
}

/// The de Boor points Q_0..Q_{N+2} of the spline's B-spline form (see
/// bspline_curve in the header). Segment i's inner Bézier points lie on the
/// leg Q_{i+1} Q_{i+2}, cut in the ratio D_{i-1} : D_i : D_{i+1} (the lecture's
/// first and third rows of step 2). Solving those two rows for Q_{i+1}:
///     Q_{i+1} = ((D_{i-1} + D_i) b_{3i+1} - D_{i-1} b_{3i+2}) / D_i.
/// Open: D_{-1} = 0 gives Q_1 = b_1, and Q_0 = b_0, Q_{N+1} = b_{3N-1},
/// Q_{N+2} = b_{3N}. Closed: the intervals are cyclic and Q_0 = Q_N,
/// Q_{N+1} = Q_1, Q_{N+2} = Q_2.
template <class T>
std::vector<T> de_boor_coefficients(const PiecewiseCubic<T>& s) {
  const std::size_t N = s.segments();
  const bool closed = s.end == EndCondition::kPeriodic;
  const Intervals D{s.t, closed};
  std::vector<T> Q(N + 3);
  for (std::size_t i = 0; i < N; ++i) {
    const long k = static_cast<long>(i);
    const std::array<T, 4> b = bezier_ordinates(s, i);
    Q[i + 1] = ((D(k - 1) + D(k)) * b[1] - D(k - 1) * b[2]) / D(k);
  }
  if (closed) {
    Q[0] = Q[N];
    Q[N + 1] = Q[1];
    Q[N + 2] = Q[2];
  } else {
    const std::array<T, 4> last = bezier_ordinates(s, N - 1);
    Q[0] = s.a[0];
    Q[N + 1] = last[2];
    Q[N + 2] = last[3];
  }
  return Q;
}

/// The knot vector of the B-spline form: clamped (t_0 x4, t_1..t_{N-1}, t_N x4),
/// or periodic, U[3 + j] = t_{j mod N} + (j div N) T for j = -3..N+3, T = t_N - t_0.
std::vector<double> spline_knots(const std::vector<double>& t, bool closed) {
  const long N = static_cast<long>(t.size()) - 1;
  std::vector<double> U;
  if (!closed) {
    U.assign(3, t.front());
    U.insert(U.end(), t.begin(), t.end());
    U.insert(U.end(), 3, t.back());
    return U;
  }
  const double T = t.back() - t.front();
  for (long j = -3; j <= N + 3; ++j) {
    if (j >= 0 && j <= N) {
      U.push_back(t[static_cast<std::size_t>(j)]);  // the nodes themselves, unrounded
      continue;
    }
    const long r = ((j % N) + N) % N;
    const long q = (j - r) / N;
    U.push_back(t[static_cast<std::size_t>(r)] + static_cast<double>(q) * T);
  }
  return U;
}

// --- the lecture's Bézier spline through de Boor points -----------------------------

/// Step 2 of ch. 1 §1.6's three-step algorithm. Unknowns d_0..d_N (open)
/// or d_0..d_{N-1} (closed). The row of interior node p_i comes from
///     (D_{i-1} + D_i) p_i = D_i b_{3i-1} + D_{i-1} b_{3i+1}            (C1 at p_i)
/// with b_{3i-1} on the leg d_{i-1} d_i (segment i-1) and b_{3i+1} on d_i d_{i+1}:
///     (D_{i-1} + D_i) p_i = D_i^2 / S_{i-1} d_{i-1}
///                         + (D_i (D_{i-2} + D_{i-1}) / S_{i-1} + D_{i-1} (D_i + D_{i+1}) / S_i) d_i
///                         + D_{i-1}^2 / S_i d_{i+1},
///     S_i = D_{i-1} + D_i + D_{i+1}.
/// (The lecture multiplies the whole row by a single S, which is right when the
/// intervals are equal, as in its equidistant case 6 b_3 = d_0 + 4 d_1 + d_2;
/// segments i-1 and i have their own S in general.)
std::vector<Vec3> solve_de_boor(const std::string& what, const std::vector<double>& t, const std::vector<Vec3>& P,
                                EndCondition end, Vec3 b1, Vec3 b_last) {
  const bool closed = end == EndCondition::kPeriodic;
  check_input(what, t, P, closed ? 1 : 0);
  if (closed) check_not_repeated(what, P);
  if (end == EndCondition::kClamped) {
    require_finite(b1, what, "b_1");
    require_finite(b_last, what, "b_last");
  }
  const Intervals D{t, closed};
  const long N = D.count();  // segments
  // One de Boor point per data point: open N + 1 = d_0..d_N, closed N = d_0..d_{N-1}.
  const std::size_t unknowns = P.size();
  std::vector<double> lower(unknowns, 0.0), diag(unknowns, 0.0), upper(unknowns, 0.0);
  std::vector<Vec3> rhs(unknowns);
  for (std::size_t r = 0; r < unknowns; ++r) {
    const long i = static_cast<long>(r);
    if (!closed && (i == 0 || i == N)) continue;  // end rows below
    const double S_before = D(i - 2) + D(i - 1) + D(i);
    const double S_here = D(i - 1) + D(i) + D(i + 1);
    lower[r] = D(i) * D(i) / S_before;
    diag[r] = D(i) * (D(i - 2) + D(i - 1)) / S_before + D(i - 1) * (D(i) + D(i + 1)) / S_here;
    upper[r] = D(i - 1) * D(i - 1) / S_here;
    rhs[r] = (D(i - 1) + D(i)) * P[r];
  }
  if (closed) return solve_cyclic_tridiagonal(lower, diag, upper, rhs);

  const std::size_t last = static_cast<std::size_t>(N);
  if (end == EndCondition::kClamped) {
    // Step 1, the lecture's choice: b_1 and b_{3N-1} given; D_{-1} = D_N = 0 makes
    // them the end de Boor points.
    diag[0] = 1;
    rhs[0] = b1;
    diag[last] = 1;
    rhs[last] = b_last;
  } else {
    // Natural ends: S''(t_0) = 0, i.e. b_0 - 2 b_1 + b_2 = 0, with b_1 = d_0 and
    // b_2 = (D_1 d_0 + D_0 d_1) / (D_0 + D_1):
    //     (2 D_0 + D_1) d_0 - D_0 d_1 = (D_0 + D_1) p_0, and mirrored at t_N.
    diag[0] = 2 * D(0) + D(1);
    upper[0] = -D(0);
    rhs[0] = (D(0) + D(1)) * P[0];
    lower[last] = -D(N - 1);
    diag[last] = 2 * D(N - 1) + D(N - 2);
    rhs[last] = (D(N - 2) + D(N - 1)) * P[last];
  }
  return solve_tridiagonal(lower, diag, upper, rhs);
}

/// Step 3: each segment's inner Bézier points on its leg d_i d_{i+1}:
///     b_{3i+1} = ((D_i + D_{i+1}) d_i + D_{i-1} d_{i+1}) / S_i
///     b_{3i+2} = (D_{i+1} d_i + (D_{i-1} + D_i) d_{i+1}) / S_i.
/// (The lecture marches along with its equations 1) and 3), the C1 and C2
/// conditions at each node; the legs give the same points without carrying
/// rounding errors from segment to segment. The tests check 1) and 3).)
std::vector<BezierCurve> bezier_from_de_boor(const std::vector<double>& t, const std::vector<Vec3>& P,
                                             const std::vector<Vec3>& d, bool closed) {
  const Intervals D{t, closed};
  const long N = D.count();
  const int dimension = dimension_of(P) == 2 && dimension_of(d) == 2 ? 2 : 3;
  std::vector<BezierCurve> segments;
  for (long i = 0; i < N; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const std::size_t k1 = closed ? (k + 1) % P.size() : k + 1;
    const Vec3 d_here = d[k], d_next = d[closed ? (k + 1) % d.size() : k + 1];
    const double S = D(i - 1) + D(i) + D(i + 1);
    BezierCurve segment;
    segment.P = std::vector<Vec3>{P[k], ((D(i) + D(i + 1)) * d_here + D(i - 1) * d_next) / S,
                 (D(i + 1) * d_here + (D(i - 1) + D(i)) * d_next) / S, P[k1]};
    segment.a = t[k];
    segment.b = t[k + 1];
    segment.dimension = dimension;
    segments.push_back(segment);
  }
  return segments;
}

void check_end_kind(const std::string& what, EndCondition end) {
  if (end == EndCondition::kClamped)
    fail(ErrorCode::kEmptyInput,
         what + ": clamped ends need the inner Bezier points b_1 and b_last (use the overload that takes them)");
}

}  // namespace

// --- construction ------------------------------------------------------------------

ScalarCubicSpline natural_cubic_spline(const std::vector<double>& t, const std::vector<double>& y) {
  return natural(t, y);
}
CubicSpline natural_cubic_spline(const std::vector<double>& t, const std::vector<Vec3>& P) { return natural(t, P); }

ScalarCubicSpline clamped_cubic_spline(const std::vector<double>& t, const std::vector<double>& y,
                                       double slope_start, double slope_end) {
  return clamped(t, y, slope_start, slope_end);
}
CubicSpline clamped_cubic_spline(const std::vector<double>& t, const std::vector<Vec3>& P, Vec3 tangent_start,
                                 Vec3 tangent_end) {
  return clamped(t, P, tangent_start, tangent_end);
}

ScalarCubicSpline periodic_cubic_spline(const std::vector<double>& t, const std::vector<double>& y) {
  return periodic(t, y);
}
CubicSpline periodic_cubic_spline(const std::vector<double>& t, const std::vector<Vec3>& P) { return periodic(t, P); }

// --- evaluation ----------------------------------------------------------------------

std::size_t segment_index(const std::vector<double>& t, double u) {
  if (t.size() < 2)
    fail(ErrorCode::kTooFewPoints, "segment_index: " + std::to_string(t.size()) + " nodes, at least 2 needed",
         {{"nodes", t.size()}});
  if (!(u >= t.front() && u <= t.back()))
    fail(std::isnan(u) ? ErrorCode::kNotFinite : ErrorCode::kParameterOutsideDomain,
         "segment_index: t=" + num(u) + " outside [" + num(t.front()) + ", " + num(t.back()) + "]",
         {{"t", u}, {"a", t.front()}, {"b", t.back()}});
  // The first node greater than u ends u's segment; u == t[N] stays in the last one.
  const auto above = std::upper_bound(t.begin(), t.end(), u);
  const std::size_t i = static_cast<std::size_t>(above - t.begin()) - 1;
  return std::min(i, t.size() - 2);
}

double spline_value(const ScalarCubicSpline& s, double u) { return spline_derivative(s, u, 0); }
Vec3 spline_point(const CubicSpline& s, double u) { return spline_derivative(s, u, 0); }

double spline_derivative(const ScalarCubicSpline& s, double u, int k) {
  return derivative_of_segment(s, segment_index(s.t, u), u, k);
}
Vec3 spline_derivative(const CubicSpline& s, double u, int k) {
  return derivative_of_segment(s, segment_index(s.t, u), u, k);
}

double segment_derivative(const ScalarCubicSpline& s, std::size_t i, double u, int k) {
  return derivative_of_segment(s, i, u, k);
}
Vec3 segment_derivative(const CubicSpline& s, std::size_t i, double u, int k) {
  return derivative_of_segment(s, i, u, k);
}

// --- other forms ---------------------------------------------------------------------

std::vector<BezierCurve> bezier_segments(const CubicSpline& s) {
  std::vector<BezierCurve> segments;
  for (std::size_t i = 0; i < s.segments(); ++i) {
    const std::array<Vec3, 4> b = bezier_ordinates(s, i);
    BezierCurve segment;
    segment.P = std::vector<Vec3>(b.begin(), b.end());
    segment.a = s.t[i];
    segment.b = s.t[i + 1];
    segment.dimension = s.dimension;
    segments.push_back(segment);
  }
  return segments;
}

BsplineCurve bspline_curve(const CubicSpline& s) {
  if (s.segments() == 0) fail(ErrorCode::kEmptyInput, "bspline_curve: the spline has no segments", {{"segments", 0}});
  BsplineCurve curve;
  curve.p = 3;
  curve.U = spline_knots(s.t, s.end == EndCondition::kPeriodic);
  curve.P = de_boor_coefficients(s);
  curve.dimension = s.dimension;
  return curve;
}

BsplineCurve bspline_curve(const ScalarCubicSpline& s) {
  if (s.segments() == 0) fail(ErrorCode::kEmptyInput, "bspline_curve: the spline has no segments", {{"segments", 0}});
  BsplineCurve curve;
  curve.p = 3;
  curve.U = spline_knots(s.t, s.end == EndCondition::kPeriodic);
  const std::vector<double> Q = de_boor_coefficients(s);
  // Greville abscissae: sum_i xi_i N_i(u) = u for a cubic B-spline on any knots,
  // so the control points (xi_i, Q_i) trace the graph (u, S(u)).
  for (std::size_t i = 0; i < Q.size(); ++i) {
    const double xi = (curve.U[i + 1] + curve.U[i + 2] + curve.U[i + 3]) / 3;
    curve.P.push_back({xi, Q[i], 0});
  }
  curve.dimension = 2;
  return curve;
}

// --- interpolating cubic Bézier splines --------------------------------------------

std::vector<Vec3> de_boor_points_through(const std::vector<double>& t, const std::vector<Vec3>& P, Vec3 b1,
                                         Vec3 b_last) {
  return solve_de_boor("de_boor_points_through", t, P, EndCondition::kClamped, b1, b_last);
}

std::vector<Vec3> de_boor_points_through(const std::vector<double>& t, const std::vector<Vec3>& P,
                                         EndCondition end) {
  check_end_kind("de_boor_points_through", end);
  return solve_de_boor("de_boor_points_through", t, P, end, {}, {});
}

std::vector<BezierCurve> bezier_spline_through(const std::vector<double>& t, const std::vector<Vec3>& P, Vec3 b1,
                                               Vec3 b_last) {
  const std::vector<Vec3> d = solve_de_boor("bezier_spline_through", t, P, EndCondition::kClamped, b1, b_last);
  return bezier_from_de_boor(t, P, d, false);
}

std::vector<BezierCurve> bezier_spline_through(const std::vector<double>& t, const std::vector<Vec3>& P,
                                               EndCondition end) {
  check_end_kind("bezier_spline_through", end);
  const std::vector<Vec3> d = solve_de_boor("bezier_spline_through", t, P, end, {}, {});
  return bezier_from_de_boor(t, P, d, end == EndCondition::kPeriodic);
}

}  // namespace gllab::spline
