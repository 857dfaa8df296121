// tests/spline/tessellate_test.cpp — curve flattening, ear clipping and
// surface tessellation (common/spline/tessellate.cpp).
//
// Every surface here is analytic (a sphere patch, the saddle z = xy, a bicubic
// Bézier patch written out with its Bernstein polynomials), so the true point
// and normal are known at every (u, v) and each triangle can be measured
// against the surface exactly as tessellate.h defines the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/nurbs.h"
#include "spline/surface.h"
#include "spline/tessellate.h"
#include "spline/trim.h"
#include "spline_test_support.h"

namespace gllab::spline {
namespace {

const double kPi = std::acos(-1.0);

/// Dense evaluation for "the true curve": 10,000 samples per curve.
constexpr int kDenseSamples = 10000;
/// Unit normals: |n| = 1 up to round-off of one normalisation.
constexpr double kUnitLengthEps = 1e-12;
/// Vertex normals come from the evaluator: they match the analytic normal up to round-off.
constexpr double kVertexNormalAngleDegrees = 1e-6;
/// The tilt docs/glu.md counts for GLU's slivers: faces more than 20° off the surface.
constexpr double kSliverTiltDegrees = 20;
/// Round-off allowance when comparing a measured error or area with its bound
/// (sums of a few thousand products of numbers near 1).
constexpr double kRoundOff = 1e-12;
/// docs/glu.md: GLU's meshes of coarsely trimmed bicubics were 5-23 % too large;
/// a tessellator that honours its tolerance must stay far below that.
constexpr double kMaxTrimmedAreaError = 0.01;
/// The NURBS circle hole of examples/trimmed_nurbs_surface.json is flattened
/// to at least this share of the disc's area at every tolerance tested.
constexpr double kHolePolygonMinShare = 0.9;

// ---- analytic curves -------------------------------------------------------------------

Vec3 unit_circle(double t) { return {std::cos(t), std::sin(t), 0}; }

/// A cubic Bézier from its four points (Bernstein form, notes "Higher Order Surfaces").
struct Cubic {
  Vec3 p0, p1, p2, p3;
  Vec3 operator()(double t) const {
    const double s = 1 - t;
    return s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3;
  }
};

double distance_to_segment(Vec3 q, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double len2 = dot(d, d);
  const double s = len2 > 0 ? std::clamp(dot(q - a, d) / len2, 0.0, 1.0) : 0.0;
  return norm(q - (a + s * d));
}

/// The largest distance from the curve (dense samples) to the chord of the
/// segment whose parameter interval holds the sample.
double max_chord_deviation(const std::function<Vec3(double)>& f, double a, double b,
                           const std::vector<CurveSample>& samples, ChordError kind = ChordError::Chordal) {
  double worst = 0;
  std::size_t k = 0;
  for (int i = 0; i <= kDenseSamples; ++i) {
    const double t = a + (b - a) * i / kDenseSamples;
    while (k + 2 < samples.size() && samples[k + 1].t < t) ++k;
    const CurveSample &s0 = samples[k], &s1 = samples[k + 1];
    const Vec3 q = f(t);
    const double e = kind == ChordError::Chordal
                         ? distance_to_segment(q, s0.point, s1.point)
                         : norm(q - lerp(s0.point, s1.point, (t - s0.t) / (s1.t - s0.t)));
    worst = std::max(worst, e);
  }
  return worst;
}

// ---- analytic surfaces (point, unit normal, partials) ----------------------------------

/// Sphere of radius R: S(u, v) = R (cos v cos u, cos v sin u, sin v), outward normal.
SurfaceEvaluator sphere(double R) {
  return [R](double u, double v) {
    SurfaceSample s;
    const Vec3 n{std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)};
    s.point = R * n;
    s.normal = n;
    s.du = R * Vec3{-std::cos(v) * std::sin(u), std::cos(v) * std::cos(u), 0};
    s.dv = R * Vec3{-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v)};
    return s;
  };
}

/// The saddle z = x y: S_u = (1, 0, v), S_v = (0, 1, u), n ~ (-v, -u, 1).
SurfaceSample saddle(double u, double v) {
  SurfaceSample s;
  s.point = {u, v, u * v};
  s.du = {1, 0, v};
  s.dv = {0, 1, u};
  s.normal = normalized(cross(s.du, s.dv));
  return s;
}

/// The plane z = 0 with the identity parametrisation.
SurfaceSample plane(double u, double v) { return {{u, v, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}}; }

/// A bicubic Bézier patch over (u, v) in [0, 1]^2 with a 4 x 4 net: a hill with
/// a dip, x = 3u, y = 3v, heights chosen by hand (not symmetric).
struct Bicubic {
  double z[4][4] = {{0, 0.5, 0.25, 0}, {0.25, 1.5, 1.25, 0.5}, {0, 1.75, -0.5, 0.25}, {0.5, 0.25, 0.75, 0}};
  static double B(int i, double t) {
    const double s = 1 - t;
    switch (i) {
      case 0: return s * s * s;
      case 1: return 3 * s * s * t;
      case 2: return 3 * s * t * t;
      default: return t * t * t;
    }
  }
  static double dB(int i, double t) {
    const double s = 1 - t;
    switch (i) {
      case 0: return -3 * s * s;
      case 1: return 3 * s * s - 6 * s * t;
      case 2: return 6 * s * t - 3 * t * t;
      default: return 3 * t * t;
    }
  }
  SurfaceSample operator()(double u, double v) const {
    Vec3 p, su, sv;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const Vec3 P{static_cast<double>(i), static_cast<double>(j), z[i][j]};
        p += B(i, u) * B(j, v) * P;
        su += dB(i, u) * B(j, v) * P;
        sv += B(i, u) * dB(j, v) * P;
      }
    return {p, normalized(cross(su, sv)), su, sv};
  }
};

// ---- measuring a mesh -------------------------------------------------------------------

struct MeshReport {
  double max_deviation = 0;       // at barycentres and edge midpoints
  double max_normal_length_error = 0;
  double max_vertex_normal_angle = 0;  // degrees
  double max_face_tilt = 0;            // degrees, face normal vs surface normal at the barycentre
  int faces_tilted_over_20 = 0;
  double min_angle = 180;              // degrees, smallest triangle angle in 3D
  int below_5_degrees = 0;             // triangles with an angle below 5°
  double area_below_5_degrees = 0;     // their share of the area
};

double angle_degrees(Vec3 a, Vec3 b) {
  return std::atan2(norm(cross(a, b)), dot(a, b)) * 180 / kPi;
}

MeshReport measure(const Mesh& mesh, const SurfaceEvaluator& surface) {
  MeshReport r;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    r.max_normal_length_error = std::max(r.max_normal_length_error, std::abs(norm(mesh.normals[i]) - 1));
    const SurfaceSample s = surface(mesh.uv[i].x, mesh.uv[i].y);
    r.max_vertex_normal_angle = std::max(r.max_vertex_normal_angle, angle_degrees(mesh.normals[i], s.normal));
  }
  for (const auto& t : mesh.triangles) {
    const Vec3 P[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    const Vec2 Q[3] = {mesh.uv[t[0]], mesh.uv[t[1]], mesh.uv[t[2]]};
    // Barycentre and the three edge midpoints, mapped through (u, v).
    const double w[4][3] = {{1 / 3.0, 1 / 3.0, 1 / 3.0}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
    for (const auto& b : w) {
      const Vec2 q = b[0] * Q[0] + b[1] * Q[1] + b[2] * Q[2];
      const Vec3 p = b[0] * P[0] + b[1] * P[1] + b[2] * P[2];
      r.max_deviation = std::max(r.max_deviation, norm(surface(q.x, q.y).point - p));
    }
    const Vec2 qc = (Q[0] + Q[1] + Q[2]) / 3;
    const double tilt = angle_degrees(cross(P[1] - P[0], P[2] - P[0]), surface(qc.x, qc.y).normal);
    r.max_face_tilt = std::max(r.max_face_tilt, tilt);
    if (tilt > kSliverTiltDegrees) ++r.faces_tilted_over_20;
    double least = 180;
    for (int k = 0; k < 3; ++k) least = std::min(least, angle_degrees(P[(k + 1) % 3] - P[k], P[(k + 2) % 3] - P[k]));
    r.min_angle = std::min(r.min_angle, least);
    if (least < 5) ++r.below_5_degrees, r.area_below_5_degrees += norm(cross(P[1] - P[0], P[2] - P[0])) / 2;
  }
  r.area_below_5_degrees /= mesh_area(mesh);
  return r;
}

void print(const std::string& what, const Mesh& mesh, const MeshReport& r) {
  std::cout << "  [" << what << "] " << mesh.triangles.size() << " triangles, " << mesh.positions.size()
            << " vertices, max deviation " << r.max_deviation << ", max face tilt " << r.max_face_tilt
            << "°, min angle " << r.min_angle << "°, " << r.below_5_degrees << " triangles below 5° ("
            << r.area_below_5_degrees * 100 << " % of the area)\n";
}

/// Edges used once, counted over undirected edges.
std::size_t count_boundary_edges(const Mesh& mesh) { return boundary_edges(mesh).size(); }

/// Each edge is used by at most two triangles, and then in opposite directions.
bool consistently_oriented_manifold(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (++directed[{t[k], t[(k + 1) % 3]}] > 1) return false;
  return true;
}

TrimLoop closed_loop(std::vector<Vec2> points) {
  points.push_back(points.front());
  TrimLoop loop;
  loop.pieces.push_back({std::move(points), std::nullopt});
  return loop;
}
TrimLoop square_loop(double a0, double b0, double a1, double b1, bool ccw) {
  std::vector<Vec2> p{{a0, b0}, {a1, b0}, {a1, b1}, {a0, b1}};
  if (!ccw) std::reverse(p.begin(), p.end());
  return closed_loop(p);
}

// ---- curve flattening --------------------------------------------------------------------

TEST(FlattenCurve, CircleDeviationWithinTolerance) {
  for (double tol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    FlattenOptions o;
    o.tolerance = tol;
    const auto s = flatten_curve(unit_circle, 0, 2 * kPi, o);
    EXPECT_EQ(s.front().t, 0);
    EXPECT_EQ(s.back().t, 2 * kPi);
    EXPECT_LE(max_chord_deviation(unit_circle, 0, 2 * kPi, s), tol) << "tol " << tol;
  }
}

TEST(FlattenCurve, CircleSegmentsGrowLikeOneOverSqrtTolerance) {
  // Property: a circle's chord of angle θ sags 1 - cos(θ/2) ≈ θ²/8, so
  // segments N ≈ π / sqrt(2 · 0.9 tol). Bisection makes N a power of two, so
  // N · sqrt(tol) stays within [π / sqrt(1.8), 2 π / sqrt(1.8)] = [2.34, 4.68].
  std::cout << "  circle: tolerance -> segments\n";
  for (double tol = 1e-2; tol >= 1e-9; tol /= 10) {
    FlattenOptions o;
    o.tolerance = tol;
    const double n = static_cast<double>(flatten_curve(unit_circle, 0, 2 * kPi, o).size() - 1);
    std::cout << "    " << tol << " -> " << n << "\n";
    EXPECT_GE(n * std::sqrt(tol), kPi / std::sqrt(1.8)) << tol;
    EXPECT_LE(n * std::sqrt(tol), 2 * kPi / std::sqrt(1.8)) << tol;
  }
}

TEST(FlattenCurve, CubicsWithinTolerance) {
  // A plain arc-like cubic, a cubic with an inflection in its middle (the
  // S-curve: its midpoint lies ON the chord), and one with a tight turn.
  const Cubic cubics[] = {{{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}},
                          {{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 0}},
                          {{0, 0, 0}, {4, 1, 0}, {-1, 1, 1}, {3, 0, 0}}};
  for (const Cubic& c : cubics)
    for (double tol : {1e-2, 1e-3, 1e-4, 1e-5}) {
      for (ChordError kind : {ChordError::Chordal, ChordError::Parametric}) {
        FlattenOptions o;
        o.tolerance = tol;
        o.error = kind;
        const auto s = flatten_curve(c, 0, 1, o);
        EXPECT_LE(max_chord_deviation(c, 0, 1, s, kind), tol) << "tol " << tol;
      }
    }
}

TEST(FlattenCurve, InflectionNeedsMoreThanTheMidpoint) {
  // The S-curve's midpoint is on its chord; the quarter points are not. Even
  // with no forced bisection (min_depth 0) the three-sample test splits it.
  const Cubic s_curve{{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 0}};
  EXPECT_EQ(distance_to_segment(s_curve(0.5), s_curve(0), s_curve(1)), 0);
  FlattenOptions o;
  o.tolerance = 1e-3;
  o.min_depth = 0;
  const auto s = flatten_curve(s_curve, 0, 1, o);
  EXPECT_GT(s.size(), 2u);
  EXPECT_LE(max_chord_deviation(s_curve, 0, 1, s), o.tolerance);
}

TEST(FlattenCurve, MinDepthGuardsAgainstSamplesOnTheChord) {
  // y = 0.1 sin(4 π t) is 0 at t = 1/4, 1/2, 3/4: with min_depth 0 the three
  // samples see a straight line. The default min_depth (2) finds the waves.
  const auto wave = [](double t) { return Vec3{t, 0.1 * std::sin(4 * kPi * t), 0}; };
  FlattenOptions o;
  o.tolerance = 1e-3;
  o.min_depth = 0;
  EXPECT_EQ(flatten_curve(wave, 0, 1, o).size(), 2u);  // fooled, as documented
  o.min_depth = kMinFlattenDepth;
  const auto s = flatten_curve(wave, 0, 1, o);
  EXPECT_LE(max_chord_deviation(wave, 0, 1, s), o.tolerance);
}

TEST(FlattenCurve, MaxDepthStopsAtAJump) {
  // A step has no chordal approximation; bisection stops at max_depth.
  const auto step = [](double t) { return Vec3{t, t < 1 / 3.0 ? 0.0 : 1.0, 0}; };
  FlattenOptions o;
  o.tolerance = 1e-6;
  o.max_depth = 12;
  const auto s = flatten_curve(step, 0, 1, o);
  EXPECT_LE(s.size(), (1u << 12) + 1);
  // Only the interval holding the jump is split at each level: 4 forced
  // segments (min_depth 2), then two more breakpoints per level below that.
  EXPECT_LE(s.size(), 4u + 1 + 2 * (12 - kMinFlattenDepth));
}

TEST(FlattenCurve, SameCurveSameSamples) {
  // Determinism: flattening twice gives bit-identical parameters and points.
  const Cubic c{{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};
  const auto a = flatten_curve(c, 0.25, 0.75), b = flatten_curve(c, 0.25, 0.75);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].t, b[k].t);
    EXPECT_EQ(a[k].point, b[k].point);
  }
  EXPECT_EQ(a.front().t, 0.25);
  EXPECT_EQ(a.back().t, 0.75);
}

TEST(FlattenCurve, BadInputIsRejected) {
  FlattenOptions o;
  o.tolerance = 0;
  EXPECT_THROW(flatten_curve(unit_circle, 0, 1, o), std::invalid_argument);
  EXPECT_THROW(flatten_curve(unit_circle, 1, 0), std::invalid_argument);
  try {
    flatten_curve([](double t) { return Vec3{t, t > 0.5 ? NAN : 0, 0}; }, 0, 1);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("flatten_curve: C(", 0), 0u) << e.what();
  }
  const auto s = flatten_curve(unit_circle, 0.5, 0.5);
  EXPECT_EQ(s.size(), 2u);
}

// ---- ear clipping ---------------------------------------------------------------------------

double triangles_area(const std::vector<Vec2>& pts, const std::vector<std::array<int, 3>>& tris) {
  double a = 0;
  for (const auto& t : tris) {
    const double s = cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]) / 2;
    EXPECT_GT(s, 0);  // counter-clockwise, not degenerate
    a += s;
  }
  return a;
}

/// The points of all loops, in order: what triangulate_polygon's indices refer to.
std::vector<Vec2> concat(const std::vector<std::vector<Vec2>>& loops) {
  std::vector<Vec2> all;
  for (const auto& loop : loops)
    for (const Vec2& p : loop) all.push_back(p);
  return all;
}

TEST(TriangulatePolygon, ConvexAndConcaveCounts) {
  // n points -> n - 2 triangles, covering the polygon's area (Meisters' two ears).
  const std::vector<Vec2> l_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const auto tris = triangulate_polygon({l_shape});
  EXPECT_EQ(tris.size(), 4u);
  EXPECT_DOUBLE_EQ(triangles_area(l_shape, tris), 3);
}

TEST(TriangulatePolygon, CollinearPointsStayVertices) {
  // A square with extra points on its sides (hanging vertices of neighbours):
  // every point is used, so no T-junction appears.
  const std::vector<Vec2> p{{0, 0}, {0.5, 0}, {1, 0}, {1, 0.25}, {1, 0.5}, {1, 1}, {0, 1}, {0, 0.5}};
  const auto tris = triangulate_polygon({p});
  EXPECT_EQ(tris.size(), p.size() - 2);
  EXPECT_DOUBLE_EQ(triangles_area(p, tris), 1);
  std::set<int> used;
  for (const auto& t : tris) used.insert(t.begin(), t.end());
  EXPECT_EQ(used.size(), p.size());
}

TEST(TriangulatePolygon, SquareWithHole) {
  // n = 8 points, h = 1 hole -> n - 2 + 2h = 8 triangles; area 1 - 1/4.
  const std::vector<Vec2> outer{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Vec2> hole{{0.25, 0.25}, {0.25, 0.75}, {0.75, 0.75}, {0.75, 0.25}};
  const auto tris = triangulate_polygon({outer, hole});
  EXPECT_EQ(tris.size(), 8u);
  EXPECT_DOUBLE_EQ(triangles_area(concat({outer, hole}), tris), 0.75);
}

TEST(TriangulatePolygon, TwoHoles) {
  const std::vector<Vec2> outer{{0, 0}, {4, 0}, {4, 2}, {0, 2}};
  const std::vector<Vec2> h1{{0.5, 0.5}, {0.5, 1.5}, {1.5, 1.5}, {1.5, 0.5}};
  const std::vector<Vec2> h2{{2.5, 0.5}, {2.5, 1.5}, {3.5, 1.5}, {3.5, 0.5}};
  const auto tris = triangulate_polygon({outer, h1, h2});
  EXPECT_EQ(tris.size(), 12u - 2 + 4);
  EXPECT_DOUBLE_EQ(triangles_area(concat({outer, h1, h2}), tris), 8 - 2);
}

// ---- surfaces: tolerance, normals -----------------------------------------------------------

struct Case {
  std::string name;
  SurfaceEvaluator surface;
  UvDomain domain;
};

std::vector<Case> analytic_cases() {
  return {{"sphere patch R=2", sphere(2), {0, kPi / 2, -kPi / 4, kPi / 3}},
          {"saddle z=xy", saddle, {-1, 1, -1, 1}},
          {"bicubic", Bicubic{}, {0, 1, 0, 1}}};
}

TEST(TessellateSurface, EveryTriangleWithinToleranceOnAnalyticSurfaces) {
  for (const Case& c : analytic_cases())
    for (double tol : {1e-2, 1e-3, 1e-4}) {
      const Mesh mesh = tessellate_surface(c.surface, c.domain, TessellationOptions::adaptive(tol));
      const MeshReport r = measure(mesh, c.surface);
      print(c.name + ", tol " + num(tol), mesh, r);
      EXPECT_LE(r.max_deviation, tol + kRoundOff) << c.name << " tol " << tol;
      EXPECT_LE(r.max_normal_length_error, kUnitLengthEps);
      EXPECT_LE(r.max_vertex_normal_angle, kVertexNormalAngleDegrees);
      EXPECT_EQ(r.faces_tilted_over_20, 0);
      EXPECT_TRUE(consistently_oriented_manifold(mesh));
    }
}

TEST(TessellateSurface, TrianglesGrowLikeOneOverTolerance) {
  // Property: on a curved patch each triangle covers an area ~ tolerance (its
  // size h has h² · curvature ~ tol), so count x tolerance stays bounded as
  // the tolerance shrinks 100-fold.
  std::vector<double> products;
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const Mesh m = tessellate_surface(sphere(2), {0, kPi / 2, -kPi / 4, kPi / 3}, TessellationOptions::adaptive(tol));
    products.push_back(static_cast<double>(m.triangles.size()) * tol);
  }
  EXPECT_LT(products.back() / products.front(), 4);
  EXPECT_GT(products.back() / products.front(), 0.25);
}

TEST(TessellateSurface, FixedStepsGiveTwoTrianglesPerCell) {
  // GLU_DOMAIN_DISTANCE-style sampling: exactly nu x nv x 2 triangles.
  for (const auto& [nu, nv] : std::vector<std::pair<int, int>>{{1, 1}, {7, 5}, {16, 3}}) {
    const Mesh m = tessellate_surface(Bicubic{}, {0, 1, 0, 1}, TessellationOptions::fixed_steps(nu, nv));
    EXPECT_EQ(m.triangles.size(), static_cast<std::size_t>(nu * nv * 2));
    EXPECT_EQ(m.positions.size(), static_cast<std::size_t>((nu + 1) * (nv + 1)));
    EXPECT_EQ(count_boundary_edges(m), static_cast<std::size_t>(2 * (nu + nv)));
  }
}

TEST(TessellateSurface, PlaneNeedsOnlyTheMinimumDepth) {
  // A plane is flat at once: 4 x 4 cells (kMinQuadtreeDepth = 2), 32 triangles, area 6.
  const Mesh m = tessellate_surface(plane, {0, 3, 0, 2}, TessellationOptions::adaptive(1e-6));
  EXPECT_EQ(m.triangles.size(), 32u);
  EXPECT_NEAR(mesh_area(m), 6, kRoundOff);
}

TEST(TessellateSurface, BadInputIsRejected) {
  EXPECT_THROW(tessellate_surface(plane, {0, 0, 0, 1}, TessellationOptions::adaptive(1e-3)), std::invalid_argument);
  EXPECT_THROW(tessellate_surface(plane, {0, 1, 0, 1}, TessellationOptions::adaptive(0)), std::invalid_argument);
  EXPECT_THROW(tessellate_surface(plane, {0, 1, 0, 1}, TessellationOptions::fixed_steps(0, 3)), std::invalid_argument);
  const SurfaceEvaluator broken = [](double u, double v) {
    SurfaceSample s = plane(u, v);
    if (u == 0.75 && v == 0.5) s.point.z = NAN;
    return s;
  };
  try {
    tessellate_surface(broken, {0, 1, 0, 1}, TessellationOptions::fixed_steps(4, 4));
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "tessellate_surface: at (u, v)=(0.75, 0.5): point=(0.75, 0.5, nan) is not finite");
  }
}

TEST(TessellateSurface, MissingNormalIsComputedFromPartials) {
  const SurfaceEvaluator no_normal = [](double u, double v) {
    SurfaceSample s = saddle(u, v);
    s.normal = {};
    return s;
  };
  const Mesh m = tessellate_surface(no_normal, {-1, 1, -1, 1}, TessellationOptions::fixed_steps(4, 4));
  const MeshReport r = measure(m, saddle);
  EXPECT_LE(r.max_normal_length_error, kUnitLengthEps);
  EXPECT_LE(r.max_vertex_normal_angle, kVertexNormalAngleDegrees);
}

// ---- trimmed surfaces -------------------------------------------------------------------------

TEST(TessellateSurface, PlanarSquareWithHoleHasExactArea) {
  // Outer [0.1, 0.9]^2 (ccw) minus hole [0.3, 0.6]^2 (cw): 0.64 - 0.09 = 0.55.
  // A plane is reproduced exactly by any triangulation, so the area is exact
  // up to round-off: the trimmed region, no more (GLU's slivers would add area).
  const std::vector<TrimLoop> trims{square_loop(0.1, 0.1, 0.9, 0.9, true), square_loop(0.3, 0.3, 0.6, 0.6, false)};
  for (const auto& opt : {TessellationOptions::adaptive(1e-3), TessellationOptions::fixed_steps(5, 7)}) {
    const Mesh m = tessellate_surface(plane, {0, 1, 0, 1}, opt, trims);
    EXPECT_NEAR(mesh_area(m), 0.55, kRoundOff);
    EXPECT_TRUE(consistently_oriented_manifold(m));
    // The mesh boundary is the trim: every boundary edge lies on one of the 8 sides.
    for (const auto& e : boundary_edges(m)) {
      const Vec2 a = m.uv[e[0]], b = m.uv[e[1]];
      const bool on_trim = [&] {
        for (double x : {0.1, 0.9, 0.3, 0.6})
          if ((a.x == x && b.x == x) || (a.y == x && b.y == x)) return true;
        return false;
      }();
      EXPECT_TRUE(on_trim) << num(a) << "-" << num(b);
    }
  }
}

TEST(TessellateSurface, TrimOnDomainEdgeKeepsWholePatch) {
  // The Red Book's outer loop runs along the domain edge: nothing is cut, and
  // the mesh is the untrimmed one, vertex for vertex.
  const std::vector<TrimLoop> trims{square_loop(0, 0, 1, 1, true)};
  const Mesh trimmed = tessellate_surface(Bicubic{}, {0, 1, 0, 1}, TessellationOptions::adaptive(1e-3), trims);
  const Mesh plain = tessellate_surface(Bicubic{}, {0, 1, 0, 1}, TessellationOptions::adaptive(1e-3));
  ASSERT_EQ(trimmed.triangles.size(), plain.triangles.size());
  EXPECT_EQ(trimmed.positions, plain.positions);
  EXPECT_EQ(mesh_area(trimmed), mesh_area(plain));
}

TEST(TessellateSurface, PlanarSquareWithCircleHoleMatchesAnalyticArea) {
  // Outer [0.1, 0.9]^2 (polyline, ccw) and a NURBS circle hole (nurbs.h's
  // exact circle, reversed to run clockwise) of radius r = 0.25. On the plane
  // z = 0 the tolerance is a (u, v) distance: the hole's polygon lies inside
  // the circle by at most tol, so its area is between pi r^2 (1 - 2 tol / r)
  // and pi r^2, and the mesh area between 0.64 - pi r^2 and 0.64 - pi r^2 (1 - 2 tol / r).
  const double r = 0.25, pi_r2 = kPi * r * r;
  TrimLoop hole;
  hole.pieces.push_back({{}, reversed(circle({0.5, 0.5, 0}, r))});
  const std::vector<TrimLoop> trims{square_loop(0.1, 0.1, 0.9, 0.9, true), hole};
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const Mesh m = tessellate_surface(plane, {0, 1, 0, 1}, TessellationOptions::adaptive(tol), trims);
    const double area = mesh_area(m);
    EXPECT_GE(area, 0.64 - pi_r2 - kRoundOff) << tol;
    EXPECT_LE(area, 0.64 - pi_r2 * (1 - 2 * tol / r) + kRoundOff) << tol;
    EXPECT_TRUE(consistently_oriented_manifold(m));
    const MeshReport rep = measure(m, plane);
    print("plane, circle hole, tol " + num(tol), m, rep);
  }
}

TEST(TessellateSurface, SpherePatchAreaWithinToleranceBound) {
  // Analytic area of S over [u0, u1] x [v0, v1] minus a (u, v) square hole
  // [a0, a1] x [b0, b1]: R^2 (u1 - u0)(sin v1 - sin v0) - R^2 (a1 - a0)(sin b1 - sin b0).
  // Every mesh point is within tol of the sphere, i.e. at distance >= R - tol
  // from its centre: the mesh area is at least (1 - tol / R)^2 of the true area,
  // and (inscribed in the convex sphere) at most the true area.
  const double R = 2, u0 = 0, u1 = kPi / 2, v0 = -kPi / 4, v1 = kPi / 3;
  const double a0 = 0.5, a1 = 1, b0 = -0.25, b1 = 0.5;
  const double full = R * R * (u1 - u0) * (std::sin(v1) - std::sin(v0));
  const double holed = full - R * R * (a1 - a0) * (std::sin(b1) - std::sin(b0));
  // The outer loop runs along the domain edge (a hole needs an outer loop);
  // the hole is a 5-point polyline, the coarse kind that makes GLU fan slivers (docs/glu.md).
  const std::vector<TrimLoop> trims{square_loop(u0, v0, u1, v1, true), square_loop(a0, b0, a1, b1, false)};
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const Mesh plain = tessellate_surface(sphere(R), {u0, u1, v0, v1}, TessellationOptions::adaptive(tol));
    const Mesh cut = tessellate_surface(sphere(R), {u0, u1, v0, v1}, TessellationOptions::adaptive(tol), trims);
    const double shrink = (1 - tol / R) * (1 - tol / R);
    EXPECT_LE(mesh_area(plain), full);
    EXPECT_GE(mesh_area(plain), full * shrink);
    EXPECT_LE(mesh_area(cut), holed);
    EXPECT_GE(mesh_area(cut), holed * shrink);
    const MeshReport r = measure(cut, sphere(R));
    print("sphere with square hole, tol " + num(tol), cut, r);
    std::cout << "    area error " << (mesh_area(cut) - holed) / holed * 100 << " %\n";
    EXPECT_LE(r.max_deviation, tol + kRoundOff);
    EXPECT_EQ(r.faces_tilted_over_20, 0);
  }
}

TEST(TessellateSurface, CoarsePolylineTrimMakesNoSlivers) {
  // docs/glu.md: a 5-point polyline square trim on a bicubic made GLU fan long
  // slivers across the region (area 5-23 % too large, faces tilted > 20°).
  // Here the trim edges are refined and the cells cut, so every triangle is
  // within the tolerance, none tilts by 20°, and the area matches the
  // integral of |S_u x S_v| (Gauss-Legendre, 8 points on each of 32 x 32
  // sub-squares) to within kMaxTrimmedAreaError.
  const Bicubic b;
  const std::vector<TrimLoop> trims{square_loop(0.1, 0.15, 0.9, 0.85, true), square_loop(0.4, 0.35, 0.65, 0.6, false)};
  const auto area_of = [&](double x0, double x1, double y0, double y1) {
    static const double g[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    double sum = 0;
    const int n = 32;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double xa = x0 + (x1 - x0) * i / n, xb = x0 + (x1 - x0) * (i + 1) / n;
        const double ya = y0 + (y1 - y0) * j / n, yb = y0 + (y1 - y0) * (j + 1) / n;
        for (int p = 0; p < 8; ++p)
          for (int q = 0; q < 8; ++q) {
            const SurfaceSample s = b((xa + xb) / 2 + (xb - xa) / 2 * g[p], (ya + yb) / 2 + (yb - ya) / 2 * g[q]);
            sum += w[p] * w[q] * (xb - xa) / 2 * (yb - ya) / 2 * norm(cross(s.du, s.dv));
          }
      }
    return sum;
  };
  const double exact = area_of(0.1, 0.9, 0.15, 0.85) - area_of(0.4, 0.65, 0.35, 0.6);
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const Mesh m = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::adaptive(tol), trims);
    const MeshReport r = measure(m, b);
    print("bicubic, coarse square trims, tol " + num(tol), m, r);
    const double error = (mesh_area(m) - exact) / exact;
    std::cout << "    area error " << error * 100 << " %\n";
    EXPECT_LE(r.max_deviation, tol + kRoundOff);
    EXPECT_EQ(r.faces_tilted_over_20, 0);
    EXPECT_LT(std::abs(error), kMaxTrimmedAreaError);
    EXPECT_TRUE(consistently_oriented_manifold(m));
  }
}

/// Distance from p to the segment a-b in (u, v).
double distance_to_segment_2d(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  const double s = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + s * d));
}

TEST(TessellateSurface, RandomTrimsKeepAreaManifoldAndTolerance) {
  // Property, 40 random trims: a star-shaped outer loop (or the domain
  // square) with up to two star-shaped holes, a third of the coordinates
  // rounded to 1/16 so that points fall on cell lines and edges run along
  // them. For each, adaptive and fixed steps:
  //  - the triangles tile the trimmed region exactly: their (u, v) area is
  //    the loops' signed area (shoelace, trim.h), to round-off;
  //  - the mesh is a consistently oriented manifold, every triangle
  //    counter-clockwise in (u, v);
  //  - every boundary edge lies on a trim edge;
  //  - adaptive: every triangle within the tolerance.
  unsigned state = 2024;
  const auto rnd = [&] { return (state = state * 1664525u + 1013904223u) / 4294967296.0; };
  const auto star = [&](Vec2 centre, double r0, double r1, int n, bool ccw) {
    std::vector<Vec2> p;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * kPi * (k + 0.3 * rnd()) / n, r = r0 + (r1 - r0) * rnd();
      Vec2 q{centre.x + r * std::cos(a), centre.y + r * std::sin(a)};
      if (rnd() < 0.3) q.x = std::round(q.x * 16) / 16;
      if (rnd() < 0.3) q.y = std::round(q.y * 16) / 16;
      q = {std::clamp(q.x, 0.0, 1.0), std::clamp(q.y, 0.0, 1.0)};
      if (p.empty() || p.back() != q) p.push_back(q);
    }
    if (!ccw) std::reverse(p.begin(), p.end());
    return closed_loop(p);
  };
  int tested = 0;
  for (int c = 0; tested < 40; ++c) {
    std::vector<TrimLoop> loops;
    loops.push_back(c % 5 == 0 ? square_loop(0, 0, 1, 1, true) : star({0.5, 0.5}, 0.2, 0.55, 3 + c % 12, true));
    for (int h = 0; h < c % 3; ++h)
      loops.push_back(star({0.3 + 0.4 * rnd(), 0.3 + 0.4 * rnd()}, 0.02, 0.12, 3 + (c + h) % 8, false));
    std::vector<TrimPolygon> polygons;
    try {
      polygons = validate_trim_loops(loops, {0, 1, 0, 1});
    } catch (const std::invalid_argument&) {
      continue;  // crossing loops: GLU would refuse them too
    }
    ++tested;
    double want = 0;
    for (const TrimPolygon& p : polygons) want += signed_area(p);
    const SurfaceEvaluator surface = c % 2 ? SurfaceEvaluator(plane) : SurfaceEvaluator(Bicubic{});
    for (const auto& opt : {TessellationOptions::adaptive(1e-3), TessellationOptions::fixed_steps(3 + c % 7, 5 + c % 4)}) {
      const Mesh m = tessellate_surface(surface, {0, 1, 0, 1}, opt, loops);
      double area = 0;
      for (const auto& t : m.triangles) {
        const double a = cross(m.uv[t[1]] - m.uv[t[0]], m.uv[t[2]] - m.uv[t[0]]) / 2;
        EXPECT_GT(a, 0) << "case " << c;
        area += a;
      }
      EXPECT_NEAR(area, want, kRoundOff) << "case " << c;
      EXPECT_TRUE(consistently_oriented_manifold(m)) << "case " << c;
      for (const auto& e : boundary_edges(m)) {
        double best = 1;
        for (const TrimPolygon& p : polygons)
          for (std::size_t k = 0; k < p.size(); ++k) {
            const Vec2 a = p[k], b = p[(k + 1) % p.size()];
            best = std::min(best, std::max(distance_to_segment_2d(m.uv[e[0]], a, b), distance_to_segment_2d(m.uv[e[1]], a, b)));
          }
        EXPECT_LT(best, kRoundOff) << "case " << c << ": " << num(m.uv[e[0]]) << "-" << num(m.uv[e[1]]);
      }
      if (opt.sampling == Sampling::Adaptive) {
        EXPECT_LE(measure(m, surface).max_deviation, opt.tolerance + kRoundOff) << "case " << c;
      }
    }
  }
}

TEST(TessellateSurface, ExampleTrimmedNurbsSurfaceEndToEnd) {
  // examples/trimmed_nurbs_surface.json, typed in: a rational bicubic hill
  // (weights 2 in the middle) trimmed to [0.05, 0.95]^2 by a closed polyline
  // and holed by the exact NURBS circle of radius 0.2 about (0.5, 0.5), run
  // clockwise. Evaluated by surface.h (surface_evaluator), so this checks the
  // whole path a lab takes; the true surface is surface_point/surface_normal.
  BsplineSurface s;
  s.p = s.q = 3;
  s.U = s.V = {0, 0, 0, 0, 1, 1, 1, 1};
  s.nu = s.nv = 4;
  const double z[4][4] = {{0, 0, 0, 0}, {0, 1.5, 1.5, 0}, {0, 1.5, 1.5, 0}, {0, 0, 0, 0}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      s.P.push_back({static_cast<double>(i), static_cast<double>(j), z[i][j]});
      s.w.push_back((i == 1 || i == 2) && (j == 1 || j == 2) ? 2.0 : 1.0);
    }
  s.trims.push_back(closed_loop({{0.05, 0.05}, {0.95, 0.05}, {0.95, 0.95}, {0.05, 0.95}}));
  BsplineCurve hole;
  hole.p = 2;
  hole.U = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  hole.P = {{0.7, 0.5, 0}, {0.7, 0.3, 0}, {0.5, 0.3, 0}, {0.3, 0.3, 0}, {0.3, 0.5, 0},
            {0.3, 0.7, 0}, {0.5, 0.7, 0}, {0.7, 0.7, 0}, {0.7, 0.5, 0}};
  const double h = std::sqrt(0.5);
  hole.w = {1, h, 1, h, 1, h, 1, h, 1};
  hole.dimension = 2;
  s.trims.push_back(TrimLoop{{TrimPiece{{}, hole}}});
  const SurfaceEvaluator exact = [&s](double u, double v) {
    return SurfaceSample{surface_point(s, u, v), surface_normal(s, u, v), {}, {}};
  };
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const Mesh m = tessellate_surface(surface_evaluator(s), uv_domain(s), TessellationOptions::adaptive(tol), s.trims);
    const MeshReport r = measure(m, exact);
    print("example trimmed NURBS surface, tol " + num(tol), m, r);
    EXPECT_LE(r.max_deviation, tol + kRoundOff);
    EXPECT_LE(r.max_vertex_normal_angle, kVertexNormalAngleDegrees);
    EXPECT_EQ(r.faces_tilted_over_20, 0);
    EXPECT_TRUE(consistently_oriented_manifold(m));
    // In (u, v) the mesh covers the square minus the hole's inscribed polygon:
    // at least 0.81 - pi 0.2^2, and the hole polygon is most of the disc.
    double uv_area = 0;
    for (const auto& t : m.triangles) uv_area += cross(m.uv[t[1]] - m.uv[t[0]], m.uv[t[2]] - m.uv[t[0]]) / 2;
    EXPECT_GE(uv_area, 0.81 - kPi * 0.04);
    EXPECT_LE(uv_area, 0.81 - kPi * 0.04 * kHolePolygonMinShare);
  }
}

// ---- crack-free patch edges --------------------------------------------------------------------

/// The vertices of mesh m with u == u_edge, ordered by v.
std::vector<Vec3> edge_points(const Mesh& m, double u_edge) {
  std::vector<std::pair<double, Vec3>> on;
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    if (m.uv[i].x == u_edge) on.push_back({m.uv[i].y, m.positions[i]});
  std::sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec3> out;
  for (const auto& [v, p] : on) out.push_back(p);
  return out;
}

/// True when every boundary edge runs along the outer rectangle of the union domain.
bool only_outer_boundary(const Mesh& m, UvDomain outer) {
  for (const auto& e : boundary_edges(m)) {
    const Vec2 a = m.uv[e[0]], b = m.uv[e[1]];
    const bool along = (a.x == outer.u0 && b.x == outer.u0) || (a.x == outer.u1 && b.x == outer.u1) ||
                       (a.y == outer.v0 && b.y == outer.v0) || (a.y == outer.v1 && b.y == outer.v1);
    if (!along) return false;
  }
  return true;
}

TEST(Weld, MergesSharedVerticesAndDropsCollapsedTriangles) {
  // Two triangles of the unit square given as separate meshes: welded, they
  // share the diagonal (4 vertices, the outline = 4 boundary edges). A third
  // mesh whose triangle collapses to a segment after welding is dropped.
  Mesh a, b, c;
  a.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  b.positions = {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  c.positions = {{0, 0, 0}, {1, 0, 0}, {1, kWeldTolerance / 2, 0}};
  for (Mesh* m : {&a, &b, &c}) {
    m->normals.assign(3, {0, 0, 1});
    m->uv.assign(3, {});
    m->triangles = {{0, 1, 2}};
  }
  const Mesh w = weld({a, b, c});
  EXPECT_EQ(w.positions.size(), 4u);
  EXPECT_EQ(w.triangles.size(), 2u);
  EXPECT_EQ(boundary_edges(w).size(), 4u);
  EXPECT_DOUBLE_EQ(mesh_area(w), 1);
  EXPECT_THROW(weld({a}, -1), std::invalid_argument);
}

TEST(TessellatePatches, SplitDomainSharesEdgeVerticesAndWeldsWithoutCracks) {
  // One surface, its domain split at u = um: the two halves tessellated on
  // their own (the same tolerance) put bit-identical vertices on u = um, and
  // the welded mesh has boundary edges only on the outer rectangle.
  for (const Case& c : analytic_cases()) {
    const double um = (c.domain.u0 + c.domain.u1) / 2;
    const UvDomain left{c.domain.u0, um, c.domain.v0, c.domain.v1}, right{um, c.domain.u1, c.domain.v0, c.domain.v1};
    for (double tol : {1e-2, 1e-3, 1e-4}) {
      const auto opt = TessellationOptions::adaptive(tol);
      const Mesh a = tessellate_surface(c.surface, left, opt), b = tessellate_surface(c.surface, right, opt);
      const auto ea = edge_points(a, um), eb = edge_points(b, um);
      EXPECT_EQ(ea, eb) << c.name << " tol " << tol;
      EXPECT_GE(ea.size(), 5u);
      const Mesh both = tessellate_patches({{c.surface, left, {}}, {c.surface, right, {}}}, opt);
      EXPECT_EQ(both.positions.size(), a.positions.size() + b.positions.size() - ea.size());
      EXPECT_EQ(both.triangles.size(), a.triangles.size() + b.triangles.size());
      EXPECT_TRUE(only_outer_boundary(both, c.domain)) << c.name << " tol " << tol;
      EXPECT_TRUE(consistently_oriented_manifold(both));
    }
  }
}

TEST(TessellatePatches, FourPatchesOfTheSaddleWeldIntoOneSheet) {
  // 2 x 2 patches: every inner edge used twice; the boundary is the outer
  // square, 4 sides' worth of edges.
  std::vector<Patch> patches;
  for (double u0 : {-1.0, 0.0})
    for (double v0 : {-1.0, 0.0}) patches.push_back({saddle, {u0, u0 + 1, v0, v0 + 1}, {}});
  const Mesh m = tessellate_patches(patches, TessellationOptions::adaptive(1e-3));
  EXPECT_TRUE(only_outer_boundary(m, {-1, 1, -1, 1}));
  EXPECT_TRUE(consistently_oriented_manifold(m));
  const MeshReport r = measure(m, saddle);
  EXPECT_LE(r.max_deviation, 1e-3 + kRoundOff);
}

TEST(TessellatePatches, TrimNearSharedEdgeKeepsEdgeVertices) {
  // A hole in the left patch close to the shared edge cuts the cells along it
  // (the ear-clipped strip path); the shared edge still carries exactly the
  // edge samples, so the right patch, untrimmed, still fits.
  const UvDomain left{0, 0.5, 0, 1}, right{0.5, 1, 0, 1};
  const std::vector<TrimLoop> hole{square_loop(0, 0, 0.5, 1, true), square_loop(0.45, 0.3, 0.49, 0.7, false)};
  const auto opt = TessellationOptions::adaptive(1e-4);
  const Mesh a = tessellate_surface(Bicubic{}, left, opt, hole), b = tessellate_surface(Bicubic{}, right, opt);
  EXPECT_EQ(edge_points(a, 0.5), edge_points(b, 0.5));
  const Mesh both = tessellate_patches({{Bicubic{}, left, hole}, {Bicubic{}, right, {}}}, opt);
  // Boundary: the outer square plus the hole's four sides.
  for (const auto& e : boundary_edges(both)) {
    const Vec2 p = both.uv[e[0]], q = both.uv[e[1]];
    const bool outer = (p.x == 0 && q.x == 0) || (p.x == 1 && q.x == 1) || (p.y == 0 && q.y == 0) || (p.y == 1 && q.y == 1);
    const bool on_hole = (p.x == 0.45 && q.x == 0.45) || (p.x == 0.49 && q.x == 0.49) || (p.y == 0.3 && q.y == 0.3) ||
                         (p.y == 0.7 && q.y == 0.7);
    EXPECT_TRUE(outer || on_hole) << num(p) << "-" << num(q);
  }
  const MeshReport r = measure(both, Bicubic{});
  print("bicubic halves, hole near the shared edge, tol 1e-4", both, r);
}

/// The bicubic's net split at u = 1/2 by de Casteljau (notes "Higher Order Surfaces", "midpoint
/// subdivision"): two separately written Bézier patches over [0, 1]^2 each.
Bicubic half_of(const Bicubic& b, bool right) {
  Bicubic h;
  for (int j = 0; j < 4; ++j) {
    const double p0 = b.z[0][j], p1 = b.z[1][j], p2 = b.z[2][j], p3 = b.z[3][j];
    const double q1 = (p0 + p1) / 2, m = (p1 + p2) / 2, r2 = (p2 + p3) / 2;
    const double q2 = (q1 + m) / 2, r1 = (m + r2) / 2, mid = (q2 + r1) / 2;
    const double left_z[4] = {p0, q1, q2, mid}, right_z[4] = {mid, r1, r2, p3};
    for (int i = 0; i < 4; ++i) h.z[i][j] = right ? right_z[i] : left_z[i];
  }
  return h;
}

TEST(TessellatePatches, SubdividedBezierHalvesWeldWithoutCracks) {
  // Two patches that agree on their shared edge only up to round-off (each has
  // its own control net; x runs 0..3 on both, so the join is C^1 in shape, and
  // the partials along the edge agree). The same tolerance picks the same edge samples; welding
  // (kWeldTolerance) merges the round-off apart vertices.
  const Bicubic b;
  const Bicubic l = half_of(b, false), r = half_of(b, true);
  // Place the right half next to the left one: x' = x + 3.
  const SurfaceEvaluator right = [r](double u, double v) {
    SurfaceSample s = r(u, v);
    s.point.x += 3;
    return s;
  };
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const Mesh m = tessellate_patches({{l, {0, 1, 0, 1}, {}}, {right, {0, 1, 0, 1}, {}}}, TessellationOptions::adaptive(tol));
    // Only the outer boundary: the 4 outer sides of the two patches.
    std::size_t inner = 0;
    for (const auto& e : boundary_edges(m)) {
      const Vec3 p = m.positions[e[0]], q = m.positions[e[1]];
      if (std::abs(p.x - 3) <= kWeldTolerance && std::abs(q.x - 3) <= kWeldTolerance) ++inner;
    }
    EXPECT_EQ(inner, 0u) << "tol " << tol;
    EXPECT_TRUE(consistently_oriented_manifold(m));
  }
}

// ---- contour_segments: iso-curves on a mesh (ch. 1 §1.7 "Iso-curves") ----------------

double segment_length(const std::array<Vec3, 2>& s) { return norm(s[1] - s[0]); }

// On the saddle z = xy the mesh's vertices lie on the surface; each contour
// point is linear in z along its edge, so its height is the level up to
// round-off, and the segments chain: every end is shared by two segments except
// the two ends of each open curve, which lie on the domain's boundary.
TEST(ContourSegments, SaddleContoursAreAtTheLevelAndChainIntoCurves) {
  const Mesh m = tessellate_surface(saddle, {-1, 1, -1, 1}, TessellationOptions::fixed_steps(10, 10));
  for (double level : {-0.5, -0.1, 0.3, 0.7}) {
    const auto segments = contour_segments(m, {0, 0, 1}, level);
    ASSERT_FALSE(segments.empty()) << level;
    std::map<std::array<double, 3>, int> ends;
    for (const auto& sg : segments)
      for (const Vec3& p : sg) {
        EXPECT_NEAR(p.z, level, kRoundOff) << level;
        ++ends[{p.x, p.y, p.z}];
      }
    int open_ends = 0;
    for (const auto& [p, count] : ends) {
      EXPECT_LE(count, 2) << level;
      if (count == 1) {
        ++open_ends;
        EXPECT_TRUE(std::fabs(p[0]) == 1 || std::fabs(p[1]) == 1) << "open end inside the domain at " << p[0] << ", " << p[1];
      }
    }
    EXPECT_EQ(open_ends, 4) << level;  // xy = c is a hyperbola: two branches across the square
  }
}

// A linear height field is reproduced exactly by any mesh: the contours of
// z = x + 2 y are the lines x + 2 y = c, cut to the square.
TEST(ContourSegments, LinearFieldGivesStraightLinesOfTheRightLength) {
  const auto tilted = [](double u, double v) {
    return SurfaceSample{{u, v, u + 2 * v}, normalized(Vec3{-1, -2, 1}), {1, 0, 1}, {0, 1, 2}};
  };
  const Mesh m = tessellate_surface(tilted, {-1, 1, -1, 1}, TessellationOptions::fixed_steps(7, 5));
  const double level = 0.5;
  double length = 0;
  for (const auto& sg : contour_segments(m, {0, 0, 1}, level)) {
    for (const Vec3& p : sg) EXPECT_NEAR(p.x + 2 * p.y, level, kRoundOff);
    length += segment_length(sg);
  }
  // x + 2y = 0.5 crosses the square from (-1, 0.75) to (1, -0.25): length sqrt(4 + 1).
  EXPECT_NEAR(length, std::sqrt(5.0), kRoundOff);
}

// A level through grid vertices (z = x at x = 0, a column of the 4 x 4 grid)
// is drawn once: no doubled and no zero-length segments.
TEST(ContourSegments, LevelThroughVerticesIsDrawnOnce) {
  const auto ramp = [](double u, double v) { return SurfaceSample{{u, v, u}, normalized(Vec3{-1, 0, 1}), {1, 0, 1}, {0, 1, 0}}; };
  const Mesh m = tessellate_surface(ramp, {-1, 1, -1, 1}, TessellationOptions::fixed_steps(4, 4));
  double length = 0;
  for (const auto& sg : contour_segments(m, {0, 0, 1}, 0)) {
    EXPECT_GT(segment_length(sg), 0);
    length += segment_length(sg);
  }
  EXPECT_NEAR(length, 2, kRoundOff);  // the line x = 0 from y = -1 to y = 1, once
  EXPECT_TRUE(contour_segments(m, {0, 0, 1}, 1.5).empty());  // above the mesh
}

TEST(ContourSegments, ErrorsNameTheDirectionAndLevel) {
  const Mesh m = tessellate_surface(plane, {0, 1, 0, 1}, TessellationOptions::fixed_steps(2, 2));
  EXPECT_THROW(contour_segments(m, {0, 0, 0}, 0), std::invalid_argument);
  try {
    contour_segments(m, {0, 0, 1}, std::nan(""));
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contour_segments: level=nan is not finite"), std::string::npos) << e.what();
  }
}

// ---- surface area and mesh fidelity ------------------------------------------------------

/// Radon's rule is exact for degree 5, so its error falls like h^6 with the
/// triangle size h. Measured, relative: 1.1e-12 for the sphere patch in 8 x 8
/// cells (7e-11 in 4 x 4, 3e-7 in one cell), 1.3e-12 between the bicubic's
/// meshes at tolerance 1e-3 and 1e-4 (5.8e-10 at 1e-2, whose cells are
/// larger). 1e-10 keeps a margin of 70 over both and is ten million times
/// below the 0.1 % that tells a mesh's area apart from the surface's.
constexpr double kQuadratureRelative = 1e-10;

using testing::error_of;

TEST(SurfaceArea, PlaneSquareIsOne) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.normals.assign(4, {0, 0, 1});
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_NEAR(surface_area(plane, m), 1.0, kRoundOff);
}

TEST(SurfaceArea, SpherePatchMatchesTheAnalyticArea) {
  // Area of R (cos v cos u, cos v sin u, sin v) over [0, a] x [0, b]:
  // integral of R^2 cos v du dv = R^2 a sin b. The flat triangles' own area
  // (mesh_area) is smaller: the quadrature does not measure them.
  const double R = 2, a = kPi / 2, b = kPi / 3;
  const double exact = R * R * a * std::sin(b);
  const Mesh m = tessellate_surface(sphere(R), {0, a, 0, b}, TessellationOptions::fixed_steps(8, 8));
  EXPECT_NEAR(surface_area(sphere(R), m) / exact, 1.0, kQuadratureRelative);
  EXPECT_LT(mesh_area(m) / exact, 1.0 - 1e-3);
}

TEST(SurfaceArea, SameRegionSameAreaWhateverTheTriangles) {
  // The trimmed region of a polyline trim is the same polygon at every
  // tolerance, so the quadrature agrees while the triangle counts differ.
  const Bicubic b;
  const std::vector<TrimLoop> trims{square_loop(0.1, 0.15, 0.9, 0.85, true), square_loop(0.4, 0.35, 0.65, 0.6, false)};
  const Mesh coarse = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::adaptive(1e-3), trims);
  const Mesh fine = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::adaptive(1e-4), trims);
  ASSERT_GT(fine.triangles.size(), 4 * coarse.triangles.size());
  EXPECT_NEAR(surface_area(b, coarse) / surface_area(b, fine), 1.0, kQuadratureRelative);
}

TEST(MeshFidelity, OwnTessellationIsWithinToleranceInsideAndAlongTrims) {
  // tessellate.h: trim edges are refined until their image is within the
  // tolerance, so the rim obeys it as well as the inside; no face tilts.
  const Bicubic b;
  const std::vector<TrimLoop> trims{square_loop(0.1, 0.15, 0.9, 0.85, true), square_loop(0.4, 0.35, 0.65, 0.6, false)};
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    const Mesh m = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::adaptive(tol), trims);
    const MeshFidelity f = mesh_fidelity(m, b, kSliverTiltDegrees);
    EXPECT_LE(f.max_deviation, tol + kRoundOff) << "tol " << tol;
    EXPECT_LE(f.max_trim_deviation, tol + kRoundOff) << "tol " << tol;
    EXPECT_GT(f.max_trim_deviation, 0) << "tol " << tol;  // the rim is measured at all
    EXPECT_EQ(f.tilted_faces, 0u) << "tol " << tol;
  }
}

TEST(MeshFidelity, UnrefinedTrimEdgesAndCoarseCellsMissTheTolerance) {
  // Fixed steps refine nothing (tessellate.h, as GLU_DOMAIN_DISTANCE): on 2 x 2
  // cells of the bicubic hill both the inside and the rim are far off
  // (measured 0.17 and 0.086); the two triangles of one cell are too flat for
  // the hill, one of them tilts by 22.8 degrees (measured).
  constexpr double kTol = 1e-3;
  const Bicubic b;
  const Mesh m = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::fixed_steps(2, 2),
                                    {square_loop(0.1, 0.15, 0.9, 0.85, true)});
  const MeshFidelity f = mesh_fidelity(m, b, kSliverTiltDegrees);
  EXPECT_GT(f.max_deviation, 10 * kTol);
  EXPECT_GT(f.max_trim_deviation, 10 * kTol);
  const Mesh one = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::fixed_steps(1, 1));
  EXPECT_EQ(mesh_fidelity(one, b, kSliverTiltDegrees).tilted_faces, 1u);
}

TEST(MeshFidelity, ReversedTriangleTiltsByAbout180Degrees) {
  const Bicubic b;
  Mesh m = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::adaptive(1e-3));
  ASSERT_EQ(mesh_fidelity(m, b, kSliverTiltDegrees).tilted_faces, 0u);
  std::swap(m.triangles[7][0], m.triangles[7][1]);
  const MeshFidelity f = mesh_fidelity(m, b, kSliverTiltDegrees);
  EXPECT_EQ(f.tilted_faces, 1u);
  EXPECT_EQ(f.tilted, std::vector<std::size_t>{7});
  EXPECT_GT(f.max_tilt_degrees, 179);
}

TEST(MeshFidelity, WeldingFindsTheRimOfAnUnweldedMesh) {
  // GLU sends every strip's vertices again: each triangle its own three
  // vertices here, so without welding every edge would count as rim.
  const Bicubic b;
  const Mesh m = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::fixed_steps(4, 4));
  Mesh loose;
  for (const auto& t : m.triangles) {
    const int first = static_cast<int>(loose.positions.size());
    for (int k : t) {
      loose.positions.push_back(m.positions[k]);
      loose.normals.push_back(m.normals[k]);
      loose.uv.push_back(m.uv[k]);
    }
    loose.triangles.push_back({first, first + 1, first + 2});
  }
  EXPECT_EQ(mesh_fidelity(loose, b, kSliverTiltDegrees).max_trim_deviation,
            mesh_fidelity(m, b, kSliverTiltDegrees).max_trim_deviation);
  EXPECT_ERROR_HAS(mesh_fidelity(loose, b, kSliverTiltDegrees, -1), "weld_tolerance=-1");
}

TEST(MeshFidelity, BadInputIsRejected) {
  const Bicubic b;
  Mesh m = tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::fixed_steps(1, 1));
  EXPECT_ERROR_HAS(mesh_fidelity(m, b, -1), "tilt_degrees=-1 must be in [0, 180]");
  EXPECT_ERROR_HAS(mesh_fidelity(m, b, 181), "tilt_degrees=181");
  m.triangles.push_back({0, 1, 99});
  EXPECT_ERROR_HAS(mesh_fidelity(m, b, 20), "triangle 2 uses vertex 99 of 4");
  EXPECT_ERROR_HAS(surface_area(b, m), "surface_area: triangle 2 uses vertex 99");
  m.triangles.pop_back();
  m.uv.pop_back();
  EXPECT_ERROR_HAS(surface_area(b, m), "the mesh has 3 (u, v) for 4 vertices");
}

// kMaxTrimPoints: a tolerance far below the surface's size would flatten and
// refine a curve trim into billions of points (issue 20: minutes, gigabytes).
// It is refused with one line naming the tolerance; the same trim at a real
// tolerance tessellates.
TEST(TessellateLimits, TrimPointsHaveALimit) {
  const Bicubic b;
  TrimPiece piece;
  piece.curve = circle({0.5, 0.5, 0}, 0.3);  // counter-clockwise: an outer loop
  const std::vector<TrimLoop> trims{TrimLoop{{piece}}};
  EXPECT_GT(tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::adaptive(1e-3), trims).triangles.size(), 0u);
  try {
    tessellate_surface(b, {0, 1, 0, 1}, TessellationOptions::adaptive(1e-300), trims);
    FAIL() << "tolerance 1e-300 accepted";
  } catch (const SplineError& e) {
    EXPECT_EQ(e.code(), ErrorCode::kOutOfRange);
    EXPECT_NE(std::string(e.what()).find("more than 1048576 points at tolerance=1e-300"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace gllab::spline
