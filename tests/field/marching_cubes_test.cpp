// tests/field/marching_cubes_test.cpp — field::marching_cubes: convergence
// on a sphere, topology of spheres, tori and blobs (lecture notes ch. 1,
// §1.5 Blobby objects and §1.7 Surface representations, Iso-surfaces),
// closed surfaces with the asymptotic decider where Lorensen and Cline's
// case table leaves holes, the vertex formula, and the 15 base cases.
#include "field/marching_cubes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <set>

#include "field/density.h"
#include "field/marching_squares.h"
#include "field/mesh_measures.h"

namespace gllab::field {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 vertex(const IndexedMesh& m, std::size_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

// ---- the sphere -------------------------------------------------------------------

struct SphereErrors {
  double radius, area, volume;
};

// The sphere r = 0.8 as the zero set of its signed distance, on [-1, 1]^3
// with spacing h = 2 / cells (a centre off the grid's symmetry planes).
SphereErrors sphere_errors(int cells) {
  const double r = 0.8;
  const Vec3 centre{0.013, -0.021, 0.007};
  const Grid3 g = sample([&](const Vec3& x) { return sphere_field(x, centre, r); },
                         Vec3{-1, -1, -1}, Vec3{1, 1, 1}, cells + 1, cells + 1, cells + 1);
  const McResult res = marching_cubes(g, 0);
  SphereErrors e{0, 0, 0};
  for (std::size_t v = 0; v < res.mesh.vertex_count(); ++v)
    e.radius = std::max(e.radius, std::abs(norm(vertex(res.mesh, v) - centre) - r));
  e.area = std::abs(surface_area(res.mesh) - 4 * kPi * r * r);
  // The enclosed volume does not depend on the origin for a closed mesh.
  e.volume = std::abs(enclosed_volume(res.mesh) - 4.0 / 3 * kPi * r * r * r);
  return e;
}

TEST(MarchingCubes, SphereConvergesAtSecondOrder) {
  // Linear interpolation along an edge of a smooth field puts each vertex
  // O(h^2) off the surface; the mesh's area and volume follow at O(h^2).
  const SphereErrors e[3] = {sphere_errors(16), sphere_errors(32), sphere_errors(64)};
  for (int k = 0; k + 1 < 3; ++k) {
    const double radius_order = std::log2(e[k].radius / e[k + 1].radius);
    const double area_order = std::log2(e[k].area / e[k + 1].area);
    const double volume_order = std::log2(e[k].volume / e[k + 1].volume);
    std::printf(
        "[ order    ] h = 2/%d -> 2/%d: radius %.2f (%.2e), area %.2f (%.2e), volume %.2f (%.2e)\n",
        16 << k, 32 << k, radius_order, e[k + 1].radius, area_order, e[k + 1].area, volume_order,
        e[k + 1].volume);
    EXPECT_GE(radius_order, 1.8);
    EXPECT_GE(area_order, 1.8);
    EXPECT_GE(volume_order, 1.8);
  }
}

TEST(MarchingCubes, SphereIsClosedOrientedAndOutward) {
  const Grid3 g = sample(
      [](const Vec3& x) {
        return sphere_field(x, Vec3{0, 0, 0}, 0.7);
      },
      Vec3{-1, -1, -1}, Vec3{1, 1, 1}, 30, 30, 30);
  const McResult res = marching_cubes(g, 0);
  const MeshTopology t = topology(res.mesh);
  EXPECT_TRUE(t.closed_and_oriented());
  EXPECT_EQ(t.euler(), 2);
  EXPECT_EQ(t.components, 1u);
  EXPECT_GT(enclosed_volume(res.mesh), 0);  // counter-clockwise from outside
  // The normals point outward: along the radius, to O(h) (central differences).
  ASSERT_EQ(res.mesh.normals.size(), res.mesh.positions.size());
  for (std::size_t v = 0; v < res.mesh.vertex_count(); ++v) {
    const Vec3 p = vertex(res.mesh, v);
    const Vec3 n{res.mesh.normals[3 * v], res.mesh.normals[3 * v + 1], res.mesh.normals[3 * v + 2]};
    EXPECT_NEAR(norm(n), 1, 1e-6);
    EXPECT_GT(dot(n, normalized(p)), 0.99);
  }
  // Every triangle's geometric normal agrees with the outward direction.
  for (std::size_t f = 0; f < res.mesh.triangle_count(); ++f) {
    const Vec3 a = vertex(res.mesh, res.mesh.indices[3 * f]),
               b = vertex(res.mesh, res.mesh.indices[3 * f + 1]),
               c = vertex(res.mesh, res.mesh.indices[3 * f + 2]);
    EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0) << "triangle " << f;
  }
}

TEST(MarchingCubes, EachCrossedGridEdgeHasOneVertexAtTheLinearInterpolation) {
  const Grid3 g = sample(
      [](const Vec3& x) {
        return sphere_field(x, Vec3{0.05, 0, 0}, 0.6);
      },
      Vec3{-1, -1, -1}, Vec3{1, 1, 1}, 12, 11, 10);
  const double c = 0.01;
  const McResult res = marching_cubes(g, c, {FaceRule::kDecider, false, false});
  EXPECT_TRUE(res.mesh.normals.empty());
  // Expected: one vertex per grid edge whose ends are on different sides,
  // p0 + t (p1 - p0) with t = (c - f0) / (f1 - f0), p0 the lower end.
  std::set<std::array<float, 3>> expected, got;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        for (int a = 0; a < 3; ++a) {
          const int i1 = i + (a == 0), j1 = j + (a == 1), k1 = k + (a == 2);
          if (i1 >= g.nx || j1 >= g.ny || k1 >= g.nz) continue;
          const double f0 = g.at(i, j, k), f1 = g.at(i1, j1, k1);
          if ((f0 > c) == (f1 > c)) continue;
          const double t = (c - f0) / (f1 - f0);
          const Vec3 p = g.point(i, j, k) + t * (g.point(i1, j1, k1) - g.point(i, j, k));
          expected.insert({float(p.x), float(p.y), float(p.z)});
        }
  for (std::size_t v = 0; v < res.mesh.vertex_count(); ++v)
    got.insert(
        {res.mesh.positions[3 * v], res.mesh.positions[3 * v + 1], res.mesh.positions[3 * v + 2]});
  EXPECT_EQ(got.size(), res.mesh.vertex_count());  // no vertex twice
  EXPECT_EQ(got, expected);
}

TEST(MarchingCubes, OutputIsDeterministicAndInGridOrder) {
  const Grid3 g = sample([](const Vec3& x) { return torus_field(x, 0.6, 0.25); },
                         Vec3{-1, -1, -0.5}, Vec3{1, 1, 0.5}, 33, 33, 17);
  McOptions o;
  o.record_cells = true;
  const McResult a = marching_cubes(g, 0, o), b = marching_cubes(g, 0, o);
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(a.mesh.indices, b.mesh.indices);
  ASSERT_FALSE(a.cells.empty());
  std::uint32_t next = 0;
  for (std::size_t n = 0; n < a.cells.size(); ++n) {
    const McCell& c = a.cells[n];
    if (n > 0) {
      const McCell& p = a.cells[n - 1];
      EXPECT_LT(std::make_tuple(p.k, p.j, p.i), std::make_tuple(c.k, c.j, c.i));
    }
    EXPECT_NE(c.mask, 0);
    EXPECT_NE(c.mask, 255);
    EXPECT_EQ(c.base, base_case_of(c.mask));
    EXPECT_EQ(c.first_triangle, next);  // the cells' triangles in order, none elsewhere
    EXPECT_GT(c.triangle_count, 0u);
    next += c.triangle_count;
  }
  EXPECT_EQ(next, a.mesh.triangle_count());
}

TEST(MarchingCubes, TorusHasEulerCharacteristicZero) {
  const Grid3 g = sample([](const Vec3& x) { return torus_field(x, 0.6, 0.25); },
                         Vec3{-1, -1, -0.5}, Vec3{1, 1, 0.5}, 41, 41, 21);
  const MeshTopology t = topology(marching_cubes(g, 0).mesh);
  EXPECT_TRUE(t.closed_and_oriented());
  EXPECT_EQ(t.euler(), 0);
  EXPECT_EQ(t.components, 1u);
}

// ---- blobs (lecture notes §1.5) -----------------------------------------------------

BlobField two_blobs(double d) {
  return {{{Vec3{-d / 2, 0, 0}, 1, 1}, {Vec3{d / 2, 0, 0}, 1, 1}}, Density::kHermite};
}

TEST(MarchingCubes, TwoBlobsMergeAtTheMergeDistance) {
  // merge_distance: 2 f(d / 2) = c. 10 % farther: two spheres; 10 % nearer:
  // one surface with a neck (radius about 0.29 here; spacing 0.04).
  const double c = 0.5, dstar = merge_distance(Density::kHermite, 1, 1, c);
  for (const auto& [factor, components] : {std::pair{1.1, 2}, std::pair{0.9, 1}}) {
    const BlobField f = two_blobs(factor * dstar);
    const Grid3 g = sample([&](const Vec3& x) { return f.value(x); }, Vec3{-1.5, -0.8, -0.8},
                           Vec3{1.5, 0.8, 0.8}, 76, 41, 41);
    const McResult res = marching_cubes(g, c);
    const MeshTopology t = topology(res.mesh);
    EXPECT_TRUE(t.closed_and_oriented()) << factor;
    EXPECT_EQ(t.components, std::size_t(components)) << factor;
    EXPECT_EQ(t.euler(), 2 * components) << factor;  // spheres
    EXPECT_GT(enclosed_volume(res.mesh), 0);
    // The slice z = 0 by marching squares: as many closed curves.
    const Grid2 slice = sample(
        [&](double x, double y) {
          return f.value(Vec3{x, y, 0});
        },
        -1.5, -0.8, 1.5, 0.8, 76, 41);
    const auto lines = marching_squares(slice, c).polylines();
    EXPECT_EQ(lines.size(), std::size_t(components)) << factor;
    for (const auto& l : lines) EXPECT_EQ(l.front(), l.back());
  }
}

// Lab 08's default, d = 1.4 b > merge distance 1.347 b: two closed spheres.
TEST(MarchingCubes, BenchmarkFieldIsTwoClosedSurfaces) {
  const MeshTopology t = topology(marching_cubes(two_blob_benchmark_field(96), 0.5).mesh);
  EXPECT_TRUE(t.closed_and_oriented());
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.euler(), 4);
}

// ---- saddle faces: the decider against Lorensen and Cline ---------------------------------

// Values uniform in [0, 1) inside, 0 (outside of c = 0.5) on the border, so
// that every surface closes inside the grid: boundary edges can only be holes.
Grid3 random_grid(std::uint32_t seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  Grid3 g;
  g.nx = g.ny = g.nz = n;
  g.values.resize(std::size_t(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const bool border = i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
        float v = u(rng);
        if (v == 0.5f) v = 0.25f;
        g.values[(std::size_t(k) * n + j) * n + i] = border ? 0.0f : v;
      }
  return g;
}

TEST(MarchingCubes, DeciderClosesEveryRandomField) {
  std::size_t saddle_cells = 0, lc_holes = 0;
  for (std::uint32_t seed = 1; seed <= 40; ++seed) {
    const Grid3 g = random_grid(seed, 10);
    McOptions o;
    o.record_cells = true;
    const McResult res = marching_cubes(g, 0.5, o);
    for (const McCell& c : res.cells) saddle_cells += c.saddle_faces != 0;
    const MeshTopology t = topology(res.mesh);
    EXPECT_TRUE(t.closed_and_oriented())
        << "seed " << seed << ": boundary " << t.boundary_edges << ", non-manifold "
        << t.nonmanifold_edges << ", misoriented " << t.misoriented_edges;
    o.faces = FaceRule::kLorensenCline;
    lc_holes += topology(marching_cubes(g, 0.5, o).mesh).boundary_edges;
  }
  EXPECT_GT(saddle_cells, 1000u);  // many cells with a saddle face were tested
  EXPECT_GT(lc_holes, 0u);         // and the case table alone leaves holes there
}

// Two cells sharing the saddle face x = 1 of a 4 x 4 x 4 grid whose border
// is outside: cell (0, 1, 1) has its two inside corners on that face's
// diagonal (case 3), cell (1, 1, 1) those two and its whole face x = 2 (six
// corners). The case table separates the inside corners of the first (two
// of eight) and the outside corners of the second (six): the two cells cut
// the face differently and the surface has a hole there.
Grid3 disagreeing_cells() {
  Grid3 g;
  g.nx = g.ny = g.nz = 4;
  g.values.assign(64, 0.2f);
  auto set = [&](int i, int j, int k, float v) { g.values[(k * 4 + j) * 4 + i] = v; };
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        if (i == 0 || j == 0 || k == 0 || i == 3 || j == 3 || k == 3) set(i, j, k, 0);
  set(1, 1, 1, 1);  // the face x = 1: (1,1,1) and (1,2,2) inside, (1,2,1) and (1,1,2) at 0.2
  set(1, 2, 2, 1);
  for (int j = 1; j <= 2; ++j)
    for (int k = 1; k <= 2; ++k) set(2, j, k, 1);  // the face x = 2: inside
  return g;
}

TEST(MarchingCubes, CaseTableLeavesAHoleTheDeciderCloses) {
  const Grid3 g = disagreeing_cells();
  McOptions o;
  o.record_cells = true;
  const McResult decider = marching_cubes(g, 0.5, o);
  auto cell = [](const McResult& r, int i) {
    for (const McCell& c : r.cells)
      if (c.i == i && c.j == 1 && c.k == 1) return c;
    return McCell{};
  };
  // Face x = 1 is +x (bit 1) of cell 0 and -x (bit 0) of cell 1, a saddle for both.
  EXPECT_EQ(__builtin_popcount(cell(decider, 0).mask), 2);
  EXPECT_EQ(__builtin_popcount(cell(decider, 1).mask), 6);
  EXPECT_TRUE(cell(decider, 0).saddle_faces & 2);
  EXPECT_TRUE(cell(decider, 1).saddle_faces & 1);
  EXPECT_EQ(cell(decider, 0).base, 3);  // a face diagonal
  const MeshTopology td = topology(decider.mesh);
  EXPECT_TRUE(td.closed_and_oriented());
  EXPECT_EQ(td.boundary_edges, 0u);
  o.faces = FaceRule::kLorensenCline;
  const MeshTopology tl = topology(marching_cubes(g, 0.5, o).mesh);
  EXPECT_GT(tl.boundary_edges, 0u);
  // Without a saddle face both rules give the same triangles.
  const Grid3 s = sample(
      [](const Vec3& x) {
        return sphere_field(x, Vec3{0, 0, 0}, 0.7);
      },
      Vec3{-1, -1, -1}, Vec3{1, 1, 1}, 20, 20, 20);
  EXPECT_EQ(marching_cubes(s, 0).mesh.indices, marching_cubes(s, 0, o).mesh.indices);
}

TEST(MarchingCubes, DeciderFollowsTheFaceSaddleValue) {
  // The face x = 1 above: saddle value (1 * 1 - 0.2 * 0.2) / (1 + 1 - 0.4) =
  // 0.6 > 0.5, so its inside corners are joined across it: cell 0's six
  // crossings make one loop, 4 triangles. With 0 instead of 0.2 the saddle
  // value is (1 - 0) / 2 = 0.5, not > c: separated, two corner triangles.
  McOptions o;
  o.record_cells = true;
  auto cell0 = [&](const Grid3& g) {
    const McResult r = marching_cubes(g, 0.5, o);
    EXPECT_TRUE(topology(r.mesh).closed_and_oriented());
    for (const McCell& c : r.cells)
      if (c.i == 0 && c.j == 1 && c.k == 1) return c.triangle_count;
    return 0u;
  };
  Grid3 g = disagreeing_cells();
  EXPECT_EQ(cell0(g), 4u);
  g.values[(2 * 4 + 1) * 4 + 1] = 0;  // (1, 1, 2)
  g.values[(1 * 4 + 2) * 4 + 1] = 0;  // (1, 2, 1)
  EXPECT_EQ(cell0(g), 2u);
}

// ---- the 15 base cases --------------------------------------------------------------------

int popcount(int m) { return __builtin_popcount(unsigned(m)); }
bool in(int m, int c) { return (m >> c) & 1; }
int axes_differing(int a, int b) { return popcount(a ^ b); }  // 1 edge, 2 face diagonal, 3 body

TEST(BaseCases, FifteenClassesCoverEveryMask) {
  std::set<int> classes;
  for (int m = 0; m < 256; ++m) {
    const int k = base_case_of(std::uint8_t(m));
    ASSERT_GE(k, 0);
    ASSERT_LE(k, 14);
    classes.insert(k);
    EXPECT_EQ(base_case_of(std::uint8_t(255 - m)), k) << m;  // complement
  }
  EXPECT_EQ(classes.size(), 15u);
  for (int k = 0; k < 15; ++k) EXPECT_EQ(base_case_of(base_case_mask(k)), k);
}

// A rotation maps a mask to its class: a quarter turn about x, about y, about z.
int rotate(int mask, int axis) {
  int out = 0;
  for (int c = 0; c < 8; ++c) {
    int x = c & 1, y = (c >> 1) & 1, z = c >> 2, nx = x, ny = y, nz = z;
    if (axis == 0) ny = 1 - z, nz = y;
    if (axis == 1) nz = 1 - x, nx = z;
    if (axis == 2) nx = 1 - y, ny = x;
    if (in(mask, c)) out |= 1 << (nx | ny << 1 | nz << 2);
  }
  return out;
}

TEST(BaseCases, RotationsKeepTheClass) {
  for (int m = 0; m < 256; ++m)
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(base_case_of(std::uint8_t(rotate(m, axis))), base_case_of(std::uint8_t(m)));
  // A mirror image need not be a rotation: 11 and 14 are mirror images.
  auto mirror = [](int m) {  // swap x and y
    int out = 0;
    for (int c = 0; c < 8; ++c)
      if (in(m, c)) out |= 1 << ((c & 4) | (c & 1) << 1 | (c >> 1 & 1));
    return out;
  };
  EXPECT_EQ(base_case_of(std::uint8_t(mirror(base_case_mask(11)))), 14);
}

// The representatives as Lorensen and Cline's figure draws them, checked by
// the corners' relations (edge: one axis apart, face diagonal: two, body: three).
TEST(BaseCases, RepresentativesMatchTheFigure) {
  auto corners = [](int k) {
    std::vector<int> c;
    for (int b = 0; b < 8; ++b)
      if (in(base_case_mask(k), b)) c.push_back(b);
    return c;
  };
  auto pairs = [&](int k, int d) {  // pairs of inside corners d axes apart
    const auto c = corners(k);
    int n = 0;
    for (std::size_t a = 0; a < c.size(); ++a)
      for (std::size_t b = a + 1; b < c.size(); ++b) n += axes_differing(c[a], c[b]) == d;
    return n;
  };
  auto on_one_face = [&](int k) {  // all inside corners share a coordinate
    const auto c = corners(k);
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
        if (std::all_of(c.begin(), c.end(), [&](int b) { return ((b >> axis) & 1) == side; }))
          return true;
    return false;
  };
  EXPECT_EQ(base_case_mask(0), 0);
  EXPECT_EQ(popcount(base_case_mask(1)), 1);  // one corner
  EXPECT_EQ(pairs(2, 1), 1);                  // an edge
  EXPECT_EQ(pairs(3, 2), 1);                  // a face diagonal
  EXPECT_EQ(pairs(4, 3), 1);                  // a body diagonal
  EXPECT_TRUE(on_one_face(5));                // three corners of a face
  EXPECT_EQ(popcount(base_case_mask(5)), 3);
  EXPECT_EQ(pairs(6, 1), 1);  // an edge + a far corner
  EXPECT_EQ(pairs(6, 3), 1);
  EXPECT_EQ(pairs(7, 2), 3);    // pairwise face-diagonal
  EXPECT_TRUE(on_one_face(8));  // a face
  EXPECT_EQ(popcount(base_case_mask(8)), 4);
  for (int k : {9, 11, 14}) {  // four, not on a face, connected
    EXPECT_EQ(popcount(base_case_mask(k)), 4) << k;
    EXPECT_FALSE(on_one_face(k)) << k;
    EXPECT_EQ(pairs(k, 1), 3) << k;  // three edges: a tree
  }
  EXPECT_EQ(pairs(9, 3), 0);   // 9: a corner and its neighbours
  EXPECT_EQ(pairs(11, 3), 1);  // 11, 14: a chain end to end
  EXPECT_EQ(pairs(14, 3), 1);
  EXPECT_EQ(pairs(10, 1), 2);  // two opposite edges
  EXPECT_EQ(pairs(10, 3), 2);
  EXPECT_EQ(popcount(base_case_mask(12)), 4);  // case 5 + a corner
  EXPECT_EQ(pairs(12, 1), 2);
  EXPECT_EQ(pairs(13, 2), 6);  // the tetrahedron
}

// ---- bad input --------------------------------------------------------------------------------

std::string message_of(const Grid3& g, double c) {
  try {
    marching_cubes(g, c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(MarchingCubes, BadInputThrowsNamingTheValue) {
  Grid3 g = sample([](const Vec3& x) { return x.x; }, Vec3{0, 0, 0}, Vec3{1, 1, 1}, 3, 3, 3);
  EXPECT_EQ(message_of(g, NAN), "marching_cubes: c=nan (the iso value must be finite)");
  EXPECT_EQ(message_of(g, INFINITY), "marching_cubes: c=inf (the iso value must be finite)");
  Grid3 bad = g;
  bad.values[(1 * 3 + 2) * 3 + 1] = INFINITY;  // (1, 2, 1)
  EXPECT_EQ(message_of(bad, 0.5), "marching_cubes: value(1, 2, 1)=inf (values must be finite)");
  bad = g;
  bad.values[5] = NAN;  // (2, 1, 0)
  EXPECT_EQ(message_of(bad, 0.5), "marching_cubes: value(2, 1, 0)=nan (values must be finite)");
  bad = g;
  bad.spacing.y = 0;
  EXPECT_EQ(message_of(bad, 0.5), "marching_cubes: spacing.y=0 (must be positive and finite)");
  bad = g;
  bad.spacing.z = -0.5;
  EXPECT_EQ(message_of(bad, 0.5), "marching_cubes: spacing.z=-0.5 (must be positive and finite)");
  bad = g;
  bad.nx = 1;
  bad.values.resize(9);
  EXPECT_EQ(message_of(bad, 0.5), "marching_cubes: grid nx=1 (must be at least 2)");
  bad = g;
  bad.values.pop_back();
  EXPECT_EQ(message_of(bad, 0.5), "marching_cubes: values.size()=26 (nx ny nz = 27)");
  EXPECT_THROW(base_case_mask(15), std::invalid_argument);
}

}  // namespace
}  // namespace gllab::field
