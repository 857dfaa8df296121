// common/spline/bspline_interpolation.cpp — see bspline_interpolation.h.
#include "spline/bspline_interpolation.h"

#include <stdexcept>
#include <string>

#include "spline/tridiagonal.h"

namespace gllab::spline {
namespace {

double ratio(double num, double den) { return den == 0 ? 0 : num / den; }

}  // namespace

std::vector<double> notes_clamped_knots(const std::vector<double>& params) {
  if (params.size() < 2)
    throw std::invalid_argument("notes_clamped_knots: needs >= 2 parameters, got " +
                                std::to_string(params.size()));
  std::vector<double> U(3, params.front());
  U.insert(U.end(), params.begin(), params.end());
  U.insert(U.end(), 3, params.back());
  return U;
}

BsplineCurve notes_interpolating_bspline(const std::vector<double>& U, const std::vector<Vec3>& X) {
  const std::size_t m = X.size();  // m = n - 1 data points
  if (m < 2) throw std::invalid_argument("notes_interpolating_bspline: needs >= 2 points, got " +
                                         std::to_string(m));
  if (U.size() != m + 6)
    throw std::invalid_argument("notes_interpolating_bspline: needs " + std::to_string(m + 6) +
                                " knots, got " + std::to_string(U.size()));
  for (std::size_t i = 1; i < U.size(); ++i)
    if (!(U[i] >= U[i - 1])) throw std::invalid_argument("notes_interpolating_bspline: knot " +
                                                         std::to_string(i) + " decreases");
  for (std::size_t i = 4; i <= m + 2; ++i)
    if (!(U[i] > U[i - 1])) throw std::invalid_argument("notes_interpolating_bspline: breakpoint " +
                                                        std::to_string(i) + " repeats");
  const std::vector<double>& t = U;
  const std::size_t n = m + 1;
  std::vector<double> lower(m), diag(m), upper(m);
  for (std::size_t i = 0; i < m; ++i) {
    // Notes' closed forms, "Interpolation": N_{i,4} at t_{i+3}, N_{i+1,4} at t_{(i+1)+2},
    // N_{i+2,4} at t_{(i+2)+1}.
    const double alpha = ratio((t[i + 4] - t[i + 3]) * (t[i + 4] - t[i + 3]),
                               (t[i + 4] - t[i + 1]) * (t[i + 4] - t[i + 2]));
    const std::size_t j = i + 1;
    const double beta = ratio((t[j + 2] - t[j]) * (t[j + 3] - t[j + 2]),
                              (t[j + 3] - t[j + 1]) * (t[j + 3] - t[j])) +
                        ratio((t[j + 4] - t[j + 2]) * (t[j + 2] - t[j + 1]),
                              (t[j + 4] - t[j + 1]) * (t[j + 3] - t[j + 1]));
    const std::size_t k = i + 2;
    const double gamma = ratio((t[k + 1] - t[k]) * (t[k + 1] - t[k]),
                               (t[k + 2] - t[k]) * (t[k + 3] - t[k]));
    // Unknowns p_1..p_{n-1} (row i couples p_i, p_{i+1}, p_{i+2}); p_0 = p_1, p_n = p_{n-1}.
    lower[i] = alpha, diag[i] = beta, upper[i] = gamma;
    if (i == 0) diag[i] += alpha, lower[i] = 0;
    if (i == m - 1) diag[i] += gamma, upper[i] = 0;
  }
  const std::vector<Vec3> inner = solve_tridiagonal(lower, diag, upper, X);
  BsplineCurve c;
  c.p = 3;
  c.U = U;
  c.P.push_back(inner.front());
  c.P.insert(c.P.end(), inner.begin(), inner.end());
  c.P.push_back(inner.back());
  if (c.P.size() != n + 1) throw std::logic_error("notes_interpolating_bspline: size");
  return c;
}

}  // namespace gllab::spline
