// tests/spline/forward_differences_test.cpp — plotting a cubic by forward
// differences (common/spline/forward_differences.cpp).
//
// Every expected value names its origin: exact arithmetic on dyadic data (where
// no operation rounds, forward differences must equal the polynomial exactly),
// the stated error growth (about n unit roundoffs after n steps, against a few
// for Horner at any n), the B-spline evaluator of bspline.cpp, or the lecture
// notes' loop run as written.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "spline/bspline.h"
#include "spline/forward_differences.h"
#include "spline_test_support.h"

namespace gllab::spline {
namespace {

using testing::error_of;

// Coefficients (a, b, c, d) of a segment of the notes' zigzag: values of size ~3.
std::array<Vec3, 4> zigzag() { return uniform_cubic_coefficients({-3, -1, 0}, {-1, 2, 0}, {1, -2, 0}, {3, 1, 0}); }

/// The largest |Q(t)| on [0, 1], sampled: the scale the errors are counted in.
double scale(const std::array<Vec3, 4>& abcd) {
  double m = 0;
  for (const Vec3& q : cubic_by_horner<double>(abcd, 1000)) m = std::max(m, norm(q));
  return m;
}

// Small integer coefficients and steps = 2^6: delta^3 = 2^-18, every difference
// is a multiple of 2^-18 below 2^6, which float's 24 bits hold: no operation
// rounds, so both precisions give the polynomial exactly.
TEST(ForwardDifferences, ExactOnDyadicData) {
  const std::array<Vec3, 4> abcd = {Vec3{3, -2, 1}, Vec3{-5, 4, 0}, Vec3{2, 1, -3}, Vec3{1, 0, 2}};
  const auto exact = cubic_by_horner<double>(abcd, 64);
  EXPECT_EQ(cubic_by_forward_differences<double>(abcd, 64), exact);
  EXPECT_EQ(cubic_by_forward_differences<float>(abcd, 64), exact);
  EXPECT_EQ(cubic_by_horner<float>(abcd, 64), exact);
}

// Error growth: after n steps forward differences are off by up to about n
// unit roundoffs of the curve's size; Horner stays within a few at any n.
TEST(ForwardDifferences, ErrorGrowsWithStepsAndHornersDoesNot) {
  const auto abcd = zigzag();
  const double size = scale(abcd);
  const double eps_f = std::numeric_limits<float>::epsilon(), eps_d = std::numeric_limits<double>::epsilon();
  for (int n : {10, 1000, 100000, 1000000}) {
    const double fd_f = cubic_plot_error(abcd, n, CubicMethod::kForwardFloat);
    const double fd_d = cubic_plot_error(abcd, n, CubicMethod::kForwardDouble);
    EXPECT_LE(fd_f, (n + 10) * eps_f * size) << "n = " << n;
    EXPECT_LE(fd_d, (n + 10) * eps_d * size) << "n = " << n;
    // Horner: t rounds once and each of 3 multiply-adds once, with |a| + |b| + |c| + |d| of ~ 3 size.
    EXPECT_LE(cubic_plot_error(abcd, n, CubicMethod::kHornerFloat), 8 * eps_f * size) << "n = " << n;
    EXPECT_LE(cubic_plot_error(abcd, n, CubicMethod::kHornerDouble), 8 * eps_d * size) << "n = " << n;
  }
  // The drift is real, not just allowed: from 10^3 to 10^6 steps it grows at least 100-fold.
  EXPECT_GT(cubic_plot_error(abcd, 1000000, CubicMethod::kForwardFloat),
            100 * cubic_plot_error(abcd, 1000, CubicMethod::kForwardFloat));
  EXPECT_GT(cubic_plot_error(abcd, 1000000, CubicMethod::kForwardDouble),
            100 * cubic_plot_error(abcd, 1000, CubicMethod::kForwardDouble));
}

// The notes' plot of a uniform cubic B-spline, by forward differences, lies on
// the B-spline that bspline.cpp evaluates (segment i at u = 3 + i + t on uniform knots).
TEST(ForwardDifferences, UniformBsplinePlotLiesOnTheCurve) {
  const std::vector<Vec3> P = {{-4, 1, 0}, {-3, 3, 0}, {-2, 4, 0}, {-1, 2, 0}, {1, 3, 0}, {2, 1, 0}, {3, 4, 0}};
  const int steps = 50;
  const std::vector<Vec3> plot = plot_uniform_cubic_bspline(P, steps);
  ASSERT_EQ(plot.size(), (P.size() - 3) * steps + 1);
  for (std::size_t i = 0; i + 3 < P.size(); ++i)
    for (int k = 0; k <= steps; ++k)
      testing::expect_near_vec(plot[i * steps + k], uniform_cubic_point(P, static_cast<int>(i), k / double(steps)),
                               testing::kSameCurve);
}

// The plot by forward differences and by Horner: the same points to rounding.
TEST(ForwardDifferences, PlotMethodsAgree) {
  const std::vector<Vec3> P = {{-4, 1, 0}, {-3, 3, 0}, {-2, 4, 0}, {-1, 2, 0}, {1, 3, 0}, {2, 1, 0}};
  const auto fd = plot_uniform_cubic_bspline(P, 200);
  const auto horner = plot_uniform_cubic_bspline(P, 200, CubicMethod::kHornerDouble);
  ASSERT_EQ(fd.size(), horner.size());
  for (std::size_t k = 0; k < fd.size(); ++k) testing::expect_near_vec(fd[k], horner[k], testing::kSameCurve);
}

// The notes' brute-force loop, run as written with delta = 0.05: t reaches
// 0.05 * 20 = 1.0000000000000002 > 1 after 20 points, so t = 1 is never drawn,
// and as each segment starts with MoveTo, every joint has a gap of one step.
TEST(ForwardDifferences, BruteForceLoopMissesTheEndNotesSlip) {
  const double delta = 0.05;
  int points = 0;
  double last = 0;
  for (double t = 0; t <= 1; t += delta) {
    ++points;
    last = t;
  }
  EXPECT_EQ(points, 20);  // not the 21 of t = 0, 0.05, ..., 1
  EXPECT_LT(last, 0.96);
  // Counting steps (as cubic_by_forward_differences does) gives all 21.
  EXPECT_EQ(cubic_by_forward_differences<double>(zigzag(), 20).size(), 21u);
}

TEST(ForwardDifferences, BadInputIsNamed) {
  EXPECT_ERROR_HAS(cubic_by_forward_differences<double>(zigzag(), 0), "steps=0");
  EXPECT_ERROR_HAS(cubic_by_horner<float>(zigzag(), kMaxForwardDifferenceSteps + 1), "steps=16777217");
  EXPECT_ERROR_HAS(plot_uniform_cubic_bspline({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, 10), "3 points");
  EXPECT_ERROR_HAS(plot_uniform_cubic_bspline({{0, 0, 0}, {1, 0, 0}, {2, NAN, 0}, {3, 0, 0}}, 10), "P[2]");
  const std::vector<Vec3> many(1003, Vec3{1, 2, 3});  // 1000 segments x 2^15 steps > 2^24 points
  EXPECT_ERROR_HAS(plot_uniform_cubic_bspline(many, 1 << 15), "1000 segments x steps=32768");
}

}  // namespace
}  // namespace gllab::spline
