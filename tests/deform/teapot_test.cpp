// tests/deform/teapot_test.cpp — Newell's teapot: the table, the oriented
// patches and the welded mesh (common/deform/teapot.cpp).
//
// Every expected value names its origin: the table itself (its entries read
// off, teapot.h lists what it is), a property of the teapot (its mirror
// symmetry, its smooth seams, the convex hull of a Bézier patch), a count
// derived in teapot.h, or an integral computed a second way.
#include "deform/teapot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "spline/quadrature.h"

namespace gllab::deform {
namespace {

using spline::BezierSurface;

// ---- tolerances (named, never loosened to pass) -----------------------------

/// A few double operations on values of size 3: 1e-15 each, with room.
constexpr double kDouble = 1e-12;
/// The mesh's floats: one rounding of a value up to 3.5 is 2e-7; with the
/// face normals' differences, 1e-6.
constexpr double kFloat = 1e-6;

// ---- helpers -----------------------------------------------------------------

Vec3 vertex(const IndexedMesh& m, std::size_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}
Vec3 normal(const IndexedMesh& m, std::size_t v) {
  return {m.normals[3 * v], m.normals[3 * v + 1], m.normals[3 * v + 2]};
}
double max_abs(Vec3 a) { return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}); }

/// The mesh's vertices within kFloat of p.
std::vector<std::size_t> vertices_at(const IndexedMesh& m, Vec3 p) {
  std::vector<std::size_t> out;
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    if (max_abs(vertex(m, v) - p) <= kFloat) out.push_back(v);
  return out;
}

/// sum over the triangles of p0 . (p1 x p2) / 6: the signed volume the
/// triangles enclose with the origin (the divergence theorem on each cone).
double signed_volume(const IndexedMesh& m) {
  double v = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Vec3 a = vertex(m, m.indices[3 * t]), b = vertex(m, m.indices[3 * t + 1]);
    const Vec3 c = vertex(m, m.indices[3 * t + 2]);
    v += dot(a, cross(b, c)) / 6;
  }
  return v;
}

/// (1/3) integral over [0, 1]^2 of (S - o) . (Su x Sv) du dv: the same signed
/// volume for the patch itself (divergence theorem, div x = 3). The integrand
/// has degree 3 + 2 + 3 = 8 in u and in v, so the 5-point Gauss–Legendre rule
/// (exact to degree 9) gives it exactly, up to rounding.
double patch_volume(const BezierSurface& s, Vec3 o) {
  const spline::GaussRule g = spline::gauss_legendre(5);
  double sum = 0;
  for (std::size_t a = 0; a < g.x.size(); ++a)
    for (std::size_t b = 0; b < g.x.size(); ++b) {
      const spline::SurfacePartials d =
          spline::surface_partials(s, (g.x[a] + 1) / 2, (g.x[b] + 1) / 2);
      sum += g.w[a] * g.w[b] / 4 * dot(d.S - o, cross(d.Su, d.Sv)) / 3;
    }
  return sum;
}

/// The edge e of a patch's net (0: u = 0, 1: u = 1, 2: v = 0, 3: v = 1), its
/// 4 control points in order.
std::vector<Vec3> net_edge(const BezierSurface& s, int e) {
  std::vector<Vec3> out;
  for (int r = 0; r < 4; ++r)
    out.push_back(e == 0 ? s.point(0, r) : e == 1 ? s.point(3, r) : e == 2 ? s.point(r, 0)
                                                                           : s.point(r, 3));
  return out;
}
Vec3 edge_point(const BezierSurface& s, int e, double t) {
  const double u = e == 0 ? 0 : e == 1 ? 1 : t, v = e == 2 ? 0 : e == 3 ? 1 : t;
  return spline::surface_point(s, u, v);
}
Vec3 edge_normal(const BezierSurface& s, int e, double t) {
  const double u = e == 0 ? 0 : e == 1 ? 1 : t, v = e == 2 ? 0 : e == 3 ? 1 : t;
  return spline::surface_normal(s, u, v);
}

/// Two patches' edges with the same 4 control points, in the same order or
/// reversed (reversed = true): a shared boundary curve.
struct SharedEdge {
  int p, ep, q, eq;
  bool reversed;
};
std::vector<SharedEdge> shared_edges() {
  const std::vector<BezierSurface>& patches = teapot_patches();
  std::vector<SharedEdge> out;
  for (int p = 0; p < kTeapotPatchCount; ++p)
    for (int q = p + 1; q < kTeapotPatchCount; ++q)
      for (int ep = 0; ep < 4; ++ep)
        for (int eq = 0; eq < 4; ++eq) {
          const std::vector<Vec3> a = net_edge(patches[p], ep), b = net_edge(patches[q], eq);
          // A collapsed edge (a pole: one point 4 times) is not a curve.
          if (a[0] == a[1] && a[1] == a[2] && a[2] == a[3]) continue;
          const std::vector<Vec3> rb(b.rbegin(), b.rend());
          if (a == b || a == rb) out.push_back({p, ep, q, eq, a != b});
        }
  return out;
}

// ---- the table -----------------------------------------------------------------

// The data (teapot.h): 306 entries, 32 patches of 16 indices; 294 distinct
// points (the bottom repeats 12 of the body's); entries 204, 205, 215 and 222
// used by no patch.
TEST(TeapotTable, HasNewellsCounts) {
  const std::vector<Vec3>& points = teapot_control_points();
  const std::vector<std::array<int, 16>>& patches = teapot_patch_indices();
  ASSERT_EQ(points.size(), 306u);
  ASSERT_EQ(patches.size(), 32u);
  std::set<int> used;
  for (const std::array<int, 16>& patch : patches)
    for (int i : patch) {
      ASSERT_GE(i, 0);
      ASSERT_LT(i, kTeapotPointCount);
      used.insert(i);
    }
  std::set<int> unused;
  for (int i = 0; i < kTeapotPointCount; ++i)
    if (!used.count(i)) unused.insert(i);
  EXPECT_EQ(unused, (std::set<int>{204, 205, 215, 222}));
  std::set<std::tuple<double, double, double>> distinct;
  for (const Vec3& p : points) distinct.insert({p.x, p.y, p.z});
  EXPECT_EQ(distinct.size(), 294u);
  // The 12 repeats are the bottom's copies of the body's lowest row (z = 0.15).
  std::map<std::tuple<double, double, double>, int> first;
  std::vector<std::pair<int, int>> repeats;
  for (int i = 0; i < kTeapotPointCount; ++i) {
    const auto [it, added] = first.try_emplace({points[i].x, points[i].y, points[i].z}, i);
    if (!added) repeats.push_back({it->second, i});
  }
  ASSERT_EQ(repeats.size(), 12u);
  for (const auto& [body, bottom] : repeats) {
    EXPECT_GE(body, 84) << bottom;   // the body's lower ring: entries 84..119
    EXPECT_LE(body, 119) << bottom;
    EXPECT_GE(bottom, 269) << body;  // the bottom: entries 269..305
    EXPECT_EQ(points[bottom].z, 0.15);
  }
}

// The table's order (teapot.h): rim, body, handle, spout, lid, bottom.
TEST(TeapotTable, PartsCoverThePatchesInOrder) {
  const char* const names[] = {"rim", "body", "handle", "spout", "lid", "bottom"};
  int next = 0;
  for (std::size_t i = 0; i < teapot_parts().size(); ++i) {
    EXPECT_STREQ(teapot_parts()[i].name, names[i]);
    EXPECT_EQ(teapot_parts()[i].first, next);
    next += teapot_parts()[i].count;
  }
  EXPECT_EQ(next, kTeapotPatchCount);
}

// Property of the teapot: it is mirror-symmetric about the plane y = 0, and
// the table gives every point used with its mirror image, exactly.
TEST(TeapotTable, IsMirrorSymmetricAboutY0) {
  const std::vector<Vec3>& points = teapot_control_points();
  std::set<std::tuple<double, double, double>> used;
  for (const std::array<int, 16>& patch : teapot_patch_indices())
    for (int i : patch) used.insert({points[i].x, points[i].y, points[i].z});
  for (const auto& [x, y, z] : used)
    EXPECT_TRUE(used.count({x, -y, z})) << x << " " << y << " " << z;
}

// The data: the extreme entries are the handle's (-3, 0, 1.8) and (-3, 0, 2.25),
// the spout's (3.525, 0, 2.49375), the body's (0, -2, 0.9) and (0, 2, 0.9), the
// bottom's centre (0, 0, 0) and the knob's top (0, 0, 3.15).
TEST(TeapotTable, ControlPointsSpanTheTeapotsBox) {
  const std::vector<Vec3>& points = teapot_control_points();
  Vec3 lo = points[0], hi = points[0];
  for (const std::array<int, 16>& patch : teapot_patch_indices())
    for (int i : patch) {
      const Vec3 p = points[i];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  EXPECT_EQ(lo.x, -3.0);
  EXPECT_EQ(hi.x, 3.525);
  EXPECT_EQ(lo.y, -2.0);
  EXPECT_EQ(hi.y, 2.0);
  EXPECT_EQ(lo.z, 0.0);
  EXPECT_EQ(hi.z, 3.15);
}

// ---- the patches -----------------------------------------------------------------

// teapot.h: bicubic on [0, 1]^2, each row of the table reversed.
TEST(TeapotPatches, AreTheTablesRowsReversed) {
  const std::vector<BezierSurface>& patches = teapot_patches();
  ASSERT_EQ(patches.size(), 32u);
  for (int p = 0; p < kTeapotPatchCount; ++p) {
    const BezierSurface& s = patches[p];
    EXPECT_EQ(s.n, 3);
    EXPECT_EQ(s.m, 3);
    EXPECT_EQ(s.a, 0.0);
    EXPECT_EQ(s.b, 1.0);
    EXPECT_EQ(s.c, 0.0);
    EXPECT_EQ(s.d, 1.0);
    ASSERT_EQ(s.P.size(), 16u);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        EXPECT_EQ(s.point(i, j),
                  teapot_control_points()[teapot_patch_indices()[p][i * 4 + 3 - j]]);
  }
}

// The data: neighbours share a boundary row or column of the net. Counted
// by part: rim 4 around + 4 onto the body; body 4 + 4 around + 4 between
// its rings; body onto bottom 4; bottom 4 around (from the pole out); lid 4 +
// 4 around + 4 between knob and lid; handle and spout each 2 seams along
// each of their two tubes + 2 between the tubes' pieces = 6. 52 in all.
// Along each, the two boundary curves are one curve (C0), and the normals of
// the two patches agree (the teapot is smooth there: e.g. across the rim and
// the body the net points (1.4375, 2.53125), (1.5, 2.4), (1.75, 1.875) of the
// y = 0 column lie on one line), pointing the same way.
TEST(TeapotPatches, NeighboursMeetSmoothlyAlongSharedEdges) {
  const std::vector<BezierSurface>& patches = teapot_patches();
  const std::vector<SharedEdge> shared = shared_edges();
  EXPECT_EQ(shared.size(), 52u);
  for (const SharedEdge& e : shared)
    for (int k = 0; k <= 10; ++k) {
      const double t = k / 10.0, tq = e.reversed ? 1 - t : t;
      const Vec3 a = edge_point(patches[e.p], e.ep, t), b = edge_point(patches[e.q], e.eq, tq);
      EXPECT_LE(max_abs(a - b), kDouble) << e.p << "/" << e.q << " t = " << t;
      const Vec3 na = edge_normal(patches[e.p], e.ep, t), nb = edge_normal(patches[e.q], e.eq, tq);
      EXPECT_LE(max_abs(na - nb), 1e-9) << e.p << "/" << e.q << " t = " << t;
    }
}

// Orientation (teapot.h): the rim, body, lid and bottom, with the annulus
// z = 2.4, 1.3 <= r <= 1.4 between lid and rim, enclose a solid; its volume
// (1/3) sum of integral (S - o) . (Su x Sv), o = (0, 0, 2.4) in the annulus's
// plane (so the annulus adds nothing), is positive only if the normals point
// out. Computed a second way: those rings are the profile (r(u), z(u)) of the
// table's y = 0 column swept along the table's quarter circle (1, 0), (1, 0.56),
// (0.56, 1), (0, 1), scaled by r, so V = A ∮ r^2 dz with A the area inside that
// quasi-circle: by Green's theorem on the cubic, A = 4 (1/2 + 3c/5 - 3c^2/20)
// = 3.15584 for c = 0.56 (a little more than pi: the circle's usual constant
// is 4 (sqrt 2 - 1) / 3 = 0.5523). The knob's top ring uses 0.5625 for 0.56
// (0.45 / 0.8), which the second way ignores: 1.2e-4 of volume, so the two
// agree to 2e-4.
TEST(TeapotPatches, EncloseTheVolumeOfTheirProfile) {
  const std::vector<BezierSurface>& patches = teapot_patches();
  double volume = 0;
  for (int p = 0; p < kTeapotPatchCount; ++p)
    if (p < 12 || p >= 20) volume += patch_volume(patches[p], {0, 0, 2.4});
  // The profile, counter-clockwise in (r, z): bottom, body, rim, lid, knob
  // (the table's y = 0 columns, from the centre of the bottom round to the top).
  const double profile[6][4][2] = {
      {{0, 0}, {1.425, 0}, {1.5, 0.075}, {1.5, 0.15}},
      {{1.5, 0.15}, {1.5, 0.225}, {2, 0.45}, {2, 0.9}},
      {{2, 0.9}, {2, 1.35}, {1.75, 1.875}, {1.5, 2.4}},
      {{1.5, 2.4}, {1.4375, 2.53125}, {1.3375, 2.53125}, {1.4, 2.4}},
      {{1.3, 2.4}, {1.3, 2.55}, {0.4, 2.55}, {0.2, 2.7}},
      {{0.2, 2.7}, {0, 2.85}, {0.8, 3.15}, {0, 3.15}}};
  const double quarter[4][2] = {{1, 0}, {1, 0.56}, {0.56, 1}, {0, 1}};
  const auto bezier = [](const double (*P)[2], int k, double t, bool derivative) {
    const double s = 1 - t;
    if (derivative)
      return 3 * (s * s * (P[1][k] - P[0][k]) + 2 * s * t * (P[2][k] - P[1][k]) +
                  t * t * (P[3][k] - P[2][k]));
    return s * s * s * P[0][k] + 3 * s * s * t * P[1][k] + 3 * s * t * t * P[2][k] +
           t * t * t * P[3][k];
  };
  // Gauss–Legendre with 5 points: r^2 z' has degree 8, x y' - y x' degree 5.
  const spline::GaussRule g = spline::gauss_legendre(5);
  double area = 0, swept = 0;
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    const double t = (g.x[i] + 1) / 2, w = g.w[i] / 2;
    area += 4 * w *
            (bezier(quarter, 0, t, false) * bezier(quarter, 1, t, true) -
             bezier(quarter, 1, t, false) * bezier(quarter, 0, t, true)) / 2;
    for (const auto& piece : profile) {
      const double r = bezier(piece, 0, t, false);
      swept += w * r * r * bezier(piece, 1, t, true);
    }
  }
  EXPECT_GT(volume, 0);
  EXPECT_NEAR(volume, area * swept, 2e-4);
  EXPECT_NEAR(area, 2 + 12 * 0.56 / 5 - 3 * 0.56 * 0.56 / 5, kDouble);
}

// ---- the mesh ----------------------------------------------------------------------

// The counts derived in teapot.h: 32 k^2 + 4 k + 2 vertices, 64 k^2 - 8 k
// triangles; k = 1 by hand: rim + body + bottom 1 + 4 x 4, lid 1 + 2 x 4,
// handle and spout 3 x 2 each: 38; 2 per patch but one at each of the 8
// pole cells: 56.
TEST(TeapotMesh, CountsFollowTheFormula) {
  const IndexedMesh one = teapot_mesh(1);
  EXPECT_EQ(one.vertex_count(), 38u);
  EXPECT_EQ(one.triangle_count(), 56u);
  for (std::size_t k : {2u, 3u, 8u, 16u}) {
    const IndexedMesh m = teapot_mesh(static_cast<int>(k));
    EXPECT_EQ(m.vertex_count(), 32 * k * k + 4 * k + 2) << k;
    EXPECT_EQ(m.triangle_count(), 64 * k * k - 8 * k) << k;
    EXPECT_EQ(m.positions.size(), 3 * m.vertex_count());
    EXPECT_EQ(m.normals.size(), 3 * m.vertex_count());
    EXPECT_TRUE(m.colours.empty());
    for (std::uint32_t i : m.indices) EXPECT_LT(i, m.vertex_count());
  }
}

// teapot.h: per_patch outside 1..kMaxTeapotPerPatch throws, naming the value.
TEST(TeapotMesh, RejectsPerPatchOutsideItsRange) {
  for (int bad : {0, -3, kMaxTeapotPerPatch + 1}) {
    try {
      teapot_mesh(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("per_patch = " + std::to_string(bad)),
                std::string::npos)
          << e.what();
    }
  }
}

// A consistently oriented mesh uses every edge at most once in each
// direction; the edges used once are the boundary (teapot.h: the rim's inner
// edge and the lid's outer edge, 4k each; the two ends of handle and spout,
// 2k each: 16k in all). No edge is used by more than two triangles.
TEST(TeapotMesh, IsConsistentlyOrientedWithTheExpectedBoundary) {
  const std::size_t k = 8;
  const IndexedMesh m = teapot_mesh(static_cast<int>(k));
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int c = 0; c < 3; ++c)
      ++directed[{m.indices[3 * t + c], m.indices[3 * t + (c + 1) % 3]}];
  std::size_t boundary = 0;
  for (const auto& [edge, uses] : directed) {
    EXPECT_EQ(uses, 1) << edge.first << "->" << edge.second;
    if (!directed.count({edge.second, edge.first})) ++boundary;
  }
  EXPECT_EQ(boundary, 16 * k);
}

// Every normal has unit length and lies on the outer side of each of its
// triangles: (p1 - p0) x (p2 - p0) . n > 0 at every corner, poles included,
// once the cells are small enough to follow the surface: from per_patch = 6 on
// (teapot.h; below that some chords cut across the rim's and the spout's
// tight lips).
TEST(TeapotMesh, NormalsAreUnitAndAgreeWithTheWinding) {
  for (int k : {6, 8, 56}) {
    const IndexedMesh m = teapot_mesh(k);
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
      ASSERT_NEAR(norm(normal(m, v)), 1.0, kFloat) << "k = " << k << " vertex " << v;
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      const std::uint32_t* c = &m.indices[3 * t];
      const Vec3 face = cross(vertex(m, c[1]) - vertex(m, c[0]), vertex(m, c[2]) - vertex(m, c[0]));
      for (int i = 0; i < 3; ++i)
        ASSERT_GT(dot(face, normal(m, c[i])), 0) << "k = " << k << " triangle " << t;
    }
  }
}

// Normals known from the data, one or more per part, so that every part is
// shown to face out:
//   - bottom's centre (0, 0, 0): the bottom's second row is at z = 0, so it is
//     flat there: (0, 0, -1); the knob's top (0, 0, 3.15) likewise (0, 0, 1);
//   - the body at z = 0.9, r = 2: its profile (2, 1.35), (2, 0.9), (2, 0.45)
//     is vertical, so the normal is radial: (+-1, 0, 0), (0, +-1, 0);
//   - the handle's outermost point (-3, 0, 1.8): its profile (-3, 2.25),
//     (-3, 1.8), (-3, 1.35) is vertical and its cross-section runs along y:
//     (-1, 0, 0);
//   - the spout at (3.3, 0, 2.4): along it (3.3, 2.4) - (2.4, 2.025) = (0.9,
//     0.375), around it along y, so n = (0.375, 0, -0.9) / 0.975, down and out
//     (the underside of the rising spout).
// The point (-2, 0, 0.9) is also the end of the handle, which meets the body
// there at a crease: two vertices, the body's one radial.
TEST(TeapotMesh, NormalsAtKnownPointsPointOut) {
  const IndexedMesh m = teapot_mesh(8);
  const auto expect_normal = [&m](Vec3 p, Vec3 n) {
    const std::vector<std::size_t> at = vertices_at(m, p);
    ASSERT_EQ(at.size(), 1u) << p.x << " " << p.y << " " << p.z;
    EXPECT_LE(max_abs(normal(m, at[0]) - n), kFloat) << p.x << " " << p.y << " " << p.z;
  };
  expect_normal({0, 0, 0}, {0, 0, -1});
  expect_normal({0, 0, 3.15}, {0, 0, 1});
  expect_normal({2, 0, 0.9}, {1, 0, 0});
  expect_normal({0, 2, 0.9}, {0, 1, 0});
  expect_normal({0, -2, 0.9}, {0, -1, 0});
  expect_normal({-3, 0, 1.8}, {-1, 0, 0});
  expect_normal({3.3, 0, 2.4}, {0.375 / 0.975, 0, -0.9 / 0.975});
  const std::vector<std::size_t> crease = vertices_at(m, {-2, 0, 0.9});
  ASSERT_EQ(crease.size(), 2u);
  const bool first_is_body = max_abs(normal(m, crease[0]) - Vec3{-1, 0, 0}) <= kFloat;
  const bool second_is_body = max_abs(normal(m, crease[1]) - Vec3{-1, 0, 0}) <= kFloat;
  EXPECT_NE(first_is_body, second_is_body);
}

// Property of the teapot: mirror-symmetric about y = 0, normals included (the
// mirror patch is sampled at v and 1 - v: the same grid).
TEST(TeapotMesh, IsMirrorSymmetricAboutY0) {
  const IndexedMesh m = teapot_mesh(8);
  std::vector<std::size_t> order(m.vertex_count());
  for (std::size_t v = 0; v < order.size(); ++v) order[v] = v;
  std::sort(order.begin(), order.end(), [&m](std::size_t a, std::size_t b) {
    return m.positions[3 * a] < m.positions[3 * b];
  });
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const Vec3 p = vertex(m, v), n = normal(m, v);
    const Vec3 mp{p.x, -p.y, p.z}, mn{n.x, -n.y, n.z};
    // The candidates with x within kFloat, found by bisection on the sorted x.
    auto it = std::lower_bound(order.begin(), order.end(), p.x - kFloat,
                               [&m](std::size_t w, double x) { return m.positions[3 * w] < x; });
    bool found = false;
    for (; it != order.end() && m.positions[3 * *it] <= p.x + kFloat && !found; ++it)
      found = max_abs(vertex(m, *it) - mp) <= kFloat && max_abs(normal(m, *it) - mn) <= kFloat;
    EXPECT_TRUE(found) << "no mirror image of vertex " << v << " (" << p.x << ", " << p.y << ", "
                       << p.z << ")";
  }
}

// The box of the mesh: inside the control points' box (a Bézier patch lies in
// the convex hull of its net) and reaching it where the extreme control point
// is a patch corner, so a grid point: x = -3 (handle), y = -+2 (body), z = 0
// (bottom) and 3.15 (knob). The spout's tip is not a corner: its extreme is the
// y = 0 column of its net, x(t) with control values 3.3, 3.525, 3.45, 3.2,
// largest at t = 0.4100 with x = 3.434075; the grid of k = 56 samples it at
// 23 / 56 = 0.4107, 1e-6 lower.
TEST(TeapotMesh, BoundingBoxMatchesTheData) {
  const IndexedMesh m = teapot_mesh(56);
  Vec3 lo = vertex(m, 0), hi = vertex(m, 0);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const Vec3 p = vertex(m, v);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  EXPECT_NEAR(lo.x, -3, kFloat);
  EXPECT_NEAR(lo.y, -2, kFloat);
  EXPECT_NEAR(hi.y, 2, kFloat);
  EXPECT_NEAR(lo.z, 0, kFloat);
  EXPECT_NEAR(hi.z, 3.15, kFloat);
  EXPECT_NEAR(hi.x, 3.434075, 1e-5);
  EXPECT_LE(hi.x, 3.434076);
}

// The signed volume of the triangles converges to that of the patches, (1/3)
// sum of integral S . (Su x Sv) (exact by Gauss, patch_volume), at the rate of
// an inscribed triangulation of a smooth surface, O(h^2): halving the cells
// quarters the difference. (Both count the teapot with its open handle and
// spout and the gap under the lid as they are, about the origin.)
TEST(TeapotMesh, SignedVolumeConvergesToThePatchesAtSecondOrder) {
  double exact = 0;
  for (const BezierSurface& s : teapot_patches()) exact += patch_volume(s, {0, 0, 0});
  const double e16 = exact - signed_volume(teapot_mesh(16));
  const double e32 = exact - signed_volume(teapot_mesh(32));
  EXPECT_GT(signed_volume(teapot_mesh(8)), 0);
  EXPECT_GT(e16 / e32, 3.6);
  EXPECT_LT(e16 / e32, 4.4);
}

}  // namespace
}  // namespace gllab::deform
