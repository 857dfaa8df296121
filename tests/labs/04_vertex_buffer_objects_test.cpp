// tests/labs/04_vertex_buffer_objects_test.cpp — lab 04's promises about time:
// headless renders fix it (--time), the ripple uploaded with glBufferSubData
// depends on it, and the `later` view is the default view a quarter period on.
// Origin of the numbers: the lab data, kPeriod = 2 s, and `later` adds
// kPeriod / 4 = 0.5 s to State::time (04_vertex_buffer_objects.cpp).
#include <gtest/gtest.h>

#include <string>

#include "image/compare.h"
#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::ScratchDir;

constexpr char kQuarterPeriod[] = "0.5";  // kPeriod / 4, seconds

// The view at `time` seconds (lab_test_support.h).
gllab::Image render(const ScratchDir& dir, const std::string& view, const std::string& time) {
  return gllab::testing::render_view("04_vertex_buffer_objects", dir, view, {}, time);
}

TEST(VertexBufferObjects, LaterViewIsDefaultAQuarterPeriodOn) {
  ScratchDir dir("lab04");
  const gllab::Comparison c =
      gllab::compare_images(render(dir, "default", kQuarterPeriod), render(dir, "later", "0"), 0);
  EXPECT_EQ(c.differing_pixels, 0) << "max delta " << c.max_delta;
}

// The comparison above can fail: the buffer contents follow the time, so the
// default view at 0 s and at 0.5 s differ (the crests moved).
TEST(VertexBufferObjects, RippleMovesWithTime) {
  ScratchDir dir("lab04");
  const gllab::Comparison c =
      gllab::compare_images(render(dir, "default", "0"), render(dir, "default", kQuarterPeriod), 0);
  EXPECT_GT(c.differing_pixels, 1000);
}

}  // namespace
