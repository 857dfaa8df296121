// tests/spline/basis_change_test.cpp — common/spline/basis_change.{h,cpp}, the notes'
// "Changing Bases" (P1 = M1^-1 M2 P2). Property: the curve keeps its shape through every
// change of basis (all 16 ordered pairs of Bézier, uniform B-spline, Hermite, power),
// compared at kSamples parameters; and each basis point agrees with the core's own
// evaluator of that form (de Casteljau, hermite_point) where one exists.
#include "spline/basis_change.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "spline/bezier.h"
#include "spline/interpolation.h"

namespace gllab::spline {
namespace {

// Data of size <= 5; the B-spline basis inverse has entries up to 6 in size, so a round
// trip multiplies round-off by at most a few hundred: 1e-11 is far above it.
constexpr double kShapeTolerance = 1e-11;
constexpr int kSamples = 101;
constexpr CubicBasis kBases[] = {CubicBasis::kBezier, CubicBasis::kUniformBspline,
                                 CubicBasis::kHermite, CubicBasis::kPower};

TEST(ChangeCubicBasis, EveryOrderedPairKeepsTheCurve) {
  std::mt19937 rng(308);  // fixed seed
  std::uniform_real_distribution<double> c(-5, 5);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec3> P(4);
    for (Vec3& p : P) p = {c(rng), c(rng), c(rng)};
    for (CubicBasis from : kBases) {
      for (CubicBasis to : kBases) {
        const std::vector<Vec3> Q = change_cubic_basis(P, from, to);
        double worst = 0;
        for (int k = 0; k < kSamples; ++k) {
          const double u = static_cast<double>(k) / (kSamples - 1);
          const Vec3 d = cubic_basis_point(P, from, u) - cubic_basis_point(Q, to, u);
          worst = std::max(worst, norm(d));
        }
        EXPECT_LE(worst, kShapeTolerance)
            << static_cast<int>(from) << " -> " << static_cast<int>(to);
        if (from == to) {
          for (int i = 0; i < 4; ++i) EXPECT_LE(norm(Q[i] - P[i]), kShapeTolerance);
        }
      }
    }
    // The matrix forms agree with the core's own evaluators of each form.
    BezierCurve b;
    b.P = P;
    for (int k = 0; k < kSamples; ++k) {
      const double u = static_cast<double>(k) / (kSamples - 1);
      EXPECT_LE(norm(cubic_basis_point(P, CubicBasis::kBezier, u) - bezier_point(b, u)),
                kShapeTolerance);
      EXPECT_LE(norm(cubic_basis_point(P, CubicBasis::kHermite, u) -
                     hermite_point(P[0], P[1], P[2], P[3], u)),
                kShapeTolerance);
    }
  }
}

TEST(ChangeCubicBasis, KnownConversions) {
  // Uniform B-spline -> Bézier, by hand from the matrices: b_0 = (P0 + 4 P1 + P2) / 6,
  // b_1 = (2 P1 + P2) / 3, b_2 = (P1 + 2 P2) / 3, b_3 = (P1 + 4 P2 + P3) / 6
  // (the standard B-spline-to-Bézier rule, e.g. Farin, "Curves and Surfaces for CAGD").
  const std::vector<Vec3> P = {{0, 0, 0}, {6, 0, 0}, {6, 6, 0}, {0, 6, 0}};
  const std::vector<Vec3> b =
      change_cubic_basis(P, CubicBasis::kUniformBspline, CubicBasis::kBezier);
  const std::vector<Vec3> expected = {{5, 1, 0}, {6, 2, 0}, {6, 4, 0}, {5, 5, 0}};
  for (int i = 0; i < 4; ++i) EXPECT_LE(norm(b[i] - expected[i]), kShapeTolerance) << i;
  // Bézier -> Hermite: X'(0) = 3 (b_1 - b_0), X'(1) = 3 (b_3 - b_2) (ch. 1 §1.6).
  const std::vector<Vec3> h =
      change_cubic_basis(expected, CubicBasis::kBezier, CubicBasis::kHermite);
  EXPECT_LE(norm(h[0] - expected[0]), kShapeTolerance);
  EXPECT_LE(norm(h[1] - Vec3{3, 3, 0}), kShapeTolerance);
  EXPECT_LE(norm(h[2] - expected[3]), kShapeTolerance);
  EXPECT_LE(norm(h[3] - Vec3{-3, 3, 0}), kShapeTolerance);
  EXPECT_THROW(change_cubic_basis({{0, 0, 0}}, CubicBasis::kBezier, CubicBasis::kPower),
               std::invalid_argument);
}

}  // namespace
}  // namespace gllab::spline
