// tests/field/marching_squares_test.cpp — field::marching_squares (lecture
// notes ch. 1, §1.7 Surface representations, Iso-curves): one shared point
// per crossed edge, inside on the left, and the saddle cells decided
// naively or by the asymptotic decider (Nielson and Hamann 1991).
#include "field/marching_squares.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

namespace gllab::field {
namespace {

TEST(MarchingSquares, CircleIsOneClosedCounterClockwisePolyline) {
  const double r = 0.7;
  const Grid2 g =
      sample([&](double x, double y) { return r - std::hypot(x, y); }, -1, -1, 1, 1, 41, 41);
  const IsoCurves curves = marching_squares(g, 0);
  const auto lines = curves.polylines();
  ASSERT_EQ(lines.size(), 1u);
  const auto& l = lines[0];
  EXPECT_EQ(l.front(), l.back());
  EXPECT_EQ(l.size(), curves.points.size() + 1);  // every point once (the first again at the end)
  EXPECT_EQ(curves.segments.size(), curves.points.size());
  // Inside (f > 0, the disc) on the left: the loop runs counter-clockwise,
  // its shoelace area positive and close to pi r^2.
  double area = 0;
  for (std::size_t k = 0; k + 1 < l.size(); ++k) {
    const auto& p = curves.points[l[k]];
    const auto& q = curves.points[l[k + 1]];
    area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    EXPECT_NEAR(std::hypot(p[0], p[1]), r, 2e-3);
  }
  EXPECT_NEAR(area, M_PI * r * r, 5e-3);
  EXPECT_EQ(curves.cells.size(), curves.segments.size());  // no saddle: one segment per cell
}

// One cell, corners f00 = f11 = 1 inside, f10 = f01 = v outside, c = 0.5.
Grid2 saddle_cell(double v) {
  Grid2 g;
  g.nx = g.ny = 2;
  g.values = {1, v, v, 1};  // (0,0) (1,0) (0,1) (1,1)
  return g;
}

TEST(MarchingSquares, SaddleCellNaiveAndDeciderJoinDifferently) {
  // The bilinear saddle value (f00 f11 - f10 f01) / (f00 + f11 - f10 - f01)
  // = (1 - 0.04) / 1.6 = 0.6 > 0.5: the inside corners connect through the
  // cell. The naive table cuts each inside corner off instead.
  const Grid2 g = saddle_cell(0.2);
  const IsoCurves naive = marching_squares(g, 0.5, Saddle::kNaive);
  const IsoCurves decider = marching_squares(g, 0.5, Saddle::kDecider);
  ASSERT_EQ(naive.cells.size(), 1u);
  EXPECT_EQ(naive.cells[0].mask, 5);
  EXPECT_TRUE(naive.cells[0].saddle);
  ASSERT_EQ(naive.segments.size(), 2u);
  ASSERT_EQ(decider.segments.size(), 2u);
  std::set<std::array<double, 2>> pn(naive.points.begin(), naive.points.end()),
      pd(decider.points.begin(), decider.points.end());
  EXPECT_EQ(pn, pd);  // the same four crossings
  // Which corners each segment cuts off: its two crossings lie on the two edges at that corner.
  auto cuts_off = [&](const IsoCurves& c, int corner_x, int corner_y) {
    for (const auto& s : c.segments) {
      const auto& p = c.points[s[0]];
      const auto& q = c.points[s[1]];
      if (std::abs(p[0] - corner_x) + std::abs(p[1] - corner_y) < 1 &&
          std::abs(q[0] - corner_x) + std::abs(q[1] - corner_y) < 1)
        return true;
    }
    return false;
  };
  EXPECT_TRUE(cuts_off(naive, 0, 0));  // naive: the inside corners are cut off
  EXPECT_TRUE(cuts_off(naive, 1, 1));
  EXPECT_TRUE(cuts_off(decider, 1, 0));  // decider: the outside corners are
  EXPECT_TRUE(cuts_off(decider, 0, 1));
  // The known answer: the bilinear interpolant's saddle point, here the
  // cell's centre by symmetry, has f = 0.6 > c. Inside is on the left of
  // every segment; the decider's segments have the centre on their left
  // (inside, as f says), the naive ones on their right (outside, wrongly).
  EXPECT_NEAR(g.bilinear(0.5, 0.5), 0.6, 1e-15);
  auto centre_on_left = [](const IsoCurves& c, const std::array<int, 2>& s) {
    const auto& p = c.points[s[0]];
    const auto& q = c.points[s[1]];
    return (q[0] - p[0]) * (0.5 - p[1]) - (q[1] - p[1]) * (0.5 - p[0]) > 0;
  };
  for (const auto& s : decider.segments) EXPECT_TRUE(centre_on_left(decider, s));
  for (const auto& s : naive.segments) EXPECT_FALSE(centre_on_left(naive, s));
  // Below the saddle value: with v = 0.05 it is (1 - 0.0025) / 1.9 = 0.525 >
  // 0.5, still joined; at c = 0.55 > 0.525 the decider separates, as naive.
  EXPECT_EQ(marching_squares(saddle_cell(0.05), 0.55, Saddle::kDecider).segments,
            marching_squares(saddle_cell(0.05), 0.55, Saddle::kNaive).segments);
}

TEST(MarchingSquares, RandomFieldsCloseInTheInterior) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Grid2 g;
    g.nx = 30;
    g.ny = 25;
    g.values.resize(std::size_t(g.nx) * g.ny);
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const bool border = i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1;
        g.values[std::size_t(j) * g.nx + i] = border ? 0 : u(rng);  // outside on the border
      }
    for (Saddle rule : {Saddle::kNaive, Saddle::kDecider}) {
      const IsoCurves c = marching_squares(g, 0.5, rule);
      std::map<int, int> uses;
      for (const auto& s : c.segments) ++uses[s[0]], ++uses[s[1]];
      for (const auto& [p, n] : uses) ASSERT_EQ(n, 2) << "point " << p;  // no point in 3 segments
      std::size_t points = 0;
      for (const auto& l : c.polylines()) {
        EXPECT_EQ(l.front(), l.back());  // closed
        points += l.size() - 1;
      }
      EXPECT_EQ(points, c.points.size());
    }
  }
}

TEST(MarchingSquares, OpenCurvesEndOnTheBorder) {
  // The half-plane x < 0.3 inside: one open polyline from border to border,
  // one point per row of cells' edges, running up (+y) so that -x is on its left.
  const Grid2 g = sample([](double x, double) { return 0.3 - x; }, -1, -1, 1, 1, 9, 9);
  const IsoCurves c = marching_squares(g, 0);
  const auto lines = c.polylines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].front(), lines[0].back());
  EXPECT_EQ(lines[0].size(), 9u);
  EXPECT_DOUBLE_EQ(c.points[lines[0].front()][1], -1);
  EXPECT_DOUBLE_EQ(c.points[lines[0].back()][1], 1);
  for (int p : lines[0]) EXPECT_NEAR(c.points[p][0], 0.3, 1e-15);
}

std::string message_of(const Grid2& g, double c) {
  try {
    marching_squares(g, c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(MarchingSquares, BadInputThrowsNamingTheValue) {
  Grid2 g = saddle_cell(0.2);
  EXPECT_EQ(message_of(g, NAN), "marching_squares: c=nan (the iso value must be finite)");
  Grid2 bad = g;
  bad.values[2] = INFINITY;
  EXPECT_EQ(message_of(bad, 0.5), "marching_squares: value(0, 1)=inf (values must be finite)");
  bad = g;
  bad.hx = 0;
  EXPECT_EQ(message_of(bad, 0.5), "marching_squares: hx=0 (must be positive)");
  bad = g;
  bad.ny = 1;
  EXPECT_EQ(message_of(bad, 0.5), "marching_squares: grid ny=1 (must be at least 2)");
}

}  // namespace
}  // namespace gllab::field
