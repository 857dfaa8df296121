// lab 22 · trimmed NURBS surfaces                               difficulty: ★★★★
// The Red Book's hill (surface.c, trim.c) cut by gluBeginTrim/gluEndTrim
// (lecture notes ch. 1, §1.7 Surface representations, "Trimming", and
// "Trimming a B-spline surface with OpenGL"): the outer boundary is a NURBS
// curve (GLU_MAP1_TRIM_2), one hole an exact NURBS circle (GLU_MAP1_TRIM_3),
// one a Bézier arch closed by a gluPwlCurve (as in trim.c), and a rectangular
// hole has an island in it. Lab 23 tessellates the same hill with the own core.
// Notice: GLU keeps what lies left of every trim curve: the outer loop and the
//   island run counter-clockwise, the holes clockwise. In outline_patch GLU
//   draws the trim curves it sampled, and its triangles fan out from them.
// Try: in reversed_outer_loop: which error does GLU raise, and which loop does
//   the own core name? Then reverse the island instead (loops_of): what then?
// Keys: [s]/[S] GLU steps  [e]/[E] polyline points per edge
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: default, outline_patch, reversed_outer_loop (an error view)
// Reference: reference_images/22_trimmed_nurbs__*.png

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_arrays.h"
#include "gl/glu_errors.h"
#include "gl/glu_nurbs.h"
#include "gl/nurbs_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/surface.h"
#include "spline/trim.h"

namespace {

namespace spline = gllab::spline;
using gllab::draw_panel_caption;
using gllab::Panel;
using gllab::State;
using spline::Vec2;

// Lab data (edit me) -------------------------------------------------------
// surface.c's hill: 4 x 4 control points (2 (i - 1.5), 2 (j - 1.5), z), the
// middle four up at z = 3; [mouse] drags them (point list P, row i along u).
const std::vector<spline::Vec3> kHill = {
    {-3, -3, -3}, {-3, -1, -3}, {-3, 1, -3}, {-3, 3, -3}, {-1, -3, -3}, {-1, -1, 3},
    {-1, 1, 3},   {-1, 3, -3},  {1, -3, -3}, {1, -1, 3},  {1, 1, 3},    {1, 3, -3},
    {3, -3, -3},  {3, -1, -3},  {3, 1, -3},  {3, 3, -3}};
GLfloat kKnots[8] = {0, 0, 0, 0, 1, 1, 1, 1};  // one cubic Bézier piece: in u, in v, the arch

// The trim loops in (u, v). The outer boundary: a closed quadratic B-spline, a
// square with rounded corners, counter-clockwise (uniform knots, clamped).
const std::vector<spline::Vec3> kOuter = {{.5, .03, 0}, {.97, .03, 0}, {.97, .5, 0}, {.97, .97, 0},
    {.5, .97, 0}, {.03, .97, 0}, {.03, .5, 0}, {.03, .03, 0}, {.5, .03, 0}};
GLfloat kOuterKnots[12] = {0, 0, 0, 1 / 7.f, 2 / 7.f, 3 / 7.f, 4 / 7.f, 5 / 7.f, 6 / 7.f, 1, 1, 1};
// The unit circle as a NURBS curve (The NURBS Book §7.5): 9 points on the
// square around it from (1, 0) counter-clockwise, weight √2/2 at its corners.
const double kW = std::sqrt(2.0) / 2;
const double kCircle[9][3] = {{1, 0, 1},    {1, 1, kW},  {0, 1, 1},   {-1, 1, kW}, {-1, 0, 1},
                              {-1, -1, kW}, {0, -1, 1},  {1, -1, kW}, {1, 0, 1}};  // u, v, w
GLfloat kCircleKnots[12] = {0, 0, 0, .25f, .25f, .5f, .5f, .75f, .75f, 1, 1, 1};
// trim.c's hole, half size: a cubic Bézier arch over the top, clockwise, and a
// polyline back under it; a rectangular hole (clockwise) with an island in it.
GLfloat kArch[4][2] = {{.61f, .7f}, {.61f, .81f}, {.83f, .81f}, {.83f, .7f}};
const std::vector<Vec2> kArchBase = {{.83, .7}, {.72, .59}, {.61, .7}};
const std::vector<Vec2> kRectangle = {{.15, .12}, {.15, .45}, {.85, .45}, {.85, .12}, {.15, .12}};
const gllab::Rgb kGlu{0.95f, 0.6f, 0.25f}, kWire{0.1f, 0.1f, 0.1f}, kLine{0.4f, 0.9f, 0.4f};

// One GLU NURBS object, made in init() as surface.c makes theNurb.
GLUnurbs* g_nurb = nullptr;

// GLU calls this inside the failing call (never exit(0), as the Red Book does).
void GLAPIENTRY on_nurbs_error(GLenum code) {
  gllab::report_glu_error(code, "gluNurbsSurface (trimmed hill)");
}

// The trim loops as GLU takes them --------------------------------------------
// A circle of radius r about (cu, cv) as GLU_MAP1_TRIM_3 takes it: every point
// premultiplied by its weight, (w u, w v, w). Clockwise, it cuts a hole.
std::vector<GLfloat> circle(double cu, double cv, double r, bool clockwise) {
  std::vector<GLfloat> ctl;
  for (int i = 0; i < 9; ++i) {
    const double* p = kCircle[clockwise ? 8 - i : i];
    const double w = p[2];
    ctl.insert(ctl.end(), {GLfloat(w * (cu + r * p[0])), GLfloat(w * (cv + r * p[1])), GLfloat(w)});
  }
  return ctl;
}

// The five loops, each a list of pieces (gllab::GluTrimPiece: a type, its
// points and their stride, and for a gluNurbsCurve its order and knots), each
// piece starting where the one before ends. reversed_outer_loop runs the
// outer one the other way round.
std::vector<gllab::GluTrimLoop> loops_of(const State& s, bool reversed_outer) {
  const int n = s.integer("per_edge");
  std::vector<spline::Vec3> outer = kOuter;
  if (reversed_outer) std::reverse(outer.begin(), outer.end());
  return {{{GLU_MAP1_TRIM_2, gllab::glu_points(outer, 2), 2, 3, kOuterKnots}},     // outer boundary
          {{GLU_MAP1_TRIM_3, circle(0.27, 0.7, 0.13, true), 3, 3, kCircleKnots}},  // round hole
          {{GLU_MAP1_TRIM_2, {&kArch[0][0], &kArch[0][0] + 4 * 2}, 2, 4, kKnots},  // trim.c's
           {GLU_MAP1_TRIM_2, gllab::densified_pwl(kArchBase, n), 2}},             // hole
          {{GLU_MAP1_TRIM_2, gllab::densified_pwl(kRectangle, n), 2}},            // rectangle
          {{GLU_MAP1_TRIM_3, circle(0.5, 0.285, 0.1, false), 3, 3, kCircleKnots}}};  // its island
}

// The trimmed hill through GLU (surface.c and trim.c's display()): cubic
// (order 4) in u and v, the point (i, j) at ctl[(4 i + j) * 3].
const GLint kKnotCount = GLint(std::size(kKnots));

void draw_glu_hill(const State& s, bool reversed_outer, GLenum display_mode) {
  std::vector<GLfloat> ctl = gllab::glu_points(s.points("P"));  // the dragged points
  std::vector<gllab::GluTrimLoop> loops = loops_of(s, reversed_outer);
  gluNurbsProperty(g_nurb, GLU_U_STEP, GLfloat(s.get("steps")));  // GLU_DOMAIN_DISTANCE (init)
  gluNurbsProperty(g_nurb, GLU_V_STEP, GLfloat(s.get("steps")));
  gluNurbsProperty(g_nurb, GLU_DISPLAY_MODE, GLfloat(display_mode));
  gluBeginSurface(g_nurb);
  gluNurbsSurface(g_nurb, kKnotCount, kKnots, kKnotCount, kKnots, 4 * 3, 3, ctl.data(), 4, 4,
                  GL_MAP2_VERTEX_3);
  for (gllab::GluTrimLoop& loop : loops) {
    gluBeginTrim(g_nurb);
    for (gllab::GluTrimPiece& p : loop) {
      if (p.knots)  // GLU reads count + order knots
        gluNurbsCurve(g_nurb, p.count() + p.order, p.knots, p.stride, p.points.data(), p.order,
                      p.type);
      else
        gluPwlCurve(g_nurb, p.count(), p.points.data(), p.stride, p.type);
    }
    gluEndTrim(g_nurb);
  }
  gluEndSurface(g_nurb);
}

// The same hill and loops for the own core: each GLU call's arguments, read
// back by gllab::core_surface and core_trims (gl/glu_arrays.h).
spline::BsplineSurface own_hill(const State& s, bool reversed_outer) {
  const std::vector<GLfloat> ctl = gllab::glu_points(s.points("P"));
  spline::BsplineSurface S = gllab::core_surface(kKnotCount, kKnots, kKnotCount, kKnots, 4 * 3, 3,
                                                 ctl.data(), 4, 4, GL_MAP2_VERTEX_3);
  S.trims = gllab::core_trims(loops_of(s, reversed_outer));
  return S;
}

// Drawing -------------------------------------------------------------------
// One panel's camera: the hill seen from above, u to the right, v up, tilted
// 30° so that its height shows.
void camera(const State& s, const Panel& p) {
  gllab::ortho_fit(p.width, p.height, 3.4, 3.4, 20);
  gllab::enable_headlight();
  gllab::apply_orbit(s);
  glTranslated(0, 0.408, 0);  // up a little: the numbers go below
  glRotatef(-30.f, 1.f, 0.f, 0.f);
}

// How many triangles GLU makes of the hill with the lab's properties (read
// back from GLU's tessellator, gl/glu_nurbs.h: not the lesson).
std::string glu_triangles(const spline::BsplineSurface& S) {
  const gllab::GluNurbsProperties properties = gllab::GluNurbsProperties::of(g_nurb);
  return std::to_string(gllab::glu_triangle_count(S, properties, "trimmed hill")) + " triangles";
}

// The loops in (u, v) beside GLU's trimmed hill.
void draw_loops_and_hill(const State& s, bool reversed_outer) {
  const spline::BsplineSurface S = own_hill(s, reversed_outer);
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  gllab::draw_trim_domain(left, S.trims);  // the (u, v) square, pieces coloured by GLU call
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(s, right);
  glColor3f(kGlu.r, kGlu.g, kGlu.b);
  gllab::fill_then_edges([&](GLenum mode) { draw_glu_hill(s, reversed_outer, mode); }, {});
  gllab::draw_control_points(s, "P", {0.9f, 0.9f, 0.5f}, 7.f);
  gllab::leave_panels(s.width, s.height);
  draw_panel_caption(left, 0, "the 5 trim loops in (u, v)");
  draw_panel_caption(left, 1, "counter-clockwise: outer, island");
  draw_panel_caption(left, 2, "clockwise: the three holes");
  draw_panel_caption(right, 0, "gluNurbsSurface, trimmed");
  if (!reversed_outer) {
    draw_panel_caption(right, -2, gllab::fmt("GLU_DOMAIN_DISTANCE %g steps", s.get("steps")));
    draw_panel_caption(right, -1, glu_triangles(S));
    return;
  }
  try {  // GLU drew nothing (its error is below); the own core says which loop is wrong
    spline::validate_trim_loops(S.trims, spline::uv_domain(S));
  } catch (const spline::TrimLoopError& e) {
    const Panel all{0, 0, s.width, s.height, s.width, s.height};  // the whole window
    draw_panel_caption(all, 0, "own core: trim loop " + std::to_string(e.loop) + " " + e.summary);
    draw_panel_caption(all, 1, e.rule);
    draw_panel_caption(right, 3, "GLU drew nothing: see below");
  }
}

void draw_default(const State& s) { draw_loops_and_hill(s, false); }
// An error view: GLU raises NURBS error 28 and draws nothing (headless: exit 1).
void draw_reversed(const State& s) { draw_loops_and_hill(s, true); }

// GLU_OUTLINE_PATCH: the trim curves as GLU sampled them; beside it its triangles.
void draw_outline_patch(const State& s) {
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  camera(s, left);
  glDisable(GL_LIGHTING);
  glColor3f(kLine.r, kLine.g, kLine.b);
  glLineWidth(2.f);
  draw_glu_hill(s, false, GLU_OUTLINE_PATCH);
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(s, right);
  glColor3f(kGlu.r, kGlu.g, kGlu.b);
  gllab::fill_then_edges([&](GLenum mode) { draw_glu_hill(s, false, mode); }, kWire);
  gllab::leave_panels(s.width, s.height);
  draw_panel_caption(left, 0, "GLU_OUTLINE_PATCH:");
  draw_panel_caption(left, 1, "the trim curves GLU sampled");
  draw_panel_caption(right, 0, "GLU_OUTLINE_POLYGON");
  draw_panel_caption(right, 1, "over GLU_FILL");
  draw_panel_caption(right, -1, glu_triangles(own_hill(s, false)));
}

// init / shutdown ------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  glEnable(GL_AUTO_NORMAL);  // else GLU sends no normals (lab 21)
  g_nurb = gluNewNurbsRenderer();
  gluNurbsCallback(g_nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_nurbs_error));
  gluNurbsProperty(g_nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);  // GLU_U_STEP per unit of u
}

void shutdown() { gluDeleteNurbsRenderer(g_nurb); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "22_trimmed_nurbs",
      "lab 22 · trimmed NURBS surfaces",
      {{"default", "the trim loops in (u, v) and GLU's trimmed surface", draw_default, kOrbit},
       {"outline_patch", "GLU_OUTLINE_PATCH: the trim curves GLU sampled; its triangles",
        draw_outline_patch, kOrbit},
       {"reversed_outer_loop", "the outer loop clockwise: GLU NURBS error 28", draw_reversed,
        kOrbit | kErrorView}},
      {{"steps", 24, 2, 100, "GLU_DOMAIN_DISTANCE: GLU_U_STEP = GLU_V_STEP"},
       {"per_edge", 16, 1, 64, "points per edge of the densified polylines"}},
      {{'s', "GLU steps +4", "steps", +4}, {'S', "GLU steps -4", "steps", -4},
       {'e', "polyline points per edge +4", "per_edge", +4}, {'E', "per edge -4", "per_edge", -4}},
      init};
  lab.shutdown = shutdown;
  lab.points = {{"P", kHill, "control points P(i, j) of the hill, row by row (i along u)", 3}};
  lab.model = [](const State& s) -> gllab::Model { return own_hill(s, false); };
  return lab;
}
