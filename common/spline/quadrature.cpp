// common/spline/quadrature.cpp — Gauss–Legendre nodes and weights (quadrature.h).
#include "spline/quadrature.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gllab::spline {

namespace {

// P_n(x) and P_n'(x) by the three-term recurrence; P_n' = n (x P_n - P_{n-1}) / (x^2 - 1).
void legendre(int n, double x, double& p, double& dp) {
  double p0 = 1, p1 = x;
  for (int k = 1; k < n; ++k) {
    const double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
    p0 = p1;
    p1 = p2;
  }
  p = p1;
  dp = n * (x * p1 - p0) / (x * x - 1);
}

}  // namespace

GaussRule gauss_legendre(int n) {
  if (n < 1 || n > kMaxGaussPoints)
    throw std::invalid_argument("gauss_legendre: n = " + std::to_string(n) + " (must be 1.." +
                                std::to_string(kMaxGaussPoints) + ")");
  const double pi = std::acos(-1.0);
  GaussRule rule;
  rule.x.resize(n);
  rule.w.resize(n);
  // The roots come in pairs -x, +x: find the positive one of each pair.
  for (int i = 1; i <= (n + 1) / 2; ++i) {
    double x = std::cos(pi * (i - 0.25) / (n + 0.5)), p = 0, dp = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      legendre(n, x, p, dp);
      const double step = p / dp;
      x -= step;
      if (std::fabs(step) <= 1e-16) break;
    }
    legendre(n, x, p, dp);
    const double w = 2 / ((1 - x * x) * dp * dp);
    rule.x[n - i] = x, rule.w[n - i] = w;
    rule.x[i - 1] = -x, rule.w[i - 1] = w;
  }
  if (n % 2 == 1) rule.x[n / 2] = 0;  // the middle root, exactly
  return rule;
}

}  // namespace gllab::spline
