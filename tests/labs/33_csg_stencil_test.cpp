// tests/labs/33_csg_stencil_test.cpp — what lab 33 promises (lecture notes, "3-D Graphics",
// "Solid Representation", "Constructive Solid Geometry"):
//  - ray_cast: the stencil rendering (Goldfeather and SCS) equals the core's exact ray cast
//    (Roth 1982) through every pixel centre, but for pixels a 1-pixel shift explains (the
//    48-sided polygons of spheres and cylinders against the exact silhouettes), for every
//    tree of the catalogue (nested differences, transforms under operators, every shape) and
//    for the classic object with each box-sphere operator;
//  - passes: the passes count as the lab's comment says (Goldfeather: per literal one depth
//    pass, two per other literal, one merge; SCS: k rounds over k subtracted primitives).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "33_csg_stencil";
constexpr int kTrees = 16;  // space::csg_catalogue(): the classic object, 12 more, 3 sieves

// The lab says "agrees" when, of its 256 x 256 = 65,536 pixels, at most 8 differ with no
// 1-pixel shift to explain them (a stray pixel where an edge of one polygon meets another's;
// measured: 0 to 4), else "disagrees: N pixels ...". 0 here: it agrees, else N (-1: no line).
constexpr double kUnexplained = 0;

double unexplained(const ScratchDir& dir, const std::vector<std::string>& sets) {
  const std::vector<std::string> text = view_text(kLab, dir, "ray_cast", sets);
  for (const std::string& line : text)
    if (line == "agrees: at most 8 pixels no shift explains") return 0;
  const std::vector<double> n = numbers_after(text, "disagrees:");
  return n.size() == 1 ? n[0] : -1;
}

TEST(CsgStencilLab, EveryTreeAgreesWithTheRayCastByBothAlgorithms) {
  ScratchDir dir("lab33");
  for (int tree = 0; tree < kTrees; ++tree)
    for (int scs = 0; scs < 2; ++scs) {
      const double n = unexplained(dir, {"tree=" + std::to_string(tree), "scs=" + std::to_string(scs)});
      EXPECT_GE(n, 0) << "tree " << tree;
      EXPECT_LE(n, kUnexplained) << "tree " << tree << (scs ? " SCS" : " Goldfeather");
    }
}

TEST(CsgStencilLab, EachOperatorAndAMovedSphereAgreeWithTheRayCast) {
  ScratchDir dir("lab33op");
  for (int op = 0; op < 3; ++op)
    for (int scs = 0; scs < 2; ++scs) {
      const double n = unexplained(dir, {"op=" + std::to_string(op), "scs=" + std::to_string(scs),
                                         "S[0]=0.3,0.2,0.4"});
      EXPECT_GE(n, 0);
      EXPECT_LE(n, kUnexplained) << "op " << op << (scs ? " SCS" : " Goldfeather");
    }
}

TEST(CsgStencilLab, PassesCountAsTheAlgorithmsSay) {
  ScratchDir dir("lab33passes");
  // The classic object is one product of 5 literals (box, sphere, −cyl x, −cyl y, −cyl z).
  // Goldfeather: per literal 1 depth pass + 2 per other literal + 1 merge = 10; 5 x 10 = 50.
  const std::vector<double> g =
      numbers_after(view_text(kLab, dir, "goldfeather"), "Goldfeather: 1 products,");
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0], 50);
  // SCS: 1 front-face pass, 3 rounds over the 3 cylinders, 1 count, 1 merge = 12.
  const std::vector<double> s = numbers_after(view_text(kLab, dir, "scs"), "SCS: 1 products,");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0], 12);
  // Stopped after pass 2, the view says which pass that was; past the end, that it ended.
  bool named = false, ended = false;
  for (const std::string& line : view_text(kLab, dir, "passes", {"pass=2"}))
    named |= line == "box: parity of sphere's faces in front";
  for (const std::string& line : view_text(kLab, dir, "passes", {"pass=60"}))
    ended |= line == "−cyl z: merged into R, shaded where it won (the last pass)";
  EXPECT_TRUE(named);
  EXPECT_TRUE(ended);
}

}  // namespace
