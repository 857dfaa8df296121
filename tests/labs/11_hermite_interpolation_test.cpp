// tests/labs/11_hermite_interpolation_test.cpp — what lab 11 promises:
// hermite_basis prints the lecture notes' Hermite example (lecture notes ch. 1,
// §1.6 Spline representations, "Hermite interpolation": the inverted matrix and
// H0 = 2t³ - 3t² + 1, H0bar = t³ - 2t² + t, H1 = -2t³ + 3t², H1bar = t³ - t²),
// and in hermite a tangent handle moves only the segments that meet at its
// point (segment i depends on p_i, m_i, p_(i+1), m_(i+1) alone).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::colour_mask;
using gllab::testing::mask_count;
using gllab::testing::pixels_differing;
using gllab::testing::render_view;
using gllab::testing::Rgb8;
using gllab::testing::ScratchDir;

const std::string kLab = "11_hermite_interpolation";

bool has_line(const std::vector<std::string>& lines, const std::string& line) {
  for (const std::string& l : lines)
    if (l == line) return true;
  return false;
}

// The notes' matrix, (c0 c1 c2 c3) = M (f(0) f'(0) f(1) f'(1)), row by row as
// the panel prints it ("  %4g %4g %4g %4g"), and the four polynomials.
TEST(HermiteInterpolationLab, BasisViewPrintsTheLectureNotesExample) {
  ScratchDir dir("lab11");
  const std::vector<std::string> text = gllab::testing::view_text(kLab, dir, "hermite_basis");
  for (const char* row : {"     1    0    0    0", "     0    1    0    0", "    -3   -2    3   -1",
                          "     2    1   -2    1"})
    EXPECT_TRUE(has_line(text, row)) << "no matrix row '" << row << "'";
  EXPECT_TRUE(has_line(text, "H0 (value at 0): 2t³ - 3t² + 1"));
  EXPECT_TRUE(has_line(text, "H0bar (slope at 0): t³ - 2t² + t"));
  EXPECT_TRUE(has_line(text, "H1 (value at 1): -2t³ + 3t²"));
  EXPECT_TRUE(has_line(text, "H1bar (slope at 1): t³ - t²"));
  // The check can fail: a row the notes do not have is not found.
  EXPECT_FALSE(has_line(text, "    -3   -2    3    1"));
}

// Segment i is drawn in series_colour(i + 2) (common/gl/spline_draw.cpp):
// segment 0 (0.45, 0.9, 0.4), segment 1 (0.4, 0.7, 1) in 8 bits.
const Rgb8 kSegment0{115, 230, 102}, kSegment1{102, 179, 255};

// The handle of P[0] (T[0], default (-2, 1.5)) belongs to segment 0 only: moving
// it leaves every pixel of segment 1 where it was. The handle of P[2] (T[2],
// default (3.3, 1)) belongs to segment 1 only, so moving it must change segment 1.
// Moves of 0.3 lab units, about 15 pixels at the view's scale.
TEST(HermiteInterpolationLab, AHandleMovesOnlyTheSegmentsAtItsPoint) {
  ScratchDir dir("lab11");
  const gllab::Image base = render_view(kLab, dir, "hermite", {"labels=0"});
  const gllab::Image first = render_view(kLab, dir, "hermite", {"labels=0", "T[0]=-2.3,1.2"});
  const gllab::Image last = render_view(kLab, dir, "hermite", {"labels=0", "T[2]=3.6,1.3"});
  const gllab::Image segment1 = colour_mask(base, {kSegment1});
  ASSERT_GT(mask_count(segment1), 200) << "segment 1 not found in its colour";
  EXPECT_EQ(pixels_differing(segment1, colour_mask(first, {kSegment1})), 0);
  EXPECT_GT(pixels_differing(colour_mask(base, {kSegment0}), colour_mask(first, {kSegment0})), 0);
  EXPECT_GT(pixels_differing(segment1, colour_mask(last, {kSegment1})), 0);
}

}  // namespace
