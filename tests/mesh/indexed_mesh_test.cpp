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

// Without a ripple (amplitude 0) the rippled torus is make_torus's, vertex for
// vertex, in the same order: the same formulas (P = c + r n, normal n), so the
// floats agree to rounding.
TEST(RippledTorus, WithoutRippleIsTheTorus) {
  const gllab::IndexedMesh m = gllab::make_torus(12, 8, 1.0, 0.4);
  const std::vector<float> v = gllab::rippled_torus(12, 8, 1.0, 0.4, 3, 0.0, 0.7);
  ASSERT_EQ(v.size(), 6 * m.vertex_count());
  for (std::size_t i = 0; i < m.vertex_count(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(v[6 * i + k], m.positions[3 * i + k], kFloatTolerance) << i;
      EXPECT_NEAR(v[6 * i + 3 + k], m.normals[3 * i + k], kFloatTolerance) << i;
    }
}

// Property: with a ripple, every point is rho(u) = r + A sin(m u - phase) from
// the tube centre (R cos u, R sin u, 0), and the normal has unit length. It
// differs from the plain normal where rho' != 0: at u = 0 with phase 0,
// rho' = A m, so the normal tilts along the ring (y < 0 at the outer equator).
TEST(RippledTorus, PointsLieOnTheRippledTubeWithUnitNormals) {
  const int rings = 16, sides = 6, waves = 2;
  const double R = 1.0, r = 0.4, A = 0.1;
  const std::vector<float> v = gllab::rippled_torus(rings, sides, R, r, waves, A, 0.0);
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const float* p = &v[6 * std::size_t(i * sides + j)];
      const double u = 2 * M_PI * i / rings, rho = r + A * std::sin(waves * u);
      EXPECT_NEAR(std::hypot(p[0] - R * std::cos(u), p[1] - R * std::sin(u), p[2]), rho,
                  kFloatTolerance);
      EXPECT_NEAR(std::hypot(p[3], p[4], p[5]), 1.0, kFloatTolerance);
    }
  EXPECT_LT(v[4], -0.05f) << "vertex (0, 0): the normal leans back along the ring";
}

// 4 corners per square, counter-clockwise from +z, two greys alternating.
TEST(CheckerFloor, QuadsCoverTheSquareCounterClockwise) {
  const gllab::ColouredQuads f = gllab::checker_floor(4, 2.f, -0.5f);
  ASSERT_EQ(f.positions.size(), 4u * 4u * 4u * 3u);
  ASSERT_EQ(f.colours.size(), f.positions.size());
  double area = 0;
  for (std::size_t q = 0; q < 16; ++q) {
    const float* c = &f.positions[12 * q];
    for (int k = 0; k < 4; ++k) {
      const float* a = c + 3 * k;
      const float* b = c + 3 * ((k + 1) % 4);
      area += 0.5 * (a[0] * b[1] - b[0] * a[1]);  // shoelace: > 0 when counter-clockwise
      EXPECT_EQ(a[2], -0.5f);
    }
  }
  EXPECT_NEAR(area, 4.0 * 4.0, 1e-5);  // [-2, 2]^2, every square counted positive
  EXPECT_NE(f.colours[0], f.colours[12]) << "neighbours differ";
  EXPECT_EQ(f.colours[0], f.colours[12 * 5]) << "diagonal neighbours agree";
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
