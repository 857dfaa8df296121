// tests/gl/nurbs_suite.cpp — see nurbs_suite.h.
#include "nurbs_suite.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "io/spline_json.h"
#include "spline/bspline.h"
#include "spline/nurbs.h"
#include "spline/surface.h"

namespace gllab::testing {

using spline::BsplineCurve;
using spline::BsplineSurface;
using spline::TrimLoop;
using spline::TrimPiece;
using spline::Vec2;
using spline::Vec3;

namespace {

const std::filesystem::path kExamples = std::filesystem::path(GLLAB_SOURCE_DIR) / "examples";

BsplineCurve curve_of(int p, std::vector<double> U, std::vector<Vec3> P, std::vector<double> w = {},
                      int dimension = 3) {
  BsplineCurve c;
  c.p = p;
  c.U = std::move(U);
  c.P = std::move(P);
  c.w = std::move(w);
  c.dimension = dimension;
  return c;
}

/// A surface from a net given as rows along u: P[i][j].
BsplineSurface surface_of(int p, int q, std::vector<double> U, std::vector<double> V,
                          const std::vector<std::vector<Vec3>>& rows, const std::vector<std::vector<double>>& weights = {}) {
  BsplineSurface s;
  s.p = p;
  s.q = q;
  s.U = std::move(U);
  s.V = std::move(V);
  s.nu = static_cast<int>(rows.size());
  s.nv = static_cast<int>(rows.front().size());
  for (const auto& row : rows) s.P.insert(s.P.end(), row.begin(), row.end());
  for (const auto& row : weights) s.w.insert(s.w.end(), row.begin(), row.end());
  return s;
}

/// A smooth net over [0, nu-1] x [0, nv-1]: z = a bump, so normals vary.
std::vector<std::vector<Vec3>> bump_net(int nu, int nv, double height) {
  std::vector<std::vector<Vec3>> rows(static_cast<std::size_t>(nu));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double x = double(i) / (nu - 1), y = double(j) / (nv - 1);
      const double z = height * std::sin(3.0 * x + 0.5) * std::cos(2.5 * y - 0.7) + 0.3 * height * x * y;
      rows[static_cast<std::size_t>(i)].push_back({double(i), double(j) + 0.2 * std::sin(1.7 * i), z});
    }
  return rows;
}

TrimPiece polyline_piece(std::vector<Vec2> points) {
  TrimPiece piece;
  piece.polyline = std::move(points);
  return piece;
}

TrimPiece curve_piece(BsplineCurve curve) {
  TrimPiece piece;
  curve.dimension = 2;
  for (Vec3& q : curve.P) q.z = 0;
  piece.curve = std::move(curve);
  return piece;
}

TrimLoop loop_of(std::vector<TrimPiece> pieces) {
  TrimLoop loop;
  loop.pieces = std::move(pieces);
  return loop;
}

/// The profile curve of a surface of revolution: the 2D curve turned into
/// the xz-plane (x = distance from the axis, z = height; revolved_surface).
BsplineCurve in_xz_plane(BsplineCurve c) {
  for (Vec3& q : c.P) q = {q.x, 0, q.y};
  c.dimension = 3;
  return c;
}

}  // namespace

std::vector<Vec2> dense_loop(const std::vector<Vec2>& corners, int per_edge) {
  std::vector<Vec2> out;
  const std::size_t n = corners.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = corners[k], b = corners[(k + 1) % n];
    for (int s = 0; s < per_edge; ++s) {
      const double t = double(s) / per_edge;
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  out.push_back(corners.front());
  return out;
}

// ---- curves ----------------------------------------------------------------------

std::vector<CurveCase> curve_suite() {
  std::vector<CurveCase> s;
  s.push_back({"line_p1_2d", "degree 1, clamped, 2D: the control polygon itself",
               curve_of(1, {0, 0, 1, 2, 3, 4, 4}, {{0, 0, 0}, {1, 2, 0}, {2, 0.5, 0}, {3, 2.5, 0}, {4, 1, 0}}, {}, 2)});
  s.push_back({"quadratic_clamped_2d", "degree 2, clamped uniform knots, 2D",
               spline::clamped_curve({{0, 0, 0}, {1, 3, 0}, {3, 3.5, 0}, {4, 0.5, 0}, {6, 1, 0}, {7, 3, 0}}, 2, 2)});
  s.push_back({"cubic_clamped_3d", "degree 3, clamped, 3D: examples/cubic_bspline_curve.json",
               io::read_curve(kExamples / "cubic_bspline_curve.json")});
  s.push_back({"cubic_unclamped_2d", "degree 3, unclamped uniform knots 0..10 (domain [3, 7]), 2D",
               curve_of(3, spline::uniform_knots(6, 3),
                        {{0, 0, 0}, {1, 2, 0}, {2.5, 2.5, 0}, {4, 0, 0}, {5.5, -1, 0}, {6.5, 1.5, 0}, {8, 2, 0}}, {}, 2)});
  s.push_back({"cubic_periodic_2d", "degree 3, periodic (closed, C2 where it closes): spline::periodic_curve, 2D",
               spline::periodic_curve({{2, 0, 0}, {1.2, 1.6, 0}, {-0.6, 1.4, 0}, {-2, 0.2, 0}, {-1, -1.5, 0}, {1, -1.2, 0}},
                                      3, 2)});
  s.push_back({"quartic_clamped_3d", "degree 4, clamped, non-uniform interior knots, 3D",
               curve_of(4, {0, 0, 0, 0, 0, 0.15, 0.4, 0.8, 1, 1, 1, 1, 1},
                        {{0, 0, 0}, {1, 2, 1}, {2, 3, -1}, {3.5, 1, 0}, {4, -1, 2}, {5, 0, 1}, {6, 2, 0}, {7, 1, -1}})});
  s.push_back({"quintic_clamped_3d", "degree 5, clamped uniform knots, 3D",
               spline::clamped_curve({{0, 0, 0}, {1, 1, 2}, {2, 3, 1}, {3, 2, -1}, {4, 0, 0}, {5, -1, 1}, {6, 1, 2},
                                      {7, 2, 0}, {8, 0, -1}},
                                     5)});
  s.push_back({"cubic_multiplicity_p_2d", "degree 3, interior knot 0.5 of multiplicity p = 3: a corner (C0), 2D",
               curve_of(3, {0, 0, 0, 0, 0.25, 0.5, 0.5, 0.5, 0.75, 1, 1, 1, 1},
                        {{0, 0, 0}, {1, 2, 0}, {2, 2.5, 0}, {3, 1, 0}, {4, 3, 0}, {5, 2, 0}, {6, 0, 0}, {7, 1, 0},
                         {8, 2.5, 0}},
                        {}, 2)});
  s.push_back({"quadratic_break_multiplicity_p_plus_1_2d",
               "degree 2, interior knot 0.5 of multiplicity p + 1 = 3: two separate pieces (a jump), 2D",
               curve_of(2, {0, 0, 0, 0.25, 0.5, 0.5, 0.5, 0.75, 1, 1, 1},
                        {{0, 0, 0}, {1, 2, 0}, {2, 1, 0}, {3, 2.5, 0}, {3.5, 0, 0}, {4.5, 1, 0}, {5.5, 2.5, 0},
                         {6.5, 0.5, 0}},
                        {}, 2)});
  s.push_back({"nurbs_circle_2d", "the exact circle (The NURBS Book Ex. 7.2): rational, degree 2, 9 points, 2D",
               spline::circle({1, 2, 0}, 1.5)});
  {
    // The lecture's conic by r (ch. 1 §1.6): r = 0.3, an ellipse arc, in a tilted plane.
    BsplineCurve conic = spline::conic_arc({0, 0, 0}, {2, 3, 1}, {4, 0, 2}, 0.3);
    s.push_back({"rational_conic_3d", "rational quadratic conic arc, r = 0.3 (ellipse, ch. 1 §1.6), 3D", conic});
  }
  s.push_back({"rational_cubic_unclamped_3d", "degree 3, unclamped uniform knots, weights 0.5 to 3, 3D",
               curve_of(3, spline::uniform_knots(6, 3),
                        {{0, 0, 0}, {1, 2, 1}, {2, 3, -1}, {3, 0, 0}, {4, -1, 2}, {5, 1, 1}, {6, 2, 0}},
                        {1, 0.5, 3, 1, 2, 0.7, 1})});
  s.push_back({"closed_square_p1_3d", "degree 1, closed (first point = last), a skew square in 3D",
               curve_of(1, {0, 0, 1, 2, 3, 4, 4}, {{0, 0, 0}, {2, 0, 1}, {2, 2, 0}, {0, 2, 1}, {0, 0, 0}})});
  s.push_back({"rational_quartic_3d", "degree 4, clamped, rational (weights 0.4 to 2.5), 3D",
               curve_of(4, {0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3},
                        {{0, 0, 0}, {1, 3, 0}, {3, 3, 2}, {4, 0, 1}, {6, -1, 0}, {7, 2, 1}, {8, 3, 0}},
                        {1, 2.5, 0.4, 1.5, 0.8, 2, 1})});
  return s;
}

// ---- surfaces -----------------------------------------------------------------------

std::vector<SurfaceCase> surface_suite() {
  std::vector<SurfaceCase> s;
  s.push_back({"bilinear_flat_2d", "degrees 1 x 1, clamped, flat in z = 0 (a 2D patch): normals all +z",
               surface_of(1, 1, {0, 0, 0.4, 1, 1}, {0, 0, 1, 1},
                          {{{0, 0, 0}, {0.2, 2, 0}}, {{1.5, -0.3, 0}, {1.2, 1.8, 0}}, {{3, 0.2, 0}, {3.2, 2.2, 0}}})});
  s.push_back({"biquadratic_clamped", "degrees 2 x 2, clamped uniform knots, 4 x 4 points",
               surface_of(2, 2, spline::clamped_uniform_knots(3, 2), spline::clamped_uniform_knots(3, 2),
                          bump_net(4, 4, 1.0))});
  s.push_back({"bicubic_hill", "degrees 3 x 3, clamped, 5 x 5: examples/bicubic_surface.json",
               io::read_surface(kExamples / "bicubic_surface.json")});
  s.push_back({"bicubic_unclamped", "degrees 3 x 3, unclamped uniform knots both ways (domain [3, 6] x [3, 6])",
               surface_of(3, 3, spline::uniform_knots(5, 3), spline::uniform_knots(5, 3), bump_net(6, 6, 1.5))});
  s.push_back({"degrees_1x3", "degree 1 along u, 3 along v: a ruled, piecewise flat surface",
               surface_of(1, 3, spline::clamped_uniform_knots(3, 1), spline::clamped_uniform_knots(4, 3),
                          bump_net(4, 5, 1.0))});
  s.push_back({"degrees_5x4", "degree 5 along u, 4 along v, 7 x 6 points, clamped",
               surface_of(5, 4, spline::clamped_uniform_knots(6, 5), spline::clamped_uniform_knots(5, 4),
                          bump_net(7, 6, 1.2))});
  s.push_back({"bicubic_multiplicity_p", "degrees 3 x 3, U knot 0.5 of multiplicity p = 3: a crease (C0) along v",
               surface_of(3, 3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1}, spline::clamped_uniform_knots(4, 3),
                          bump_net(7, 5, 1.0))});
  {
    // Multiplicity p + 1 = 3 at u = 0.5 splits the net in two: rows 0..3 make
    // u < 0.5, rows 4..7 u > 0.5, and the left limit at 0.5 is row 3, the
    // right one row 4. Rows 3 and 4 coincide, so the halves meet in a crease.
    auto rows = bump_net(8, 4, 1.0);
    rows[4] = rows[3];
    s.push_back({"biquadratic_multiplicity_p_plus_1",
                 "degrees 2 x 2, U knot 0.5 of multiplicity p + 1 = 3, rows 3 and 4 equal: two patches meeting in a crease",
                 surface_of(2, 2, {0, 0, 0, 0.25, 0.5, 0.5, 0.5, 0.75, 1, 1, 1}, spline::clamped_uniform_knots(3, 2),
                            rows)});
  }
  {
    // A circle of radius 0.7 around (2, 0) in the xz-plane, revolved: rational both ways.
    const BsplineCurve profile = in_xz_plane(spline::circle({2, 0, 0}, 0.7));
    s.push_back({"nurbs_torus", "torus: the NURBS circle revolved (A8.1, The NURBS Book), rational, closed both ways",
                 spline::revolved_surface(profile)});
  }
  {
    const BsplineCurve profile =
        spline::clamped_curve({{1, 0, 0}, {1.6, 0, 0.5}, {0.6, 0, 1.2}, {0.8, 0, 2}, {1.3, 0, 2.5}}, 3);
    s.push_back({"nurbs_vase", "a cubic profile revolved (A8.1): rational along v only, no pole",
                 spline::revolved_surface(profile)});
  }
  {
    // A tube: clamped cubic along u (the axis), periodic cubic along v (8
    // points around, the first 3 repeated: the closed B-spline of the notes "B-Spline Polynomials").
    std::vector<std::vector<Vec3>> rows;
    const int around = 8;
    for (int i = 0; i < 5; ++i) {
      std::vector<Vec3> row;
      const double radius = 1.0 + 0.3 * std::sin(1.3 * i);
      for (int j = 0; j < around + 3; ++j) {
        const double a = 2 * 3.14159265358979323846 * (j % around) / around;
        row.push_back({radius * std::cos(a), radius * std::sin(a), 1.0 * i});
      }
      rows.push_back(row);
    }
    s.push_back({"periodic_tube", "clamped cubic along u, periodic cubic along v (closed, C2): a tube",
                 surface_of(3, 3, spline::clamped_uniform_knots(4, 3), spline::uniform_knots(around + 2, 3), rows)});
  }
  {
    BsplineSurface hill = io::read_surface(kExamples / "bicubic_surface.json");
    hill.trims = {loop_of({polyline_piece(dense_loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 16))}),
                  // An L-shaped hole, clockwise.
                  loop_of({polyline_piece(
                      dense_loop({{0.25, 0.25}, {0.25, 0.75}, {0.5, 0.75}, {0.5, 0.5}, {0.75, 0.5}, {0.75, 0.25}}, 8))})};
    s.push_back({"trimmed_polyline_hole", "the hill with an L-shaped polyline hole (clockwise) in a polyline square",
                 hill});
  }
  {
    BsplineSurface patch = coarse_trim_example().surface;
    patch.trims[0] = loop_of({polyline_piece(dense_loop({{0.05, 0.05}, {0.95, 0.05}, {0.95, 0.95}, {0.05, 0.95}}, 16))});
    s.push_back({"trimmed_nurbs_circle_hole",
                 "examples/trimmed_nurbs_surface.json (rational patch, NURBS circle hole), its 5-point outer loop "
                 "densified",
                 patch});
  }
  {
    BsplineSurface hill = io::read_surface(kExamples / "bicubic_surface.json");
    // A hole of three pieces, clockwise: bottom edge leftwards, left edge
    // upwards (polylines), then a rational conic arc (r = 0.4) back through
    // the upper right.
    BsplineCurve arc = spline::conic_arc({0.3, 0.7, 0}, {0.75, 0.75, 0}, {0.7, 0.3, 0}, 0.4);
    hill.trims = {loop_of({polyline_piece(dense_loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 16))}),
                  loop_of({polyline_piece({{0.7, 0.3}, {0.6, 0.3}, {0.5, 0.3}, {0.4, 0.3}, {0.3, 0.3}}),
                           polyline_piece({{0.3, 0.3}, {0.3, 0.4}, {0.3, 0.5}, {0.3, 0.6}, {0.3, 0.7}}),
                           curve_piece(arc)})};
    s.push_back({"trimmed_hole_of_pieces", "a hole of three pieces: two polylines and a rational conic arc", hill});
  }
  {
    BsplineSurface hill = io::read_surface(kExamples / "bicubic_surface.json");
    // Outer square, a circle hole (clockwise: the circle reversed), and in
    // it a diamond island (counter-clockwise again).
    hill.trims = {loop_of({polyline_piece(dense_loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 16))}),
                  loop_of({curve_piece(spline::reversed(spline::circle({0.5, 0.5, 0}, 0.35)))}),
                  loop_of({polyline_piece(dense_loop({{0.5, 0.35}, {0.65, 0.5}, {0.5, 0.65}, {0.35, 0.5}}, 6))})};
    s.push_back({"trimmed_island_in_hole", "nested loops: a NURBS circle hole with a polyline island in it", hill});
  }
  {
    BsplineSurface patch = io::read_surface(kExamples / "trimmed_nurbs_surface.json");
    // A NURBS circle as the outer loop (rational: GLU_MAP1_TRIM_3) and a
    // triangle hole.
    patch.trims = {loop_of({curve_piece(spline::circle({0.5, 0.5, 0}, 0.45))}),
                   loop_of({polyline_piece(dense_loop({{0.4, 0.4}, {0.5, 0.62}, {0.62, 0.4}}, 8))})};
    s.push_back({"trimmed_nurbs_outer_disk", "rational patch cut to a disk by a NURBS circle, with a triangle hole",
                 patch});
  }
  return s;
}

SurfaceCase coarse_trim_example() {
  return {"trimmed_example_coarse_outer_loop",
          "examples/trimmed_nurbs_surface.json as it is: its outer loop is a 5-point polyline",
          io::read_surface(kExamples / "trimmed_nurbs_surface.json")};
}

// ---- bad inputs ---------------------------------------------------------------

std::vector<BadCurve> bad_curves() {
  const BsplineCurve good = spline::clamped_curve({{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}}, 3);
  std::vector<BadCurve> out;
  auto with = [&](std::string name, auto change, std::string message) {
    BsplineCurve c = good;
    change(c);
    out.push_back({std::move(name), c, std::move(message)});
  };
  with("decreasing_knots", [](BsplineCurve& c) { c.U = {0, 0, 0, 0, 0.8, 0.2, 1, 1, 1}; },
       "knot vector: U[5]=0.2 < U[4]=0.8 (must be non-decreasing)");
  with("too_few_knots_for_order", [](BsplineCurve& c) { c.P.resize(3); c.U = {0, 0, 0, 0, 1, 1, 1}; },
       "degree p=3 needs at least p + 1 = 4 control points, has 3");
  with("end_knot_multiplicity_above_order", [](BsplineCurve& c) { c.U = {0, 0, 0, 0, 0, 1, 1, 1, 1}; },
       "knot 0 has multiplicity 5 (U[0..4]), more than p + 1 = 4");
  with("interior_knot_multiplicity_above_order", [](BsplineCurve& c) { c.U = {0, 0.5, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}; },
       "knot 0.5 has multiplicity 5 (U[1..5]), more than p + 1 = 4");
  with("empty_domain", [](BsplineCurve& c) { c.U = {0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1}; },
       "the domain [U[3], U[5]] = [0.5, 0.5] is empty");
  with("order_33_above_both_limits",
       [](BsplineCurve& c) {
         c.p = 32;
         c.P.clear();
         for (int i = 0; i < 33; ++i) c.P.push_back({double(i), double(i % 3), 0});
         c.U = spline::clamped_uniform_knots(32, 32);
       },
       "degree p=32 exceeds kMaxDegree=31");
  with("order_25_above_glu_limit_only",
       [](BsplineCurve& c) {
         c.p = 24;
         c.P.clear();
         for (int i = 0; i < 25; ++i) c.P.push_back({double(i), double(i % 3), 0});
         c.U = spline::clamped_uniform_knots(24, 24);
       },
       "");  // the core accepts degree <= kMaxDegree = 31; GLU stops at order 24
  with("one_knot_short", [](BsplineCurve& c) { c.U = {0, 0, 0, 0, 0.5, 1, 1, 1}; },
       "knot vector has 8 knots, needs n + p + 2 = 9 (5 points, degree 3)");
  with("degree_zero", [](BsplineCurve& c) { c.p = 0; c.U = {0, 0.25, 0.5, 0.75, 1}; }, "degree p=0 must be >= 1");
  with("weight_zero", [](BsplineCurve& c) { c.w = {1, 1, 0, 1, 1}; }, "weights: w[2]=0 must be > 0");
  with("weight_negative", [](BsplineCurve& c) { c.w = {1, 1, -1, 1, 1}; }, "weights: w[2]=-1 must be > 0");
  with("no_control_points", [](BsplineCurve& c) { c.P.clear(); c.U = {0, 0, 0, 0}; }, "no control points");
  return out;
}

std::vector<BadSurface> bad_surfaces() {
  const BsplineSurface good = io::read_surface(kExamples / "bicubic_surface.json");  // domain [0, 1]^2
  std::vector<BadSurface> out;
  auto with = [&](std::string name, auto change, std::string message) {
    BsplineSurface s = good;
    change(s);
    out.push_back({std::move(name), s, std::move(message)});
  };
  const auto square = [](double a, double b) { return dense_loop({{a, a}, {b, a}, {b, b}, {a, b}}, 4); };
  const auto reversed = [](std::vector<Vec2> v) { return std::vector<Vec2>(v.rbegin(), v.rend()); };
  with("decreasing_u_knots", [](BsplineSurface& s) { s.U = {0, 0, 0, 0, 0.7, 0.3, 1, 1, 1}; },
       "U knot vector: U[5]=0.3 < U[4]=0.7 (must be non-decreasing)");
  with("decreasing_v_knots", [](BsplineSurface& s) { s.V = {0, 0, 0, 0, 0.7, 0.3, 1, 1, 1}; },
       "V knot vector: V[5]=0.3 < V[4]=0.7 (must be non-decreasing)");
  with("u_knot_multiplicity_above_order", [](BsplineSurface& s) { s.U = {0, 0, 0, 0, 0, 1, 1, 1, 1}; },
       "knot 0 has multiplicity 5 (U[0..4]), more than p + 1 = 4");
  with("u_one_knot_short", [](BsplineSurface& s) { s.U = {0, 0, 0, 0, 1, 1, 1, 1}; },
       "U knot vector has 8 knots, needs n + p + 2 = 9 (5 points, degree 3)");
  with("weight_negative",
       [](BsplineSurface& s) {
         s.w.assign(s.P.size(), 1.0);
         s.w[7] = -0.5;
       },
       "weight w(1, 2)=-0.5 must be > 0");
  with("outer_loop_clockwise", [&](BsplineSurface& s) { s.trims = {loop_of({polyline_piece(reversed(square(0.1, 0.9)))})}; },
       "trim loop 0 (outer) runs clockwise");
  with("hole_counter_clockwise",
       [&](BsplineSurface& s) {
         s.trims = {loop_of({polyline_piece(square(0.1, 0.9))}), loop_of({polyline_piece(square(0.3, 0.7))})};
       },
       "trim loop 1 (hole in loop 0) runs counter-clockwise");
  with("loops_cross",
       [&](BsplineSurface& s) {
         s.trims = {loop_of({polyline_piece(square(0.1, 0.9))}),
                    loop_of({polyline_piece(reversed(square(0.5, 0.95)))})};
       },
       "crosses edge");
  with("loop_crosses_itself",
       [&](BsplineSurface& s) {
         s.trims = {loop_of({polyline_piece({{0.1, 0.1}, {0.9, 0.9}, {0.9, 0.1}, {0.1, 0.9}, {0.1, 0.1}})})};
       },
       "crosses edge");
  with("trim_outside_domain",
       [&](BsplineSurface& s) { s.trims = {loop_of({polyline_piece(dense_loop({{-0.5, 0}, {1, 0}, {1, 1}, {0, 1}}, 4))})}; },
       "lies outside the domain [0, 1] x [0, 1]");
  with("trim_loop_without_pieces", [&](BsplineSurface& s) { s.trims = {TrimLoop{}}; }, "trim loop 0: has no pieces");
  with("trim_loop_not_closed",
       [&](BsplineSurface& s) {
         s.trims = {loop_of({polyline_piece({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}, {0.1, 0.2}})})};
       },
       "trim loop 0: not closed: piece 0 ends at (0.1, 0.2), piece 0 starts at (0.1, 0.1)");
  with("trim_curve_decreasing_knots",
       [&](BsplineSurface& s) {
         BsplineCurve c = spline::circle({0.5, 0.5, 0}, 0.3);
         c.U[4] = 0.1;  // 0, 0, 0, 0.25, 0.1, ...
         s.trims = {loop_of({curve_piece(c)})};
       },
       "trim loop 0: piece 0 (curve): knot vector: U[4]=0.1 < U[3]=0.25 (must be non-decreasing)");
  return out;
}

const CurveCase& curve_case(const std::vector<CurveCase>& suite, const std::string& name) {
  for (const CurveCase& c : suite)
    if (c.name == name) return c;
  throw std::out_of_range("no curve case named '" + name + "'");
}

const SurfaceCase& surface_case(const std::vector<SurfaceCase>& suite, const std::string& name) {
  for (const SurfaceCase& c : suite)
    if (c.name == name) return c;
  throw std::out_of_range("no surface case named '" + name + "'");
}

}  // namespace gllab::testing
