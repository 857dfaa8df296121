// tests/mesh/level_of_detail_test.cpp — the resolution chosen from the size on
// screen (common/mesh/level_of_detail.h).
#include "mesh/level_of_detail.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace {

constexpr double kExact = 1e-12;
constexpr unsigned kSeed = 36;

// The sagitta of a hexagon in the unit circle: 1 - cos(30 deg) = 1 - sqrt(3)/2;
// of a square: 1 - cos(45 deg) = 1 - sqrt(2)/2.
TEST(ChordError, HexagonAndSquareByHand) {
  EXPECT_NEAR(gllab::chord_error(1, 6), 1 - std::sqrt(3.0) / 2, kExact);
  EXPECT_NEAR(gllab::chord_error(2, 4), 2 * (1 - std::sqrt(2.0) / 2), kExact);
  EXPECT_NEAR(gllab::chord_error(5, 2), 5, kExact);  // a diameter misses the circle by r
}

// A circle of 100 px at 0.5 px: 1 - cos(pi/n) <= 0.005 needs
// pi/n <= acos(0.995) = 0.100042, so n >= 31.40: 32 (by hand).
TEST(SegmentsForChordError, HundredPixelCircleAtHalfAPixelNeeds32) {
  EXPECT_EQ(gllab::segments_for_chord_error(100, 0.5), 32);
}

// Property: the answer is the smallest n that meets the error, on random sizes.
TEST(SegmentsForChordError, IsTheSmallestCountMeetingTheError) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> log_radius(-2, 4), log_error(-3, 0.5);
  for (int i = 0; i < 5000; ++i) {
    const double r = std::pow(10, log_radius(rng)), e = std::pow(10, log_error(rng));
    const int n = gllab::segments_for_chord_error(r, e, 3);
    EXPECT_GE(n, 3);
    EXPECT_LE(gllab::chord_error(r, n), e) << r << " " << e;
    if (n > 3) {
      EXPECT_GT(gllab::chord_error(r, n - 1), e) << r << " " << e;
    }
  }
}

// Small circles need only the minimum; the error halves, n grows by sqrt(2)
// (1 - cos x ~ x^2 / 2): from 100 px at 0.5 px (32) to 400 px, n doubles to 63 or 64.
TEST(SegmentsForChordError, SmallCirclesGetTheMinimumAndCountsGrowLikeTheSquareRoot) {
  EXPECT_EQ(gllab::segments_for_chord_error(0.2, 0.5, 3), 3);
  EXPECT_EQ(gllab::segments_for_chord_error(0, 0.5, 5), 5);
  const int n = gllab::segments_for_chord_error(400, 0.5);
  EXPECT_GE(n, 63);
  EXPECT_LE(n, 64);
}

// gluPerspective(fovy = 90 deg) in a 512 px high viewport: f = 256 / tan(45 deg) = 256 px,
// so a unit length at depth 4 covers 64 px.
TEST(ProjectedLength, NinetyDegreeCamera) {
  const double f = gllab::focal_length_px(90, 512);
  EXPECT_NEAR(f, 256, kExact);
  EXPECT_NEAR(gllab::projected_length(1, 4, f), 64, kExact);
}

TEST(LevelOfDetail, BadInputThrowsNamingTheValue) {
  try {
    gllab::segments_for_chord_error(1, 0);
    FAIL() << "zero error accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max error=0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gllab::segments_for_chord_error(1e20, 1e-20), std::invalid_argument);
  EXPECT_THROW(gllab::chord_error(1, 1), std::invalid_argument);
  EXPECT_THROW(gllab::projected_length(1, 0, 256), std::invalid_argument);
  EXPECT_THROW(gllab::focal_length_px(180, 512), std::invalid_argument);
}

}  // namespace
