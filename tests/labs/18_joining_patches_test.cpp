// tests/labs/18_joining_patches_test.cpp — what lab 18's joins construct.
// join_ck makes rows 0..k of the right patch from the left one (each column
// continued beyond u = 1: lecture notes ch. 1, §1.7 Surface representations,
// "Spline surfaces"; "Higher Order Surfaces", "Joining Bezier Patches"), and
// the right patch's rows 1..3 are the list Q[0..11]: the entries of the rows
// a view makes change nothing, the others move the patch.
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

const std::string kLab = "18_joining_patches";

// Threshold 0: same geometry, same pixels on llvmpipe.
TEST(JoiningPatchesLab, ConstructedRowsIgnoreTheirListEntries) {
  ScratchDir dir("lab18");
  struct Case {
    const char* view;
    const char* set;
    bool free;
  };
  const Case cases[] = {
      {"join_c0", "Q[1]=2.5,-0.5,1.6", true},  {"join_c1", "Q[1]=2.5,-0.5,1.6", false},
      {"join_c1", "Q[5]=3.5,-0.5,0.8", true},  {"join_c2", "Q[5]=3.5,-0.5,0.8", false},
      {"join_c2", "Q[9]=4.5,-0.5,0.6", true},  {"join_c2", "P[9]=0.5,-0.5,1.3", true},
      // join_c1 from below: the same rows made.
      {"join_c1_below", "Q[1]=2.5,-0.5,1.6", false}, {"join_c1_below", "Q[5]=3.5,-0.5,0.8", true},
  };
  for (const Case& c : cases) {
    const long long differing = pixels_differing(render_view(kLab, dir, c.view, {"labels=0"}),
                                                 render_view(kLab, dir, c.view, {"labels=0", c.set}));
    if (c.free) EXPECT_GT(differing, 0) << c.view << " --set " << c.set << " should change a patch";
    else EXPECT_EQ(differing, 0) << c.view << " --set " << c.set << " should be ignored (the row is made)";
  }
}

}  // namespace
