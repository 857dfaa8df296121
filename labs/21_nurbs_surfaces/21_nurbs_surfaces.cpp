// lab 21 · NURBS surfaces with gluNurbsSurface                 difficulty: ★★★☆
// A rational B-spline hill drawn by GLU's NURBS renderer (lecture notes ch. 1,
// §1.6 Spline representations, "Displaying B-spline surfaces with OpenGL"),
// bicubic and biquadratic, lit with GL_AUTO_NORMAL; GLU's display modes, and a
// display list beside the direct call (both bicubic). Lab 23 shows GLU's
// sampling methods, lab 24 the own core's tessellation of the same hill.
// Notice: without GL_AUTO_NORMAL the surface gets one normal and looks flat.
//   A display list keeps the triangles it was compiled with (the notes'
//   caution): zoom in and only the direct call gets finer.
// Try: raise the weight to 10: where does the hill go? In display_list zoom in: how
//   many triangles would the list need at zoom 8?
// Keys: [c] control net  [w]/[W] weight  [t]/[T] finer/coarser
//   [z]/[Z] zoom  right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: default, display_modes, display_list
// Reference: reference_images/21_nurbs_surfaces__*.png

#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_arrays.h"
#include "gl/glu_errors.h"
#include "gl/nurbs_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"

namespace {

namespace spline = gllab::spline;
using gllab::draw_panel_caption;
using gllab::fmt;
using gllab::Panel;
using gllab::State;

// Lab data (edit me) -------------------------------------------------------
// A 5 x 5 control net over [-2, 2]^2, P(i, j) = (i - 2, j - 2, height), i along
// u, row by row; [mouse] drags them (point list P). Weights 1 but P(2, 2)'s.
const std::vector<spline::Vec3> kNet = {
    {-2, -2, 0.0}, {-2, -1, 0.3}, {-2, 0, 0.5}, {-2, 1, 0.3}, {-2, 2, 0.0},
    {-1, -2, 0.3}, {-1, -1, 1.4}, {-1, 0, 1.8}, {-1, 1, 1.2}, {-1, 2, 0.4},
    {0, -2, 0.5},  {0, -1, 1.9},  {0, 0, 2.6},  {0, 1, 1.5},  {0, 2, 0.6},
    {1, -2, 0.2},  {1, -1, 1.0},  {1, 0, 1.4},  {1, 1, 0.4},  {1, 2, -0.4},
    {2, -2, 0.0},  {2, -1, 0.2},  {2, 0, 0.3},  {2, 1, -0.5}, {2, 2, -1.0}};
constexpr int kMiddle = 2 * 5 + 2;  // P(2, 2): its weight is the `weight` parameter
constexpr int kBicubic = 3;         // the degree of display_modes and display_list
// Clamped uniform knots for 5 points (lecture notes "Higher Order Surfaces",
// "Nonperiodic Knot Vectors"), on [0, 1]: bicubic (order 4) and biquadratic.
GLfloat kCubic[9] = {0, 0, 0, 0, .5f, 1, 1, 1, 1};
GLfloat kQuadratic[8] = {0, 0, 0, 1 / 3.f, 2 / 3.f, 1, 1, 1};
const gllab::Rgb kGlu{0.95f, 0.6f, 0.25f}, kNetInk{0.9f, 0.9f, 0.5f}, kWire{0.1f, 0.1f, 0.1f};

// One GLU NURBS object, made in init() as the Red Book's surface.c does.
GLUnurbs* g_nurb = nullptr;

// GLU calls this inside the failing call (never exit(0), as the Red Book does).
void GLAPIENTRY on_nurbs_error(GLenum code) { gllab::report_glu_error(code, "the hill"); }

// The hill through GLU ----------------------------------------------------------
// The arrays gluNurbsSurface takes for one degree: GL_MAP2_VERTEX_4 wants every
// point premultiplied by its weight, (w x, w y, w z, w); P(i, j) at (5 i + j) * 4.
struct Hill { std::vector<GLfloat> ctl; GLfloat* knots; GLint knot_count, order; };
Hill hill_of(const State& s, int degree) {
  Hill h{{}, kCubic, GLint(std::size(kCubic)), degree + 1};
  if (degree == 2) h.knots = kQuadratic, h.knot_count = GLint(std::size(kQuadratic));
  for (int k = 0; k < 25; ++k) {
    const spline::Vec3 p = s.points("P")[k];
    const double w = k == kMiddle ? s.get("weight") : 1.0;
    h.ctl.insert(h.ctl.end(), {GLfloat(w * p.x), GLfloat(w * p.y), GLfloat(w * p.z), GLfloat(w)});
  }
  return h;
}

// GLU_PATH_LENGTH (init()): no edge longer than this many pixels ([t]/[T] halve or double it).
double path_px(const State& s) { return s.get("path_px") / std::pow(2.0, s.get("finer")); }

void draw_hill(const State& s, int degree, GLenum display_mode) {
  Hill h = hill_of(s, degree);
  gluNurbsProperty(g_nurb, GLU_SAMPLING_TOLERANCE, GLfloat(path_px(s)));
  gluNurbsProperty(g_nurb, GLU_DISPLAY_MODE, GLfloat(display_mode));
  gluBeginSurface(g_nurb);
  gluNurbsSurface(g_nurb, h.knot_count, h.knots, h.knot_count, h.knots, 5 * 4, 4, h.ctl.data(),
                  h.order, h.order, GL_MAP2_VERTEX_4);
  gluEndSurface(g_nurb);
}

// The same hill for the own core (gl/glu_arrays.h), for the numbers.
spline::BsplineSurface own_hill(const State& s, int degree) {
  const Hill h = hill_of(s, degree);
  return gllab::core_surface(h.knot_count, h.knots, h.knot_count, h.knots, 5 * 4, 4, h.ctl.data(),
                             h.order, h.order, GL_MAP2_VERTEX_4);
}

// How many triangles GLU makes of it with the same properties, under the
// current matrices (read back from GLU's tessellator: not the lesson).
std::string triangles(const State& s, int degree) {
  const gllab::GluNurbsProperties p = gllab::GluNurbsProperties::of(g_nurb);
  return std::to_string(gllab::glu_triangle_count(own_hill(s, degree), p, "hill")) + " triangles";
}

// Drawing -------------------------------------------------------------------
// One panel's camera: the net's square tilted 60° towards us, turned 30°.
void camera(const State& s, const Panel& p, double zoom = 1) {
  gllab::ortho_fit(p.width, p.height, 3.1 / zoom, 2.9 / zoom, 20);
  gllab::enable_headlight();  // a direction in eye space: set before the turns
  gllab::apply_orbit(s);
  glRotatef(-60.f, 1.f, 0.f, 0.f);
  glRotatef(-30.f, 0.f, 0.f, 1.f);
}

// GLU's hill in its colour, lit, its triangles' edges on top if asked.
void draw_glu(const State& s, int degree, bool edges) {
  glColor3f(kGlu.r, kGlu.g, kGlu.b);
  gllab::fill_then_edges([&](GLenum mode) { draw_hill(s, degree, mode); },
                         edges ? std::optional(kWire) : std::nullopt);
}

void draw_default(const State& s) {
  for (int degree : {3, 2}) {
    const Panel p = gllab::enter_panel(3 - degree, 0, 2, 1, s.width, s.height);
    camera(s, p);
    draw_glu(s, degree, false);
    const std::string count = triangles(s, degree);  // under the same matrices
    if (s.flag("net")) gllab::draw_control_net(s.points("P"), 5, 5, kNetInk);
    if (s.flag("net")) gllab::draw_control_points(s, "P", kNetInk);  // [mouse] drags them
    std::string knots;
    for (double u : own_hill(s, degree).U) knots += fmt(" %.2g", u);
    draw_panel_caption(p, 0, degree == 3 ? "bicubic, p = q = 3" : "biquadratic, p = q = 2");
    draw_panel_caption(p, 1, "U = V =" + knots);
    draw_panel_caption(p, -2, fmt("GLU_PATH_LENGTH %g px per edge", path_px(s)));
    draw_panel_caption(p, -1, count);
  }
  gllab::leave_panels(s.width, s.height);
}

// GLU_FILL, its triangles' edges (GLU_OUTLINE_POLYGON), the patches' boundaries
// (GLU_OUTLINE_PATCH), and GLU_FILL without GL_AUTO_NORMAL.
void draw_display_modes(const State& s) {
  const GLenum modes[] = {GLU_FILL, GLU_OUTLINE_POLYGON, GLU_OUTLINE_PATCH, GLU_FILL};
  for (int k = 0; k < 4; ++k) {
    const Panel p = gllab::enter_panel(k % 2, k / 2, 2, 2, s.width, s.height);
    camera(s, p);
    glColor3f(kGlu.r, kGlu.g, kGlu.b);
    if (k == 3) {  // GLU sends no normals: every vertex keeps the current one
      glDisable(GL_AUTO_NORMAL);
      glNormal3f(0.f, 0.f, 1.f);
    }
    if (modes[k] == GLU_FILL) {
      draw_glu(s, kBicubic, false);
    } else {  // lines in kGlu, unlit
      glDisable(GL_LIGHTING);
      draw_hill(s, kBicubic, modes[k]);
      glEnable(GL_LIGHTING);
    }
    const std::string name = gllab::glu_enum_name(modes[k]);
    draw_panel_caption(p, 0, k == 3 ? name + ", no GL_AUTO_NORMAL" : name);
  }
  gllab::leave_panels(s.width, s.height);
}

// The display list: compiled for the data it draws, never for the camera.
GLuint g_list = 0;
std::string g_list_key, g_list_triangles;  // the state it was compiled from (all but the zoom)

void compile_list_if_stale(const State& s) {
  State unzoomed = s;  // the key: every parameter and point but the zoom, and the window size
  unzoomed.set("zoom", 1);
  const std::string key = unzoomed.as_arguments() + fmt(" %g", s.width) + fmt("x%g", s.height);
  if (key == g_list_key) return;
  g_list_key = key;
  g_list_triangles = triangles(s, kBicubic);
  glNewList(g_list, GL_COMPILE);  // GLU samples now, under these matrices
  draw_glu(s, kBicubic, true);
  glEndList();
}

void draw_display_list(const State& s) {
  const double zoom = s.get("zoom");
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  camera(s, left, zoom);
  draw_glu(s, kBicubic, true);  // GLU samples again, at this zoom
  const std::string direct = triangles(s, kBicubic);
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(s, right);
  compile_list_if_stale(s);
  camera(s, right, zoom);
  glCallList(g_list);
  gllab::leave_panels(s.width, s.height);
  draw_panel_caption(left, 0, "gluNurbsSurface, zoom " + fmt("%g", zoom));
  draw_panel_caption(left, -1, "direct call: " + direct);
  draw_panel_caption(right, 0, "glCallList, zoom " + fmt("%g", zoom));
  draw_panel_caption(right, 1, "(compiled at zoom 1)");
  draw_panel_caption(right, -1, "display list: " + g_list_triangles);
}

// init / shutdown ------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  // GL's evaluators, which GLU's renderer drives, compute a normal at every
  // vertex only with GL_AUTO_NORMAL: without it the lit hill is one flat colour.
  glEnable(GL_AUTO_NORMAL);
  g_list = glGenLists(1);  // one name for the program's life
  g_nurb = gluNewNurbsRenderer();
  gluNurbsCallback(g_nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_nurbs_error));
  gluNurbsProperty(g_nurb, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH);  // GLU's default, in pixels
  // GLU 9.0.2 reads GLU_U_STEP and GLU_V_STEP for it too: with 8 the bicubic hill
  // takes 389 triangles, with GLU's default 100 it takes 455 (measured).
  gluNurbsProperty(g_nurb, GLU_U_STEP, 8.f);
  gluNurbsProperty(g_nurb, GLU_V_STEP, 8.f);
}

void shutdown() {
  glDeleteLists(g_list, 1);
  gluDeleteNurbsRenderer(g_nurb);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "21_nurbs_surfaces",
      "lab 21 · NURBS surfaces with gluNurbsSurface",
      {{"default", "bicubic and biquadratic gluNurbsSurface, the control net, triangles",
        draw_default, kOrbit},
       {"display_modes", "the three GLU_DISPLAY_MODEs, and GLU_FILL without GL_AUTO_NORMAL",
        draw_display_modes, kOrbit},
       {"display_list", "direct call vs a display list compiled at zoom 1, both zoomed",
        draw_display_list, kOrbit}},
      {{"weight", 2, 0.25, 10, "weight of the middle control point P(2, 2)"},
       {"net", 1, 0, 1, "default: show the control net"},
       {"path_px", 40, 1, 200, "GLU_PATH_LENGTH: longest edge, pixels"},
       {"finer", 0, -3, 3, "path_px / 2^finer"},
       {"zoom", 3, 1, 8, "display_list: camera zoom (the list was compiled at 1)"}},
      {{'c', "control net on/off (default)", "net"},
       {'w', "weight of P(2, 2) +0.5", "weight", +0.5}, {'W', "weight -0.5", "weight", -0.5},
       {'t', "finer sampling (path_px / 2)", "finer", +1}, {'T', "coarser (x 2)", "finer", -1},
       {'z', "zoom +1 (display_list)", "zoom", +1}, {'Z', "zoom -1 (display_list)", "zoom", -1}},
      init};
  lab.shutdown = shutdown;
  lab.points = {{"P", kNet, "control points P(i, j), row by row (i along u)", 3}};
  lab.model = [](const State& s) -> gllab::Model { return own_hill(s, kBicubic); };
  return lab;
}
