// tests/image/compare_test.cpp · tests for common/image/compare.cpp
// Small images whose statistics can be worked out by hand (the arithmetic is in
// the comments), plus properties over many inputs.
#include "image/compare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "test_images.h"

using gllab::Comparison;
using gllab::Image;
using gllab::Tolerance;

namespace {

using gllab::testing::random_image;
using gllab::testing::rgba_at;

// Hand-computed results are exact fractions; the PSNR literals are rounded to
// the digits written, so they get a looser tolerance.
constexpr double kExact = 1e-12;     // same formula evaluated twice
constexpr double kDbDigits = 1e-6;   // a PSNR literal written to 8 significant digits

// Every pixel (r, g, b, a).
Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = r, p[1] = g, p[2] = b, p[3] = a;
    }
  return img;
}

// --- compare_images ------------------------------------------------------------

TEST(CompareImages, IdenticalImagesHaveNoDifferenceAndInfinitePsnr) {
  const Image img = random_image(16, 9, 1);
  const Comparison c = gllab::compare_images(img, img, 0);
  EXPECT_EQ(c.total_pixels, 16 * 9);
  EXPECT_EQ(c.differing_pixels, 0);
  EXPECT_EQ(c.max_delta, 0);
  EXPECT_EQ(c.mean_abs_error, 0.0);
  // MSE is 0, so PSNR = 10 log10(255^2 / 0) = +infinity (compare.h).
  EXPECT_TRUE(std::isinf(c.psnr) && c.psnr > 0) << c.psnr;
  EXPECT_TRUE(c.passes(Tolerance{0, 0.0}));
}

TEST(CompareImages, OneChannelOffByTenIn2x2) {
  const Image reference = filled(2, 2, 50, 60, 70, 255);
  Image test = reference;
  test.pixel(1, 0)[1] += 10;  // green of one pixel: 60 -> 70

  // A pixel differs when its max channel delta > threshold: 10 > 9, but not 10 > 10.
  const Comparison at9 = gllab::compare_images(reference, test, 9);
  EXPECT_EQ(at9.differing_pixels, 1);
  EXPECT_EQ(gllab::compare_images(reference, test, 10).differing_pixels, 0);

  EXPECT_EQ(at9.total_pixels, 4);
  EXPECT_EQ(at9.max_delta, 10);
  // 2x2 pixels * 4 channels = 16 samples; one is off by 10.
  // MAE = 10/16 = 0.625; MSE = 10^2/16 = 6.25;
  // PSNR = 10 log10(255^2 / 6.25) = 10 log10(10404) = 40.172003 dB.
  EXPECT_NEAR(at9.mean_abs_error, 10.0 / 16.0, kExact);
  EXPECT_NEAR(at9.psnr, 10.0 * std::log10(255.0 * 255.0 / (100.0 / 16.0)), kExact);
  EXPECT_NEAR(at9.psnr, 40.1720034, kDbDigits);
}

TEST(CompareImages, DeltasAreAbsoluteAndCountEveryChannel) {
  // 2x1: pixel 0 has R +3 and G -4 (max channel delta 4), pixel 1 has A -200.
  Image reference = filled(2, 1, 100, 100, 100, 250);
  Image test = reference;
  test.pixel(0, 0)[0] = 103;
  test.pixel(0, 0)[1] = 96;
  test.pixel(1, 0)[3] = 50;

  // Pixel deltas are 4 and 200: both exceed 3, only the second exceeds 4.
  EXPECT_EQ(gllab::compare_images(reference, test, 3).differing_pixels, 2);
  const Comparison c = gllab::compare_images(reference, test, 4);
  EXPECT_EQ(c.differing_pixels, 1);
  EXPECT_EQ(c.max_delta, 200);
  // 8 samples: MAE = (3 + 4 + 200)/8 = 25.875; MSE = (9 + 16 + 40000)/8 = 5003.125;
  // PSNR = 10 log10(65025 / 5003.125) = 11.138390 dB.
  EXPECT_NEAR(c.mean_abs_error, 25.875, kExact);
  EXPECT_NEAR(c.psnr, 11.1383901, kDbDigits);
  // Swapping the images changes no statistic (all deltas are absolute).
  const Comparison swapped = gllab::compare_images(test, reference, 4);
  EXPECT_EQ(swapped.differing_pixels, c.differing_pixels);
  EXPECT_EQ(swapped.max_delta, c.max_delta);
  EXPECT_EQ(swapped.mean_abs_error, c.mean_abs_error);
  EXPECT_EQ(swapped.psnr, c.psnr);
}

TEST(CompareImages, BlackAgainstWhiteIsTheLargestDifference) {
  // RGB off by 255, alpha equal: MAE = 3*255/4 = 191.25; MSE = 3*255^2/4,
  // PSNR = 10 log10(4/3) = 1.2493874 dB.
  const Comparison c = gllab::compare_images(filled(3, 3, 0, 0, 0, 255),
                                             filled(3, 3, 255, 255, 255, 255), 254);
  EXPECT_EQ(c.max_delta, 255);
  EXPECT_EQ(c.differing_pixels, 9);  // 255 > 254 everywhere
  EXPECT_NEAR(c.mean_abs_error, 191.25, kExact);
  EXPECT_NEAR(c.psnr, 1.2493874, kDbDigits);
}

TEST(CompareImages, SizeMismatchNamesBothSizes) {
  try {
    gllab::compare_images(Image(512, 512), Image(256, 256), 0);
    ADD_FAILURE() << "no exception";
  } catch (const gllab::ImageError& e) {
    EXPECT_STREQ(e.what(), "compare: size mismatch: reference 512x512, test 256x256");  // compare.h
  }
}

TEST(CompareImages, BadInputsThrowInvalidArgument) {
  const Image img(2, 2);
  EXPECT_THROW(gllab::compare_images(img, img, -1), std::invalid_argument);
  EXPECT_THROW(gllab::compare_images(img, img, 256), std::invalid_argument);
  EXPECT_THROW(gllab::compare_images(Image{}, Image{}, 0), std::invalid_argument);  // 0x0
  Image short_rgba = img;
  short_rgba.rgba.pop_back();
  EXPECT_THROW(gllab::compare_images(img, short_rgba, 0), std::invalid_argument);
}

// --- Comparison::passes ----------------------------------------------------------

TEST(ComparisonPasses, BoundaryShareIsInclusive) {
  // 1 differing pixel of 100x10 = 1000: share 1/1000. IEEE division is correctly
  // rounded, and so is the literal 0.001, so both are the same double.
  const Image reference = filled(100, 10, 0, 0, 0, 255);
  Image test = reference;
  test.pixel(42, 7)[0] = 255;
  const Comparison c = gllab::compare_images(reference, test, 2);
  ASSERT_EQ(c.differing_pixels, 1);
  EXPECT_EQ(c.differing_share(), 0.001);

  EXPECT_TRUE(c.passes(Tolerance{2, 0.001}));     // share <= max: pass at equality
  EXPECT_FALSE(c.passes(Tolerance{2, 0.000999}));  // just under the share: fail
  EXPECT_FALSE(c.passes(Tolerance{2, 0.0}));
  EXPECT_TRUE(c.passes(Tolerance{2, 1.0}));
}

TEST(ComparisonPasses, ToleranceWithAnotherThresholdThrows) {
  // differing_pixels was counted with threshold 2; a Tolerance that says 5 would
  // be judged on the wrong count, so passes() refuses loudly.
  const Image img(2, 2);
  const Comparison c = gllab::compare_images(img, img, 2);
  EXPECT_THROW(c.passes(Tolerance{5, 0.5}), std::invalid_argument);
}

// --- heat_map -------------------------------------------------------------------

TEST(HeatMap, UnchangedPixelsAreDarkGreyAndChangedOnesHot) {
  const Image reference = filled(3, 2, 100, 150, 200, 255);
  Image test = reference;
  test.pixel(2, 1)[2] = 0;  // blue 200 -> 0: delta 200

  const Image map = gllab::heat_map(reference, test, 8);
  ASSERT_EQ(map.width, reference.width);
  ASSERT_EQ(map.height, reference.height);
  // Unchanged: luma = (77*100 + 150*150 + 29*200 + 128) >> 8 = 36128 >> 8 = 141,
  // grey = 141/4 = 35 (compare.cpp: Rec. 601 weights in 1/256ths, then luma/4).
  EXPECT_EQ(rgba_at(map, 0, 0), (std::vector<std::uint8_t>{35, 35, 35, 255}));
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      if (x == 2 && y == 1) continue;
      const std::uint8_t* p = map.pixel(x, y);
      EXPECT_TRUE(p[0] == p[1] && p[1] == p[2]) << x << "," << y;
    }
  // Changed: on the yellow-to-red ramp (compare.h), fully opaque.
  const std::uint8_t* hot = map.pixel(2, 1);
  EXPECT_EQ(hot[0], 255);
  EXPECT_EQ(hot[2], 0);
  EXPECT_EQ(hot[3], 255);
}

TEST(HeatMap, RampRunsFromYellowToRed) {
  // compare.h: yellow (255,255,0) just over the threshold, red (255,0,0) at 255,
  // and green never increases in between (property over every delta).
  constexpr int kThreshold = 10;
  const Image reference = filled(1, 1, 0, 0, 0, 255);
  int previous_green = 256;
  for (int delta = kThreshold + 1; delta <= 255; ++delta) {
    Image test = reference;
    test.pixel(0, 0)[0] = std::uint8_t(delta);
    const std::vector<std::uint8_t> p = rgba_at(gllab::heat_map(reference, test, kThreshold), 0, 0);
    EXPECT_EQ(p[0], 255) << delta;
    EXPECT_EQ(p[2], 0) << delta;
    EXPECT_LE(p[1], previous_green) << delta;
    previous_green = p[1];
    if (delta == kThreshold + 1) {
      EXPECT_EQ(p, (std::vector<std::uint8_t>{255, 255, 0, 255}));
    }
    if (delta == 255) {
      EXPECT_EQ(p, (std::vector<std::uint8_t>{255, 0, 0, 255}));
    }
  }
}

TEST(HeatMap, Threshold254LeavesOnlyRed) {
  // The ramp has one step (delta 255), which is red.
  const Comparison c = gllab::compare_images(filled(1, 1, 0, 0, 0, 0), filled(1, 1, 255, 0, 0, 0), 254);
  EXPECT_EQ(c.differing_pixels, 1);
  const Image map = gllab::heat_map(filled(1, 1, 0, 0, 0, 0), filled(1, 1, 255, 0, 0, 0), 254);
  EXPECT_EQ(rgba_at(map, 0, 0), (std::vector<std::uint8_t>{255, 0, 0, 255}));
}

TEST(HeatMap, HotPixelsMatchCompareImagesCount) {
  // Property: heat_map marks exactly the pixels compare_images counts as differing
  // (hot pixels have red 255 and blue 0; grey ones have red <= 255/4).
  const Image reference = random_image(32, 16, 5);
  Image test = reference;
  std::mt19937 rng(6);
  std::uniform_int_distribution<int> nudge(-20, 20);
  for (auto& b : test.rgba) b = std::uint8_t(std::clamp(b + nudge(rng), 0, 255));
  for (int threshold : {0, 5, 12, 19, 20}) {
    const Image map = gllab::heat_map(reference, test, threshold);
    long long hot = 0;
    for (int y = 0; y < map.height; ++y)
      for (int x = 0; x < map.width; ++x) hot += map.pixel(x, y)[0] == 255 ? 1 : 0;
    EXPECT_EQ(hot, gllab::compare_images(reference, test, threshold).differing_pixels) << threshold;
  }
}

TEST(HeatMap, SizeMismatchNamesBothSizes) {
  try {
    gllab::heat_map(Image(4, 3), Image(3, 4), 0);
    ADD_FAILURE() << "no exception";
  } catch (const gllab::ImageError& e) {
    EXPECT_STREQ(e.what(), "heat_map: size mismatch: reference 4x3, test 3x4");
  }
}

// --- shift tolerance -----------------------------------------------------------
// A white vertical line one pixel wide at column `column` on black, 9x9.
Image vertical_line(int column, std::uint8_t r = 255, std::uint8_t g = 255, std::uint8_t b = 255) {
  Image img = filled(9, 9, 0, 0, 0, 255);
  for (int y = 0; y < img.height; ++y) {
    std::uint8_t* p = img.pixel(column, y);
    p[0] = r, p[1] = g, p[2] = b;
  }
  return img;
}

TEST(ShiftTolerance, LineOnePixelOverIsExcusedWithRadiusOne) {
  // Line at column 4 vs column 5: columns 4 and 5 differ in all 9 rows = 18 pixels.
  const gllab::Comparison c = gllab::compare_images(vertical_line(4), vertical_line(5), 0, 1);
  EXPECT_EQ(c.differing_pixels, 18);
  EXPECT_EQ(c.mismatched_pixels, 0);
}

TEST(ShiftTolerance, RadiusZeroExcusesNothing) {
  const gllab::Comparison c = gllab::compare_images(vertical_line(4), vertical_line(5), 0, 0);
  EXPECT_EQ(c.mismatched_pixels, c.differing_pixels);
}

TEST(ShiftTolerance, LineTwoPixelsOverIsNotExcusedWithRadiusOne) {
  // Columns 3 and 5: at column 3 the test has black, and the test's pixels
  // within one pixel of column 3 (columns 2..4) are all black, so the
  // reference's white is not found near it: all 18 differing pixels count.
  const gllab::Comparison c = gllab::compare_images(vertical_line(3), vertical_line(5), 0, 1);
  EXPECT_EQ(c.differing_pixels, 18);
  EXPECT_EQ(c.mismatched_pixels, 18);
}

TEST(ShiftTolerance, WrongColourIsNotExcused) {
  // Same place, red instead of white: no nearby pixel of the test is white.
  const gllab::Comparison c =
      gllab::compare_images(vertical_line(4), vertical_line(4, 255, 0, 0), 0, 1);
  EXPECT_EQ(c.differing_pixels, 9);
  EXPECT_EQ(c.mismatched_pixels, 9);
}

TEST(ShiftTolerance, MissingLineIsNotExcused) {
  // The line is gone: the reference's white exists nowhere in the test.
  const gllab::Comparison c =
      gllab::compare_images(vertical_line(4), filled(9, 9, 0, 0, 0, 255), 0, 1);
  EXPECT_EQ(c.mismatched_pixels, 9);
}

TEST(ShiftTolerance, PassesJudgesMismatchedShareAndChecksTheRadius) {
  const gllab::Comparison c = gllab::compare_images(vertical_line(4), vertical_line(5), 0, 1);
  gllab::Tolerance t;
  t.shift_radius = 1;
  EXPECT_TRUE(c.passes(t));  // 0 mismatched <= 0 allowed
  t.shift_radius = 0;
  EXPECT_THROW(c.passes(t), std::invalid_argument);
  EXPECT_THROW(gllab::compare_images(vertical_line(4), vertical_line(5), 0, -1), std::invalid_argument);
  EXPECT_THROW(gllab::compare_images(vertical_line(4), vertical_line(5), 0, gllab::kMaxShiftRadius + 1),
               std::invalid_argument);
}

TEST(ShiftTolerance, HeatMapShowsExcusedPixelsBlueAndMismatchedHot) {
  const Image excused = gllab::heat_map(vertical_line(4), vertical_line(5), 0, 1);
  EXPECT_EQ(rgba_at(excused, 4, 0), (std::vector<std::uint8_t>{0, 96, 255, 255}));
  const Image hot = gllab::heat_map(vertical_line(3), vertical_line(5), 0, 1);
  EXPECT_EQ(hot.pixel(3, 0)[0], 255);
  EXPECT_EQ(hot.pixel(3, 0)[2], 0);
}

// --- edge contrast: a shift excuses only a thin feature ------------------------

// A horizontal ramp, 9x9: column x has grey level base + step * x.
Image ramp(int base, int step) {
  Image img = filled(9, 9, 0, 0, 0, 255);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 9; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = p[1] = p[2] = static_cast<std::uint8_t>(base + step * x);
    }
  return img;
}

TEST(EdgeContrast, ALineMovedOnePixelIsStillExcused) {
  // Columns 4 and 5 differ by 255 from their neighbours (white on black):
  // both are on a thin feature, so the 18 differing pixels stay excused.
  const Comparison c = gllab::compare_images(vertical_line(4), vertical_line(5), 0, 1, 48);
  EXPECT_EQ(c.differing_pixels, 18);
  EXPECT_EQ(c.mismatched_pixels, 0);
  EXPECT_EQ(c.shifted_pixels(), 18);
}

TEST(EdgeContrast, ASmoothSurfaceWhoseShadeChangedIsNotExcused) {
  // A ramp of 10 per column, brightened by 10: each test shade appears one
  // column over in the reference, so a bare shift excuses every pixel, but
  // neighbours differ by only 10 < 48: no thin feature, all 81 count.
  const Image reference = ramp(40, 10), test = ramp(50, 10);
  const Comparison anywhere = gllab::compare_images(reference, test, 2, 1);
  EXPECT_EQ(anywhere.differing_pixels, 81);
  // Columns 0 and 8 (2 x 9 pixels): their shade has no neighbour to borrow from.
  EXPECT_EQ(anywhere.mismatched_pixels, 18);
  const Comparison on_edges = gllab::compare_images(reference, test, 2, 1, 48);
  EXPECT_EQ(on_edges.mismatched_pixels, 81);
  EXPECT_EQ(on_edges.edge_contrast, 48);
}

TEST(EdgeContrast, ScoreIsTheLargerShareInUnitsOfItsLimit) {
  // 18 shifted pixels of 81, none unexcused.
  const Comparison c = gllab::compare_images(vertical_line(4), vertical_line(5), 0, 1, 48);
  Tolerance t{0, 0.01, 1, 48, 18.0 / 81.0};
  EXPECT_NEAR(c.score(t), 1.0, kExact);
  EXPECT_TRUE(c.passes(t));
  t.max_shifted_share = 9.0 / 81.0;  // half of what moved: twice the limit
  EXPECT_NEAR(c.score(t), 2.0, kExact);
  EXPECT_FALSE(c.passes(t));
  t.max_shifted_share = 0;  // nothing may move
  EXPECT_EQ(c.score(t), HUGE_VAL);
  t.edge_contrast = 0;  // not the contrast the counts were made with
  EXPECT_THROW(c.score(t), std::invalid_argument);
  EXPECT_THROW(gllab::compare_images(vertical_line(4), vertical_line(5), 0, 1, 256), std::invalid_argument);
  // Identical images score 0 under any limits, zero ones included.
  EXPECT_EQ(gllab::compare_images(ramp(0, 1), ramp(0, 1), 0, 1, 48).score({0, 0, 1, 48, 0}), 0.0);
}

TEST(EdgeContrast, HeatMapShowsAnUnexcusedSurfaceHot) {
  const Image map = gllab::heat_map(ramp(40, 10), ramp(50, 10), 2, 1, 48);
  EXPECT_EQ(map.pixel(4, 4)[0], 255);
  EXPECT_EQ(map.pixel(4, 4)[2], 0);
}

}  // namespace
