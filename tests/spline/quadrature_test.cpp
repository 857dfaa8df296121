// tests/spline/quadrature_test.cpp — Gauss–Legendre quadrature
// (common/spline/quadrature.cpp).
//
// Every expected value names its origin: the exact integral of x^k, the
// closed-form nodes and weights of Abramowitz and Stegun table 25.4 (the
// roots of P_2..P_5 in radicals), the rule's error term A&S 25.4.30, or a
// property of the rule (symmetry, the weights' sum).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "spline/quadrature.h"

namespace gllab::spline {
namespace {

// ---- tolerances (named, never loosened to pass) -----------------------------

/// One rounding of a value of size 1 (2^-52): the unit the bounds below count in.
constexpr double kUlp = 0x1p-52;
/// A node or weight against its closed form: Newton stops at a step <= 1e-16
/// (below half an ulp of nodes in [0.5, 1)), the weight is a few operations on
/// it, and the closed form itself rounds a square root or two: 4 ulps.
constexpr double kClosedForm = 4 * kUlp;
/// sum w_i x_i^k against the exact integral: n products and n additions of
/// terms whose absolute values sum to at most 2, each node and weight already
/// within a few ulps: 4 n ulps of 2.
double exactness_bound(int n) { return 4.0 * n * 2 * kUlp; }

/// integral_{-1}^{1} x^k dx: 2 / (k + 1) for even k, 0 for odd k.
double monomial_integral(int k) { return k % 2 ? 0.0 : 2.0 / (k + 1); }

double rule_sum(const GaussRule& r, int k) {
  double s = 0;
  for (std::size_t i = 0; i < r.x.size(); ++i) s += r.w[i] * std::pow(r.x[i], k);
  return s;
}

std::string error_of(int n) {
  try {
    gauss_legendre(n);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

// ---- exactness -------------------------------------------------------------

TEST(Quadrature, IntegratesEveryMonomialUpToDegreeTwoNMinusOne) {
  // Gauss 1814 (A&S 25.4.29): the n-point rule is exact for degree <= 2n - 1.
  for (int n = 1; n <= kMaxGaussPoints; ++n) {
    const GaussRule r = gauss_legendre(n);
    for (int k = 0; k <= 2 * n - 1; ++k)
      EXPECT_NEAR(rule_sum(r, k), monomial_integral(k), exactness_bound(n)) << "n " << n
                                                                           << " k " << k;
  }
}

TEST(Quadrature, MissesXToTheTwoNByTheErrorTermOfAbramowitzStegun) {
  // A&S 25.4.30: integral - rule = f^(2n)(xi) 2^(2n+1) (n!)^4 / ((2n+1) ((2n)!)^3);
  // for f = x^(2n), f^(2n) = (2n)! is constant, so the error is exactly
  // E_n = 2^(2n+1) (n!)^4 / ((2n+1) ((2n)!)^2) > 0: the rule is not exact.
  // n = 1..8, where E_n (>= 2.6e-9) is far above the rounding bound.
  for (int n = 1; n <= 8; ++n) {
    double fact_n = 1, fact_2n = 1;
    for (int i = 2; i <= n; ++i) fact_n *= i;
    for (int i = 2; i <= 2 * n; ++i) fact_2n *= i;
    const double e = std::pow(2.0, 2 * n + 1) * std::pow(fact_n, 4) /
                     ((2 * n + 1) * fact_2n * fact_2n);
    ASSERT_GT(e, 1e6 * exactness_bound(n)) << "n " << n;
    const double missed = monomial_integral(2 * n) - rule_sum(gauss_legendre(n), 2 * n);
    EXPECT_NEAR(missed, e, exactness_bound(n)) << "n " << n;
  }
}

// ---- the rule's shape -------------------------------------------------------

TEST(Quadrature, WeightsArePositiveAndSumToTwo) {
  // k = 0 of the exactness: sum w_i = integral of 1 = 2.
  for (int n = 1; n <= kMaxGaussPoints; ++n) {
    const GaussRule r = gauss_legendre(n);
    ASSERT_EQ(r.x.size(), std::size_t(n));
    ASSERT_EQ(r.w.size(), std::size_t(n));
    double sum = 0;
    for (double w : r.w) {
      EXPECT_GT(w, 0) << "n " << n;
      sum += w;
    }
    EXPECT_NEAR(sum, 2.0, exactness_bound(n)) << "n " << n;
  }
}

TEST(Quadrature, NodesAreIncreasingInsideAndSymmetric) {
  // P_n is even or odd: its roots come in pairs -x, +x with equal weights (the
  // header computes one of each pair, so the pair is exact, bit for bit), and
  // an odd n has the root 0 (exactly 0).
  for (int n = 1; n <= kMaxGaussPoints; ++n) {
    const GaussRule r = gauss_legendre(n);
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(r.x[i], -1.0);
      EXPECT_LT(r.x[i], 1.0);
      if (i > 0) {
        EXPECT_LT(r.x[i - 1], r.x[i]) << "n " << n << " i " << i;
      }
      EXPECT_EQ(r.x[i], -r.x[n - 1 - i]) << "n " << n << " i " << i;
      EXPECT_EQ(r.w[i], r.w[n - 1 - i]) << "n " << n << " i " << i;
    }
    if (n % 2 == 1) {
      EXPECT_EQ(r.x[n / 2], 0.0) << "n " << n;
    }
  }
}

TEST(Quadrature, OnePointRuleIsTheMidpointRule) {
  // P_1 = x: the root 0, the weight 2 / ((1 - 0) 1^2) = 2.
  const GaussRule r = gauss_legendre(1);
  EXPECT_EQ(r.x[0], 0.0);
  EXPECT_EQ(r.w[0], 2.0);
}

// ---- the closed forms of A&S table 25.4 ------------------------------------

void expect_rule(int n, const double (&x)[5], const double (&w)[5]) {
  const GaussRule r = gauss_legendre(n);
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(r.x[i], x[i], kClosedForm) << "n " << n << " node " << i;
    EXPECT_NEAR(r.w[i], w[i], kClosedForm) << "n " << n << " weight " << i;
  }
}

TEST(Quadrature, TwoToFivePointsMatchTheClosedFormsOfAbramowitzStegun) {
  // A&S table 25.4 gives the nodes and weights to 15 digits; these are the
  // same numbers in radicals, the roots of P_2..P_5:
  //   P_2 = (3x^2 - 1)/2:      x = +-1/sqrt(3), w = 1
  //   P_3 = (5x^3 - 3x)/2:     x = 0 (w 8/9), +-sqrt(3/5) (w 5/9)
  //   P_4 = (35x^4 - 30x^2 + 3)/8: x^2 = 3/7 -+ (2/7) sqrt(6/5), w = (18 +- sqrt 30)/36
  //   P_5: x = 0 (w 128/225), x = (1/3) sqrt(5 -+ 2 sqrt(10/7)), w = (322 +- 13 sqrt 70)/900
  const double r3 = 1 / std::sqrt(3.0);
  expect_rule(2, {-r3, r3}, {1, 1});
  const double q35 = std::sqrt(3.0 / 5);
  expect_rule(3, {-q35, 0, q35}, {5.0 / 9, 8.0 / 9, 5.0 / 9});
  const double a4 = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5));
  const double b4 = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
  const double wa4 = (18 + std::sqrt(30.0)) / 36, wb4 = (18 - std::sqrt(30.0)) / 36;
  expect_rule(4, {-b4, -a4, a4, b4}, {wb4, wa4, wa4, wb4});
  const double a5 = std::sqrt(5 - 2 * std::sqrt(10.0 / 7)) / 3;
  const double b5 = std::sqrt(5 + 2 * std::sqrt(10.0 / 7)) / 3;
  const double wa5 = (322 + 13 * std::sqrt(70.0)) / 900, wb5 = (322 - 13 * std::sqrt(70.0)) / 900;
  expect_rule(5, {-b5, -a5, 0, a5, b5}, {wb5, wa5, 128.0 / 225, wa5, wb5});
}

TEST(Quadrature, FourAndFivePointsMatchTheDigitsPrintedInAbramowitzStegun) {
  // A&S table 25.4, p. 916, as printed (15 decimals): a check of the radicals
  // above against the book, to its last printed digit.
  constexpr double kPrinted = 1e-15;
  const GaussRule r4 = gauss_legendre(4);
  EXPECT_NEAR(r4.x[2], 0.339981043584856, kPrinted);
  EXPECT_NEAR(r4.x[3], 0.861136311594053, kPrinted);
  EXPECT_NEAR(r4.w[2], 0.652145154862546, kPrinted);
  EXPECT_NEAR(r4.w[3], 0.347854845137454, kPrinted);
  const GaussRule r5 = gauss_legendre(5);
  EXPECT_NEAR(r5.x[3], 0.538469310105683, kPrinted);
  EXPECT_NEAR(r5.x[4], 0.906179845938664, kPrinted);
  EXPECT_NEAR(r5.w[2], 0.568888888888889, kPrinted);
  EXPECT_NEAR(r5.w[3], 0.478628670499366, kPrinted);
  EXPECT_NEAR(r5.w[4], 0.236926885056189, kPrinted);
}

// ---- bad input ---------------------------------------------------------------

TEST(Quadrature, CountOutsideOneToMaxThrowsNamingN) {
  // quadrature.h: n from 1 to kMaxGaussPoints, else std::invalid_argument naming n.
  EXPECT_EQ(error_of(0), "gauss_legendre: n = 0 (must be 1..64)");
  EXPECT_EQ(error_of(-3), "gauss_legendre: n = -3 (must be 1..64)");
  EXPECT_EQ(error_of(kMaxGaussPoints + 1), "gauss_legendre: n = 65 (must be 1..64)");
  EXPECT_NO_THROW(gauss_legendre(kMaxGaussPoints));
}

}  // namespace
}  // namespace gllab::spline
