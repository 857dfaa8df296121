// lab 17 · Bézier surfaces                                   difficulty: ★★★☆
// A bicubic tensor-product Bézier patch (lecture notes ch. 1, §1.7 Surface representations,
// "Bézier tensor product", "De Casteljau algorithm for surfaces", "The twist vector"; "Higher
// Order Surfaces", "Bezier Patches"): de Casteljau in both directions, iso-parameter lines and
// normals Xu x Xv, zero and constant twist. Lab 18 joins a second patch to it, lab 19 hands it
// to OpenGL's evaluator (glMap2f).
// Notice: the inner net points set the corner twists, 9 (b11 - b10 - b01 + b00);
//   with zero twist every v-tangent along an edge is the same vector. Seen from
//   below, the underside is lit with -N (GL_LIGHT_MODEL_TWO_SIDE).
// Try: de_casteljau, then [v] to de_casteljau_v_first: which nets change, and
//   which points do not? In constant_twist, drag b33 until Xuv = 0: which view?
// Keys: [s]/[S] u  [t]/[T] v  [m] normals  [c] nets  [n] labels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: de_casteljau, de_casteljau_v_first, iso_lines_normals (from below),
//   zero_twist, constant_twist
// Reference: reference_images/17_bezier_surfaces__*.png

#include <cmath>
#include <cstddef>
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
using gllab::format_text;
using gllab::Rgb;
using gllab::State;
using sp::BezierSurface;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// b_ij = P[4 i + j], i along u (x), j along v (y): a hill with a dip, on [0, 1]^2.
const std::vector<Vec3> kPatch = {
    {-1.5, -1.5, 0},    {-1.5, -.5, .42}, {-1.5, .5, .56}, {-1.5, 1.5, 0},
    {-.5, -1.5, .42},   {-.5, -.5, 1.68}, {-.5, .5, 1.4},  {-.5, 1.5, .7},
    {.5, -1.5, .21},    {.5, -.5, 1.26},  {.5, .5, 1.19},  {.5, 1.5, .98},
    {1.5, -1.5, -.14},  {1.5, -.5, .84},  {1.5, .5, .84},  {1.5, 1.5, 1.26}};
// The points the mouse moves: all 16, or in the twist views only the two edges
// through b00 (and b33, which sets the constant twist).
const std::vector<std::size_t> kAll = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
const std::vector<std::size_t> kEdges = {0, 1, 2, 3, 4, 8, 12};
const std::vector<std::size_t> kEdgesB33 = {0, 1, 2, 3, 4, 8, 12, 15};
constexpr double kTolerance = 2e-3;  // tessellation, object units (the patch is 3 wide)
constexpr double kSize = 1;          // the patch's scale on screen (lab 18 shows two at 0.62)
const Rgb kClay{.85f, .55f, .35f}, kSea{.35f, .6f, .85f}, kNet{.75f, .75f, .8f},
    kFree{1.f, .9f, .3f}, kCurve{.3f, 1.f, .5f}, kText{1.f, 1.f, 1.f}, kRed{1.f, .35f, .3f};

// The patches ------------------------------------------------------------------
BezierSurface patch_of(const State& s) { return {3, 3, s.points("P")}; }

// zero_twist / constant_twist: the core makes the patch from the edge curves through b00 and the
// twist, here b33 - b30 - b03 + b00 (the sum of the 9 cells' 9 (b11 - b10 - b01 + b00)) or zero.
BezierSurface twist_patch(const State& s, bool zero) {
  const BezierSurface p = patch_of(s);
  const Vec3 twist = p.point(3, 3) - p.point(3, 0) - p.point(0, 3) + p.point(0, 0);
  return sp::constant_twist_patch(sp::iso_curve_v(p, 0), sp::iso_curve_u(p, 0),
                                  zero ? Vec3{} : twist);
}

sp::Mesh mesh_of(const BezierSurface& p) {
  return sp::tessellate_surface(sp::surface_evaluator(p), sp::uv_domain(p),
                                sp::TessellationOptions::adaptive(kTolerance));
}

// Drawing ----------------------------------------------------------------------
// "name (x, y, z)" to two decimals; round-off below 0.005 prints as 0, not -0.00.
std::string vec(const std::string& name, Vec3 p) {
  const auto r = [](double x) { return std::fabs(x) < 5e-3 ? 0.0 : x; };
  return name + format_text(" (%.2f, %.2f, %.2f)", r(p.x), r(p.y), r(p.z));
}

// One light that stays with the eye; both sides lit: the back of a polygon
// with -N, so the underside is lit as the light falls on it (seen from below
// in iso_lines_normals, elevation < 0).
void camera(const State& s, double elevation = 25) {
  gllab::ortho_fit(s.width, s.height, 2.4, 2.4);
  gllab::enable_headlight();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gllab::apply_orbit(s);     // right-drag, wheel, [0]: s.camera
  glTranslated(0, -0.3, 0);  // below the text panel
  gllab::look_from_above(elevation, 30);
  glScaled(kSize, kSize, kSize);
}

void caption(const State& s, const std::vector<std::string>& lines) {
  if (s.flag("labels")) gllab::draw_text_panel(8, 8, lines, kText);
}

// The net of p, and the points of list P the view lets the mouse move.
void draw_net(const State& s, const BezierSurface& p, const std::vector<std::size_t>& free) {
  if (!s.flag("nets")) return;
  gllab::draw_control_net(p.P, 4, 4, kNet);
  gllab::draw_control_points(s, "P", free, kFree);
}

// The notes' scheme at (u, v) (u first): one Bézier curve per column of the net, evaluated at u
// (the nets b^{k,0}, dim); their points b^{3,0}_j are the control polygon of the surface curve v ->
// X(u, v) (green), evaluated at v (b^{3,l}, cyan). v first: rows instead of columns.
void draw_scheme(const State& s, bool u_first) {
  const BezierSurface p = patch_of(s);
  const double u = s.get("u"), v = s.get("v");
  const sp::BezierSurfaceConstruction c =
      sp::de_casteljau(p, u, v, u_first ? sp::SurfaceDirection::U : sp::SurfaceDirection::V);
  camera(s);
  gllab::draw_surface(mesh_of(p), kClay);
  draw_net(s, p, kAll);
  glDisable(GL_DEPTH_TEST);  // the construction in front, as on the slides
  for (std::size_t k = 1; k < c.nets.size(); ++k) {
    const bool first_steps = k < 3;  // b^{1,0}, b^{2,0}: inside the columns' schemes
    const Rgb colour = first_steps ? Rgb{.45f, .6f, .45f} : k == 3 ? kCurve : Rgb{.4f, .9f, 1.f};
    gllab::draw_control_net(c.nets[k].P, c.nets[k].rows, c.nets[k].cols, colour);
  }
  gllab::draw_curve(u_first ? sp::iso_curve_u(p, u) : sp::iso_curve_v(p, v), kCurve, 2.f);
  gllab::draw_arrow(c.point, c.point + 0.25 * c.partials.Su, kRed, 3.f);
  gllab::draw_arrow(c.point, c.point + 0.25 * c.partials.Sv, kSea, 3.f);  // tangent to green
  gllab::draw_dots({c.point}, kText, 10.f);
  glEnable(GL_DEPTH_TEST);
  caption(s, {u_first ? "u first: each column at u, then the green polygon at v"
                      : "v first: each row at v, then the green polygon at u",
              vec("X(u, v) =", c.point) + format_text("  at u %.2f, v %.2f", u, v),
              vec("Xu/4 (red) =", 0.25 * c.partials.Su),
              vec("Xv/4 (blue) =", 0.25 * c.partials.Sv),
              "either order: X = sum_i sum_j B_i(u) B_j(v) b_ij"});
}

void draw_u_first(const State& s) { draw_scheme(s, true); }
void draw_v_first(const State& s) { draw_scheme(s, false); }

// Iso-parameter lines X(u_k, v), X(u, v_k) (core iso curves) and the unit
// normals (Xu x Xv)/|Xu x Xv| as needles in the middle of each grid cell,
// seen from 20 degrees below: the far part shows its top and the needles, the
// near part its underside (the needles' feet).
void draw_iso_lines_normals(const State& s) {
  const BezierSurface p = patch_of(s);
  camera(s, -20);
  gllab::draw_surface(mesh_of(p), kClay);
  draw_net(s, p, kAll);
  const int lines = 8;  // intervals each way
  sp::Mesh needles;     // points and normals only: draw_normal_needles draws them
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
              "white: N = (Xu x Xv) / |Xu x Xv|",
              "from below: in front the underside, lit with -N"});
}

// The v-tangents Xv along the edge v = 0 and the corner twists.
void draw_twist(const State& s, bool zero) {
  const BezierSurface p = twist_patch(s, zero);
  camera(s);
  gllab::draw_surface(mesh_of(p), kClay);
  draw_net(s, p, zero ? kEdges : kEdgesB33);
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

void draw_zero_twist(const State& s) { draw_twist(s, true); }
void draw_constant_twist(const State& s) { draw_twist(s, false); }

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "17_bezier_surfaces",
      "lab 17 · Bézier surfaces",
      {{"de_casteljau", "the surface de Casteljau scheme at (u, v), u first, with Xu and Xv",
        draw_u_first, kOrbit},
       {"de_casteljau_v_first", "the same scheme v first: other nets, the same point",
        draw_v_first, kOrbit},
       {"iso_lines_normals", "iso-parameter lines and normals Xu x Xv, from below",
        draw_iso_lines_normals, kOrbit},
       {"zero_twist", "the translational patch of two edges: Xuv = 0 everywhere",
        draw_zero_twist, kOrbit},
       {"constant_twist", "the same edges, b33 sets one twist for the whole patch",
        draw_constant_twist, kOrbit}},
      {{"u", 0.45, 0, 1, "de Casteljau u (the notes' s)"},
       {"v", 0.3, 0, 1, "de Casteljau v (the notes' t)"},
       {"normals", 1, 0, 1, "normal needles"},
       {"nets", 1, 0, 1, "control nets and draggable points"},
       {"labels", 1, 0, 1, "formulas and values"}},
      {{'s', "u +0.05", "u", +0.05}, {'S', "u -0.05", "u", -0.05},
       {'t', "v +0.05", "v", +0.05}, {'T', "v -0.05", "v", -0.05},
       {'m', "normal needles on/off", "normals"}, {'c', "control nets on/off", "nets"},
       {'n', "labels on/off", "labels"}},
      init};
  lab.points = {{"P", kPatch, "the patch's net b_ij = P[4i + j]", 3}};
  // Ctrl+S saves the net P as a clamped bicubic B-spline surface.
  lab.model = [](const State& s) -> gllab::Model { return sp::to_bspline(patch_of(s)); };
  return lab;
}
