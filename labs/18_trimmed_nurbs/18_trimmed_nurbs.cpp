// lab 18 · trimmed NURBS surfaces                               difficulty: ★★★★
// The Red Book's hill (surface.c, trim.c) trimmed by gluBeginTrim/gluEndTrim
// (seed 000 §1.7 "Trimming"): an outer boundary that is a NURBS curve
// (GLU_MAP1_TRIM_2), a hole cut by an exact NURBS circle (GLU_MAP1_TRIM_3), a
// hole made of a Bézier curve and a gluPwlCurve (as in trim.c), and a hole
// with an island in it. Beside GLU, the own core's trimmed tessellation.
// Notice: GLU keeps what lies left of every trim curve: the outer loop and the
//   island run counter-clockwise, the holes clockwise. GLU does not refine the
//   edges of a gluPwlCurve: a coarse square gets slivers fanned from its
//   corners across the surface (view slivers), 5-30 % too much area.
// Try: in slivers press [E] until the polyline is coarse again: when do the
//   slivers come back? Look at reversed_outer_loop: which error does GLU
//   raise, and which loop does the own core name?
// Keys: [t]/[T] finer/coarser  [s]/[S] GLU steps  [e]/[E] polyline points
//   [h] help  [Esc] quit
// Views: default, own_vs_glu, slivers, reversed_outer_loop (an error view)
// Reference: reference_images/18_trimmed_nurbs__*.png

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/nurbs_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/nurbs.h"
#include "spline/surface.h"
#include "spline/trim.h"

namespace {

namespace spline = gllab::spline;
using gllab::fmt;
using gllab::Panel;
using gllab::State;
using spline::BsplineSurface;
using spline::Vec2;
using spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The hill: 4 x 4 control points (i - 1.5, j - 1.5) x 2, the middle four up
// at z = 3, the rest at z = -3; one bicubic Bézier patch over [0, 1]^2.
const std::vector<Vec3> kHill = {{-3, -3, -3}, {-3, -1, -3}, {-3, 1, -3}, {-3, 3, -3},
                                 {-1, -3, -3}, {-1, -1, 3},  {-1, 1, 3},  {-1, 3, -3},
                                 {1, -3, -3},  {1, -1, 3},   {1, 1, 3},   {1, 3, -3},
                                 {3, -3, -3},  {3, -1, -3},  {3, 1, -3},  {3, 3, -3}};
// Trim loops in (u, v). The outer boundary, counter-clockwise: the control
// points of a closed quadratic B-spline, a square with rounded corners.
const std::vector<Vec3> kOuter = {{0.5, 0.03, 0},  {0.97, 0.03, 0}, {0.97, 0.5, 0},  {0.97, 0.97, 0}, {0.5, 0.97, 0},
                                  {0.03, 0.97, 0}, {0.03, 0.5, 0},  {0.03, 0.03, 0}, {0.5, 0.03, 0}};
// trim.c's hole, half size: a cubic Bézier over the top, clockwise, and a
// polyline back under it.
const std::vector<Vec3> kArch = {{0.61, 0.7, 0}, {0.61, 0.81, 0}, {0.83, 0.81, 0}, {0.83, 0.7, 0}};
const std::vector<Vec2> kArchBase = {{0.83, 0.7}, {0.72, 0.59}, {0.61, 0.7}};
// A rectangular hole (clockwise) and the island in it.
const std::vector<Vec2> kRectangle = {{0.15, 0.12}, {0.15, 0.45}, {0.85, 0.45}, {0.85, 0.12}, {0.15, 0.12}};
// slivers: a 5-point square (counter-clockwise), as coarse as trim.c's.
const std::vector<Vec2> kSquare = {{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}, {0.1, 0.1}};
constexpr double kTiltDegrees = 20;  // a face this far from the surface's normal is a sliver
const gllab::Rgb kGlu{0.95f, 0.6f, 0.25f}, kOwn{0.35f, 0.65f, 0.95f}, kWire{0.1f, 0.1f, 0.1f},
    kText{1.f, 1.f, 1.f}, kPwl{1.f, 1.f, 1.f}, kTrim2{0.4f, 0.9f, 0.4f}, kTrim3{0.45f, 0.7f, 1.f},
    kSliver{1.f, 0.25f, 0.25f}, kDim{0.25f, 0.26f, 0.3f};

// The polyline with `per_edge` points on each edge: what GLU needs.
std::vector<Vec2> densified(const std::vector<Vec2>& p, int per_edge) {
  std::vector<Vec2> out;
  for (std::size_t k = 0; k + 1 < p.size(); ++k)
    for (int i = 0; i < per_edge; ++i) out.push_back(p[k] + (double(i) / per_edge) * (p[k + 1] - p[k]));
  out.push_back(p.back());
  return out;
}

spline::TrimPiece pwl(std::vector<Vec2> p) { return {std::move(p), std::nullopt}; }
spline::TrimPiece curve(spline::BsplineCurve c) { return {{}, std::move(c)}; }

// The loops of a view: GLU gets them in this order, each between
// gluBeginTrim and gluEndTrim, each piece as gluPwlCurve or gluNurbsCurve.
std::vector<spline::TrimLoop> trims_of(const State& s, const std::string& view, bool dense = true) {
  const int n = s.integer("per_edge");
  if (view == "slivers") return {{{pwl(dense ? densified(kSquare, n) : kSquare)}}};
  const spline::BsplineCurve outer = spline::clamped_curve(kOuter, 2, 2);  // GLU_MAP1_TRIM_2
  return {{{curve(view == "reversed_outer_loop" ? spline::reversed(outer) : outer)}},
          {{curve(spline::reversed(spline::circle({0.27, 0.7, 0}, 0.13)))}},  // TRIM_3, clockwise
          {{curve(spline::clamped_curve(kArch, 3, 2)), pwl(densified(kArchBase, n))}},
          {{pwl(densified(kRectangle, n))}},
          {{curve(spline::circle({0.5, 0.285, 0}, 0.1))}}};  // the island: counter-clockwise
}

BsplineSurface surface_of(const State& s, std::vector<spline::TrimLoop> trims) {
  const std::vector<double> U = {0, 0, 0, 0, 1, 1, 1, 1};
  return {3, 3, U, U, 4, 4, s.points("P"), {}, std::move(trims)};
}

// Drawing -------------------------------------------------------------------
// One panel's camera: the hill seen from above, u to the right, v up, tilted
// 30° so that its height shows; `extent` units from the centre to the edge.
void camera(const Panel& p, double extent = 3.4) {
  gllab::ortho_fit(p.width, p.height, extent, extent, 20);
  gllab::enable_headlight();
  glTranslated(0, 0.12 * extent, 0);  // up a little: the numbers go below
  glRotatef(-30.f, 1.f, 0.f, 0.f);
}

void caption(const Panel& p, int l, const std::string& t, gllab::Rgb c = kText) { draw_panel_caption(p, l, t, c); }

double finer(const State& s) { return std::pow(2.0, s.get("finer")); }

gllab::GluNurbsProperties glu_sampling(const State& s) {
  gllab::GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;
  p.u_step = p.v_step = float(s.get("steps") * finer(s));
  return p;
}

spline::Mesh own_mesh(const BsplineSurface& S, const State& s) {
  const auto options = spline::TessellationOptions::adaptive(s.get("tol") / finer(s));
  return spline::tessellate_surface(spline::surface_evaluator(S), spline::uv_domain(S), options, S.trims);
}

void uv_camera(const Panel& p) {  // the (u, v) square [0, 1]^2 in the middle of the panel
  gllab::ortho_fit(p.width, p.height, 0.62, 0.62);
  glTranslated(-0.5, -0.5, 0);
}

// The (u, v) square with the loops: gluPwlCurve white, GLU_MAP1_TRIM_2 green,
// GLU_MAP1_TRIM_3 blue, an arrowhead where each piece ends.
void draw_loops(const Panel& p, const std::vector<spline::TrimLoop>& trims) {
  uv_camera(p);
  gllab::draw_polyline({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0.5f, 0.5f, 0.55f}, 1.f, true);
  for (const spline::TrimLoop& loop : trims)
    for (const spline::TrimPiece& piece : loop.pieces) {
      std::vector<Vec3> line;
      for (Vec2 q : piece.polyline) line.push_back({q.x, q.y, 0});
      const gllab::Rgb c = !piece.curve ? kPwl : piece.curve->rational() ? kTrim3 : kTrim2;
      if (piece.curve) {
        gllab::draw_curve(*piece.curve, c);
        const auto [a, b] = spline::domain(*piece.curve);  // the arrow on its last 2 %
        line = {spline::curve_point(*piece.curve, b - 0.02 * (b - a)), spline::curve_point(*piece.curve, b)};
      } else {
        gllab::draw_polyline(line, c);
      }
      const Vec3 tip = line.back(), d = 0.03 * normalized(tip - line[line.size() - 2]), n{-d.y, d.x, 0};
      gllab::draw_polyline({tip - d + 0.6 * n, tip, tip - d - 0.6 * n}, c, 2.f);
    }
}

void draw_glu(const BsplineSurface& S, const gllab::GluNurbsProperties& props, bool edges) {
  glColor3f(kGlu.r, kGlu.g, kGlu.b);
  gllab::draw_glu_surface(S, props, "trimmed hill", edges ? std::optional(kWire) : std::nullopt);
}

void draw_default(const State& s) {
  const std::vector<spline::TrimLoop> trims = trims_of(s, s.view());
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  draw_loops(left, trims);
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(right);
  const BsplineSurface S = surface_of(s, trims);
  draw_glu(S, glu_sampling(s), false);
  gllab::draw_control_points(s, "P", {0.9f, 0.9f, 0.5f}, 7.f);
  const std::size_t n = gllab::glu_triangle_count(S, glu_sampling(s), "trimmed hill");
  gllab::leave_panels(s.width, s.height);
  caption(left, 0, "the 5 trim loops in (u, v)");
  caption(left, 1, "counter-clockwise: outer, island");
  caption(left, 2, "clockwise: the three holes");
  caption(left, -3, "gluPwlCurve", kPwl);
  caption(left, -2, "gluNurbsCurve GLU_MAP1_TRIM_2", kTrim2);
  caption(left, -1, "gluNurbsCurve GLU_MAP1_TRIM_3", kTrim3);
  caption(right, 0, "gluNurbsSurface, trimmed");
  caption(right, -2, fmt("GLU_DOMAIN_DISTANCE %g steps", glu_sampling(s).u_step));
  caption(right, -1, std::to_string(n) + " triangles");
}

void draw_own_vs_glu(const State& s) {
  const BsplineSurface S = surface_of(s, trims_of(s, "default"));
  const auto surface = spline::surface_evaluator(S);
  const spline::Mesh own = own_mesh(S, s);
  const spline::Mesh glu = gllab::GluNurbs(glu_sampling(s)).capture_surface(S, "trimmed hill").mesh;
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  camera(left);
  draw_glu(S, glu_sampling(s), true);
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(right);
  glColor3f(kOwn.r, kOwn.g, kOwn.b);
  gllab::draw_mesh_with_edges(own, kWire);
  gllab::leave_panels(s.width, s.height);
  const auto fg = spline::mesh_fidelity(glu, surface, kTiltDegrees);
  const auto fo = spline::mesh_fidelity(own, surface, kTiltDegrees);
  caption(left, 0, fmt("GLU_DOMAIN_DISTANCE %g steps", glu_sampling(s).u_step));
  caption(left, -3, std::to_string(glu.triangles.size()) + " triangles");
  caption(left, -2, "max deviation " + fmt("%.2e", fg.max_deviation));
  caption(left, -1, "along trims " + fmt("%.2e", fg.max_trim_deviation));
  caption(right, 0, "own core, tolerance " + fmt("%g", s.get("tol") / finer(s)));
  caption(right, -3, std::to_string(own.triangles.size()) + " triangles");
  caption(right, -2, "max deviation " + fmt("%.2e", fo.max_deviation));
  caption(right, -1, "along trims " + fmt("%.2e", fo.max_trim_deviation));
}

// GLU fed the coarse square and the dense one, the own core, and GLU's coarse
// triangles in (u, v): the fans from the corners. The numbers measure each
// mesh against the true trimmed surface (tessellate.h: surface_area, mesh_fidelity).
void draw_slivers(const State& s) {
  const BsplineSurface coarse = surface_of(s, trims_of(s, "slivers", false));
  const BsplineSurface dense = surface_of(s, trims_of(s, "slivers", true));
  const auto surface = spline::surface_evaluator(coarse);
  const spline::Mesh own = own_mesh(coarse, s);
  const double area = spline::surface_area(surface, own);  // over the own (u, v) triangles
  const spline::Mesh meshes[3] = {gllab::GluNurbs(glu_sampling(s)).capture_surface(coarse, "5-point square").mesh,
                          gllab::GluNurbs(glu_sampling(s)).capture_surface(dense, "dense square").mesh, own};
  const char* titles[3] = {"GLU, 5-point gluPwlCurve", "GLU, densified polyline", "own core"};
  glShadeModel(GL_FLAT);  // every triangle shows
  for (int k = 0; k < 3; ++k) {
    const Panel p = gllab::enter_panel(k % 2, k / 2, 2, 2, s.width, s.height);
    camera(p, 5.2);
    const spline::MeshFidelity f = spline::mesh_fidelity(meshes[k], surface, kTiltDegrees);
    if (k < 2) draw_glu(k == 0 ? coarse : dense, glu_sampling(s), true);
    else glColor3f(kOwn.r, kOwn.g, kOwn.b), gllab::draw_mesh(own);  // flat shading shows its triangles
    gllab::draw_mesh_faces(meshes[k], f.tilted, kSliver, 2.f);
    caption(p, 0, titles[k]);
    caption(p, -3, "area " + fmt("%+.2f %%", 100 * (spline::mesh_area(meshes[k]) - area) / area));
    caption(p, -2, "faces tilted > 20°: " + std::to_string(f.tilted_faces), f.tilted_faces ? kSliver : kText);
    caption(p, -1, "along trims " + fmt("%.2e", f.max_trim_deviation));
  }
  const Panel p = gllab::enter_panel(1, 1, 2, 2, s.width, s.height);
  spline::Mesh flat = meshes[0];  // GLU's coarse triangles laid out in (u, v)
  for (std::size_t k = 0; k < flat.positions.size(); ++k) flat.positions[k] = {flat.uv[k].x, flat.uv[k].y, 0};
  uv_camera(p);
  gllab::draw_mesh_wireframe(flat, kDim);
  gllab::draw_mesh_faces(flat, spline::mesh_fidelity(meshes[0], surface, kTiltDegrees).tilted, kSliver, 2.f);
  gllab::leave_panels(s.width, s.height);
  caption(p, 0, "the same triangles in (u, v)");
}

// An error view: the outer loop reversed. GLU raises NURBS error 28 and draws
// nothing (headless: exit 1); the own core names the loop.
void draw_reversed(const State& s) {
  const std::vector<spline::TrimLoop> trims = trims_of(s, s.view());
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  draw_loops(left, trims);
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(right);
  draw_glu(surface_of(s, trims), glu_sampling(s), false);
  const Panel all = gllab::enter_panel(0, 0, 1, 1, s.width, s.height);
  gllab::leave_panels(s.width, s.height);
  try {
    spline::validate_trim_loops(trims, {0, 1, 0, 1});
  } catch (const std::invalid_argument& e) {
    const std::string why = e.what();  // "trim loop 0 (outer) runs clockwise (signed area ...); outer ..."
    caption(all, 0, "own core: " + why.substr(0, why.find(" (signed")));
    caption(all, 1, why.substr(why.find("; ") + 2));
    caption(right, 3, "GLU drew nothing: see below");
  }
}

// init / display ----------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

void display(const State& s) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const std::string& v = s.view();
  if (v == "own_vs_glu") draw_own_vs_glu(s);
  else if (v == "slivers") draw_slivers(s);
  else if (v == "reversed_outer_loop") draw_reversed(s);
  else draw_default(s);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "18_trimmed_nurbs",
      "lab 18 · trimmed NURBS surfaces",
      {{"default", "the trim loops in (u, v) and GLU's trimmed surface"},
       {"own_vs_glu", "GLU's trimmed surface and the own tessellation, deviations inside and along the trims"},
       {"slivers", "a 5-point gluPwlCurve square: GLU's slivers, GLU fed a dense polyline, the own core"},
       {"reversed_outer_loop", "the outer loop clockwise: GLU NURBS error 28", true}},
      {{"steps", 24, 2, 100, "GLU_DOMAIN_DISTANCE: GLU_U_STEP = GLU_V_STEP"},
       {"tol", 0.02, 0.0005, 0.5, "the own tessellation's tolerance, object units"},
       {"finer", 0, -3, 3, "tol / 2^finer, steps x 2^finer"},
       {"per_edge", 16, 1, 64, "points per edge of the densified polylines"}},
      {{'t', "finer (tol / 2, steps x 2)", "finer", +1}, {'T', "coarser", "finer", -1},
       {'s', "GLU steps +4", "steps", +4}, {'S', "GLU steps -4", "steps", -4},
       {'e', "polyline points per edge +4", "per_edge", +4}, {'E', "points per edge -4", "per_edge", -4}},
      init,
      display};
  lab.points = {{"P", kHill, "control points P(i, j) of the hill, row by row (i along u)", 3}};
  lab.model = [](const State& s) -> gllab::Model { return surface_of(s, trims_of(s, s.view(), false)); };
  return lab;
}
