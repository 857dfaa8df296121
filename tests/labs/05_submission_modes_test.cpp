// tests/labs/05_submission_modes_test.cpp — lab 05's promise: the same mesh
// sent through immediate mode, a display list, vertex arrays and a VBO gives
// the same pixels. Origin of the expectation: the four paths hand GL the same
// triangles with the same per-vertex colour, normal and position, in the same
// order (GL_TRIANGLES), so a deterministic rasteriser (llvmpipe gives the same
// bytes in every process: the reference images rely on it) must produce
// identical images; any difference at all (threshold 0) means a path sent
// something else. The paths are written in the lab (namespace lab05).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::ScratchDir;

const std::string kLab = "05_submission_modes";
const std::vector<std::string> kPaths = {"immediate", "display_list", "vertex_arrays", "vbo"};

// The view at 2^size_log2 triangles (lab_test_support.h).
gllab::Image render(const ScratchDir& dir, const std::string& view, int size_log2) {
  return gllab::testing::render_view(kLab, dir, view, {"size_log2=" + std::to_string(size_log2)});
}

// Pixels that are not the clear colour (0.12, 0.13, 0.16 -> 31, 33, 41).
long long drawn_pixels(const gllab::Image& img) {
  long long n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (p[0] != 31 || p[1] != 33 || p[2] != 41) ++n;
    }
  return n;
}

// 2^10 (the smallest size), 2^15 (odd: a torus that is not exactly 2^15
// triangles) and 2^18 (sub-pixel triangles in places).
class FourPaths : public ::testing::TestWithParam<int> {};

TEST_P(FourPaths, ImagesAreByteIdentical) {
  ScratchDir dir("lab05");
  const gllab::Image reference = render(dir, kPaths[0], GetParam());
  // The torus covers a good part of the frame (not a blank image that would
  // trivially match): at least a fifth of the 512 x 512 pixels.
  EXPECT_GT(drawn_pixels(reference), 512 * 512 / 5);
  for (std::size_t p = 1; p < kPaths.size(); ++p) {
    const gllab::Comparison c = gllab::compare_images(reference, render(dir, kPaths[p], GetParam()), 0);
    EXPECT_EQ(c.differing_pixels, 0) << kPaths[p] << " differs from immediate, max delta " << c.max_delta;
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, FourPaths, ::testing::Values(10, 15, 18));

// The comparison can fail: the same path at two mesh sizes differs (the panel
// shows other counts and the silhouette of a coarser torus is another polygon).
TEST(SubmissionModes, DifferentMeshSizesDiffer) {
  ScratchDir dir("lab05");
  const gllab::Comparison c = gllab::compare_images(render(dir, "vbo", 10), render(dir, "vbo", 12), 0);
  EXPECT_GT(c.differing_pixels, 0);
}

}  // namespace
