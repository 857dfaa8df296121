// tests/spline/parameterization_test.cpp — parameter values for points
// (common/spline/parameterization.h; ch. 1 §1.6, "Parameterizations").
//
// Expected values are worked by hand in the comments, taken from the lecture's
// chordal example, or follow from a property (invariance under rigid or
// affine maps).
#include "spline/parameterization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace gllab::spline {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Hand-computed values involve a square root or pi at most: rounding only.
constexpr double kHandTolerance = 1e-12;
/// The lecture prints its chordal parameters with two decimals.
constexpr double kLecturePrintedPrecision = 0.01;
/// Invariance under a rigid or affine map, relative to t_n: rounding in the
/// transformed coordinates, the covariance and its eigen-decomposition.
constexpr double kInvarianceTolerance = 1e-12;
/// "Chordal is not affine invariant": a shear moves some normalized chordal
/// parameter by at least this much on the test data (it moves one by 0.35).
constexpr double kVisibleChange = 1e-2;

const std::vector<Parameterization> kAllMethods = {Parameterization::kUniform, Parameterization::kChordal,
                                                   Parameterization::kCentripetal, Parameterization::kFoley,
                                                   Parameterization::kNielson};

void expect_error(const std::function<void()>& f, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one containing \"" << part << "\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << "message: " << e.what();
  }
}

void expect_parameters(const std::vector<double>& t, const std::vector<double>& expected, double tolerance) {
  ASSERT_EQ(t.size(), expected.size());
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], expected[i], tolerance) << "t[" << i << "]";
}

std::vector<Vec3> random_points(std::size_t n, bool planar, std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-5, 5);
  std::vector<Vec3> P(n);
  for (Vec3& p : P) p = {coordinate(rng), coordinate(rng), planar ? 0.0 : coordinate(rng)};
  return P;
}

/// x -> A x + b, A given row by row.
std::vector<Vec3> affine_image(const std::vector<Vec3>& P, const double (&A)[3][3], Vec3 b) {
  std::vector<Vec3> Q;
  for (Vec3 p : P)
    Q.push_back(Vec3{A[0][0] * p.x + A[0][1] * p.y + A[0][2] * p.z, A[1][0] * p.x + A[1][1] * p.y + A[1][2] * p.z,
                     A[2][0] * p.x + A[2][1] * p.y + A[2][2] * p.z} +
                b);
  return Q;
}

// --- hand-worked values ---------------------------------------------------------------

// Points (0,0), (3,4), (3,5), (-1,2): chords (3,4), (0,1), (-4,-3) of lengths
// 5, 1, 5 (3-4-5 triangles); the closing chord (1,-2) has length sqrt(5).
const std::vector<Vec3> kFourPoints = {{0, 0, 0}, {3, 4, 0}, {3, 5, 0}, {-1, 2, 0}};

TEST(Parameters, UniformStepsByOne) {
  expect_parameters(parameters(kFourPoints, Parameterization::kUniform), {0, 1, 2, 3}, 0);
  expect_parameters(parameters(kFourPoints, Parameterization::kUniform, true), {0, 1, 2, 3, 4}, 0);
}

// ch. 1 §1.6 "Parameterizations", "Equidistant parameterization": on [a, b] the step is
// Delta t = (b - a)/n and t_i = a + i Delta t; the notes print t_i = a + i, which ends at b only
// when Delta t = 1. The core's uniform parameters step by 1 on [0, n]; rescaled to [0, 1] they
// must be i/n (1/3 apart for the four points, whatever their chords), and on [a, b] = [2, 5],
// n = 3, Delta t = 1: 2, 3, 4, 5; on [2, 8], Delta t = 2: 2, 4, 6, 8.
TEST(Parameters, EquidistantStepIsDeltaTNotesSlip) {
  const std::vector<double> unit =
      unit_interval_parameters(parameters(kFourPoints, Parameterization::kUniform));
  expect_parameters(unit, {0, 1.0 / 3, 2.0 / 3, 1}, kHandTolerance);
  using Interval = std::tuple<double, double, std::vector<double>>;
  for (const auto& [a, b, expected] :
       {Interval{2.0, 5.0, {2, 3, 4, 5}}, Interval{2.0, 8.0, {2, 4, 6, 8}}}) {
    std::vector<double> t;
    for (const double u : unit) t.push_back(a + (b - a) * u);
    expect_parameters(t, expected, kHandTolerance);
  }
}

// Chord lengths 5, 1, 5 summed: 0, 5, 6, 11; closed adds sqrt(5): 11 + sqrt(5).
TEST(Parameters, ChordalSumsChordLengthsByHand) {
  expect_parameters(parameters(kFourPoints, Parameterization::kChordal), {0, 5, 6, 11}, kHandTolerance);
  expect_parameters(parameters(kFourPoints, Parameterization::kChordal, true), {0, 5, 6, 11, 11 + std::sqrt(5.0)},
                    kHandTolerance);
}

// Square roots of 5, 1, 5: 0, sqrt5, sqrt5 + 1, 2 sqrt5 + 1; closed adds 5^(1/4).
TEST(Parameters, CentripetalSumsRootsOfChordLengthsByHand) {
  const double r5 = std::sqrt(5.0);
  expect_parameters(parameters(kFourPoints, Parameterization::kCentripetal), {0, r5, r5 + 1, 2 * r5 + 1},
                    kHandTolerance);
  expect_parameters(parameters(kFourPoints, Parameterization::kCentripetal, true),
                    {0, r5, r5 + 1, 2 * r5 + 1, 2 * r5 + 1 + std::sqrt(r5)}, kHandTolerance);
}

// Ch. 1 §1.6, "Interpolating with Bézier segments": P = (1,2), (2,1), (4,2),
// (6,6) with chordal parameters t = 0, 1.42, 3.66, 8.13 over [0, 8.13].
// Exactly: chords (1,-1), (2,1), (2,4) of lengths sqrt2, sqrt5, sqrt20, so
// t = 0, 1.41421, 3.65028, 8.12242. The lecture's values agree to its two printed
// decimals (it rounds up: 1.42, 3.66, 8.13 where 1.41, 3.65, 8.12 are nearest).
TEST(Parameters, ChordalMatchesLectureBezierInterpolationExample) {
  const std::vector<Vec3> P = {{1, 2, 0}, {2, 1, 0}, {4, 2, 0}, {6, 6, 0}};
  const std::vector<double> t = parameters(P, Parameterization::kChordal);
  const double r2 = std::sqrt(2.0), r5 = std::sqrt(5.0), r20 = std::sqrt(20.0);
  expect_parameters(t, {0, r2, r2 + r5, r2 + r5 + r20}, kHandTolerance);
  expect_parameters(t, {0, 1.42, 3.66, 8.13}, kLecturePrintedPrecision);
}

// Nielson metric of (0,0), (3,4), (3,9), the lecture's 2 x 2 formula by hand
// (ch. 1 §1.6, "Nielson metric"; 1/n sums around the mean):
//   mean = (2, 13/3); deviations x: -2, 1, 1; y: -13/3, -1/3, 14/3.
//   Sx2 = (4 + 1 + 1)/3 = 2;  Sy2 = (169 + 1 + 196)/27 = 122/9;
//   Sxy = (26/3 - 1/3 + 14/3)/3 = 13/3;  D = 2 * 122/9 - 169/9 = 25/3.
//   M = [Sy2 -Sxy; -Sxy Sx2] / D = [122/75 -13/25; -13/25 6/25].
// (The lecture prints +Sxy/D top right; a symmetric inverse has -Sxy/D in both
// corners, and only that makes the metric affine invariant, as tested below.)
TEST(NielsonMetric, LectureFormulaByHandForThreePoints) {
  const std::vector<double> M = nielson_metric({{0, 0, 0}, {3, 4, 0}, {3, 9, 0}});
  ASSERT_EQ(M.size(), 9u);
  EXPECT_NEAR(M[0], 122.0 / 75, kHandTolerance);
  EXPECT_NEAR(M[1], -13.0 / 25, kHandTolerance);
  EXPECT_NEAR(M[3], -13.0 / 25, kHandTolerance);
  EXPECT_NEAR(M[4], 6.0 / 25, kHandTolerance);
  // 2D points: nothing along z.
  EXPECT_NEAR(M[2], 0, kHandTolerance);
  EXPECT_NEAR(M[5], 0, kHandTolerance);
  EXPECT_NEAR(M[8], 0, kHandTolerance);
}

// With M above: |(3,4)|^2 = (122/75 * 9 - 2 * 13/25 * 12 + 6/25 * 16) = (122 - 104 + 32) * 3/25 = 6,
// |(0,5)|^2 = 6/25 * 25 = 6, and the closing chord |(-3,-9)|^2 = (122 - 234 + 162) * 3/25 = 6.
// (Any three points that span a plane are whitened into an equilateral
// triangle with covariance I: vertices sqrt2 from the centre, sides sqrt6.)
TEST(Parameters, NielsonChordsOfATriangleAreRootSix) {
  const std::vector<Vec3> P = {{0, 0, 0}, {3, 4, 0}, {3, 9, 0}};
  const double r6 = std::sqrt(6.0);
  expect_parameters(parameters(P, Parameterization::kNielson), {0, r6, 2 * r6}, kHandTolerance);
  expect_parameters(parameters(P, Parameterization::kNielson, true), {0, r6, 2 * r6, 3 * r6}, kHandTolerance);
}

// Foley on the same triangle: all chords sqrt6 and, in the whitened
// (equilateral) triangle, every angle is pi/3, so phi^ = min(pi - pi/3, pi/2) = pi/2.
// Open: each chord has one neighbour: dt = sqrt6 (1 + 1.5 * pi/2 * sqrt6 / (2 sqrt6))
// = sqrt6 (1 + 3 pi / 8).
TEST(Parameters, FoleyOnATriangleByHand) {
  const std::vector<Vec3> P = {{0, 0, 0}, {3, 4, 0}, {3, 9, 0}};
  const double step = std::sqrt(6.0) * (1 + 3 * kPi / 8);
  expect_parameters(parameters(P, Parameterization::kFoley), {0, step, 2 * step}, kHandTolerance);
}

// Foley on the unit square (0,0), (1,0), (1,1), (0,1):
//   mean (1/2, 1/2), Sx2 = Sy2 = 1/4, Sxy = 0, so M = 4 I and every side has
//   Nielson length 2; every angle is pi/2, so phi^ = min(pi/2, pi/2) = pi/2.
// Open: end chords have one neighbour, dt = 2 (1 + 1.5 * pi/2 * 1/2) = 2 (1 + 3pi/8);
//   the middle chord has two, dt = 2 (1 + 2 * 3pi/8) = 2 (1 + 3pi/4).
// Closed: every chord has two neighbours, dt = 2 (1 + 3pi/4).
TEST(Parameters, FoleyOnTheUnitSquareByHand) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const double end = 2 * (1 + 3 * kPi / 8), middle = 2 * (1 + 3 * kPi / 4);
  expect_parameters(parameters(P, Parameterization::kFoley), {0, end, end + middle, 2 * end + middle},
                    kHandTolerance);
  expect_parameters(parameters(P, Parameterization::kFoley, true), {0, middle, 2 * middle, 3 * middle, 4 * middle},
                    kHandTolerance);
  // A parallelogram is an affine image of the square: the same parameters.
  const std::vector<Vec3> Q = {{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 1, 0}};
  expect_parameters(parameters(Q, Parameterization::kFoley), {0, end, end + middle, 2 * end + middle},
                    kHandTolerance);
}

// Collinear points (0,0), (1,0), (3,0): the covariance has rank 1 (the lecture's
// D is 0); the metric works along the line. Mean x = 4/3, variance
// (16/9 + 1/9 + 25/9)/3 = 14/9, so a length L measures L / sqrt(14/9) = 3L/sqrt14:
// t = 0, 3/sqrt14, 9/sqrt14. Foley adds nothing on a straight run
// (phi = pi, phi^ = 0), so it equals Nielson here.
TEST(Parameters, CollinearPointsUseTheMetricAlongTheLine) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}};
  const double r14 = std::sqrt(14.0);
  expect_parameters(parameters(P, Parameterization::kNielson), {0, 3 / r14, 9 / r14}, kHandTolerance);
  expect_parameters(parameters(P, Parameterization::kFoley), {0, 3 / r14, 9 / r14}, kHandTolerance);
}

// For points spanning 3D the metric is the inverse covariance: M C = I.
TEST(NielsonMetric, InvertsTheCovarianceOfPointsSpanning3D) {
  std::mt19937 rng(5);  // fixed seed
  const std::vector<Vec3> P = random_points(12, false, rng);
  Vec3 mean;
  for (Vec3 p : P) mean += p / static_cast<double>(P.size());
  double C[3][3] = {};
  for (Vec3 p : P) {
    const double e[3] = {p.x - mean.x, p.y - mean.y, p.z - mean.z};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) C[i][j] += e[i] * e[j] / static_cast<double>(P.size());
  }
  const std::vector<double> M = nielson_metric(P);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double product = 0;
      for (int k = 0; k < 3; ++k) product += M[static_cast<std::size_t>(3 * i + k)] * C[k][j];
      EXPECT_NEAR(product, i == j ? 1.0 : 0.0, kInvarianceTolerance) << i << "," << j;
    }
}

TEST(UnitIntervalParameters, RescalesToZeroOne) {
  expect_parameters(unit_interval_parameters({0, 5, 6, 11}), {0, 5.0 / 11, 6.0 / 11, 1}, kHandTolerance);
  expect_parameters(unit_interval_parameters({2, 3, 6}), {0, 0.25, 1}, kHandTolerance);
}

// --- properties -------------------------------------------------------------------------

// Chordal uses Euclidean lengths: a rotation plus translation changes nothing.
TEST(Parameters, ChordalIsInvariantUnderRotationAndTranslation) {
  std::mt19937 rng(11);  // fixed seed
  const double c = std::cos(0.7), s = std::sin(0.7);
  // A rotation by 0.7 rad about z followed by one about x.
  const double Rz[3][3] = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
  const double Rx[3][3] = {{1, 0, 0}, {0, c, -s}, {0, s, c}};
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Vec3> P = random_points(8, false, rng);
    const std::vector<Vec3> Q = affine_image(affine_image(P, Rz, {}), Rx, {3, -7, 12});
    for (bool closed : {false, true}) {
      const std::vector<double> t = parameters(P, Parameterization::kChordal, closed);
      expect_parameters(parameters(Q, Parameterization::kChordal, closed), t, kInvarianceTolerance * t.back());
    }
  }
}

// The lecture's point about the Nielson metric (ch. 1 §1.6): it is affine
// invariant, so a shear and unequal scaling of the data leave the Nielson
// and Foley parameters unchanged, while chordal parameters (even rescaled to
// [0, 1]) change.
TEST(Parameters, NielsonAndFoleyAreAffineInvariantChordalIsNot) {
  std::mt19937 rng(13);  // fixed seed
  const double shear_2d[3][3] = {{2.0, 1.5, 0}, {0.0, 0.5, 0}, {0, 0, 1}};
  const double general_3d[3][3] = {{1.0, 2.0, -0.5}, {0.3, -1.0, 0.8}, {0.2, 0.4, 3.0}};
  double largest_chordal_change = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const bool planar = trial % 2 == 0;
    const std::vector<Vec3> P = random_points(7, planar, rng);
    const std::vector<Vec3> Q = affine_image(P, planar ? shear_2d : general_3d, {4, -2, planar ? 0.0 : 1});
    for (bool closed : {false, true}) {
      for (Parameterization method : {Parameterization::kNielson, Parameterization::kFoley}) {
        const std::vector<double> t = parameters(P, method, closed);
        expect_parameters(parameters(Q, method, closed), t, kInvarianceTolerance * t.back());
      }
      const std::vector<double> before = unit_interval_parameters(parameters(P, Parameterization::kChordal, closed));
      const std::vector<double> after = unit_interval_parameters(parameters(Q, Parameterization::kChordal, closed));
      for (std::size_t i = 0; i < before.size(); ++i)
        largest_chordal_change = std::max(largest_chordal_change, std::abs(after[i] - before[i]));
    }
  }
  EXPECT_GT(largest_chordal_change, kVisibleChange);
}

// 2D points stored with z = 0 and the same points lifted to the plane z = 5
// have the same Nielson parameters (the metric lives in the plane they span).
TEST(Parameters, NielsonIgnoresWhichPlaneHoldsPlanarPoints) {
  std::mt19937 rng(17);  // fixed seed
  std::vector<Vec3> P = random_points(6, true, rng);
  std::vector<Vec3> lifted = P;
  for (Vec3& p : lifted) p.z = 5;
  const std::vector<double> t = parameters(P, Parameterization::kNielson);
  expect_parameters(parameters(lifted, Parameterization::kNielson), t, kInvarianceTolerance * t.back());
}

// Every method gives n + 1 increasing values starting at 0, n + 2 when closed.
TEST(Parameters, EveryMethodIncreasesFromZero) {
  std::mt19937 rng(19);  // fixed seed
  const std::vector<Vec3> P = random_points(9, false, rng);
  for (Parameterization method : kAllMethods) {
    for (bool closed : {false, true}) {
      const std::vector<double> t = parameters(P, method, closed);
      ASSERT_EQ(t.size(), P.size() + (closed ? 1 : 0)) << parameterization_name(method);
      EXPECT_EQ(t[0], 0.0);
      for (std::size_t i = 1; i < t.size(); ++i) EXPECT_GT(t[i], t[i - 1]) << parameterization_name(method);
    }
  }
}

// Two points are enough; closed, the curve goes there and back.
TEST(Parameters, TwoPointsAreEnough) {
  const std::vector<Vec3> P = {{0, 0, 0}, {3, 4, 0}};
  expect_parameters(parameters(P, Parameterization::kChordal), {0, 5}, kHandTolerance);
  expect_parameters(parameters(P, Parameterization::kChordal, true), {0, 5, 10}, kHandTolerance);
  for (Parameterization method : kAllMethods) EXPECT_EQ(parameters(P, method).size(), 2u);
}

// --- errors ---------------------------------------------------------------------------------

TEST(Parameters, EmptyInputIsRejected) {
  expect_error([] { parameters({}, Parameterization::kChordal); }, "parameters (chordal): 0 points given, at least 2");
}

TEST(Parameters, OnePointIsRejected) {
  expect_error([] { parameters({{1, 2, 3}}, Parameterization::kUniform); }, "1 point given, at least 2");
}

TEST(Parameters, NanIsRejectedWithItsIndex) {
  const double nan = std::nan("");
  for (Parameterization method : kAllMethods)
    expect_error([&] { parameters({{0, 0, 0}, {nan, 1, 0}, {2, 2, 0}}, method); }, "P[1]=(nan, 1, 0) is not finite");
}

TEST(Parameters, CoincidentConsecutivePointsNameBothIndices) {
  const std::vector<Vec3> P = {{0, 0, 0}, {3, 4, 0}, {3, 4, 0}, {5, 5, 0}};
  for (Parameterization method : {Parameterization::kChordal, Parameterization::kCentripetal,
                                  Parameterization::kFoley, Parameterization::kNielson})
    expect_error([&] { parameters(P, method); }, "P[1]=(3, 4, 0) and P[2]=(3, 4, 0) coincide");
  // Uniform steps do not depend on distances: a repeated point is allowed.
  expect_parameters(parameters(P, Parameterization::kUniform), {0, 1, 2, 3}, 0);
}

// Closed: the closing chord P[n] -> P[0] must not be zero either (give each
// point once; the first point is not repeated at the end).
TEST(Parameters, ClosedWithRepeatedFirstPointIsRejected) {
  const std::vector<Vec3> P = {{0, 0, 0}, {3, 4, 0}, {6, 0, 0}, {0, 0, 0}};
  expect_error([&] { parameters(P, Parameterization::kChordal, true); },
               "P[3]=(0, 0, 0) and P[0]=(0, 0, 0) coincide");
}

TEST(NielsonMetric, AllPointsCoincidingIsRejected) {
  expect_error([] { nielson_metric({{1, 1, 1}, {1, 1, 1}}); }, "all 2 points coincide at (1, 1, 1)");
  expect_error([] { nielson_metric({}); }, "no points");
}

TEST(UnitIntervalParameters, DegenerateInputIsRejected) {
  expect_error([] { unit_interval_parameters({1}); }, "1 values given");
  expect_error([] { unit_interval_parameters({2, 2}); }, "t[0] = t[1] = 2");
}

}  // namespace
}  // namespace gllab::spline
