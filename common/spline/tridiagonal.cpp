// common/spline/tridiagonal.cpp — Thomas algorithm and its cyclic variant.
// The scalar and the Vec3 right-hand sides share one template: the matrix is
// always made of numbers, only the unknowns change type.
#include "spline/tridiagonal.h"

#include <cmath>
#include <cstddef>
#include <string>

#include "spline/errors.h"

namespace gllab::spline {
namespace {

/// A pivot counts as zero when it is this small relative to the magnitude of
/// its row (|lower| + |diag| + |upper|): a few rounding errors of that size.
constexpr double kZeroPivot = 1e-14;

bool finite(double v) { return std::isfinite(v); }
bool finite(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

template <class T>
void check_system(const std::string& what, const std::vector<double>& lower, const std::vector<double>& diag,
                  const std::vector<double>& upper, const std::vector<T>& rhs) {
  const std::size_t n = diag.size();
  if (lower.size() != n || upper.size() != n || rhs.size() != n)
    fail(ErrorCode::kSizeMismatch,
         what + ": size mismatch: lower has " + std::to_string(lower.size()) + ", diag " + std::to_string(n) +
             ", upper " + std::to_string(upper.size()) + ", rhs " + std::to_string(rhs.size()) +
             " entries (all must be equal)",
         {{"lower", lower.size()}, {"diag", n}, {"upper", upper.size()}, {"rhs", rhs.size()}});
  // Test first, build the message only on failure: at("lower", i) makes a
  // std::string, and doing that eagerly for every entry cost more than the
  // solve itself (bench/README.md, natural_spline).
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(lower[i])) require_finite(lower[i], what, at("lower", i));
    if (!std::isfinite(diag[i])) require_finite(diag[i], what, at("diag", i));
    if (!std::isfinite(upper[i])) require_finite(upper[i], what, at("upper", i));
    if (!finite(rhs[i])) require_finite(rhs[i], what, at("rhs", i));
  }
}

[[noreturn]] void zero_pivot(const std::string& what, std::size_t row, double pivot) {
  fail(ErrorCode::kSingularMatrix,
       what + ": zero pivot " + num(pivot) + " in row " + std::to_string(row) +
           " (the matrix needs pivoting or is singular)",
       {{"row", row}, {"pivot", pivot}});
}

/// Thomas algorithm (Gaussian elimination on a tridiagonal matrix; ch. 1
/// §1.6 calls it "the LU decomposition for tridiagonal matrices").
/// Forward sweep: eliminate lower[i] with row i-1, which leaves row i as
///     x[i] + upper_[i] x[i+1] = rhs_[i],
/// where upper_[i] = upper[i] / m and rhs_[i] = (rhs[i] - lower[i] rhs_[i-1]) / m
/// with the pivot m = diag[i] - lower[i] upper_[i-1].
/// Back substitution: x[N-1] = rhs_[N-1], x[i] = rhs_[i] - upper_[i] x[i+1].
template <class T>
std::vector<T> thomas(const std::string& what, const std::vector<double>& lower, const std::vector<double>& diag,
                      const std::vector<double>& upper, const std::vector<T>& rhs) {
  const std::size_t n = diag.size();
  std::vector<double> upper_(n);
  std::vector<T> x(n);  // holds rhs_ until the back substitution overwrites it
  for (std::size_t i = 0; i < n; ++i) {
    const double l = i > 0 ? lower[i] : 0.0;
    const double u = i + 1 < n ? upper[i] : 0.0;
    const double pivot = diag[i] - (i > 0 ? l * upper_[i - 1] : 0.0);
    const double row_size = std::abs(l) + std::abs(diag[i]) + std::abs(u);
    // "!(a > b)" also rejects a NaN pivot.
    if (!(std::abs(pivot) > kZeroPivot * row_size)) zero_pivot(what, i, pivot);
    upper_[i] = u / pivot;
    x[i] = (i > 0 ? rhs[i] - l * x[i - 1] : rhs[i]) / pivot;
  }
  for (std::size_t i = n; i-- > 1;) x[i - 1] = x[i - 1] - upper_[i - 1] * x[i];
  return x;
}

/// Cyclic tridiagonal system by Sherman–Morrison (Numerical Recipes, 3rd ed.,
/// §2.7.2 "Cyclic Tridiagonal Systems"). Write A = B + u v^T where B is
/// tridiagonal and the rank-one term u v^T carries the two corner entries
///     alpha = A[0][N-1] = lower[0],  beta = A[N-1][0] = upper[N-1]:
///     u = (gamma, 0, ..., 0, beta),  v = (1, 0, ..., 0, alpha / gamma),
/// so B equals A except B[0][0] = diag[0] - gamma and
/// B[N-1][N-1] = diag[N-1] - alpha beta / gamma. Solve B y = rhs and B z = u;
/// then x = y - z (v.y) / (1 + v.z). gamma = -diag[0] keeps B[0][0] away from
/// zero (Numerical Recipes' choice).
template <class T>
std::vector<T> cyclic(const std::string& what, const std::vector<double>& lower, const std::vector<double>& diag,
                      const std::vector<double>& upper, const std::vector<T>& rhs) {
  check_system(what, lower, diag, upper, rhs);
  const std::size_t n = diag.size();
  if (n == 0) return {};
  if (n == 1) {
    // One unknown: both corner entries are the matrix entry itself.
    const double a = lower[0] + diag[0] + upper[0];
    if (!(std::abs(a) > kZeroPivot * (std::abs(lower[0]) + std::abs(diag[0]) + std::abs(upper[0]))))
      zero_pivot(what, 0, a);
    return {rhs[0] / a};
  }
  if (n == 2) {
    // Row 0: diag[0] x0 + (lower[0] + upper[0]) x1; row 1: (lower[1] + upper[1]) x0 + diag[1] x1.
    // Cramer's rule on the 2 x 2 matrix [[a, b], [c, d]].
    const double a = diag[0], b = lower[0] + upper[0];
    const double c = lower[1] + upper[1], d = diag[1];
    const double det = a * d - b * c;
    const double size = (std::abs(a) + std::abs(b)) * (std::abs(c) + std::abs(d));
    if (!(std::abs(det) > kZeroPivot * size)) zero_pivot(what, 1, det);
    return {(d * rhs[0] - b * rhs[1]) / det, (a * rhs[1] - c * rhs[0]) / det};
  }
  const double alpha = lower[0];
  const double beta = upper[n - 1];
  const double gamma = -diag[0];
  if (gamma == 0) zero_pivot(what, 0, diag[0]);
  std::vector<double> b_diag = diag;
  b_diag[0] = diag[0] - gamma;
  b_diag[n - 1] = diag[n - 1] - alpha * beta / gamma;
  const std::vector<T> y = thomas(what, lower, b_diag, upper, rhs);
  std::vector<double> u(n, 0.0);
  u[0] = gamma;
  u[n - 1] = beta;
  const std::vector<double> z = thomas(what, lower, b_diag, upper, u);
  const double denominator = 1.0 + z[0] + alpha / gamma * z[n - 1];
  if (!(std::abs(denominator) > kZeroPivot))
    fail(ErrorCode::kSingularMatrix,
         what + ": the matrix is singular (Sherman–Morrison denominator 1 + v.z = " + num(denominator) + ")",
         {{"denominator", denominator}});
  const T factor = (y[0] + alpha / gamma * y[n - 1]) / denominator;
  std::vector<T> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = y[i] - z[i] * factor;
  return x;
}

}  // namespace

std::vector<double> solve_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                      const std::vector<double>& upper, const std::vector<double>& rhs) {
  check_system("solve_tridiagonal", lower, diag, upper, rhs);
  return thomas("solve_tridiagonal", lower, diag, upper, rhs);
}

std::vector<Vec3> solve_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                    const std::vector<double>& upper, const std::vector<Vec3>& rhs) {
  check_system("solve_tridiagonal", lower, diag, upper, rhs);
  return thomas("solve_tridiagonal", lower, diag, upper, rhs);
}

std::vector<double> solve_cyclic_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                             const std::vector<double>& upper, const std::vector<double>& rhs) {
  return cyclic("solve_cyclic_tridiagonal", lower, diag, upper, rhs);
}

std::vector<Vec3> solve_cyclic_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                           const std::vector<double>& upper, const std::vector<Vec3>& rhs) {
  return cyclic("solve_cyclic_tridiagonal", lower, diag, upper, rhs);
}

}  // namespace gllab::spline
