// tests/labs/17_bezier_surfaces_test.cpp — what lab 17's views construct.
//  - zero_twist and constant_twist make the patch from the two edge curves
//    through b00 (and constant_twist from b33, which sets the twist): their
//    other net points are made, so the list entries for them change nothing
//    (lecture notes ch. 1, §1.7 Surface representations, "The twist vector").
//  - de_casteljau's X(u, v) does not depend on the order of the two passes:
//    de_casteljau_v_first shows the same point and partials (§1.7, "Bézier
//    tensor product": "It does not make any difference if the algorithm is
//    applied first to parameter t or s").
// (The patch against glMap2f/glEvalMesh2 is lab 19's:
// tests/labs/19_gl_evaluators_test.cpp; the joins are lab 18's.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::pixels_differing;
using gllab::testing::render_view;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "17_bezier_surfaces";

// Points a view constructs ignore their list entries (threshold 0: same
// geometry, same pixels on llvmpipe). zero_twist keeps the edges through b00
// (P[0..3], P[0], P[4], P[8], P[12]); constant_twist also b33 = P[15].
TEST(BezierSurfacesLab, ConstructedPointsIgnoreTheirListEntries) {
  ScratchDir dir("lab17");
  struct Case {
    const char* view;
    const char* set;
    bool free;
  };
  const Case cases[] = {
      {"de_casteljau", "P[5]=-0.5,-0.5,1.98", true},
      {"zero_twist", "P[5]=-0.5,-0.5,1.98", false},
      {"constant_twist", "P[5]=-0.5,-0.5,1.98", false},
      {"constant_twist", "P[15]=1.5,1.5,1.56", true},
      {"zero_twist", "P[15]=1.5,1.5,1.56", false},
      {"zero_twist", "P[4]=-0.5,-1.5,0.72", true},
  };
  for (const Case& c : cases) {
    const long long differing = pixels_differing(render_view(kLab, dir, c.view, {"labels=0"}),
                                                 render_view(kLab, dir, c.view, {"labels=0", c.set}));
    if (c.free) EXPECT_GT(differing, 0) << c.view << " --set " << c.set << " should change the patch";
    else EXPECT_EQ(differing, 0) << c.view << " --set " << c.set << " should be ignored (the point is made)";
  }
}

// u first (de_casteljau) or v first (de_casteljau_v_first): other nets, the
// same point and partials (the caption's X(u, v), Xu/4 and Xv/4 lines are the
// same text), at the default (u, v) and at another.
TEST(BezierSurfacesLab, DeCasteljauInEitherOrderGivesTheSamePoint) {
  ScratchDir dir("lab17");
  for (const std::vector<std::string>& at :
       {std::vector<std::string>{}, std::vector<std::string>{"u=0.8", "v=0.65"}}) {
    const std::vector<std::string> u = view_text(kLab, dir, "de_casteljau", at);
    const std::vector<std::string> v = view_text(kLab, dir, "de_casteljau_v_first", at);
    ASSERT_EQ(u.size(), v.size());
    ASSERT_GE(u.size(), 4u);
    EXPECT_NE(u[0], v[0]);  // "u first: ..." against "v first: ..."
    for (std::size_t k = 1; k < u.size(); ++k) EXPECT_EQ(u[k], v[k]);
  }
  EXPECT_GT(pixels_differing(render_view(kLab, dir, "de_casteljau", {"labels=0"}),
                             render_view(kLab, dir, "de_casteljau_v_first", {"labels=0"})),
            0);  // the nets differ
}

}  // namespace
