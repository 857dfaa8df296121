// tests/labs/10_polynomial_interpolation_test.cpp — what lab 10 promises:
// adding a Newton node extends the divided-difference table without changing
// what is there (lecture notes ch. 1, §1.6 Spline representations, "Newton
// interpolation": "additional nodes can be added without having to re-compute
// all basis functions"), the new entries are the ones marked;
// and bad data (two nodes at one x) is one line naming both, not a crash.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::render_view;
using gllab::testing::ScratchDir;

const std::string kLab = "10_polynomial_interpolation";

// The table panel of newton_add_node (gllab::draw_divided_differences,
// common/gl/spline_draw.h): top-left at lab point (-6.8, -2.75) of
// ortho_fit(7, 7), which on 512 x 512 is pixel
// (round(0.2 * 512/14), 512 - round(4.25 * 512/14)) = (7, 357); 6 px padding,
// 8 x 16 glyphs, columns of 9 characters (t_j first), a title line and a
// header line before row j = 0. Entry f[t_j..t_(j+k)] is the cell in column
// k + 1, row j + 2.
constexpr int kPanelX = 7, kPanelY = 357, kPad = 6, kColumn = 9 * 8, kRow = 16;
// A glyph pixel differs from the panel's background by far more than the
// grader's channel threshold (24); anti-aliasing does not exist in the font.
constexpr int kLit = 24;
// kNew = (1, 0.4, 0.3) in the lab: (255, 102, 76).
constexpr int kNewRed = 255, kNewGreen = 102;

struct Cell {
  std::vector<bool> lit;  // the glyph pixels of the cell, row by row
  bool red = false;       // drawn in the lab's colour for new entries
};

Cell cell(const gllab::Image& im, int k, int j) {
  const std::uint8_t* background = im.pixel(kPanelX + 1, kPanelY + 1);
  const int x0 = kPanelX + kPad + (k + 1) * kColumn, y0 = kPanelY + kPad + (j + 2) * kRow;
  Cell c;
  for (int y = y0; y < y0 + kRow; ++y)
    for (int x = x0; x < x0 + kColumn; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      bool lit = false;
      for (int ch = 0; ch < 3; ++ch) lit = lit || std::abs(p[ch] - background[ch]) > kLit;
      c.lit.push_back(lit);
      if (lit && p[0] == kNewRed && p[1] == kNewGreen) c.red = true;
    }
  return c;
}

bool empty(const Cell& c) {
  for (bool b : c.lit)
    if (b) return false;
  return true;
}

TEST(PolynomialInterpolationLab, AddingANodeKeepsTheOldTableAndMarksOnlyTheNewDiagonal) {
  ScratchDir dir("lab10");
  // 4 nodes, then the same 4 and a fifth, (3, 2.5) of the lab data.
  const gllab::Image four = render_view(kLab, dir, "newton_add_node", {"nodes=4"});
  const gllab::Image five = render_view(kLab, dir, "newton_add_node", {"nodes=5"});
  for (int j = 0; j < 5; ++j)
    for (int k = 0; j + k < 5; ++k) {
      const Cell a = cell(four, k, j), b = cell(five, k, j);
      ASSERT_FALSE(empty(b)) << "k " << k << " j " << j;
      if (j + k < 4) EXPECT_EQ(a.lit, b.lit) << "old entry k " << k << " j " << j << " changed";
      // Marked in red: the diagonal of the last node only (k + j = nodes - 1).
      if (j + k < 4) EXPECT_EQ(a.red, j + k == 3) << "k " << k << " j " << j;
      EXPECT_EQ(b.red, j + k == 4) << "k " << k << " j " << j;
    }
}

TEST(PolynomialInterpolationLab, MovingAnOldNodeChangesItsEntries) {
  // The comparison above can fail: move node 1 from (2, 3) to (2, 3.5) and
  // f[t_1] = 3 becomes 3.5, so the cell k = 0, j = 1 changes.
  ScratchDir dir("lab10");
  const gllab::Image before = render_view(kLab, dir, "newton_add_node", {"nodes=5"});
  const gllab::Image after = render_view(kLab, dir, "newton_add_node", {"nodes=5", "N[1]=2,3.5"});
  EXPECT_NE(cell(before, 0, 1).lit, cell(after, 0, 1).lit);
  EXPECT_EQ(cell(before, 0, 0).lit, cell(after, 0, 0).lit);  // f[t_0] = 1 stays
}

TEST(PolynomialInterpolationLab, TwoNodesAtOneXAreOneLineNamingBoth) {
  // lagrange: P[1] dragged onto P[0]'s x = -2. The core throws; the runner
  // turns it into one line naming the view and both nodes, exit 1, no image.
  ScratchDir dir("lab10");
  const gllab::ProcessResult r = gllab::run_process(
      {gllab::testing::headless(kLab), "--set", "P[1]=-2,1", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_EQ(gllab::testing::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("view 'lagrange': lagrange_value: nodes t[0]=-2 and t[1]=-2 coincide"), std::string::npos)
      << r.err;
}

// nodes has the range [2, 6] (the lab's six Newton points): 7 is rejected.
TEST(PolynomialInterpolationLab, NodeCountOutsideItsRangeIsOneLineAndExitTwo) {
  ScratchDir dir("lab10");
  const gllab::ProcessResult r = gllab::run_process(
      {gllab::testing::headless(kLab), "--set", "nodes=7", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(gllab::testing::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("[2, 6]"), std::string::npos) << r.err;
}

}  // namespace
