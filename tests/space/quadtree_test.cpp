// tests/space/quadtree_test.cpp — the quadtree of a 2-D scene (lecture notes
// ch. 1, §1.8 Space partitioning, "Quadtrees": subdivide until each cell holds
// at most one object).
#include "space/quadtree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace {

namespace sp = gllab::space;
using sp::Vec2;

sp::ConvexPolygon2 regular(Vec2 c, double r, int n, double turn = 0) {
  sp::ConvexPolygon2 p;
  for (int k = 0; k < n; ++k)
    p.push_back(
        {c.x + r * std::cos(turn + 2 * M_PI * k / n), c.y + r * std::sin(turn + 2 * M_PI * k / n)});
  return p;
}

// Random discs (as 12-gons) that do not touch: their centres at least r1 + r2 + gap apart.
std::vector<sp::ConvexPolygon2> separated_scene(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> u(0.05, 0.95), r(0.01, 0.06);
  std::vector<std::pair<Vec2, double>> discs;
  while (int(discs.size()) < count) {
    const Vec2 c{u(rng), u(rng)};
    const double radius = r(rng);
    bool free = true;
    for (const auto& d : discs) free = free && norm(c - d.first) > radius + d.second + 0.01;
    if (free) discs.push_back({c, radius});
  }
  std::vector<sp::ConvexPolygon2> out;
  for (const auto& d : discs) out.push_back(regular(d.first, d.second, 12, 0.3));
  return out;
}

TEST(Quadtree, EveryLeafHoldsAtMostOneObjectAndLocationAgreesWithBruteForce) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 5; ++trial) {
    const std::vector<sp::ConvexPolygon2> objects = separated_scene(rng, 25);
    const sp::Quadtree tree(objects, {{0, 0}, {1, 1}}, 12);
    EXPECT_EQ(tree.crowded_leaves(), 0u);
    for (const sp::QuadNode& n : tree.nodes()) {
      if (n.first_child >= 0) continue;
      EXPECT_LE(n.objects.size(), 1u);
      for (std::size_t o = 0; o < objects.size(); ++o) {  // the leaf's list is complete
        if (sp::overlaps(objects[o], n.box)) {
          EXPECT_EQ(n.objects, std::vector<int>{int(o)});
        }
      }
    }
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 10000; ++i) {
      Vec2 p{u(rng), u(rng)};
      if (i % 4 == 1) p.x = 0.5;                                        // on the root's centre line
      if (i % 4 == 2) p = objects[std::size_t(i) % objects.size()][0];  // an object's corner
      int brute = -1;
      for (std::size_t o = 0; o < objects.size() && brute < 0; ++o)
        if (sp::contains(objects[o], p)) brute = int(o);
      EXPECT_EQ(tree.object_at(p), brute) << p.x << " " << p.y;
    }
  }
}

TEST(Quadtree, ChildrenFollowTheNumberingAndTouchingObjectsAreCounted) {
  // One square in the upper right quarter and one in the lower left: the root splits once;
  // child 3 (upper right) holds object 0, child 0 (lower left) object 1.
  const std::vector<sp::ConvexPolygon2> two = {{{.6, .6}, {.9, .6}, {.9, .9}, {.6, .9}},
                                               {{.1, .1}, {.4, .1}, {.4, .4}, {.1, .4}}};
  const sp::Quadtree t(two, {{0, 0}, {1, 1}}, 4);
  ASSERT_EQ(t.nodes().size(), 5u);
  EXPECT_EQ(t.nodes()[4].objects, std::vector<int>{0});
  EXPECT_EQ(t.nodes()[1].objects, std::vector<int>{1});
  EXPECT_TRUE(t.nodes()[2].objects.empty());
  EXPECT_EQ(t.locate({.75, .2}), 2);  // child 1, lower right
  // Two squares sharing an edge cannot be told apart by any cell: max_depth stops them.
  const std::vector<sp::ConvexPolygon2> touching = {{{.1, .1}, {.3, .1}, {.3, .3}, {.1, .3}},
                                                    {{.3, .1}, {.5, .1}, {.5, .3}, {.3, .3}}};
  const sp::Quadtree u(touching, {{0, 0}, {1, 1}}, 6);
  EXPECT_GT(u.crowded_leaves(), 0u);
  EXPECT_EQ(u.depth(), 6);
}

TEST(Quadtree, BadInputIsOneLineNamingTheValue) {
  const auto message = [](const std::vector<sp::ConvexPolygon2>& objects, int depth) {
    try {
      sp::Quadtree t(objects, {{0, 0}, {1, 1}}, depth);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const sp::ConvexPolygon2 ok = {{.1, .1}, {.2, .1}, {.2, .2}};
  EXPECT_EQ(message({ok, {{.1, .1}, {.2, .2}, {.2, .1}}}, 4),
            "quadtree: object 1 is not convex and counter-clockwise at point 0");
  EXPECT_EQ(message({{{.1, .1}, {.2, .1}}}, 4), "quadtree: object 0 has 2 points (at least 3)");
  EXPECT_EQ(message({{{.1, .1}, {NAN, .1}, {.2, .2}}}, 4),
            "quadtree: object 0: point 1 is not finite");
  EXPECT_EQ(message({ok}, 17), "quadtree: max_depth = 17 (must be 0..16)");
  // A non-convex quadrilateral (a dart).
  EXPECT_NE(message({{{0, 0}, {.4, .1}, {.1, .1}, {.1, .4}}}, 4).find("not convex"),
            std::string::npos);
}

}  // namespace
