// tests/labs/02_display_lists_test.cpp — what lab 02 promises about its views:
// a torus replayed from a display list has exactly the pixels of the same
// calls made immediately, and state set inside a list leaks out of it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::pixels_differing;
using gllab::testing::ScratchDir;

const std::string kLab = "02_display_lists";

// A view of this lab with --set arguments (lab_test_support.h).
gllab::Image render(const ScratchDir& dir, const std::string& view, const std::vector<std::string>& sets) {
  return gllab::testing::render_view(kLab, dir, view, sets);
}

long long count_colour(const gllab::Image& im, int r, int g, int b) {
  long long n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      n += p[0] == r && p[1] == g && p[2] == b;
    }
  return n;
}

// A display list records the glColor/glNormal/glVertex calls and replays the
// same values, so rasterization sees the same vertices (lab 02 header).
TEST(DisplayListsLab, TorusFromListHasTheImmediatePixels) {
  ScratchDir dir("lab02");
  const gllab::Image immediate = render(dir, "list_vs_immediate", {"path=0"});
  const gllab::Image list = render(dir, "list_vs_immediate", {"path=1"});
  EXPECT_EQ(pixels_differing(immediate, list), 0);
}

// detail=24 is not the detail init() compiled (16), so path=1 deletes the list
// and compiles it again with GL_COMPILE_AND_EXECUTE: that draw must match too.
TEST(DisplayListsLab, ListRecompiledWithCompileAndExecuteHasTheImmediatePixels) {
  ScratchDir dir("lab02");
  const gllab::Image immediate = render(dir, "list_vs_immediate", {"path=0", "detail=24"});
  const gllab::Image list = render(dir, "list_vs_immediate", {"path=1", "detail=24"});
  EXPECT_EQ(pixels_differing(immediate, list), 0);
  // The comparison can see a change: a finer torus changes the picture.
  EXPECT_GT(pixels_differing(list, render(dir, "list_vs_immediate", {"path=1"})), 0);
}

// Red Book list.c: the list sets red (1,0,0) and translates, so the bar drawn
// after the calls is red and moved; with fix=1 it keeps the green (0,1,0) set
// before them. Flat colours, no lighting: the bytes are exactly 255 or 0.
TEST(DisplayListsLab, StateSetInAListLeaksIntoTheNextPrimitive) {
  ScratchDir dir("lab02");
  const gllab::Image leak = render(dir, "state_leak", {"fix=0"});
  const gllab::Image fixed = render(dir, "state_leak", {"fix=1"});
  // The bar is 3 x 0.5 lab units at about 49 pixels per unit (512 px over
  // 10.4 units): about 3600 pixels, so 1000 is a safe lower bound.
  constexpr long long kBarPixelsAtLeast = 1000;
  EXPECT_EQ(count_colour(leak, 0, 255, 0), 0) << "no green anywhere while the colour leaks";
  EXPECT_GT(count_colour(fixed, 0, 255, 0), kBarPixelsAtLeast) << "the fixed bar is green";
  EXPECT_GT(count_colour(leak, 255, 0, 0), count_colour(fixed, 255, 0, 0) + kBarPixelsAtLeast)
      << "the leaking bar is red, on top of the four red triangles";
}

}  // namespace
