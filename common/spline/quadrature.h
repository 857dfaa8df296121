// common/spline/quadrature.h — Gauss–Legendre quadrature: integrals of
// polynomials exactly (up to rounding), of smooth functions fast.
#pragma once

#include <vector>

namespace gllab::spline {

/// The n-point Gauss–Legendre rule on [-1, 1]: nodes x_i (increasing) and
/// weights w_i with  integral_{-1}^{1} f = sum_i w_i f(x_i)  exactly for every
/// polynomial f of degree <= 2n - 1 (Gauss 1814; Abramowitz and Stegun 25.4.29).
struct GaussRule {
  std::vector<double> x, w;
};

/// The nodes are the roots of the Legendre polynomial P_n, found by Newton's
/// method from Tricomi's estimate cos(pi (i - 1/4) / (n + 1/2)) with P_n and
/// P_n' from the three-term recurrence (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1};
/// w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2). n from 1 to kMaxGaussPoints, else
/// std::invalid_argument naming n.
inline constexpr int kMaxGaussPoints = 64;
GaussRule gauss_legendre(int n);

}  // namespace gllab::spline
