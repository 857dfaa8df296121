// tests/labs/12_bezier_curves_test.cpp — what lab 12 promises about its views.
//
// de_casteljau prints the whole scheme of the lecture notes' example (ch. 1,
// §1.6 Spline representations, "Example (de Casteljau algorithm)" and
// "Example (continued)"): the polygon (0, 0), (2, 4.5), (8.5, 6.5), (11, 2)
// at t = 0.6. The expected values are the notes' scheme, worked exactly:
// b^1 = (1.2, 2.7) (5.9, 5.7) (10, 3.8), b^2 = (4.02, 4.5) (8.36, 4.56),
// X(0.6) = 0.4 (4.02, 4.5) + 0.6 (8.36, 4.56) = (6.624, 4.536) (the notes
// print (6.63, 4.54), a rounding slip), X'(0.6) = (13.02, 0.18) and
// X''(0.6) = (-3.6, -29.4) as the notes give them.
// (The comparison of the core's curve with glMap1f/glEvalMesh1 is lab 19's:
// tests/labs/19_gl_evaluators_test.cpp.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "12_bezier_curves";

bool has_line(const std::vector<std::string>& lines, const std::string& line) {
  for (const std::string& l : lines)
    if (l == line) return true;
  return false;
}

TEST(BezierCurvesLab, DeCasteljauShowsTheLectureNotesScheme) {
  ScratchDir dir("lab12");
  const std::vector<std::string> text = view_text(kLab, dir, "de_casteljau");
  for (const char* line : {"j=1: (1.2, 2.7) (5.9, 5.7) (10, 3.8)", "j=2: (4.02, 4.5) (8.36, 4.56)",
                           "X(t) = (6.624, 4.536) = b_0^3", "X'(t) = (13.02, 0.18) (green, / 3)",
                           "X''(t) = (-3.6, -29.4) (pink, / 6)"})
    EXPECT_TRUE(has_line(text, line)) << "missing: " << line;
}

// A grading fixture's mistake (tests/grading/mistakes/de_casteljau_one_minus_t.json)
// runs the scheme at 1 - t: at the default t = 0.6 the view then shows X(0.4).
// That is another line, so the test above fails for the mistake.
TEST(BezierCurvesLab, TheSchemeFollowsT) {
  ScratchDir dir("lab12");
  const std::vector<std::string> text = view_text(kLab, dir, "de_casteljau", {"t=0.4"});
  EXPECT_FALSE(has_line(text, "X(t) = (6.624, 4.536) = b_0^3"));
  // X(0.4) of the same polygon: (1 - t)^3 b0 + 3 (1 - t)^2 t b1 + 3 (1 - t) t^2 b2 + t^3 b3
  // = 0.432 (2, 4.5) + 0.288 (8.5, 6.5) + 0.064 (11, 2) = (4.016, 3.944).
  EXPECT_TRUE(has_line(text, "X(t) = (4.016, 3.944) = b_0^3"));
}

// The range of t is [0, 1]: the harness rejects 1.5 with one line naming it.
TEST(BezierCurvesLab, ParameterOutsideItsRangeIsOneLineAndExitTwo) {
  ScratchDir dir("lab12");
  const gllab::ProcessResult r = gllab::run_process(
      {gllab::testing::headless(kLab), "--set", "t=1.5", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(gllab::testing::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("[0, 1]"), std::string::npos) << r.err;
}

}  // namespace
