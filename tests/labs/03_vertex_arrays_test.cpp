// tests/labs/03_vertex_arrays_test.cpp — what lab 03 promises about its views:
// the layout of the arrays (separate or interleaved) and the draw call
// (glDrawArrays of every corner or glDrawElements of shared vertices) change
// nothing on screen, and a wrong stride does.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::pixels_differing;
using gllab::testing::ScratchDir;

const std::string kLab = "03_vertex_arrays";

// A view of this lab with --set arguments (lab_test_support.h).
gllab::Image render(const ScratchDir& dir, const std::string& view, const std::vector<std::string>& sets) {
  return gllab::testing::render_view(kLab, dir, view, sets);
}

// Stride 0 over three arrays and stride 36 over one interleaved array point GL
// at the same floats (gllab::interleaved copies them), so the pixels match.
TEST(VertexArraysLab, SeparateAndInterleavedArraysGiveIdenticalPixels) {
  ScratchDir dir("lab03");
  for (const char* call : {"call=0", "call=1"}) {
    const gllab::Image separate = render(dir, "default", {"layout=0", call});
    const gllab::Image packed = render(dir, "default", {"layout=1", call});
    EXPECT_EQ(pixels_differing(separate, packed), 0) << call;
  }
}

// gllab::unshared repeats vertex indices[i] as vertex i, so glDrawArrays sends
// the same triangles, in the same order, as glDrawElements.
TEST(VertexArraysLab, DrawArraysOfUnsharedAndDrawElementsGiveIdenticalPixels) {
  ScratchDir dir("lab03");
  for (const char* detail : {"detail=14", "detail=40"}) {
    const gllab::Image elements = render(dir, "default", {"call=0", detail});
    const gllab::Image arrays = render(dir, "default", {"call=1", detail});
    EXPECT_EQ(pixels_differing(elements, arrays), 0) << detail;
  }
}

// With stride 0, GL reads the interleaved array as packed x y z triples, so
// positions come from normals and colours: the right torus is scrambled. With
// stride 36 it is the torus again. Measured: 30213 pixels differ (11.5% of
// 512 x 512, the label included); 5% leaves room and still needs a torus-sized change.
TEST(VertexArraysLab, WrongStrideScramblesTheTorus) {
  ScratchDir dir("lab03");
  const gllab::Image wrong = render(dir, "wrong_stride", {"stride=0"});
  const gllab::Image right = render(dir, "wrong_stride", {"stride=36"});
  constexpr double kScrambledShareAtLeast = 0.05;
  EXPECT_GT(pixels_differing(wrong, right), static_cast<long long>(kScrambledShareAtLeast * 512 * 512));
}

}  // namespace
