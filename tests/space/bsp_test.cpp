// tests/space/bsp_test.cpp — BSP trees over polygons (lecture notes ch. 1,
// §1.8 Space partitioning, "BSP trees"; Fuchs, Kedem and Naylor 1980): the
// pieces cover each polygon exactly, every polygon appears once, the
// back-to-front order is right from every eye, and the three plane rules.
#include "space/bsp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <string>

namespace {

namespace sp = gllab::space;
using sp::Vec3;

const sp::SplitRule kRules[] = {sp::SplitRule::kOwnPlane, sp::SplitRule::kFewestSplits,
                                sp::SplitRule::kPca};

// Random triangles and parallelograms in [-1, 1]^3, one object each.
std::vector<sp::Polygon3> random_scene(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> u(-1, 1), s(0.1, 0.6);
  std::vector<sp::Polygon3> out;
  for (int i = 0; i < count; ++i) {
    // One draw per statement: the order of operands of * is unspecified, and gcc and
    // clang pick differently, so `s(rng) * Vec3{u(rng), ...}` gave two scenes.
    const Vec3 c{u(rng), u(rng), u(rng)};
    const double sa = s(rng);
    const Vec3 a = sa * Vec3{u(rng), u(rng), u(rng)};
    const double sb = s(rng);
    const Vec3 b = sb * Vec3{u(rng), u(rng), u(rng)};
    sp::Polygon3 p{{c, c + a, c + a + b}, i, i};
    if (i % 2) p.points.push_back(c + b);
    out.push_back(p);
  }
  return out;
}

// Ray and convex planar polygon: the hit's t, or -1.
double ray_polygon(Vec3 o, Vec3 d, const sp::Polygon3& q) {
  sp::Plane pl;
  if (!sp::polygon_plane(q, pl)) return -1;
  const double den = dot(pl.n, d);
  if (den == 0) return -1;
  const double t = (pl.d - dot(pl.n, o)) / den;
  if (t <= 0) return -1;
  const Vec3 x = o + t * d;
  for (std::size_t i = 0; i < q.points.size(); ++i) {
    const Vec3 a = q.points[i], b = q.points[(i + 1) % q.points.size()];
    if (dot(cross(b - a, x - a), pl.n) < -1e-12) return -1;
  }
  return t;
}

TEST(Bsp, PiecesCoverEachPolygonsAreaAndEachAppearsOnce) {
  std::mt19937 rng(4);
  for (const sp::SplitRule rule : kRules)
    for (int trial = 0; trial < 10; ++trial) {
      const std::vector<sp::Polygon3> scene = random_scene(rng, 40);
      const sp::BspTree tree(scene, rule);
      std::map<int, double> area;
      std::map<const sp::Polygon3*, int> seen;
      const std::vector<const sp::Polygon3*> order = tree.back_to_front({3, 2, 1});
      for (const sp::Polygon3* q : order) {
        area[q->id] += sp::polygon_area(*q);
        ++seen[q];
      }
      EXPECT_EQ(order.size(), tree.stats().fragments);
      EXPECT_EQ(seen.size(), order.size());  // each piece once
      EXPECT_EQ(area.size(), scene.size());  // each polygon there
      for (const sp::Polygon3& p : scene)
        EXPECT_NEAR(area[p.id], sp::polygon_area(p), 1e-12 * sp::polygon_area(p) + 1e-15)
            << sp::split_rule_name(rule) << " polygon " << p.id;
      EXPECT_EQ(tree.stats().fragments, scene.size() + tree.stats().splits);
      for (const sp::BspNode& n : tree.nodes()) {  // the stop rule: one object per leaf
        if (!n.leaf) continue;
        for (const sp::Polygon3& q : n.on) EXPECT_EQ(q.object, n.on[0].object);
      }
    }
}

TEST(Bsp, BackToFrontPaintsTheNearestLastAlongEveryRay) {
  // For random eyes and rays from them: among the pieces a ray hits, the one drawn last
  // must be the nearest (what the painter's algorithm relies on).
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t checked = 0;
  for (const sp::SplitRule rule : kRules) {
    const std::vector<sp::Polygon3> scene = random_scene(rng, 30);
    const sp::BspTree tree(scene, rule);
    for (int e = 0; e < 20; ++e) {
      const Vec3 eye = 4.0 * normalized(Vec3{u(rng), u(rng), u(rng)});
      const std::vector<const sp::Polygon3*> order = tree.back_to_front(eye);
      for (int r = 0; r < 200; ++r) {
        // Aim at a point inside a random polygon (a convex combination of its corners),
        // so every ray hits at least one piece and is checked.
        const sp::Polygon3& target = scene[std::size_t(r) % scene.size()];
        Vec3 aim{0, 0, 0};
        double total = 0;
        for (const Vec3& corner : target.points) {
          const double w = 0.2 + 0.6 * (u(rng) + 1) / 2;
          aim = aim + w * corner;
          total += w;
        }
        const Vec3 d = (1 / total) * aim - eye;
        double nearest = 1e300, last_t = -1;
        for (const sp::Polygon3* q : order) {
          const double t = ray_polygon(eye, d, *q);
          if (t < 0) continue;
          nearest = std::min(nearest, t);
          last_t = t;
        }
        if (last_t < 0) continue;
        EXPECT_LE(last_t, nearest * (1 + 1e-9)) << sp::split_rule_name(rule);
        ++checked;
      }
    }
  }
  // 3 rules x 20 eyes x 200 rays, each aimed inside a polygon; a ray through a shared
  // edge may miss by the 1e-12 edge test, so allow 1% of them.
  EXPECT_GT(checked, 11880u);
}

TEST(Bsp, SplitPolygonCutsASquareInTwo) {
  const sp::Polygon3 square{{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, 7, 3};
  const sp::SplitResult r = sp::split_polygon(square, {{1, 0, 0}, 0.5});
  ASSERT_EQ(r.side, sp::SplitResult::kSpanning);
  EXPECT_DOUBLE_EQ(sp::polygon_area(r.front), 3);  // x > 0.5: 1.5 x 2
  EXPECT_DOUBLE_EQ(sp::polygon_area(r.back), 1);
  EXPECT_EQ(r.front.id, 7);
  EXPECT_EQ(r.back.object, 3);
  EXPECT_EQ(sp::split_polygon(square, {{0, 0, 1}, 0}).side, sp::SplitResult::kCoplanar);
  EXPECT_EQ(sp::split_polygon(square, {{1, 0, 0}, 2}).side, sp::SplitResult::kBack);  // touches
  EXPECT_EQ(sp::split_polygon(square, {{1, 0, 0}, 0}).side, sp::SplitResult::kFront);
}

TEST(Bsp, FewestSplitsSplitsLessThanOwnPlaneOnAverage) {
  std::mt19937 rng(21);
  std::size_t own = 0, fewest = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<sp::Polygon3> scene = random_scene(rng, 60);
    own += sp::BspTree(scene, sp::SplitRule::kOwnPlane).stats().splits;
    fewest += sp::BspTree(scene, sp::SplitRule::kFewestSplits).stats().splits;
  }
  EXPECT_LT(fewest, own);
}

TEST(Bsp, PlaneSceneWithPcaGivesVerticalPlanesAndOneObjectPerRegion) {
  // Squares in z = 0 (the lab's 2-D use): PCA's e1 lies in the plane, so every plane is
  // vertical (n.z = 0), and each leaf holds pieces of one object.
  std::vector<sp::Polygon3> squares;
  for (int i = 0; i < 12; ++i) {
    const double x = (i % 4) * 0.25 + 0.02 * (i % 3), y = (i / 4) * 0.3;
    squares.push_back({{{x, y, 0}, {x + .15, y, 0}, {x + .15, y + .1, 0}, {x, y + .1, 0}}, i, i});
  }
  const sp::BspTree tree(squares, sp::SplitRule::kPca);
  std::size_t leaves = 0;
  for (const sp::BspNode& n : tree.nodes()) {
    if (n.leaf) {
      ++leaves;
      for (const sp::Polygon3& q : n.on) EXPECT_EQ(q.object, n.on[0].object);
    } else {
      EXPECT_NEAR(n.plane.n.z, 0, 1e-12);
      EXPECT_TRUE(n.on.empty());
    }
  }
  EXPECT_GE(leaves, 12u);
}

TEST(Bsp, DegeneratePolygonsAreSkippedAndCounted) {
  std::vector<sp::Polygon3> scene = {{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0, 0},
                                     {{{0, 0, 1}, {1, 1, 1}, {2, 2, 1}}, 1, 1},  // collinear
                                     {{{0, 0, 2}, {1, 0, 2}}, 2, 2},             // two points
                                     {{{0, 0, 3}, {1, 0, 3}, {0, 1, 3}}, 3, 3}};
  const sp::BspTree tree(scene, sp::SplitRule::kOwnPlane);
  EXPECT_EQ(tree.stats().polygons, 4u);
  EXPECT_EQ(tree.stats().degenerate_skipped, 2u);
  EXPECT_EQ(tree.back_to_front({0, 0, 10}).size(), 2u);
  scene[0].points[1].y = NAN;
  try {
    sp::BspTree bad(scene, sp::SplitRule::kPca);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "bsp: polygon 0, point 1 = (1, nan, 0) is not finite");
  }
}

}  // namespace
