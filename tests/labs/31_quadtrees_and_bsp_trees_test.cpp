// tests/labs/31_quadtrees_and_bsp_trees_test.cpp — what lab 31 promises
// (lecture notes ch. 1, §1.8 Space partitioning, "Quadtrees", "BSP trees",
// "Principal Component Analysis"):
//  - quadtree_vs_bsp: every quadtree cell holds at most one object (the
//    scene's objects do not touch);
//  - pca: for points on a line the main axis is the line's direction and the
//    second variance is 0; for points on a rectangle's corners the axes are
//    the rectangle's, with variances from the formula B = A^T A / (n - 1);
//  - painter: the BSP tree's order with the depth test off equals the
//    z-buffer's picture but along edges, for every plane rule and camera;
//  - split_rules: "fewest splits" splits no more than "own plane".
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_before;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "31_quadtrees_and_bsp_trees";
constexpr int kCloud = 24;  // the lab's point list P

TEST(QuadtreesAndBspTreesLab, EveryQuadtreeCellHoldsAtMostOneObject) {
  ScratchDir dir("lab31");
  const std::vector<std::string> text = view_text(kLab, dir, "quadtree_vs_bsp");
  const std::vector<double> crowded = numbers_before(text, " with more than one object");
  ASSERT_EQ(crowded.size(), 1u);
  EXPECT_EQ(crowded[0], 0);
}

// The lab's λ1, e1 and λ2 for the cloud `points` (all 24 set with --set).
struct Axes {
  double l1 = -1, e1x = 0, e1y = 0, l2 = -1;
};
Axes pca_view(const ScratchDir& dir, const std::vector<std::array<double, 2>>& points) {
  std::vector<std::string> sets;
  for (int i = 0; i < kCloud; ++i) {
    const auto& p = points[std::size_t(i) % points.size()];
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "P[%d]=%g,%g", i, p[0], p[1]);
    sets.push_back(buffer);
  }
  Axes a;
  for (const std::string& line : view_text(kLab, dir, "pca", sets)) {
    std::sscanf(line.c_str(), "lambda1 = %lf  e1 = (%lf, %lf)", &a.l1, &a.e1x, &a.e1y);
    std::sscanf(line.c_str(), "lambda2 = %lf", &a.l2);
  }
  return a;
}

TEST(QuadtreesAndBspTreesLab, PcaOfALineIsTheLinesDirection) {
  ScratchDir dir("lab31");
  std::vector<std::array<double, 2>> line;  // 24 points on y = 0.5 x, x = -0.575 .. 0.575
  for (int i = 0; i < kCloud; ++i) line.push_back({-0.575 + 0.05 * i, 0.5 * (-0.575 + 0.05 * i)});
  const Axes a = pca_view(dir, line);
  // e1 = (2, 1) / sqrt 5 up to sign; the variance across the line is 0.
  EXPECT_NEAR(std::abs(a.e1x), 2 / std::sqrt(5.0), 1e-3);
  EXPECT_NEAR(std::abs(a.e1y), 1 / std::sqrt(5.0), 1e-3);
  EXPECT_NEAR(a.l2, 0, 1e-4);
  // Along the line: x_i spaced 0.05, so var(x) = 0.05^2 n (n + 1) / 12 (n = 24 values),
  // and the length is sqrt(1 + 0.25) x: lambda1 = 1.25 var(x).
  EXPECT_NEAR(a.l1, 1.25 * 0.0025 * 24 * 25 / 12, 1e-4);
}

TEST(QuadtreesAndBspTreesLab, PcaOfARectanglesCornersIsItsAxes) {
  ScratchDir dir("lab31");
  // The corners (+-0.8, +-0.3), 6 times each: B = diag(0.64, 0.09) * 24 / 23.
  const Axes a = pca_view(dir, {{.8, .3}, {-.8, .3}, {-.8, -.3}, {.8, -.3}});
  EXPECT_NEAR(a.l1, 0.64 * 24 / 23, 1e-4);
  EXPECT_NEAR(a.l2, 0.09 * 24 / 23, 1e-4);
  EXPECT_NEAR(std::abs(a.e1x), 1, 1e-3);
  EXPECT_NEAR(a.e1y, 0, 1e-3);
}

TEST(QuadtreesAndBspTreesLab, PaintersPictureEqualsTheZBufferButAlongEdges) {
  ScratchDir dir("lab31");
  for (const char* rule : {"rule=0", "rule=1", "rule=2"})
    for (const char* camera : {"", "0,40,1", "70,-30,1"}) {
      std::vector<std::string> sets{rule};
      std::vector<std::string> text;
      if (*camera) {
        // --camera is not a --set: run the program with it.
        const std::vector<std::string> argv = {gllab::testing::headless(kLab),
                                               "--view",
                                               "painter",
                                               "--set",
                                               rule,
                                               "--camera",
                                               camera,
                                               "--print-text",
                                               "--out",
                                               (dir / "painter_camera.png").string()};
        const gllab::ProcessResult r = gllab::run_process(argv);
        ASSERT_EQ(r.exit_status, 0) << r.err;
        std::istringstream lines(r.out);
        for (std::string line; std::getline(lines, line);) text.push_back(line);
      } else {
        text = view_text(kLab, dir, "painter", sets);
      }
      double differing = -1, pixels = 0, away = -1;
      for (const std::string& line : text)
        std::sscanf(line.c_str(), "pixels differing: %lf of %lf, away from edges: %lf", &differing,
                    &pixels, &away);
      ASSERT_GE(differing, 0) << rule << " " << camera;
      // Away from an edge of the z-buffer picture, no pixel may differ: a wrong order paints a
      // whole patch. Along edges, pieces' borders and intersection lines rasterize a little
      // differently from a per-pixel depth test: at most 1 % of the panel.
      EXPECT_EQ(away, 0) << rule << " " << camera;
      EXPECT_LT(differing, pixels / 100) << rule << " " << camera;
    }
}

TEST(QuadtreesAndBspTreesLab, FewestSplitsSplitsNoMoreThanOwnPlane) {
  ScratchDir dir("lab31");
  std::vector<double> splits;  // the panels' "8 splits" lines: own plane, fewest splits, PCA
  for (const std::string& line : view_text(kLab, dir, "split_rules")) {
    int n = 0;
    char rest[16] = {};
    if (std::sscanf(line.c_str(), "%d %15s", &n, rest) == 2 && std::string(rest) == "splits")
      splits.push_back(n);
  }
  ASSERT_EQ(splits.size(), 3u);
  EXPECT_LE(splits[1], splits[0]);
}

}  // namespace
