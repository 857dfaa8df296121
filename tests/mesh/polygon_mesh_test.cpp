// tests/mesh/polygon_mesh_test.cpp — the polygon mesh of the lecture notes,
// ch. 1, §1.2 Polygonal representation (lab 06).
#include "mesh/polygon_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace {

using gllab::EdgeType;
using gllab::Normals;
using gllab::PolygonMesh;
using gllab::Vec3;

constexpr double kExact = 1e-12;          // double rounding of unit-size sums
constexpr double kFloatTolerance = 1e-6;  // float rounding in the render arrays

// The unit cube [0,1]^3: corner i has x = bit 0, y = bit 1, z = bit 2.
// Faces counter-clockwise seen from outside (checked by the normals test).
const std::vector<Vec3> kCubeCorners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                        {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const std::vector<gllab::PolygonInput> kCubeFaces = {
    {{0, 2, 3, 1}}, {{4, 5, 7, 6}},   // z = 0, z = 1
    {{0, 1, 5, 4}}, {{2, 6, 7, 3}},   // y = 0, y = 1
    {{0, 4, 6, 2}}, {{1, 3, 7, 5}}};  // x = 0, x = 1
// Their outward normals, in the same order (the definition of the unit cube).
const Vec3 kCubeNormals[] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};

PolygonMesh cube() { return gllab::build_polygon_mesh(kCubeCorners, kCubeFaces); }

// A UV sphere of radius 1 about the origin: a semicircle profile revolved.
PolygonMesh sphere(int slices, int stacks) {
  std::vector<gllab::ProfilePoint> profile;
  for (int i = 0; i <= stacks; ++i) {
    const double t = -M_PI / 2 + M_PI * i / stacks;
    profile.push_back({i == 0 || i == stacks ? 0.0 : std::cos(t), std::sin(t)});
  }
  return gllab::make_surface_of_revolution(profile, slices);
}

std::string error_of(const std::vector<Vec3>& positions, const std::vector<gllab::PolygonInput>& polygons) {
  try {
    gllab::build_polygon_mesh(positions, polygons);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

// §1.2, "Hierarchy of the representation": vertices are stored only once. A
// cube has 8 vertices, 12 edges and 6 faces, and a closed genus-0 surface has
// V - E + F = 2 (Euler).
TEST(BuildPolygonMesh, CubeStoresEachVertexAndEdgeOnce) {
  const PolygonMesh m = cube();
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.edges.size(), 12u);
  EXPECT_EQ(m.polygons.size(), 6u);
  EXPECT_EQ(static_cast<long>(m.vertices.size()) - static_cast<long>(m.edges.size()) +
                static_cast<long>(m.polygons.size()),
            2);
  // Each corner of a cube touches 3 faces.
  for (const gllab::Vertex& v : m.vertices) EXPECT_EQ(v.polygons.size(), 3u);
  EXPECT_EQ(m.surfaces[0].polygons.size(), 6u);
  EXPECT_EQ(m.triangle_count(), 12u);
}

// Property of a closed surface: every edge is used by exactly 2 polygons, and
// each polygon lists, as edge k, the edge joining its corners k and k+1.
TEST(BuildPolygonMesh, EveryCubeEdgeIsSharedByTwoFaces) {
  const PolygonMesh m = cube();
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    ASSERT_EQ(m.edges[e].polygons.size(), 2u) << "edge " << e;
    EXPECT_NEAR(m.edges[e].length, 1.0, kExact);  // unit cube
  }
  for (const gllab::Polygon& p : m.polygons)
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      const auto e = m.find_edge(p.vertices[k], p.vertices[(k + 1) % p.vertices.size()]);
      ASSERT_TRUE(e.has_value());
      EXPECT_EQ(p.edges[k], *e);
    }
  // Edge 0-1 lies on the faces z = 0 (polygon 0) and y = 0 (polygon 2).
  const auto e01 = m.find_edge(1, 0);
  ASSERT_TRUE(e01.has_value());
  EXPECT_EQ(std::set<std::size_t>(m.edges[*e01].polygons.begin(), m.edges[*e01].polygons.end()),
            (std::set<std::size_t>{0, 2}));
  EXPECT_FALSE(m.find_edge(0, 7).has_value());  // a space diagonal is no edge
}

// An open surface: the cube without its top face. The 4 edges around the hole
// have one polygon each (boundary); V - E + F = 8 - 12 + 5 = 1 for a disc.
TEST(BuildPolygonMesh, OpenBoxHasFourBoundaryEdgesUsedOnce) {
  std::vector<gllab::PolygonInput> faces = kCubeFaces;
  faces.erase(faces.begin() + 1);  // z = 1
  PolygonMesh m = gllab::build_polygon_mesh(kCubeCorners, faces);
  EXPECT_EQ(m.count(EdgeType::kBoundary), 4u);
  for (const gllab::Edge& e : m.edges) {
    const bool on_top = m.vertices[e.v0].position.z == 1 && m.vertices[e.v1].position.z == 1;
    EXPECT_EQ(e.polygons.size(), on_top ? 1u : 2u) << e.v0 << "-" << e.v1;
  }
  gllab::classify_edges(m, 45);
  EXPECT_EQ(m.count(EdgeType::kBoundary), 4u);  // still boundary, never feature
  EXPECT_EQ(m.count(EdgeType::kFeature), 8u);
}

// The cube's face normals are its outward axis directions; Newell's vector
// has length 2 * area (Tampieri, Graphics Gems III), so area = 1.
TEST(PolygonNormals, CubeFaceNormalsAreAxisAligned) {
  const PolygonMesh m = cube();
  for (std::size_t p = 0; p < m.polygons.size(); ++p) {
    EXPECT_NEAR(m.polygons[p].normal.x, kCubeNormals[p].x, kExact) << "face " << p;
    EXPECT_NEAR(m.polygons[p].normal.y, kCubeNormals[p].y, kExact) << "face " << p;
    EXPECT_NEAR(m.polygons[p].normal.z, kCubeNormals[p].z, kExact) << "face " << p;
    EXPECT_NEAR(m.polygons[p].area, 1.0, kExact);
    EXPECT_NEAR(m.polygons[p].flatness, 0.0, kExact);
  }
  // A cube corner's normal is the mean of three axis directions: (±1,±1,±1)/sqrt(3).
  EXPECT_NEAR(m.vertices[7].normal.x, 1 / std::sqrt(3.0), kExact);
  EXPECT_NEAR(m.vertices[0].normal.z, -1 / std::sqrt(3.0), kExact);
}

// A non-planar quad (the hexagon of lab 01 in small): corners at z = +-h.
// Newell's normal is the normal of the best plane, here z by symmetry, and the
// flatness is h (each corner lies h from the plane z = 0 through the centroid).
TEST(PolygonNormals, NewellHandlesANonPlanarQuad) {
  const double h = 0.25;
  const std::vector<Vec3> quad = {{1, 0, h}, {0, 1, -h}, {-1, 0, h}, {0, -1, -h}};
  const PolygonMesh m = gllab::build_polygon_mesh(quad, {{{0, 1, 2, 3}}});
  EXPECT_NEAR(m.polygons[0].normal.z, 1.0, kExact);
  EXPECT_NEAR(m.polygons[0].area, 2.0, kExact);  // the projected square has diagonal 2
  EXPECT_NEAR(m.polygons[0].flatness, h, kExact);
}

// A sphere-like mesh (UV sphere, radius 1, centre at the origin): each vertex
// normal, the mean of its polygons' normals, is close to the radial direction.
// Tolerance: 0.1 degree at 32 x 16, where one grid step is 11.25 degrees
// around and the neighbours sit symmetrically, so the errors cancel to first
// order (measured: 0.003 degree at most). A normal averaged wrongly, e.g. over
// one polygon only, is off by about half a step (5 degrees).
TEST(VertexNormals, SphereVertexNormalsAreNearlyRadial) {
  constexpr double kMaxDegrees = 0.1;
  const PolygonMesh m = sphere(32, 16);
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const Vec3 radial = gllab::spline::normalized(m.vertices[v].position);
    const double angle = std::acos(std::min(1.0, dot(radial, m.vertices[v].normal))) * 180 / M_PI;
    EXPECT_LT(angle, kMaxDegrees) << "vertex " << v;
  }
  // Every polygon faces outwards: the winding of make_surface_of_revolution.
  for (const gllab::Polygon& p : m.polygons)
    EXPECT_GT(dot(p.normal, m.vertices[p.vertices[0]].position), 0);
}

// Dihedral angle of a cube edge is 90 degrees: a feature at any threshold below.
TEST(ClassifyEdges, CubeEdgesAreFeaturesBelowNinetyDegrees) {
  PolygonMesh m = cube();
  EXPECT_EQ(m.count(EdgeType::kFeature), 0u);  // build classifies at 180: none
  EXPECT_EQ(gllab::classify_edges(m, 30), 12u);
  for (const gllab::Edge& e : m.edges) EXPECT_NEAR(e.dihedral_degrees, 90.0, 1e-9);
  EXPECT_EQ(gllab::classify_edges(m, 89.9), 12u);
  EXPECT_EQ(gllab::classify_edges(m, 90), 0u);  // equal is not above
  EXPECT_EQ(gllab::classify_edges(m, 90.1), 0u);
  EXPECT_EQ(m.count(EdgeType::kVirtual), 12u);
}

// On a finely subdivided sphere neighbouring polygons differ by about
// 360/64 = 5.6 degrees (around) or 180/32 (along): no feature edges at 30.
TEST(ClassifyEdges, FineSphereHasNoFeatureEdges) {
  PolygonMesh m = sphere(64, 32);
  EXPECT_EQ(gllab::classify_edges(m, 30), 0u);
  EXPECT_EQ(m.count(EdgeType::kBoundary), 0u);  // closed
  // The largest dihedral angle is one step of the grid, 180/32 = 5.625 degrees
  // (between neighbouring rings; around, the step shrinks by cos(latitude)).
  double largest = 0;
  for (const gllab::Edge& e : m.edges) largest = std::max(largest, e.dihedral_degrees);
  EXPECT_NEAR(largest, 180.0 / 32, 0.01);
  EXPECT_GT(gllab::classify_edges(m, 5.5), 0u);
}

// §1.2, "Comment on edges": a sharp edge is enforced by storing it (its
// vertices) several times. A cube shaded flat with sharp edges needs 4 vertices
// per face = 24; averaged across all edges it needs 8; face normals need 24 as
// well.
TEST(RenderArrays, SharpCubeDuplicatesVerticesAlongFeatureEdges) {
  PolygonMesh m = cube();
  gllab::classify_edges(m, 30);
  const gllab::IndexedMesh split = gllab::render_arrays(m, Normals::kSplitFeatures);
  EXPECT_EQ(split.vertex_count(), 24u);
  EXPECT_EQ(split.triangle_count(), 12u);
  // Each copy carries its face's normal: an axis direction.
  for (std::size_t v = 0; v < split.vertex_count(); ++v) {
    const float* n = &split.normals[3 * v];
    EXPECT_NEAR(std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]), 1.0, kFloatTolerance) << "vertex " << v;
  }
  EXPECT_EQ(gllab::render_arrays(m, Normals::kAveraged).vertex_count(), 8u);
  EXPECT_EQ(gllab::render_arrays(m, Normals::kFace).vertex_count(), 24u);
  // Without feature edges the split arrays are the averaged ones.
  gllab::classify_edges(m, 180);
  EXPECT_EQ(gllab::render_arrays(m, Normals::kSplitFeatures).vertex_count(), 8u);
}

// A cylinder with caps (profile pole - rim - rim - pole, 12 slices): the two
// rims are features (90 degrees), the side edges (30 degrees apart) virtual at
// a threshold of 45. Each rim vertex is written twice (side, cap), each pole
// once: 2 * 12 * 2 + 2 = 50 render vertices, against 26 stored.
TEST(RenderArrays, CylinderRimsAreSplitSideStaysShared) {
  PolygonMesh m = gllab::make_surface_of_revolution({{0, -1}, {1, -1}, {1, 1}, {0, 1}}, 12);
  EXPECT_EQ(m.vertices.size(), 26u);
  EXPECT_EQ(gllab::classify_edges(m, 45), 24u);
  EXPECT_EQ(gllab::render_arrays(m, Normals::kSplitFeatures).vertex_count(), 50u);
  EXPECT_EQ(gllab::render_arrays(m, Normals::kAveraged).vertex_count(), 26u);
  // The side's polygons are 360/12 = 30 degrees apart: at a threshold of
  // exactly 30 they stay virtual, whatever the rounding of acos.
  EXPECT_EQ(gllab::classify_edges(m, 30), 24u);
  // Euler: V - E + F = 26 - (12 + 12 + 12 + 12 + 12) + (12 + 12 + 12) = 2.
  EXPECT_EQ(m.edges.size(), 60u);
}

// A surface of kFlat shading is drawn with face normals even where its edges are virtual.
TEST(RenderArrays, FlatSurfaceKeepsFaceNormals) {
  gllab::Surface flat;
  flat.shading = gllab::Shading::kFlat;
  const PolygonMesh m = gllab::build_polygon_mesh(kCubeCorners, kCubeFaces, {flat});
  EXPECT_EQ(m.count(EdgeType::kFeature), 0u);
  EXPECT_EQ(gllab::render_arrays(m, Normals::kSplitFeatures).vertex_count(), 24u);
}

// Colours: the vertex attribute wins over the surface attribute.
TEST(RenderArrays, VertexColourOverridesSurfaceColour) {
  PolygonMesh m = cube();
  m.surfaces[0].colour = {0.f, 0.f, 1.f};
  m.vertices[3].colour = gllab::Colour{1.f, 0.f, 0.f};
  const gllab::IndexedMesh a = gllab::render_arrays(m, Normals::kAveraged);
  EXPECT_EQ(a.colours[3 * 3 + 0], 1.f);  // averaged arrays keep vertex order
  EXPECT_EQ(a.colours[3 * 0 + 2], 1.f);
}

TEST(BuildPolygonMesh, ErrorsNameTheBadValue) {
  EXPECT_EQ(error_of(kCubeCorners, {{{0, 1, 9}}}),
            "polygon mesh: polygon 0, corner 2: vertex index 9 out of range (8 vertices)");
  EXPECT_EQ(error_of(kCubeCorners, {{{0, 1, 3}}, {{0, 1}}}), "polygon mesh: polygon 1 has 2 vertices (need >= 3)");
  EXPECT_EQ(error_of(kCubeCorners, {{{0, 1, 0}}}), "polygon mesh: polygon 0 uses vertex 0 twice (corners 0 and 2)");
  // Three collinear points.
  EXPECT_EQ(error_of({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{{0, 1, 2}}}),
            "polygon mesh: polygon 0 is degenerate: area 0 (its vertices are collinear or coincide)");
  EXPECT_EQ(error_of({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}}, {{{0, 1, 2}}}),
            "polygon mesh: vertex 2 has a position that is not finite");
  EXPECT_EQ(error_of(kCubeCorners, {{{0, 1, 3}, 1}}), "polygon mesh: polygon 0: surface 1 out of range (1 surfaces)");
  EXPECT_EQ(error_of(kCubeCorners, {{{0, 1, 3}}, {{0, 1, 5}}}),
            "polygon mesh: polygons 0 and 1 both run from vertex 0 to vertex 1 (their windings disagree)");
  EXPECT_EQ(error_of(kCubeCorners, {}), "polygon mesh: no polygons");
}

TEST(ClassifyEdges, RejectsAnAngleOutsideZeroTo180) {
  PolygonMesh m = cube();
  EXPECT_THROW(gllab::classify_edges(m, -1), std::invalid_argument);
  EXPECT_THROW(gllab::classify_edges(m, NAN), std::invalid_argument);
}

TEST(MakeSurfaceOfRevolution, ErrorsNameTheBadValue) {
  using gllab::make_surface_of_revolution;
  EXPECT_THROW(make_surface_of_revolution({{1, 0}, {1, 1}}, 2), std::invalid_argument);
  EXPECT_THROW(make_surface_of_revolution({{1, 0}}, 8), std::invalid_argument);
  EXPECT_THROW(make_surface_of_revolution({{1, 0}, {-1, 1}}, 8), std::invalid_argument);
  EXPECT_THROW(make_surface_of_revolution({{1, 0}, {0, 1}, {1, 2}}, 8), std::invalid_argument);
  EXPECT_THROW(make_surface_of_revolution({{0, 0}, {0, 1}}, 8), std::invalid_argument);
  try {
    make_surface_of_revolution({{1, 0}, {0, 1}, {1, 2}}, 8);
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "surface of revolution: inner profile point 1 has r=0 (only the ends may)");
  }
}

// A profile made of a straight line (length 2) and a quarter circle of radius
// 0.2 (length 0.31): by length most points land on the line, by curvature all
// inner points land on the arc, where the turning is.
TEST(ResampleProfile, CurvatureSharePutsPointsWhereTheProfileTurns) {
  std::vector<gllab::ProfilePoint> dense;
  for (int i = 0; i <= 200; ++i) dense.push_back({0.8, -1.0 + 2.0 * i / 200});  // r = 0.8, z -1..1
  for (int i = 1; i <= 100; ++i) {
    const double a = M_PI / 2 * i / 100;  // quarter circle about (0.6, 1)
    dense.push_back({0.6 + 0.2 * std::cos(a), 1.0 + 0.2 * std::sin(a)});
  }
  auto on_arc = [](const std::vector<gllab::ProfilePoint>& ps) {
    int n = 0;
    for (std::size_t i = 1; i + 1 < ps.size(); ++i) n += ps[i].z > 1.0;
    return n;
  };
  const auto by_length = gllab::resample_profile(dense, 10, 0.0);
  const auto by_curvature = gllab::resample_profile(dense, 10, 1.0);
  ASSERT_EQ(by_length.size(), 11u);
  ASSERT_EQ(by_curvature.size(), 11u);
  EXPECT_EQ(on_arc(by_curvature), 9);  // all 9 inner points
  EXPECT_LE(on_arc(by_length), 2);     // 0.31 / 2.31 of 10 segments ~ 1.4
  EXPECT_EQ(by_length.front().z, dense.front().z);
  EXPECT_EQ(by_curvature.back().r, dense.back().r);
  EXPECT_THROW(gllab::resample_profile(dense, 0, 0.5), std::invalid_argument);
  EXPECT_THROW(gllab::resample_profile(dense, 301, 0.5), std::invalid_argument);
  EXPECT_THROW(gllab::resample_profile(dense, 5, 1.5), std::invalid_argument);
}

// A quarter circle of radius 1 cut into 2 equal chords (by length: the picks
// are at 0, 45 and 90 degrees) misses the arc by the sagitta 1 - cos(22.5°).
TEST(ProfileDeviation, QuarterCircleInTwoChordsMissesBySagitta) {
  constexpr double kDenseTolerance = 1e-5;  // the dense samples 0.09° apart straddle the chord midpoint
  std::vector<gllab::ProfilePoint> dense;
  for (int i = 0; i <= 1000; ++i) dense.push_back({std::cos(M_PI / 2 * i / 1000), std::sin(M_PI / 2 * i / 1000)});
  const auto picked = gllab::resample_profile(dense, 2, 0.0);
  ASSERT_EQ(picked.size(), 3u);
  EXPECT_NEAR(picked[1].r, std::cos(M_PI / 4), kExact);  // dense point 500
  EXPECT_NEAR(gllab::profile_deviation(dense, picked), 1 - std::cos(M_PI / 8), kDenseTolerance);
  EXPECT_NEAR(gllab::profile_deviation(dense, dense), 0.0, kExact);
  EXPECT_THROW(gllab::profile_deviation(dense, {dense[0]}), std::invalid_argument);
}

}  // namespace
