// lab 15 · Bézier surfaces                                   difficulty: ★★★☆
// A bicubic tensor-product Bézier patch (seed 000 §1.7, seed 004 "Bezier
// Patches"): de Casteljau in both directions, iso-parameter lines and normals
// Xu x Xv, zero and constant twist, the patch against OpenGL's own evaluator
// (glMap2f + glEvalMesh2), and a second patch joined with C0, C1 or C2.
// Notice: the inner net points set the corner twists, 9 (b11 - b10 - b01 + b00);
//   with zero twist every v-tangent along an edge is the same vector.
// Try: press [a] in own_vs_evaluator. Why does GL's patch go flat without
//   GL_AUTO_NORMAL? In join_c1, drag a point of row 2 of the left patch:
//   which points of the right patch follow, and why only those?
// Keys: [s]/[S] u  [t]/[T] v  [f] u or v first  [g]/[G] grid  [a] GL_AUTO_NORMAL
//   [m] normals  [c] nets  [n] labels  [h] help  [Esc] quit
// Views: de_casteljau, iso_lines_normals, zero_twist, constant_twist,
//   own_vs_evaluator, join_c0, join_c1, join_c2
// Reference: reference_images/15_bezier_surfaces__*.png

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bezier.h"
#include "spline/surface.h"
#include "spline/tessellate.h"

namespace {

namespace sp = gllab::spline;
using sp::BezierSurface;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// b_ij = P[4 i + j], i along u (x), j along v (y): a hill with a dip, on [0, 1]^2.
const std::vector<Vec3> kPatch = {
    {-1.5, -1.5, 0},    {-1.5, -.5, .42}, {-1.5, .5, .56}, {-1.5, 1.5, 0},
    {-.5, -1.5, .42},   {-.5, -.5, 1.68}, {-.5, .5, 1.4},  {-.5, 1.5, .7},
    {.5, -1.5, .21},    {.5, -.5, 1.26},  {.5, .5, 1.19},  {.5, 1.5, .98},
    {1.5, -1.5, -.14},  {1.5, -.5, .84},  {1.5, .5, .84},  {1.5, 1.5, 1.26}};
// Rows 1..3 of the neighbour over u in [1, 2]; its row 0 is the shared edge.
const std::vector<Vec3> kNext = {
    {2.5, -1.5, .4},   {2.5, -.5, 1.3},  {2.5, .5, .2},  {2.5, 1.5, .5},
    {3.5, -1.5, .1},   {3.5, -.5, .5},   {3.5, .5, .9},  {3.5, 1.5, .3},
    {4.5, -1.5, .2},   {4.5, -.5, .3},   {4.5, .5, .6},  {4.5, 1.5, .1}};
constexpr double kTolerance = 2e-3;  // tessellation, object units (the patch is 3 wide)
const gllab::Rgb kClay{.85f, .55f, .35f}, kSea{.35f, .6f, .85f}, kNet{.75f, .75f, .8f}, kFree{1.f, .9f, .3f},
    kMade{.85f, .5f, .85f}, kCurve{.3f, 1.f, .5f}, kText{1.f, 1.f, 1.f}, kRed{1.f, .35f, .3f};

// The patches ------------------------------------------------------------------
BezierSurface patch_of(const std::vector<Vec3>& P) { return {3, 3, P}; }

// zero_twist / constant_twist: the core makes the patch from the edge curves
// through b00 (and for the constant twist b33, which sets it).
BezierSurface shown_patch(const gllab::State& s) {
  const BezierSurface p = patch_of(s.points("P"));
  if (s.view() != "zero_twist" && s.view() != "constant_twist") return p;
  // X_uv = 9 (b11 - b10 - b01 + b00) on each of the 9 cells, whose sum is
  const Vec3 twist = p.point(3, 3) - p.point(3, 0) - p.point(0, 3) + p.point(0, 0);
  return sp::constant_twist_patch(sp::iso_curve_v(p, 0), sp::iso_curve_u(p, 0),
                                  s.view() == "zero_twist" ? Vec3{} : twist);
}

sp::Mesh mesh_of(const BezierSurface& p, int steps = 0) {
  return sp::tessellate_surface(sp::surface_evaluator(p), sp::uv_domain(p),
                                steps ? sp::TessellationOptions::fixed_steps(steps, steps)
                                      : sp::TessellationOptions::adaptive(kTolerance));
}

// Drawing ----------------------------------------------------------------------
using gllab::format_text;
// "name (x, y, z)" to two decimals; round-off below 0.005 prints as 0, not -0.00.
std::string vec(const std::string& name, Vec3 p) {
  const auto r = [](double x) { return std::fabs(x) < 5e-3 ? 0.0 : x; };
  return name + format_text(" (%.2f, %.2f, %.2f)", r(p.x), r(p.y), r(p.z));
}

// One light that stays with the eye; both sides lit (we see under the patch).
void camera(double scale) {
  gllab::enable_headlight();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gllab::look_from_above(25, 30);
  glScaled(scale, scale, scale);
}

void caption(const gllab::State& s, const std::vector<std::string>& lines) {
  if (s.flag("labels")) gllab::draw_text_panel(8, 8, lines, kText);
}

// The net of p and the points of list P the view lets the mouse move: all of
// them, but in the twist views only the two edges through b00 (and b33).
void draw_net(const gllab::State& s, const BezierSurface& p) {
  if (!s.flag("nets")) return;
  gllab::draw_control_net(p.P, 4, 4, kNet);
  std::vector<std::size_t> free = {0, 1, 2, 3, 4, 8, 12, 15};
  if (s.view() == "zero_twist") free.pop_back();
  else if (s.view() != "constant_twist") free = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  gllab::draw_control_points(s, "P", free, kFree);
}

// The seeds' scheme at (u, v) (u first): one Bézier curve per column of the
// net, evaluated at u (the nets b^{k,0}, dim); their points b^{3,0}_j are the
// control polygon of the surface curve v -> X(u, v) (green), evaluated at v
// (b^{3,l}, cyan). [f] runs v first: rows instead of columns.
void draw_de_casteljau(const gllab::State& s) {
  const BezierSurface p = shown_patch(s);
  const bool u_first = s.get("first") == 0;
  const sp::BezierSurfaceConstruction c =
      sp::de_casteljau(p, s.get("u"), s.get("v"), u_first ? sp::SurfaceDirection::U : sp::SurfaceDirection::V);
  gllab::draw_surface(mesh_of(p), kClay);
  draw_net(s, p);
  glDisable(GL_DEPTH_TEST);  // the construction in front, as on the slides
  for (std::size_t k = 1; k < c.nets.size(); ++k) {
    const bool first_steps = k < 3;  // b^{1,0}, b^{2,0}: inside the columns' schemes
    gllab::draw_control_net(c.nets[k].P, c.nets[k].rows, c.nets[k].cols,
                            first_steps ? gllab::Rgb{.45f, .6f, .45f} : k == 3 ? kCurve : gllab::Rgb{.4f, .9f, 1.f});
  }
  gllab::draw_curve(u_first ? sp::iso_curve_u(p, s.get("u")) : sp::iso_curve_v(p, s.get("v")), kCurve, 2.f);
  gllab::draw_arrow(c.point, c.point + 0.25 * c.partials.Su, kRed, 3.f);
  gllab::draw_arrow(c.point, c.point + 0.25 * c.partials.Sv, kSea, 3.f);  // one is tangent to the green curve
  gllab::draw_dots({c.point}, kText, 10.f);
  glEnable(GL_DEPTH_TEST);
  caption(s, {u_first ? "u first: each column at u, then the green polygon at v"
                      : "v first: each row at v, then the green polygon at u",
              vec("X(u, v) =", c.point) + format_text("  at u %.2f, v %.2f", s.get("u"), s.get("v")),
              vec("Xu/4 (red) =", 0.25 * c.partials.Su), vec("Xv/4 (blue) =", 0.25 * c.partials.Sv)});
}

// Iso-parameter lines X(u_k, v), X(u, v_k) (core iso curves) and the unit
// normals (Xu x Xv)/|Xu x Xv| as needles in the middle of each grid cell.
void draw_iso_lines_normals(const gllab::State& s) {
  const BezierSurface p = shown_patch(s);
  gllab::draw_surface(mesh_of(p), kClay);
  draw_net(s, p);
  const int lines = 8;  // intervals each way
  sp::Mesh needles;  // points and normals only: draw_normal_needles draws them
  for (int k = 0; k <= lines; ++k) {
    const double w = double(k) / lines;
    gllab::draw_curve(sp::iso_curve_u(p, w), kCurve, 1.5f);
    gllab::draw_curve(sp::iso_curve_v(p, w), kSea, 1.5f);
    for (int l = 0; k < lines && l < lines && s.flag("normals"); ++l) {
      const double u = (k + 0.5) / lines, v = (l + 0.5) / lines;
      needles.positions.push_back(sp::surface_point(p, u, v));
      needles.normals.push_back(sp::surface_normal(p, u, v));
    }
  }
  gllab::draw_normal_needles(needles, 0.4, kText);
  caption(s, {format_text("green X(u_k, v), blue X(u, v_k): %d + 1 lines each way", lines),
              "white: N = (Xu x Xv) / |Xu x Xv|"});
}

// The v-tangents Xv along the edge v = 0 and the corner twists.
void draw_twist(const gllab::State& s) {
  const BezierSurface p = shown_patch(s);
  gllab::draw_surface(mesh_of(p), kClay);
  draw_net(s, p);
  glDisable(GL_DEPTH_TEST);
  // Xv along the edge v = 0: how the cross tangent turns as u runs (Xuv = dXv/du).
  for (int k = 0; k <= 6; ++k) {
    const sp::SurfacePartials d = sp::surface_partials(p, k / 6.0, 0);
    gllab::draw_arrow(d.S, d.S + 0.3 * d.Sv, kSea);
  }
  std::vector<std::string> lines = {"blue: Xv/3 along the edge v = 0, red: Xuv/3"};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const sp::SurfacePartials d = sp::surface_partials(p, a, b);
      gllab::draw_arrow(d.S, d.S + d.Suv / 3, kRed);
      lines.push_back(vec(format_text("Xuv(%d, %d) =", a, b), d.Suv));
    }
  glEnable(GL_DEPTH_TEST);
  caption(s, lines);
}

// OpenGL's evaluator (Red Book ch. 12): the same 16 points as a map, a grid,
// and normals from the map's derivatives when GL_AUTO_NORMAL is on.
void draw_evaluator(const BezierSurface& p, int grid, bool auto_normal) {
  std::vector<GLfloat> points;  // x y z of b_00, b_01, ..., b_33
  for (const Vec3& b : p.P) points.insert(points.end(), {GLfloat(b.x), GLfloat(b.y), GLfloat(b.z)});
  // u (index i) steps over a row of 4 points: stride 12 floats; v steps 3.
  glMap2f(GL_MAP2_VERTEX_3, 0.f, 1.f, 12, 4, 0.f, 1.f, 3, 4, points.data());
  glEnable(GL_MAP2_VERTEX_3);
  if (auto_normal) glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(grid, 0.f, 1.f, grid, 0.f, 1.f);
  // Its strips run clockwise in (u, v) while Xu x Xv points up: tell GL which
  // side is the front, or two-sided lighting lights the back.
  glFrontFace(GL_CW);
  glEvalMesh2(GL_FILL, 0, grid, 0, grid);
  glFrontFace(GL_CCW);
  glDisable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_VERTEX_3);
}

// Left: the core's tessellation on a grid x grid; right: glEvalMesh2 on the
// same grid. Each in its own half of the window, under the same matrices.
void draw_own_vs_evaluator(const gllab::State& s) {
  const BezierSurface p = shown_patch(s);
  const int grid = s.integer("grid"), half = s.width / 2;
  for (int side = 0; side < 2; ++side) {
    glViewport(side * half, 0, half, s.height);
    gllab::ortho_fit(half, s.height, 2.4, 2.4);
    camera(1);
    glColor3f(kClay.r, kClay.g, kClay.b);
    if (side == 1) {
      draw_evaluator(p, grid, s.flag("auto_normal"));
      continue;
    }
    gllab::draw_mesh(mesh_of(p, grid));
    draw_net(s, p);
  }
  glViewport(0, 0, s.width, s.height);
  if (!s.flag("labels")) return;
  const std::string cells = format_text("%d x %d cells", grid, grid);
  gllab::draw_text_panel(8, 8, {"tessellate_surface", cells}, kText);
  gllab::draw_text_panel(half + 8, 8, {"glEvalMesh2", cells + (s.flag("auto_normal") ? "" : ", no normals")}, kText);
}

// join_ck: the neighbour's rows 0..k continue the left patch's columns (core
// joined_patch), its other rows are the list Q. The construction lines: each
// column's Bézier curve continued beyond u = 1 (de Casteljau at tau = 2).
void draw_join(const gllab::State& s, int k) {
  const BezierSurface a = patch_of(s.points("P"));
  BezierSurface b = a;  // row 0: any, joined_patch replaces it
  std::copy(s.points("Q").begin(), s.points("Q").end(), b.P.begin() + 4);
  b = sp::joined_patch(a, {3, 3, b.P, 1, 2}, k);
  gllab::draw_surface(mesh_of(a), kClay);
  gllab::draw_surface(mesh_of(b), kSea);
  if (s.flag("nets")) {
    glDisable(GL_DEPTH_TEST);  // the construction lines run under the surface too
    for (int j = 0; j < 4; ++j) {
      const sp::BezierCurve column{{a.point(0, j), a.point(1, j), a.point(2, j), a.point(3, j)}};
      const sp::BezierContinuation c = sp::continuation_points(column, k, 1);
      for (std::size_t r = 1; r < c.levels.size(); ++r)
        for (std::size_t m = 0; m < c.levels[r].size(); ++m)
          gllab::draw_polyline({c.levels[r - 1][m], c.levels[r - 1][m + 1], c.levels[r][m]}, kText, 1.f);
    }
    glEnable(GL_DEPTH_TEST);
    gllab::draw_control_net(b.P, 4, 4, kMade);
    std::vector<std::size_t> free;  // rows k+1..3 of the blue patch: Q[4k..11]
    for (std::size_t i = 4 * std::size_t(k); i < 12; ++i) free.push_back(i);
    gllab::draw_control_points(s, "Q", free, kFree);
    draw_net(s, a);
  }
  caption(s, {format_text("C%d: blue rows 0..%d made from the orange patch", k, k),
              "(each column continued beyond u = 1)"});
}

// init / display ----------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

void display(const gllab::State& s) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (s.view() == "own_vs_evaluator") return draw_own_vs_evaluator(s);
  const bool join = s.view().rfind("join_c", 0) == 0;
  gllab::ortho_fit(s.width, s.height, 2.4, 2.4);
  glTranslated(0, -0.3, 0);  // below the text panel
  camera(join ? 0.62 : 1);
  if (join) glTranslated(-1.5, 0, 0);  // both patches in the middle
  if (s.view() == "de_casteljau") draw_de_casteljau(s);
  else if (s.view() == "iso_lines_normals") draw_iso_lines_normals(s);
  else if (join) draw_join(s, s.view().back() - '0');
  else draw_twist(s);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"15_bezier_surfaces",
                 "lab 15 · Bézier surfaces",
                 {{"de_casteljau", "the surface de Casteljau scheme at (u, v), with Xu and Xv"},
                  {"iso_lines_normals", "iso-parameter lines and normals Xu x Xv as needles"},
                  {"zero_twist", "the translational patch of two edges: Xuv = 0 everywhere"},
                  {"constant_twist", "the same edges, b33 sets one twist for the whole patch"},
                  {"own_vs_evaluator", "tessellate_surface vs glMap2f + glEvalMesh2, same grid"},
                  {"join_c0", "a second patch sharing the edge only"}, {"join_c1", "its row 1 continued: C1"},
                  {"join_c2", "rows 1 and 2 continued: C2"}},
                 {{"u", 0.45, 0, 1, "de Casteljau u (the seeds' s)"}, {"v", 0.3, 0, 1, "de Casteljau v (the seeds' t)"},
                  {"first", 0, 0, 1, "de Casteljau: 0 steps along u first, 1 along v first"},
                  {"grid", 12, 1, 64, "own_vs_evaluator: cells along u and along v"},
                  {"auto_normal", 1, 0, 1, "glEnable(GL_AUTO_NORMAL) for glEvalMesh2"},
                  {"normals", 1, 0, 1, "normal needles"}, {"nets", 1, 0, 1, "control nets and draggable points"},
                  {"labels", 1, 0, 1, "formulas and values"}},
                 {{'s', "u +0.05", "u", +0.05}, {'S', "u -0.05", "u", -0.05},
                  {'t', "v +0.05", "v", +0.05}, {'T', "v -0.05", "v", -0.05},
                  {'f', "de Casteljau: u first / v first", "first"},
                  {'g', "grid +1", "grid", +1}, {'G', "grid -1", "grid", -1},
                  {'a', "GL_AUTO_NORMAL on/off", "auto_normal"}, {'m', "normal needles on/off", "normals"},
                  {'c', "control nets on/off", "nets"}, {'n', "labels on/off", "labels"}},
                 init,
                 display};
  lab.points = {{"P", kPatch, "the patch's net b_ij = P[4i + j]", 3},
                {"Q", kNext, "rows 1-3 of the joined patch (join views)", 3}};
  lab.model = [](const gllab::State& s) -> gllab::Model { return sp::to_bspline(shown_patch(s)); };
  return lab;
}
