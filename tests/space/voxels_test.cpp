// tests/space/voxels_test.cpp — voxel grids, solid voxelization by ray parity
// and the region octree (lecture notes ch. 1, §1.8 Space partitioning,
// "Voxels", "Octrees").
#include "space/voxels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "space/octree.h"

namespace {

namespace sp = gllab::space;
using sp::Vec3;

const sp::Box3 kCube{{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};

// A UV sphere of radius r, its poles shared: closed, counter-clockwise from outside.
gllab::IndexedMesh sphere_mesh(double r, int rings, int segments) {
  gllab::IndexedMesh m;
  const auto add = [&](Vec3 p) {
    m.positions.insert(m.positions.end(), {float(p.x), float(p.y), float(p.z)});
  };
  add({0, 0, -r});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = M_PI * i / rings - M_PI / 2, ph = 2 * M_PI * j / segments;
      add({r * std::cos(th) * std::cos(ph), r * std::cos(th) * std::sin(ph), r * std::sin(th)});
    }
  add({0, 0, r});
  const auto v = [&](int i, int j) { return std::uint32_t(1 + (i - 1) * segments + j % segments); };
  const std::uint32_t top = std::uint32_t(1 + (rings - 1) * segments);
  for (int j = 0; j < segments; ++j) m.indices.insert(m.indices.end(), {0, v(1, j + 1), v(1, j)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j)
      m.indices.insert(m.indices.end(), {v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i, j),
                                         v(i + 1, j + 1), v(i + 1, j)});
  for (int j = 0; j < segments; ++j)
    m.indices.insert(m.indices.end(), {v(rings - 1, j), v(rings - 1, j + 1), top});
  return m;
}

// An axis-aligned box as 12 triangles, outward.
gllab::IndexedMesh box_mesh(Vec3 lo, Vec3 hi) {
  gllab::IndexedMesh m;
  for (int c = 0; c < 8; ++c)
    m.positions.insert(m.positions.end(), {float(c & 1 ? hi.x : lo.x), float(c & 2 ? hi.y : lo.y),
                                           float(c & 4 ? hi.z : lo.z)});
  m.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
               2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  return m;
}

TEST(Voxels, SphereVolumeConvergesToFourThirdsPiRCubed) {
  // The exact sphere (signed distance) and a fine mesh of it: the voxel volume h^3 * count
  // tends to 4/3 pi r^3; the error is a surface effect, O(h) at worst, and averages out
  // to much less. Required: it falls by at least 1.5x per doubling of n overall, and is
  // below 0.5 % at n = 128.
  const double r = 1.2, exact = 4.0 / 3 * M_PI * r * r * r;
  const gllab::IndexedMesh mesh = sphere_mesh(r, 200, 400);
  std::vector<double> errors;
  for (const int n : {16, 32, 64, 128}) {
    const sp::VoxelGrid g = sp::voxelize(sp::sphere_distance({0, 0, 0}, r), kCube, n);
    const double h = g.voxel_size();
    errors.push_back(std::abs(g.solid_count() * h * h * h / exact - 1));
    const sp::VoxelGrid gm = sp::voxelize(mesh, kCube, n);
    // The mesh lies inside the sphere by at most r (1 - cos(pi / 200)) = 1.5e-4: it can
    // differ only in voxels whose centre is that close to the sphere.
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          if (g.at(i, j, k) != gm.at(i, j, k)) {
            EXPECT_LT(std::abs(norm(g.centre(i, j, k)) - r), 2e-4) << n << " " << i << j << k;
          }
  }
  EXPECT_LT(errors[3], 0.005);
  EXPECT_LT(errors[3] * 1.5 * 1.5 * 1.5, errors[0]);
}

TEST(Voxels, BoxMeshEqualsTheExactInsideTestEvenThroughEdgesAndVertices) {
  // At n = 12 over [-1.5, 1.5]^3 the voxel centres lie at -1.375 + 0.25 k; a box whose
  // faces and edges pass exactly through centre columns (x = -0.375, 0.625 ...) puts columns
  // through its edges and vertices: parity must still count each crossing once. A centre
  // on a top or bottom face counts as inside from below (crossings at z <= centre).
  const Vec3 lo{-0.375, -0.875, -1.125}, hi{0.625, 0.375, 0.875};
  const sp::VoxelGrid g = sp::voxelize(box_mesh(lo, hi), kCube, 12);
  std::size_t inside = 0;
  for (int k = 0; k < 12; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) {
        const Vec3 c = g.centre(i, j, k);
        // Columns on a side face are inside for exactly one of the two faces' triangles'
        // tie rule; compare only columns strictly inside or outside in x and y, and count
        // the rest for the parity of their crossings (0 or 2: never 1).
        const bool xy_inside = c.x > lo.x && c.x < hi.x && c.y > lo.y && c.y < hi.y;
        const bool xy_outside = c.x < lo.x || c.x > hi.x || c.y < lo.y || c.y > hi.y;
        const bool z_inside = c.z >= lo.z && c.z < hi.z;
        if (xy_inside) {
          EXPECT_EQ(g.at(i, j, k), z_inside) << i << " " << j << " " << k;
        }
        if (xy_outside) {
          EXPECT_FALSE(g.at(i, j, k)) << i << " " << j << " " << k;
        }
        inside += g.at(i, j, k);
      }
  // Whole columns: a column on the box's border is either all in (over the z range) or all
  // out, never a stray voxel, because its two crossings are found once each.
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      int count = 0;
      for (int k = 0; k < 12; ++k) count += g.at(i, j, k);
      EXPECT_TRUE(count == 0 || count == 8) << i << " " << j << ": " << count;
    }
  EXPECT_GT(inside, 0u);
}

TEST(Voxels, OpenAndInconsistentMeshesAreRejectedNamingAnEdge) {
  gllab::IndexedMesh torus = gllab::make_torus(24, 12, 1, 0.4);
  EXPECT_EQ(sp::open_edge(torus), "");
  gllab::IndexedMesh open = torus;
  open.indices.resize(open.indices.size() - 3);  // one triangle removed
  try {
    sp::voxelize(open, kCube, 8);
    FAIL() << "an open mesh was voxelized";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the mesh is not closed: edge ("), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("has 1 triangle"), std::string::npos) << e.what();
  }
  gllab::IndexedMesh flipped = torus;
  std::swap(flipped.indices[0], flipped.indices[1]);
  try {
    sp::voxelize(flipped, kCube, 8);
    FAIL() << "a flipped triangle was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("orientation is inconsistent"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(sp::voxelize(torus, kCube, 0), std::invalid_argument);
  EXPECT_THROW(sp::VoxelGrid(sp::Box3{{0, 0, 0}, {1, 2, 1}}, 4), std::invalid_argument);
}

TEST(Voxels, DegenerateTrianglesAreSkippedAndCounted) {
  // A box plus a zero-area triangle's worth of edges kept closed: a "sliver" pair (a, b, c)
  // and (c, b, a) on three collinear new points closes on itself.
  gllab::IndexedMesh m = box_mesh({-1, -1, -1}, {1, 1, 1});
  const std::uint32_t v = std::uint32_t(m.vertex_count());
  m.positions.insert(m.positions.end(), {0, 0, 0, 0.5f, 0, 0, 1.f, 0, 0});
  m.indices.insert(m.indices.end(), {v, v + 1, v + 2, v + 2, v + 1, v});
  sp::VoxelizeStats stats;
  const sp::VoxelGrid g = sp::voxelize(m, kCube, 6, &stats);
  EXPECT_EQ(stats.triangles, 14u);
  EXPECT_EQ(stats.degenerate_skipped, 2u);
  EXPECT_EQ(g.solid_count(), 4u * 4 * 4);  // centres +-0.25, +-0.75 inside [-1, 1]
}

TEST(RegionOctree, CoveredLeavesHoldExactlyTheGridsVoxels) {
  const std::vector<sp::SignedDistance> solids = {sp::sphere_distance({0.1, -0.2, 0.05}, 1.1),
                                                  sp::torus_distance({}, 1, 0.45)};
  for (std::size_t s = 0; s < solids.size(); ++s)
    for (int depth = 1; depth <= 7; ++depth) {
      const sp::VoxelGrid g = sp::voxelize(solids[s], kCube, 1 << depth);
      const sp::RegionOctree t = sp::RegionOctree::from_distance(solids[s], kCube, depth);
      EXPECT_EQ(t.covered_voxels(), g.solid_count()) << s << " depth " << depth;
      const int n = 1 << depth;
      std::size_t wrong = 0;
      for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) wrong += t.covered(g.centre(i, j, k)) != g.at(i, j, k);
      EXPECT_EQ(wrong, 0u) << s << " depth " << depth;
      // From the voxels, the same tree node for node.
      const sp::RegionOctree v = sp::RegionOctree::from_voxels(g);
      ASSERT_EQ(v.nodes().size(), t.nodes().size()) << s << " depth " << depth;
      for (std::size_t i = 0; i < v.nodes().size(); ++i) {
        EXPECT_EQ(v.nodes()[i].state, t.nodes()[i].state);
        EXPECT_EQ(v.nodes()[i].first_child, t.nodes()[i].first_child);
      }
    }
}

TEST(RegionOctree, NodesGrowWithTheSurfaceNotTheVolume) {
  // Only cubes the surface passes through split: nodes at depth d + 1 about 4 times those
  // at depth d once the cubes are small against the sphere (area / h^2), against 8 for n^3.
  std::vector<double> nodes;
  for (int depth = 4; depth <= 8; ++depth)
    nodes.push_back(
        double(sp::RegionOctree::from_distance(sp::sphere_distance({}, 1.2), kCube, depth)
                   .nodes()
                   .size()));
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    EXPECT_GT(nodes[i] / nodes[i - 1], 3.5) << i;
    EXPECT_LT(nodes[i] / nodes[i - 1], 4.5) << i;
  }
  EXPECT_LT(nodes.back(), 256.0 * 256 * 256 / 20);
}

TEST(RegionOctree, ChildrenFollowTheNumbering) {
  // A solid filling the octant x > 0, y < 0, z > 0 of the root (child 1 + 4 = 5): the root
  // splits, child 5 is covered, the others uncovered (the box's distance bound).
  const sp::SignedDistance octant = [](Vec3 p) {
    return std::max({-p.x, p.y, -p.z, p.x - 1.5, -p.y - 1.5, p.z - 1.5});
  };
  const sp::RegionOctree t = sp::RegionOctree::from_distance(octant, kCube, 3);
  ASSERT_EQ(t.nodes().size(), 9u);
  for (int c = 0; c < 8; ++c)
    EXPECT_EQ(t.nodes()[std::size_t(1 + c)].state,
              c == 5 ? sp::Coverage::kCovered : sp::Coverage::kUncovered)
        << c;
  EXPECT_EQ(t.count(sp::Coverage::kPartial), 1u);
  EXPECT_EQ(t.covered_voxels(), 4u * 4 * 4);
}

TEST(RegionOctree, BadInput) {
  EXPECT_THROW(sp::RegionOctree::from_voxels(sp::VoxelGrid(kCube, 12)), std::invalid_argument);
  EXPECT_THROW(sp::RegionOctree::from_distance(sp::sphere_distance({}, 1), kCube, 11),
               std::invalid_argument);
}

}  // namespace
