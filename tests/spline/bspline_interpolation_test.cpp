// tests/spline/bspline_interpolation_test.cpp — common/spline/bspline_interpolation.{h,cpp},
// the notes' B-spline interpolation ("Higher Order Surfaces", "Interpolation").
//
// Expected values: the conditions the notes set up (Q(t_{i+3}) = X_i, p_0 = p_1,
// p_n = p_{n-1}), checked with the project's own B-spline evaluator (bspline.h, The NURBS
// Book A3.1), and the core's clamped cubic spline (cubic_spline.h): on clamped knots
// the notes' end conditions mean zero end velocity, so the two agree exactly when the
// clamped spline is given zero end tangents, and differ for any other end tangents and
// from the natural spline.
#include "spline/bspline_interpolation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "spline/bspline.h"
#include "spline/cubic_spline.h"

namespace gllab::spline {
namespace {

constexpr double kExact = 1e-11;     // relative to the data size (coordinates up to 5)
constexpr double kDiffers = 1e-3;    // a different curve differs by more than this
constexpr int kSamples = 201;

std::vector<Vec3> random_points(std::size_t count, std::mt19937& rng) {
  std::uniform_real_distribution<double> c(-5, 5);
  std::vector<Vec3> P(count);
  for (Vec3& p : P) p = {c(rng), c(rng), c(rng)};
  return P;
}

std::vector<double> random_params(std::size_t count, std::mt19937& rng) {
  std::uniform_real_distribution<double> step(0.2, 2);
  std::vector<double> t = {0};
  while (t.size() < count) t.push_back(t.back() + step(rng));
  return t;
}

TEST(NotesBsplineInterpolation, PassesThroughTheDataWithTheNotesEndConstraints) {
  std::mt19937 rng(672);  // fixed seed
  for (std::size_t count : {2u, 3u, 4u, 9u, 30u}) {
    const std::vector<double> t = random_params(count, rng);
    const std::vector<Vec3> X = random_points(count, rng);
    // Clamped knots, and knots that continue the first/last interval outward.
    std::vector<double> open = {t[0] - 3, t[0] - 2, t[0] - 1};
    open.insert(open.end(), t.begin(), t.end());
    for (double d : {1.0, 2.0, 3.0}) open.push_back(t.back() + d);
    for (const std::vector<double>& U : {notes_clamped_knots(t), open}) {
      const BsplineCurve c = notes_interpolating_bspline(U, X);
      ASSERT_EQ(c.P.size(), count + 2);
      EXPECT_EQ(c.P[0], c.P[1]);
      EXPECT_EQ(c.P[count + 1], c.P[count]);
      for (std::size_t i = 0; i < count; ++i)
        EXPECT_LE(norm(curve_point(c, t[i]) - X[i]), kExact * 5) << count << " points, i " << i;
    }
  }
}

TEST(NotesBsplineInterpolation, OnClampedKnotsIsTheClampedSplineWithZeroEndTangents) {
  std::mt19937 rng(696);  // fixed seed
  for (std::size_t count : {2u, 5u, 12u}) {
    const std::vector<double> t = random_params(count, rng);
    const std::vector<Vec3> X = random_points(count, rng);
    const BsplineCurve c = notes_interpolating_bspline(notes_clamped_knots(t), X);
    const CubicSpline zero = clamped_cubic_spline(t, X, Vec3{0, 0, 0}, Vec3{0, 0, 0});
    const CubicSpline other = clamped_cubic_spline(t, X, Vec3{1, 0, 0}, Vec3{0, 1, 0});
    const CubicSpline natural = natural_cubic_spline(t, X);
    double same = 0, to_other = 0, to_natural = 0;
    for (int k = 0; k < kSamples; ++k) {
      const double u = k == kSamples - 1 ? t.back() : t[0] + (t.back() - t[0]) * k / (kSamples - 1);
      const Vec3 q = curve_point(c, u);
      same = std::max(same, norm(q - spline_point(zero, u)));
      to_other = std::max(to_other, norm(q - spline_point(other, u)));
      to_natural = std::max(to_natural, norm(q - spline_point(natural, u)));
    }
    EXPECT_LE(same, kExact * 5) << count;
    EXPECT_GT(to_other, kDiffers) << count;     // where they differ: the end tangents
    EXPECT_GT(to_natural, kDiffers) << count;   // S' = 0 at the ends, not S'' = 0
  }
}

TEST(NotesBsplineInterpolation, RejectsBadInput) {
  const std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}};
  EXPECT_THROW(notes_interpolating_bspline({0, 0, 0, 0, 1, 1, 1, 1}, X), std::invalid_argument);
  EXPECT_THROW(notes_interpolating_bspline(notes_clamped_knots({0, 1}), {{0, 0, 0}}),
               std::invalid_argument);
  EXPECT_THROW(notes_interpolating_bspline({0, 0, 0, 0, 1, 1, 1, 1, 1}, X), std::invalid_argument);
  EXPECT_THROW(notes_clamped_knots({0}), std::invalid_argument);
}

}  // namespace
}  // namespace gllab::spline
