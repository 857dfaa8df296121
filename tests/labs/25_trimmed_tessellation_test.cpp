// tests/labs/25_trimmed_tessellation_test.cpp — what lab 25 promises about its
// views, read from the numbers they print (--print-text):
//  - slivers: GLU fed a 5-point gluPwlCurve square makes slivers (area too
//    large, faces tilted > 20°, its rim far from the surface), GLU fed the
//    densified square and the own tessellation do not; densifying is what
//    removes them;
//  - the own tessellation keeps its tolerance inside and along the trims.
// The numbers are spline::surface_area and spline::mesh_fidelity
// (common/spline/tessellate.h, tested in tests/spline/tessellate_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "25_trimmed_tessellation";

// The three panels' numbers, in order: GLU with the 5-point square, GLU with
// the densified square, the own tessellation.
struct Panels {
  std::vector<double> area_percent, tilted, rim;
};

Panels slivers(const ScratchDir& dir, const std::vector<std::string>& sets = {}) {
  const std::vector<std::string> text = view_text(kLab, dir, "slivers", sets);
  Panels p{numbers_after(text, "area "), numbers_after(text, "faces tilted > 20°: "),
           numbers_after(text, "along trims ")};
  EXPECT_EQ(p.area_percent.size(), 3u);
  EXPECT_EQ(p.tilted.size(), 3u);
  EXPECT_EQ(p.rim.size(), 3u);
  return p;
}

// docs/glu.md: on random trimmed bicubics a coarse gluPwlCurve loop put GLU's
// area 5-23 % off, with faces tilted more than 20°. This hill is steeper
// than those (heights -3 to 3 over 6 x 6): measured +26.4 %, 46 faces at 24
// steps, the rim 0.78 off along the square's straight (u, v) edges. Fed 16
// points per edge, GLU follows the surface: -0.07 %, none tilted, 3.0e-3;
// the own core (tolerance 0.02): -0.08 %, none, 1.2e-3.
TEST(TrimmedTessellationLab, CoarsePolylineSquareMakesGluSliversAndADenseOneDoesNot) {
  constexpr double kSliverAreaPercent = 5;  // docs/glu.md's lower end
  constexpr double kCloseAreaPercent = 1;   // a mesh within 0.02 of this hill stays within it (measured 0.08 %)
  ScratchDir dir("lab25");
  const Panels p = slivers(dir);
  ASSERT_EQ(p.area_percent.size(), 3u);
  EXPECT_GT(p.area_percent[0], kSliverAreaPercent);
  EXPECT_GE(p.tilted[0], 20);
  EXPECT_GT(p.rim[0], 0.1);
  for (int k : {1, 2}) {
    EXPECT_LT(std::abs(p.area_percent[k]), kCloseAreaPercent) << "panel " << k;
    EXPECT_EQ(p.tilted[k], 0) << "panel " << k;
    EXPECT_LT(p.rim[k], 0.01) << "panel " << k;
  }
  // Finer GLU sampling does not help: the slivers are the pwl edges' (at 64 steps: 160 faces, +27.4 %).
  const Panels finer = slivers(dir, {"steps=64"});
  ASSERT_EQ(finer.area_percent.size(), 3u);
  EXPECT_GT(finer.area_percent[0], kSliverAreaPercent);
  EXPECT_GT(finer.tilted[0], p.tilted[0]);
  EXPECT_EQ(finer.rim[0], p.rim[0]);
}

// With one point per edge the "densified" polyline is the 5-point square
// itself: the second panel then shows exactly the first one's numbers.
TEST(TrimmedTessellationLab, DensifyingThePolylineIsWhatRemovesTheSlivers) {
  ScratchDir dir("lab25");
  const Panels p = slivers(dir, {"per_edge=1"});
  ASSERT_EQ(p.area_percent.size(), 3u);
  EXPECT_EQ(p.area_percent[1], p.area_percent[0]);
  EXPECT_EQ(p.tilted[1], p.tilted[0]);
  EXPECT_EQ(p.rim[1], p.rim[0]);
}

// tessellate.h: trim edges are refined until their image is within the
// tolerance, so the mesh's rim keeps it as well as its inside. Measured at
// tolerance 0.02, 0.01, 0.005: inside 1.1e-2, 8.7e-3, 3.3e-3; along the trims
// 2.1e-3, 1.5e-3, 1.2e-3. GLU's rim at the same time (24, 48, 96 steps):
// 2.5e-2, 6.4e-3, 6.4e-3: it stops improving (the chords of its densified
// gluPwlCurves), and at 0.005 it is above the tolerance, so the measure does
// fail a mesh that misses it.
TEST(TrimmedTessellationLab, OwnTessellationKeepsItsToleranceAlongTheTrims) {
  ScratchDir dir("lab25");
  for (const char* finer : {"finer=0", "finer=1", "finer=2"}) {
    const std::vector<std::string> text = view_text(kLab, dir, "own_vs_glu", {finer});
    const std::vector<double> tol = numbers_after(text, "tolerance ");
    const std::vector<double> inside = numbers_after(text, "max deviation ");
    const std::vector<double> rim = numbers_after(text, "along trims ");
    ASSERT_EQ(tol.size(), 1u) << finer;
    ASSERT_EQ(inside.size(), 2u) << finer;  // GLU, own
    ASSERT_EQ(rim.size(), 2u) << finer;
    EXPECT_LE(inside[1], tol[0]) << finer;
    EXPECT_LE(rim[1], tol[0]) << finer;
    EXPECT_GT(rim[1], 0) << finer;  // measured at all
    if (std::string(finer) == "finer=2") {
      EXPECT_GT(rim[0], tol[0]) << "GLU's rim";
    }
  }
  // The slivers view's square, coarse as it is: the own rim within 0.02 (measured 1.2e-3).
  const Panels p = slivers(dir);
  ASSERT_EQ(p.rim.size(), 3u);
  EXPECT_LE(p.rim[2], 0.02);
}

}  // namespace
