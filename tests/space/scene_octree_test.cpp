// tests/space/scene_octree_test.cpp — the octree of a scene's triangles and its
// ray queries (lecture notes ch. 1, §1.8 Space partitioning, "Octrees": cells
// hold lists of polygons, which speeds up ray tracing), against brute force.
#include "space/scene_octree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "mesh/indexed_mesh.h"

namespace {

namespace sp = gllab::space;
using sp::Vec3;

// A torus and, beside it, a second, smaller one turned upright: 2 meshes in one.
gllab::IndexedMesh scene() {
  gllab::IndexedMesh a = gllab::make_torus(120, 48, 1, 0.4), b = gllab::make_torus(60, 24, .5, .2);
  const std::uint32_t offset = std::uint32_t(a.vertex_count());
  for (std::size_t v = 0; v < b.vertex_count(); ++v) {
    const float x = b.positions[3 * v], y = b.positions[3 * v + 1], z = b.positions[3 * v + 2];
    a.positions.insert(a.positions.end(), {x + 1.6f, z, y + 0.3f});
  }
  for (std::uint32_t i : b.indices) a.indices.push_back(i + offset);
  return a;
}

TEST(SceneOctree, RayTriangleHitsTheCentroidAndMissesOutside) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  double t, u, v;
  // From (1/3, 1/3, 2) straight down: t = 2 at the centroid, u = v = 1/3.
  ASSERT_TRUE(sp::ray_triangle({{1.0 / 3, 1.0 / 3, 2}, {0, 0, -1}}, a, b, c, t, u, v));
  EXPECT_DOUBLE_EQ(t, 2);
  EXPECT_DOUBLE_EQ(u, 1.0 / 3);
  EXPECT_DOUBLE_EQ(v, 1.0 / 3);
  // Just outside the hypotenuse x + y = 1, and behind the origin: no hit.
  EXPECT_FALSE(sp::ray_triangle({{0.5, 0.5 + 1e-9, 2}, {0, 0, -1}}, a, b, c, t, u, v));
  EXPECT_FALSE(sp::ray_triangle({{0.2, 0.2, 2}, {0, 0, 1}}, a, b, c, t, u, v));
  // Both sides count: from below.
  EXPECT_TRUE(sp::ray_triangle({{0.2, 0.2, -1}, {0, 0, 1}}, a, b, c, t, u, v));
}

TEST(SceneOctree, FirstHitEqualsBruteForceOn10000RandomRays) {
  const gllab::IndexedMesh mesh = scene();
  const sp::SceneOctree octree(mesh);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.5, 2.5), w(-1, 1);
  std::size_t hits = 0, tested = 0, brute = 0;
  for (int i = 0; i < 10000; ++i) {
    sp::Ray ray{{u(rng), u(rng), u(rng)}, {w(rng), w(rng), w(rng)}};
    if (i % 10 == 1) ray.direction = {0, 0, w(rng) < 0 ? -1.0 : 1.0};  // axis-parallel
    if (i % 10 == 2) ray.direction = {w(rng), 0, 0};
    if (i % 10 == 3) {  // aimed at a vertex: ties between the triangles around it
      const std::size_t v = std::size_t(rng() % mesh.vertex_count());
      ray.direction =
          Vec3{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]} -
          ray.origin;
    }
    sp::RayStats so, sb;
    const sp::Hit a = octree.first_hit(ray, &so), b = sp::first_hit_brute_force(mesh, ray, &sb);
    ASSERT_EQ(a.hit, b.hit) << i;
    if (a.hit) {
      EXPECT_EQ(a.triangle, b.triangle) << i;
      EXPECT_EQ(a.t, b.t) << i;
      EXPECT_EQ(a.u, b.u) << i;
      EXPECT_EQ(a.v, b.v) << i;
    }
    hits += a.hit;
    tested += so.triangles_tested;
    brute += sb.triangles_tested;
  }
  EXPECT_GT(hits, 2000u);  // the cases are not all misses
  // Brute force tests every triangle; the octree, on average, under a hundredth of them.
  EXPECT_LT(tested * 100, brute);
}

TEST(SceneOctree, LeavesHoldEveryTriangleThatOverlapsThem) {
  // Each triangle lies in the union of the leaves that reference it: a point of it (its
  // centroid) lies in some leaf, and the ray through that point along the normal finds it.
  const gllab::IndexedMesh mesh = gllab::make_torus(40, 16, 1, 0.4);
  const sp::SceneOctree octree(mesh, {6, 4});
  EXPECT_GE(octree.references(), mesh.triangle_count());
  EXPECT_LE(octree.depth(), 6);
  std::size_t inside = 0;
  for (const sp::Box3& b : octree.leaf_boxes()) inside += octree.cube().contains(b.centre());
  EXPECT_EQ(inside, octree.leaf_count());
  for (std::size_t t = 0; t < mesh.triangle_count(); t += 7) {
    Vec3 c{};
    for (int k = 0; k < 3; ++k) {
      const float* p = &mesh.positions[3 * std::size_t(mesh.indices[3 * t + k])];
      c += Vec3{p[0], p[1], p[2]} / 3.0;
    }
    const sp::Ray ray{c + Vec3{0, 0, 3}, {0, 0, -1}};
    EXPECT_EQ(octree.first_hit(ray).hit, sp::first_hit_brute_force(mesh, ray).hit);
  }
}

TEST(SceneOctree, BadInputIsOneLineNamingTheValue) {
  gllab::IndexedMesh m = gllab::make_torus(8, 4, 1, .4);
  m.indices[5] = 999;
  try {
    sp::SceneOctree o(m);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "SceneOctree: index 5 = 999 is out of range (32 vertices)");
  }
  gllab::IndexedMesh n = gllab::make_torus(8, 4, 1, .4);
  n.positions[4] = NAN;
  EXPECT_THROW(sp::SceneOctree{n}, std::invalid_argument);
  EXPECT_THROW(sp::SceneOctree(gllab::make_torus(8, 4, 1, .4), {13, 8}), std::invalid_argument);
  EXPECT_THROW(sp::SceneOctree(gllab::make_torus(8, 4, 1, .4), {8, 0}), std::invalid_argument);
}

}  // namespace
