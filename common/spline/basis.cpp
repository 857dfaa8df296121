// common/spline/basis.cpp — B-spline basis functions, chapter 2 of The NURBS
// Book (Piegl & Tiller, 2nd ed.): A2.1 FindSpan, A2.2 BasisFuns, A2.3
// DersBasisFuns, A2.4 OneBasisFun, and the Cox–de Boor recursion as the lecture
// writes it (see basis.h).
//
// A2.2's loop is written once, in basis_triangle(); basis_funs() keeps its
// last column and ders_basis_funs() the whole triangle, as A2.3 does. (The
// fast layer, fast/kernels.h, has the one other copy: with the degree fixed at
// compile time and the divisions turned into per-span reciprocals.)
#include "spline/basis.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spline/errors.h"

namespace gllab::spline {

namespace {

int size_of(const std::vector<double>& U) { return static_cast<int>(U.size()); }

/// The cheap checks every raw (p, U) routine makes.
void check_degree_and_knots(const char* fn, int n, int p, const std::vector<double>& U) {
  if (p < 0)
    fail(ErrorCode::kDegreeTooLow, std::string(fn) + ": degree p=" + std::to_string(p) + " must be >= 0", {{"p", p}});
  if (p > kMaxDegree)
    fail(ErrorCode::kDegreeTooHigh,
         std::string(fn) + ": degree p=" + std::to_string(p) + " exceeds kMaxDegree=" + std::to_string(kMaxDegree),
         {{"p", p}});
  if (n < p)
    fail(ErrorCode::kTooFewPoints,
         std::string(fn) + ": n=" + std::to_string(n) + " < p=" + std::to_string(p) +
             " (needs at least p + 1 control points)",
         {{"n", n}, {"p", p}});
  if (size_of(U) != n + p + 2)
    fail(ErrorCode::kKnotCount,
         std::string(fn) + ": knot vector has " + std::to_string(U.size()) + " knots, needs n + p + 2 = " +
             std::to_string(n + p + 2) + " (n=" + std::to_string(n) + ", p=" + std::to_string(p) + ")",
         {{"knots", U.size()}, {"needed", n + p + 2}});
}

/// The checks of a single N_{i,p}(u) (one_basis_fun, cox_de_boor): p >= 0,
/// 0 <= i <= m - p - 1, u finite.
void check_one_basis_fun(const char* fn, int i, double u, int p, int m) {
  if (p < 0)
    fail(ErrorCode::kDegreeTooLow, std::string(fn) + ": degree p=" + std::to_string(p) + " must be >= 0", {{"p", p}});
  if (i < 0 || i > m - p - 1)
    fail(ErrorCode::kIndexOutOfRange,
         std::string(fn) + ": index i=" + std::to_string(i) + " out of range [0, m - p - 1] = [0, " +
             std::to_string(m - p - 1) + "]",
         {{"i", i}, {"p", p}, {"m", m}});
  require_finite(u, fn, "u");
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


}  // namespace

int last_span(int n, int p, const std::vector<double>& U) {
  int i = n;
  while (i > p && U[i] == U[i + 1]) --i;
  return i;
}


// ---- A2.1 -------------------------------------------------------------------

int find_span(int n, int p, double u, const std::vector<double>& U) {
  check_degree_and_knots("find_span", n, p, U);
  require_finite(u, "find_span", "u");
  if (!(U[p] < U[n + 1]))
    fail(ErrorCode::kEmptyDomain,
         "find_span: the domain [U[p], U[n+1]] = [" + num(U[p]) + ", " + num(U[n + 1]) + "] is empty",
         {{"U[p]", U[p]}, {"U[n+1]", U[n + 1]}});
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

// ---- A2.2 and A2.3 ----------------------------------------------------------

void basis_triangle(int i, double u, int p, const std::vector<double>& U, BasisTriangle& ndu) {
  double left[kMaxDegree + 1];
  double right[kMaxDegree + 1];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: the knot differences
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;  // upper triangle: the basis functions
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
}

void basis_funs(int i, double u, int p, const std::vector<double>& U, double* N) {
  const int m = size_of(U) - 1;
  if (p < 0 || p > kMaxDegree)
    fail(p < 0 ? ErrorCode::kDegreeTooLow : ErrorCode::kDegreeTooHigh,
         "basis_funs: degree p=" + std::to_string(p) + " out of [0, kMaxDegree]", {{"p", p}});
  if (i < p || i + p + 1 > m)
    fail(ErrorCode::kIndexOutOfRange,
         "basis_funs: span i=" + std::to_string(i) + " out of range [p, m - p - 1] = [" + std::to_string(p) + ", " +
             std::to_string(m - p - 1) + "]",
         {{"i", i}, {"p", p}, {"m", m}});
  BasisTriangle ndu;
  basis_triangle(i, u, p, U, ndu);
  for (int r = 0; r <= p; ++r) N[r] = ndu[r][p];
}

std::vector<double> basis_funs(int i, double u, int p, const std::vector<double>& U) {
  std::vector<double> N(std::max(p, 0) + 1);
  basis_funs(i, u, p, U, N.data());
  return N;
}

void ders_basis_funs(int i, double u, int p, int d, const std::vector<double>& U, double* ders) {
  const int m = size_of(U) - 1;
  if (p < 0)
    fail(ErrorCode::kDegreeTooLow, "ders_basis_funs: degree p=" + std::to_string(p) + " must be >= 0", {{"p", p}});
  if (p > kMaxDegree)
    fail(ErrorCode::kDegreeTooHigh,
         "ders_basis_funs: degree p=" + std::to_string(p) + " exceeds kMaxDegree=" + std::to_string(kMaxDegree),
         {{"p", p}});
  if (d < 0)
    fail(ErrorCode::kNegativeDerivativeOrder,
         "ders_basis_funs: derivative order d=" + std::to_string(d) + " must be >= 0", {{"d", d}});
  if (i < p || i + p + 1 > m)
    fail(ErrorCode::kIndexOutOfRange,
         "ders_basis_funs: span i=" + std::to_string(i) + " out of range [p, m - p - 1] = [" + std::to_string(p) +
             ", " + std::to_string(m - p - 1) + "]",
         {{"i", i}, {"p", p}, {"m", m}});
  const int w = p + 1;  // ders[k * w + j]: the k-th derivative of N_{i-p+j,p}
  std::fill(ders, ders + (d + 1) * w, 0.0);
  const int nd = std::min(d, p);  // derivatives above p vanish
  // ndu: basis functions (upper triangle) and knot differences (lower).
  BasisTriangle ndu;
  basis_triangle(i, u, p, U, ndu);
  for (int j = 0; j <= p; ++j) ders[j] = ndu[j][p];
  // The derivatives (The NURBS Book §2.3), two rows of coefficients a alternating.
  double a[2][kMaxDegree + 1] = {};
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
      ders[k * w + r] = dk;
      std::swap(s1, s2);
    }
  }
  // Multiply by p! / (p - k)!.
  double factor = p;
  for (int k = 1; k <= nd; ++k) {
    for (int j = 0; j <= p; ++j) ders[k * w + j] *= factor;
    factor *= (p - k);
  }
}

std::vector<std::vector<double>> ders_basis_funs(int i, double u, int p, int d, const std::vector<double>& U) {
  std::vector<double> flat(static_cast<std::size_t>(std::max(d, 0) + 1) * static_cast<std::size_t>(std::max(p, 0) + 1));
  ders_basis_funs(i, u, p, d, U, flat.data());
  std::vector<std::vector<double>> ders(d + 1);
  for (int k = 0; k <= d; ++k) ders[k].assign(flat.begin() + k * (p + 1), flat.begin() + (k + 1) * (p + 1));
  return ders;
}

// ---- one function at a time, and all of them ---------------------------------

double one_basis_fun(int i, double u, int p, const std::vector<double>& U) {
  const int m = size_of(U) - 1;
  check_one_basis_fun("one_basis_fun", i, u, p, m);
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
  check_one_basis_fun("cox_de_boor", i, u, p, m);
  return cox_de_boor_rec(i, p, u, U, active_interval(u, p, U));
}

std::vector<double> all_basis_funs(double u, int p, const std::vector<double>& U) {
  const int m = size_of(U) - 1;
  if (p < 0 || m - p - 1 < 0)
    fail(p < 0 ? ErrorCode::kDegreeTooLow : ErrorCode::kKnotCount,
         "all_basis_funs: degree p=" + std::to_string(p) + " does not fit " + std::to_string(U.size()) + " knots",
         {{"p", p}, {"knots", U.size()}});
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

}  // namespace gllab::spline
