// tests/labs/27_iso_surfaces_test.cpp — what lab 27 promises (lecture notes
// ch. 1, §1.7 Surface representations, "Iso-curves" and "Iso-surfaces"):
//  - marching squares on the lab's field at c = 0.5: the naive table separates
//    all four saddle cells (5 closed curves around the five peaks), the
//    asymptotic decider joins three of them (saddle values 0.539, 0.510 and
//    0.560 > c, the fourth 0.486 < c: worked by hand from the lab's data), so
//    four peaks share one curve: 2 curves;
//  - the 15 base cases have the triangle counts of Lorensen and Cline's 1987
//    table (their figure 3): 0, 1, 2, 2, 2, 3, 3, 3, 2, 4, 4, 4, 4, 4, 4;
//  - the two cells of ambiguous_face leave a hole by the 1987 rule and none
//    with the decider;
//  - the phantom's triangle count grows as its area over h^2: doubling the
//    samples per axis (24 -> 47 cells) multiplies it by about (47 / 23)^2 = 4.2.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_before;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "27_iso_surfaces";

TEST(IsoSurfacesLab, DeciderJoinsThreeOfTheFourSaddles) {
  ScratchDir dir("lab27");
  const std::vector<double> curves = numbers_before(view_text(kLab, dir, "squares"), " polylines at c = 0.50");
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0], 5);  // naive
  EXPECT_EQ(curves[1], 2);  // decider
  // Above every saddle value (0.56) the two rules agree.
  const std::vector<double> high =
      numbers_before(view_text(kLab, dir, "squares", {"iso=0.65"}), " polylines at c = 0.65");
  ASSERT_EQ(high.size(), 2u);
  EXPECT_EQ(high[0], high[1]);
}

TEST(IsoSurfacesLab, BaseCasesHaveTheTriangleCountsOf1987) {
  ScratchDir dir("lab27");
  std::vector<double> counts;  // "0 triangles", "1 triangle", "2 triangles", ...
  for (const std::string& line : view_text(kLab, dir, "cube_cases"))
    if (line.find(" triangle") != std::string::npos) counts.push_back(std::stod(line));
  EXPECT_EQ(counts, (std::vector<double>{0, 1, 2, 2, 2, 3, 3, 3, 2, 4, 4, 4, 4, 4, 4}));
}

TEST(IsoSurfacesLab, TheAmbiguousFaceIsAHoleOnlyByThe1987Rule) {
  ScratchDir dir("lab27");
  const std::vector<double> open = numbers_before(view_text(kLab, dir, "ambiguous_face"), " open edges: a hole");
  const std::vector<double> closed = numbers_before(view_text(kLab, dir, "ambiguous_face"), " open edges: closed");
  ASSERT_EQ(open.size(), 1u);
  EXPECT_GT(open[0], 0);
  EXPECT_EQ(closed, (std::vector<double>{0}));
}

TEST(IsoSurfacesLab, PhantomTrianglesGrowAsAreaOverHSquared) {
  ScratchDir dir("lab27");
  const std::vector<double> coarse = numbers_before(view_text(kLab, dir, "ct_phantom", {"grid=24"}), " triangles");
  const std::vector<double> fine = numbers_before(view_text(kLab, dir, "ct_phantom", {"grid=48"}), " triangles");
  ASSERT_EQ(coarse.size(), 1u);
  ASSERT_EQ(fine.size(), 1u);
  EXPECT_GT(fine[0] / coarse[0], 3.0);
  EXPECT_LT(fine[0] / coarse[0], 5.5);
}

}  // namespace
