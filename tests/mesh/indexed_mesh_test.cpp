// tests/mesh/indexed_mesh_test.cpp — the torus the submission labs draw.
#include "mesh/indexed_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

namespace {

constexpr double kFloatTolerance = 1e-6;  // float rounding of unit-size values

// Property: a closed torus has V - E + F = 0 (genus 1), and every edge is
// shared by exactly two triangles.
TEST(MakeTorus, IsClosedWithEulerCharacteristicZero) {
  const gllab::IndexedMesh m = gllab::make_torus(12, 8, 1.0, 0.4);
  EXPECT_EQ(m.vertex_count(), 12u * 8u);
  EXPECT_EQ(m.triangle_count(), 2u * 12u * 8u);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = m.indices[3 * t + k], b = m.indices[3 * t + (k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}]++;
    }
  for (const auto& [edge, uses] : edges) EXPECT_EQ(uses, 2) << edge.first << "-" << edge.second;
  const long euler = static_cast<long>(m.vertex_count()) - static_cast<long>(edges.size()) +
                     static_cast<long>(m.triangle_count());
  EXPECT_EQ(euler, 0);
}

// Property: every point is at distance r from the tube centre, and its normal
// is the unit vector from there.
TEST(MakeTorus, PointsLieOnTheTubeAndNormalsPointOut) {
  const double R = 1.0, r = 0.4;
  const gllab::IndexedMesh m = gllab::make_torus(9, 7, R, r);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const float* p = &m.positions[3 * v];
    const float* n = &m.normals[3 * v];
    const double rho = std::hypot(p[0], p[1]);
    const double c[3] = {R * p[0] / rho, R * p[1] / rho, 0};
    const double d[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
    EXPECT_NEAR(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), r, kFloatTolerance);
    EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, kFloatTolerance);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(n[k], d[k] / r, kFloatTolerance);
  }
}

// Property: triangles run counter-clockwise seen from outside, so their
// geometric normal agrees with the vertex normals.
TEST(MakeTorus, TrianglesFaceOutwards) {
  const gllab::IndexedMesh m = gllab::make_torus(16, 10, 1.0, 0.4);
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const float* a = &m.positions[3 * m.indices[3 * t]];
    const float* b = &m.positions[3 * m.indices[3 * t + 1]];
    const float* c = &m.positions[3 * m.indices[3 * t + 2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const float* vn = &m.normals[3 * m.indices[3 * t]];
    EXPECT_GT(n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2], 0) << "triangle " << t;
  }
}

TEST(TorusWithTriangles, HitsTheRequestedCountClosely) {
  for (std::size_t target : {1000u, 10000u, 100000u, 1000000u}) {
    const std::size_t got = gllab::torus_with_triangles(target).triangle_count();
    EXPECT_NEAR(static_cast<double>(got), static_cast<double>(target), 0.03 * target) << target;
  }
}

TEST(Unshared, RepeatsEachIndexedVertex) {
  const gllab::IndexedMesh m = gllab::make_torus(5, 4, 1.0, 0.4);
  const gllab::IndexedMesh u = gllab::unshared(m);
  ASSERT_EQ(u.vertex_count(), m.indices.size());
  for (std::size_t i = 0; i < m.indices.size(); ++i) {
    EXPECT_EQ(u.indices[i], i);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(u.positions[3 * i + k], m.positions[3 * m.indices[i] + k]);
  }
}

TEST(Interleaved, PacksPositionNormalColourPerVertex) {
  const gllab::IndexedMesh m = gllab::make_torus(4, 3, 1.0, 0.4);
  const std::vector<float> v = gllab::interleaved(m);
  ASSERT_EQ(v.size(), 9 * m.vertex_count());
  EXPECT_EQ(v[9 * 5 + 0], m.positions[15]);
  EXPECT_EQ(v[9 * 5 + 4], m.normals[16]);
  EXPECT_EQ(v[9 * 5 + 8], m.colours[17]);
}

TEST(MakeTorus, BadSizesAreNamed) {
  EXPECT_THROW(gllab::make_torus(2, 8, 1, 0.4), std::invalid_argument);
  EXPECT_THROW(gllab::make_torus(8, 8, 0.3, 0.4), std::invalid_argument);
  try {
    gllab::make_torus(8, 1, 1, 0.4);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sides=1"), std::string::npos) << e.what();
  }
}

}  // namespace
