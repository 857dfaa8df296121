// common/spline/knots.cpp — knot vectors: the checks every curve and surface
// makes, the domain, the standard knot vectors and the Greville abscissae
// (see knots.h).
#include "spline/knots.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spline/errors.h"

namespace gllab::spline {

namespace {
int size_of(const std::vector<double>& U) { return static_cast<int>(U.size()); }

/// The knot-vector makers' check: 1 <= p <= n.
void check_degree_fits(const char* fn, int n, int p) {
  if (p < 1 || p > n)
    fail(ErrorCode::kOutOfRange,
         std::string(fn) + ": needs 1 <= p <= n, got p=" + std::to_string(p) + ", n=" + std::to_string(n),
         {{"p", p}, {"n", n}});
}
}  // namespace

// ---- checks -----------------------------------------------------------------

void validate_knots(int p, int num_points, const std::vector<double>& U, const char* what, const char* symbol) {
  const std::string S = symbol;  // "U" or "V": the array the messages name
  const std::string w = what;  // short: no allocation (SSO)
  if (num_points < 1) fail(ErrorCode::kEmptyInput, w + ": no control points (empty input)", {{"points", num_points}});
  if (p < 1) fail(ErrorCode::kDegreeTooLow, w + ": degree p=" + std::to_string(p) + " must be >= 1", {{"p", p}});
  if (p >= num_points)
    fail(ErrorCode::kTooFewPoints,
         w + ": degree p=" + std::to_string(p) + " needs at least p + 1 = " + std::to_string(p + 1) +
             " control points, has " + std::to_string(num_points),
         {{"p", p}, {"points", num_points}});
  if (p > kMaxDegree)
    fail(ErrorCode::kDegreeTooHigh,
         w + ": degree p=" + std::to_string(p) + " exceeds kMaxDegree=" + std::to_string(kMaxDegree), {{"p", p}});
  const int needed = num_points + p + 1;
  if (size_of(U) != needed)
    fail(ErrorCode::kKnotCount,
         w + " has " + std::to_string(U.size()) + " knots, needs n + p + 2 = " + std::to_string(needed) + " (" +
             std::to_string(num_points) + " points, degree " + std::to_string(p) + ")",
         {{"knots", U.size()}, {"needed", needed}});
  // (Messages are built only on failure: validate runs on every evaluation.)
  for (std::size_t i = 0; i < U.size(); ++i)
    if (!std::isfinite(U[i])) require_finite(U[i], w, at(symbol, i));
  for (std::size_t i = 1; i < U.size(); ++i)
    if (U[i] < U[i - 1])
      fail(ErrorCode::kKnotsDecreasing,
           w + ": " + at(symbol, i) + "=" + num(U[i]) + " < " + at(symbol, i - 1) + "=" + num(U[i - 1]) +
               " (must be non-decreasing)",
           {{"i", i}, {at(symbol, i), U[i]}, {at(symbol, i - 1), U[i - 1]}});
  for (std::size_t i = 0; i < U.size();) {
    std::size_t j = i;
    while (j < U.size() && U[j] == U[i]) ++j;
    if (static_cast<int>(j - i) > p + 1)
      fail(ErrorCode::kKnotMultiplicity,
           w + ": knot " + num(U[i]) + " has multiplicity " + std::to_string(j - i) + " (" + S + "[" +
               std::to_string(i) + ".." + std::to_string(j - 1) + "]), more than p + 1 = " + std::to_string(p + 1),
           {{"knot", U[i]}, {"multiplicity", j - i}, {"p", p}});
    i = j;
  }
  const int n = num_points - 1;
  if (!(U[p] < U[n + 1]))
    fail(ErrorCode::kEmptyDomain,
         w + ": the domain [" + S + "[" + std::to_string(p) + "], " + S + "[" + std::to_string(n + 1) + "]] = [" +
             num(U[p]) + ", " + num(U[n + 1]) + "] is empty",
         {{at(symbol, p), U[p]}, {at(symbol, n + 1), U[n + 1]}});
}

ParamInterval domain(int p, const std::vector<double>& U) { return {U[p], U[U.size() - p - 1]}; }

void require_in_domain(double u, ParamInterval dom) {
  if (!(u >= dom.a && u <= dom.b))
    fail(ErrorCode::kParameterOutsideDomain,
         "u=" + num(u) + " is outside the domain [" + num(dom.a) + ", " + num(dom.b) + "]",
         {{"u", u}, {"a", dom.a}, {"b", dom.b}});
}

int knot_multiplicity(const std::vector<double>& U, double u) {
  return static_cast<int>(std::count(U.begin(), U.end(), u));
}

// ---- knot vectors -----------------------------------------------------------

std::vector<double> clamped_uniform_knots(int n, int p) {
  check_degree_fits("clamped_uniform_knots", n, p);
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
  check_degree_fits("uniform_knots", n, p);
  std::vector<double> U(n + p + 2);
  for (int i = 0; i < n + p + 2; ++i) U[i] = i;
  return U;
}

std::vector<double> greville_abscissae(int p, const std::vector<double>& U) {
  if (p < 1) fail(ErrorCode::kDegreeTooLow, "greville_abscissae: p=" + std::to_string(p) + " must be >= 1", {{"p", p}});
  if (U.size() < static_cast<std::size_t>(p) + 2)
    fail(ErrorCode::kKnotCount,
         "greville_abscissae: " + std::to_string(U.size()) + " knots for degree " + std::to_string(p) +
             " leave no control point (at least p + 2 = " + std::to_string(p + 2) + " needed)",
         {{"knots", U.size()}, {"p", p}});
  const std::size_t count = U.size() - static_cast<std::size_t>(p) - 1;
  std::vector<double> xi(count);
  for (std::size_t i = 0; i < count; ++i) {
    double sum = 0;
    for (int k = 1; k <= p; ++k) sum += U[i + static_cast<std::size_t>(k)];
    xi[i] = sum / p;
  }
  return xi;
}

}  // namespace gllab::spline
