// common/spline/interpolation.cpp — polynomial interpolation (ch. 1 §1.6).
// See interpolation.h for what each function returns.
#include "spline/interpolation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>

#include "spline/errors.h"

namespace gllab::spline {

namespace {

// ---- checks shared by every method ------------------------------------------

/// Nodes must be there, finite and pairwise distinct (ch. 1 §1.6:
/// "pairwise unequal nodes t_i"), else the Vandermonde matrix is singular and
/// L_i and the divided differences divide by zero.
void require_nodes(const std::vector<double>& nodes, const std::string& what) {
  if (nodes.empty()) fail(ErrorCode::kEmptyInput, what + ": no nodes (need at least one t_i)", {{"nodes", 0}});
  for (std::size_t i = 0; i < nodes.size(); ++i) require_finite(nodes[i], what, at("t", i));
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t k = i + 1; k < nodes.size(); ++k)
      if (nodes[i] == nodes[k])
        fail(ErrorCode::kNodesCoincide,
             what + ": nodes " + at("t", i) + "=" + num(nodes[i]) + " and " + at("t", k) + "=" + num(nodes[k]) +
                 " coincide (nodes must be pairwise distinct)",
             {{"i", i}, {"k", k}, {at("t", i), nodes[i]}});
}

/// One value per node, all finite.
template <class T>
void require_values(const std::vector<double>& nodes, const std::vector<T>& f, const std::string& what) {
  if (f.size() != nodes.size())
    fail(ErrorCode::kSizeMismatch,
         what + ": " + std::to_string(nodes.size()) + " nodes but " + std::to_string(f.size()) +
             " values (need one f_i per t_i)",
         {{"nodes", nodes.size()}, {"values", f.size()}});
  for (std::size_t i = 0; i < f.size(); ++i) require_finite(f[i], what, at("f", i));
}

// ---- Gaussian elimination with partial pivoting ---------------------------

template <class T>
std::vector<T> gauss_solve_any(std::vector<std::vector<double>> A, std::vector<T> rhs) {
  const std::string what = "gauss_solve";
  const std::size_t n = A.size();
  if (rhs.size() != n)
    fail(ErrorCode::kSizeMismatch,
         what + ": the matrix has " + std::to_string(n) + " rows but the right-hand side has " +
             std::to_string(rhs.size()) + " entries",
         {{"rows", n}, {"rhs", rhs.size()}});
  for (std::size_t r = 0; r < n; ++r) {
    if (A[r].size() != n)
      fail(ErrorCode::kSizeMismatch,
           what + ": row " + std::to_string(r) + " has " + std::to_string(A[r].size()) + " entries, expected " +
               std::to_string(n) + " (the matrix must be square)",
           {{"row", r}, {"entries", A[r].size()}, {"expected", n}});
    for (std::size_t c = 0; c < n; ++c) require_finite(A[r][c], what, "A[" + std::to_string(r) + "][" + std::to_string(c) + "]");
    require_finite(rhs[r], what, at("rhs", r));
  }

  // Forward elimination: below the diagonal, column by column.
  for (std::size_t col = 0; col < n; ++col) {
    // Partial pivoting: bring up the row with the largest |entry| in this column.
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r)
      if (std::fabs(A[r][col]) > std::fabs(A[pivot][col])) pivot = r;
    if (A[pivot][col] == 0)
      fail(ErrorCode::kSingularMatrix,
           what + ": the matrix is singular (column " + std::to_string(col) + " has no non-zero pivot)",
           {{"column", col}});
    std::swap(A[col], A[pivot]);
    std::swap(rhs[col], rhs[pivot]);

    for (std::size_t r = col + 1; r < n; ++r) {
      const double factor = A[r][col] / A[col][col];
      if (factor == 0) continue;
      A[r][col] = 0;
      for (std::size_t c = col + 1; c < n; ++c) A[r][c] -= factor * A[col][c];
      rhs[r] -= factor * rhs[col];
    }
  }

  // Back substitution: the last unknown first.
  std::vector<T> x(n);
  for (std::size_t r = n; r-- > 0;) {
    T sum = rhs[r];
    for (std::size_t c = r + 1; c < n; ++c) sum -= A[r][c] * x[c];
    x[r] = sum / A[r][r];
  }
  return x;
}

template <class T>
std::vector<T> vandermonde_any(const std::vector<double>& nodes, const std::vector<T>& f) {
  const std::string what = "vandermonde_coefficients";
  require_nodes(nodes, what);
  require_values(nodes, f, what);
  return gauss_solve_any(vandermonde_matrix(nodes), f);
}

template <class T>
T monomial_any(const std::vector<T>& c, double t) {
  T p{};
  for (std::size_t j = c.size(); j-- > 0;) p = c[j] + t * p;  // Horner
  return p;
}

template <class T>
T lagrange_any(const std::vector<double>& nodes, const std::vector<T>& f, double t) {
  const std::string what = "lagrange_value";
  require_nodes(nodes, what);
  require_values(nodes, f, what);
  require_finite(t, what, "t");
  const std::vector<double> L = lagrange_basis_all(nodes, t);
  T p{};
  for (std::size_t i = 0; i < f.size(); ++i) p += L[i] * f[i];  // p(t) = sum f_i L_i(t)
  return p;
}

template <class T>
std::vector<std::vector<T>> divided_differences_any(const std::vector<double>& nodes, const std::vector<T>& f) {
  const std::string what = "divided_difference_table";
  require_nodes(nodes, what);
  require_values(nodes, f, what);
  const std::size_t n = nodes.size() - 1;
  std::vector<std::vector<T>> table(n + 1);
  table[0] = f;  // k = 0: f[t_j] = f_j
  for (std::size_t k = 1; k <= n; ++k) {
    table[k].resize(n + 1 - k);
    for (std::size_t j = 0; j + k <= n; ++j)
      table[k][j] = (table[k - 1][j + 1] - table[k - 1][j]) / (nodes[j + k] - nodes[j]);
  }
  return table;
}

template <class T>
std::vector<T> hermite_any(const std::vector<HermiteNode<T>>& nodes) {
  const std::string what = "hermite_coefficients";
  if (nodes.empty()) fail(ErrorCode::kEmptyInput, what + ": no nodes (need at least one t_i)", {{"nodes", 0}});
  std::vector<double> t;
  std::size_t conditions = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    t.push_back(nodes[i].t);
    if (nodes[i].derivatives.empty())
      fail(ErrorCode::kEmptyInput,
           what + ": node " + std::to_string(i) + " (t=" + num(nodes[i].t) +
               ") has no conditions (give at least its value)",
           {{"i", i}, {"t", nodes[i].t}});
    for (std::size_t j = 0; j < nodes[i].derivatives.size(); ++j)
      require_finite(nodes[i].derivatives[j], what,
                     "f" + std::to_string(i) + "^(" + std::to_string(j) + ")");
    conditions += nodes[i].derivatives.size();
  }
  require_nodes(t, what);

  // One row per condition p^(j)(t_i) = f_i^(j) (ch. 1 §1.6, Theorem 3):
  // d^j/dt^j t^k = k (k-1) ... (k-j+1) t^(k-j) for k >= j, else 0.
  std::vector<std::vector<double>> A;
  std::vector<T> rhs;
  for (const HermiteNode<T>& node : nodes) {
    for (std::size_t j = 0; j < node.derivatives.size(); ++j) {
      std::vector<double> row(conditions, 0.0);
      for (std::size_t k = j; k < conditions; ++k) {
        double falling = 1;  // k!/(k-j)!
        for (std::size_t q = 0; q < j; ++q) falling *= static_cast<double>(k - q);
        row[k] = falling * std::pow(node.t, static_cast<int>(k - j));
      }
      A.push_back(std::move(row));
      rhs.push_back(node.derivatives[j]);
    }
  }
  return gauss_solve_any(std::move(A), std::move(rhs));
}

/// How far t may miss [a, b] by round-off and still count as the end, relative
/// to max(|a|, |b|, b - a): the same allowance as kBezierParameterSlack
/// (bezier.h), so a sampling loop a + i (b - a) / N never fails at i = N.
constexpr double kSegmentSlack = 4 * std::numeric_limits<double>::epsilon();

/// The segment parameter: finite, inside [a, b] (snapped onto it when it
/// misses only by round-off). The message says which end t passed.
double checked_segment_parameter(double t, double a, double b, const std::string& what) {
  require_finite(t, what, "t");
  const double slack = kSegmentSlack * std::max({std::fabs(a), std::fabs(b), b - a});
  if (t < a - slack)
    fail(ErrorCode::kParameterOutsideDomain,
         what + ": t=" + num(t) + " is outside [" + num(a) + ", " + num(b) + "] (below " + num(a) + ")",
         {{"t", t}, {"a", a}, {"b", b}});
  if (t > b + slack)
    fail(ErrorCode::kParameterOutsideDomain,
         what + ": t=" + num(t) + " is outside [" + num(a) + ", " + num(b) + "] (above " + num(b) + ")",
         {{"t", t}, {"a", a}, {"b", b}});
  return std::clamp(t, a, b);
}

void require_segment_data(Vec3 p0, Vec3 m0, Vec3 p1, Vec3 m1, const std::string& what) {
  require_finite(p0, what, "p0");
  require_finite(m0, what, "m0");
  require_finite(p1, what, "p1");
  require_finite(m1, what, "m1");
}

}  // namespace

// ---- dense linear systems ---------------------------------------------------

std::vector<double> gauss_solve(std::vector<std::vector<double>> A, std::vector<double> rhs) {
  return gauss_solve_any(std::move(A), std::move(rhs));
}

std::vector<Vec3> gauss_solve(std::vector<std::vector<double>> A, std::vector<Vec3> rhs) {
  return gauss_solve_any(std::move(A), std::move(rhs));
}

// ---- monomial form and Vandermonde -------------------------------------------

std::vector<std::vector<double>> vandermonde_matrix(const std::vector<double>& nodes) {
  const std::size_t size = nodes.size();
  std::vector<std::vector<double>> A(size, std::vector<double>(size));
  for (std::size_t i = 0; i < size; ++i) {
    double power = 1;  // t_i^j, built up by multiplication
    for (std::size_t j = 0; j < size; ++j) {
      A[i][j] = power;
      power *= nodes[i];
    }
  }
  return A;
}

std::vector<double> vandermonde_coefficients(const std::vector<double>& nodes, const std::vector<double>& f) {
  return vandermonde_any(nodes, f);
}

std::vector<Vec3> vandermonde_coefficients(const std::vector<double>& nodes, const std::vector<Vec3>& f) {
  return vandermonde_any(nodes, f);
}

double monomial_value(const std::vector<double>& c, double t) { return monomial_any(c, t); }
Vec3 monomial_value(const std::vector<Vec3>& c, double t) { return monomial_any(c, t); }

// ---- Lagrange ----------------------------------------------------------------

double lagrange_basis(const std::vector<double>& nodes, int i, double t) {
  const std::string what = "lagrange_basis";
  require_nodes(nodes, what);
  require_finite(t, what, "t");
  if (i < 0 || i >= static_cast<int>(nodes.size()))
    fail(ErrorCode::kIndexOutOfRange, what + ": i=" + std::to_string(i) + " is outside 0.." +
         std::to_string(nodes.size() - 1), {{"i", i}, {"max", nodes.size() - 1}});
  // L_i(t) = prod_{k != i} (t - t_k) / (t_i - t_k)   (ch. 1 §1.6, Theorem 2)
  const std::size_t ii = static_cast<std::size_t>(i);
  double L = 1;
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (k != ii) L *= (t - nodes[k]) / (nodes[ii] - nodes[k]);
  return L;
}

std::vector<double> lagrange_basis_all(const std::vector<double>& nodes, double t) {
  const std::string what = "lagrange_basis_all";
  require_nodes(nodes, what);
  require_finite(t, what, "t");
  std::vector<double> L(nodes.size(), 1.0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (k != i) L[i] *= (t - nodes[k]) / (nodes[i] - nodes[k]);
  return L;
}

double lagrange_value(const std::vector<double>& nodes, const std::vector<double>& f, double t) {
  return lagrange_any(nodes, f, t);
}

Vec3 lagrange_value(const std::vector<double>& nodes, const std::vector<Vec3>& f, double t) {
  return lagrange_any(nodes, f, t);
}

// ---- Newton ------------------------------------------------------------------

double newton_basis(const std::vector<double>& nodes, int i, double t) {
  const std::string what = "newton_basis";
  require_finite(t, what, "t");
  if (i < 0 || i > static_cast<int>(nodes.size()))
    fail(ErrorCode::kIndexOutOfRange,
         what + ": i=" + std::to_string(i) + " is outside 0.." + std::to_string(nodes.size()) +
             " (N_i uses the nodes t_0..t_{i-1})",
         {{"i", i}, {"max", nodes.size()}});
  double N = 1;  // N_i(t) = prod_{k=0}^{i-1} (t - t_k)   (ch. 1 §1.6)
  for (int k = 0; k < i; ++k) {
    require_finite(nodes[static_cast<std::size_t>(k)], what, at("t", static_cast<std::size_t>(k)));
    N *= t - nodes[static_cast<std::size_t>(k)];
  }
  return N;
}

std::vector<std::vector<double>> divided_difference_table(const std::vector<double>& nodes,
                                                          const std::vector<double>& f) {
  return divided_differences_any(nodes, f);
}

std::vector<std::vector<Vec3>> divided_difference_table(const std::vector<double>& nodes, const std::vector<Vec3>& f) {
  return divided_differences_any(nodes, f);
}

template <class T>
void NewtonInterpolant<T>::add_node(double t, T value) {
  const std::string what = "Newton interpolant";
  require_finite(t, what, "t");
  require_finite(value, what, "value");
  for (std::size_t j = 0; j < nodes_.size(); ++j)
    if (nodes_[j] == t)
      fail(ErrorCode::kNodesCoincide,
           what + ": t=" + num(t) + " equals node " + at("t", j) + " (nodes must be pairwise distinct)",
           {{"t", t}, {"j", j}});

  // The new node is t_n. It adds the bottom diagonal of the scheme (ch. 1
  // §1.6): f[t_n], f[t_{n-1}, t_n], ..., f[t_0..t_n]. Each entry needs the one
  // just computed and one already in the table, so nothing else changes.
  const std::size_t n = nodes_.size();
  nodes_.push_back(t);
  table_.emplace_back();        // column k = n starts empty
  table_[0].push_back(value);   // f[t_n] = f_n
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t j = n - k;  // the new entry is f[t_j..t_n]
    table_[k].push_back((table_[k - 1][j + 1] - table_[k - 1][j]) / (nodes_[j + k] - nodes_[j]));
  }
}

template <class T>
std::vector<T> NewtonInterpolant<T>::coefficients() const {
  std::vector<T> a;
  a.reserve(table_.size());
  for (const std::vector<T>& column : table_) a.push_back(column.front());  // a_k = f[t_0..t_k]
  return a;
}

template <class T>
T NewtonInterpolant<T>::operator()(double t) const {
  const std::string what = "Newton interpolant";
  if (nodes_.empty()) fail(ErrorCode::kEmptyInput, what + ": no nodes yet (call add_node first)", {{"nodes", 0}});
  require_finite(t, what, "t");
  // Nested form: start with a_n, then p = a_i + (t - t_i) p for i = n-1..0.
  std::size_t i = nodes_.size() - 1;
  T p = table_[i].front();
  while (i-- > 0) p = table_[i].front() + (t - nodes_[i]) * p;
  return p;
}

template class NewtonInterpolant<double>;
template class NewtonInterpolant<Vec3>;

// ---- cubic Hermite -------------------------------------------------------------

HermiteBasis cubic_hermite_basis(double t) {
  require_finite(t, "cubic_hermite_basis", "t");
  const double t2 = t * t, t3 = t2 * t;
  // ch. 1 §1.6, "the resulting Hermite polynomials are":
  return {2 * t3 - 3 * t2 + 1,  // H0
          t3 - 2 * t2 + t,      // H0-bar
          -2 * t3 + 3 * t2,     // H1
          t3 - t2};             // H1-bar
}

HermiteBasis cubic_hermite_basis_derivative(double t) {
  require_finite(t, "cubic_hermite_basis_derivative", "t");
  const double t2 = t * t;
  return {6 * t2 - 6 * t, 3 * t2 - 4 * t + 1, -6 * t2 + 6 * t, 3 * t2 - 2 * t};
}

const std::array<std::array<double, 4>, 4>& hermite_matrix() {
  // ch. 1 §1.6: (c0, c1, c2, c3) = M (f(0), f'(0), f(1), f'(1)).
  static const std::array<std::array<double, 4>, 4> M = {{
      {{1, 0, 0, 0}},
      {{0, 1, 0, 0}},
      {{-3, -2, 3, -1}},
      {{2, 1, -2, 1}},
  }};
  return M;
}

Vec3 hermite_point(Vec3 p0, Vec3 m0, Vec3 p1, Vec3 m1, double t) {
  const std::string what = "hermite_point";
  require_segment_data(p0, m0, p1, m1, what);
  const HermiteBasis H = cubic_hermite_basis(checked_segment_parameter(t, 0, 1, what));
  // X(t) = H0 f(0) + H1 f(1) + H0-bar f'(0) + H1-bar f'(1)   (ch. 1 §1.6)
  return H.H0 * p0 + H.H1 * p1 + H.H0bar * m0 + H.H1bar * m1;
}

double hermite_value(double f0, double d0, double f1, double d1, double t) {
  const std::string what = "hermite_value";
  require_finite(f0, what, "f0");
  require_finite(d0, what, "d0");
  require_finite(f1, what, "f1");
  require_finite(d1, what, "d1");
  const HermiteBasis H = cubic_hermite_basis(checked_segment_parameter(t, 0, 1, what));
  return H.H0 * f0 + H.H1 * f1 + H.H0bar * d0 + H.H1bar * d1;
}

Vec3 hermite_derivative(Vec3 p0, Vec3 m0, Vec3 p1, Vec3 m1, double t) {
  const std::string what = "hermite_derivative";
  require_segment_data(p0, m0, p1, m1, what);
  const HermiteBasis dH = cubic_hermite_basis_derivative(checked_segment_parameter(t, 0, 1, what));
  return dH.H0 * p0 + dH.H1 * p1 + dH.H0bar * m0 + dH.H1bar * m1;
}

Vec3 hermite_point(Vec3 p0, Vec3 m0, Vec3 p1, Vec3 m1, double t, double a, double b) {
  const std::string what = "hermite_point";
  require_segment_data(p0, m0, p1, m1, what);
  require_finite(a, what, "a");
  require_finite(b, what, "b");
  if (!(a < b))
    fail(ErrorCode::kEmptyDomain, what + ": interval [a, b] = [" + num(a) + ", " + num(b) + "] is empty (need a < b)",
         {{"a", a}, {"b", b}});
  const double h = b - a;
  const HermiteBasis H = cubic_hermite_basis((checked_segment_parameter(t, a, b, what) - a) / h);
  return H.H0 * p0 + H.H1 * p1 + h * (H.H0bar * m0 + H.H1bar * m1);
}

// ---- general Hermite -----------------------------------------------------------

std::vector<double> hermite_coefficients(const std::vector<HermiteNode<double>>& nodes) { return hermite_any(nodes); }

std::vector<Vec3> hermite_coefficients(const std::vector<HermiteNode<Vec3>>& nodes) { return hermite_any(nodes); }

}  // namespace gllab::spline
