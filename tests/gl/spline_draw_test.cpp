// tests/gl/spline_draw_test.cpp — the parts of common/gl/spline_draw.h that
// compute rather than draw: plot_ceiling and knot_vector_text.
#include "gl/spline_draw.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// The definition: the smallest of 1, 2, 5 x 10^k that is >= x.
TEST(PlotCeiling, RoundsUpToOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_EQ(gllab::plot_ceiling(1.0), 1.0);
  EXPECT_EQ(gllab::plot_ceiling(1.5), 2.0);
  EXPECT_EQ(gllab::plot_ceiling(2.0), 2.0);
  EXPECT_EQ(gllab::plot_ceiling(3.7), 5.0);
  EXPECT_EQ(gllab::plot_ceiling(7.0), 10.0);
  EXPECT_DOUBLE_EQ(gllab::plot_ceiling(3.7e-7), 5e-7);
  EXPECT_DOUBLE_EQ(gllab::plot_ceiling(0.0607), 0.1);
  // Nothing to scale: a plot of zeros (or of garbage) keeps the top at 1.
  EXPECT_EQ(gllab::plot_ceiling(0.0), 1.0);
  EXPECT_EQ(gllab::plot_ceiling(-2.0), 1.0);
  EXPECT_EQ(gllab::plot_ceiling(HUGE_VAL), 1.0);
  EXPECT_EQ(gllab::plot_ceiling(std::nan("")), 1.0);
}

// Ch. 1's knot insertion example, before and after inserting t = 0.5.
TEST(KnotVectorText, EachKnotOnceWithItsMultiplicity) {
  EXPECT_EQ(gllab::knot_vector_text({0, 0, 0, 0, .2, .4, .6, .8, 1, 1, 1, 1}), " 0x4 0.2 0.4 0.6 0.8 1x4");
  EXPECT_EQ(gllab::knot_vector_text({0, 0, 0, 0, .2, .4, .5, .6, .8, 1, 1, 1, 1}), " 0x4 0.2 0.4 0.5 0.6 0.8 1x4");
  EXPECT_EQ(gllab::knot_vector_text({0, 1, 2, 3, 4, 4, 5}), " 0 1 2 3 4x2 5");
  EXPECT_EQ(gllab::knot_vector_text({}), "");
}

}  // namespace
