// tests/field/mesh_measures_test.cpp — topology, area and volume of meshes
// with known answers: a cube (6 faces, 12 triangles), the shared torus
// (common/mesh), an open and a misoriented mesh.
#include "field/mesh_measures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gllab::field {
namespace {

// The unit cube [0, 1]^3, each face two triangles counter-clockwise from outside.
IndexedMesh cube() {
  IndexedMesh m;
  for (int c = 0; c < 8; ++c)
    m.positions.insert(m.positions.end(), {float(c & 1), float((c >> 1) & 1), float(c >> 2)});
  // faces as corner cycles counter-clockwise seen from outside
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads)
    m.indices.insert(m.indices.end(),
                     {std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2]),
                      std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
  return m;
}

TEST(MeshMeasures, Cube) {
  const IndexedMesh m = cube();
  const MeshTopology t = topology(m);
  EXPECT_EQ(t.vertices, 8u);
  EXPECT_EQ(t.edges, 18u);  // 12 cube edges + 6 face diagonals
  EXPECT_EQ(t.triangles, 12u);
  EXPECT_EQ(t.euler(), 2);  // 8 - 18 + 12
  EXPECT_TRUE(t.closed_and_oriented());
  EXPECT_EQ(t.components, 1u);
  EXPECT_DOUBLE_EQ(surface_area(m), 6);
  EXPECT_DOUBLE_EQ(enclosed_volume(m), 1);
}

TEST(MeshMeasures, TorusFromTheSharedMesh) {
  const IndexedMesh m = make_torus(48, 24, 1, 0.4);
  const MeshTopology t = topology(m);
  EXPECT_TRUE(t.closed_and_oriented());
  EXPECT_EQ(t.euler(), 0);
  EXPECT_EQ(t.components, 1u);
  // Inscribed polyhedron: a little below 2 pi^2 R r^2 and 4 pi^2 R r.
  EXPECT_NEAR(enclosed_volume(m), 2 * M_PI * M_PI * 0.16, 0.02 * 2 * M_PI * M_PI * 0.16);
  EXPECT_NEAR(surface_area(m), 4 * M_PI * M_PI * 0.4, 0.01 * 4 * M_PI * M_PI * 0.4);
}

TEST(MeshMeasures, OpenFlippedAndTwoComponents) {
  IndexedMesh m = cube();
  IndexedMesh open = m;
  open.indices.resize(open.indices.size() - 6);  // drop the top face
  const MeshTopology to = topology(open);
  EXPECT_EQ(to.boundary_edges, 4u);
  EXPECT_FALSE(to.closed_and_oriented());
  IndexedMesh flipped = m;
  std::swap(flipped.indices[1], flipped.indices[2]);  // one triangle turned over
  const MeshTopology tf = topology(flipped);
  EXPECT_EQ(tf.misoriented_edges, 3u);
  EXPECT_EQ(tf.boundary_edges, 0u);
  IndexedMesh two = m;  // a second cube, shifted: two components, the volume twice
  for (int c = 0; c < 8; ++c)
    two.positions.insert(two.positions.end(),
                         {float(c & 1) + 3, float((c >> 1) & 1), float(c >> 2)});
  for (std::size_t k = 0; k < m.indices.size(); ++k) two.indices.push_back(m.indices[k] + 8);
  const MeshTopology t2 = topology(two);
  EXPECT_EQ(t2.components, 2u);
  EXPECT_EQ(t2.euler(), 4);
  EXPECT_NEAR(enclosed_volume(two), 2, 1e-12);
  IndexedMesh inverted = m;  // all triangles turned over: negative volume
  for (std::size_t f = 0; f < 12; ++f)
    std::swap(inverted.indices[3 * f + 1], inverted.indices[3 * f + 2]);
  EXPECT_DOUBLE_EQ(enclosed_volume(inverted), -1);
  EXPECT_TRUE(topology(inverted).closed_and_oriented());
}

}  // namespace
}  // namespace gllab::field
