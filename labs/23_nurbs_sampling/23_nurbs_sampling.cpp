// lab 23 · GLU's sampling methods                               difficulty: ★★★☆
// How GLU decides how many triangles a NURBS surface gets (lecture notes ch. 1,
// §1.6 Spline representations, "Displaying B-spline surfaces with OpenGL": "The
// approximation depends on the viewing distance"): the five GLU_SAMPLING_METHODs
// on lab 21's hill, each with its tolerance, and the triangles each makes.
// Notice: halving an edge length about quadruples the triangles, halving an
//   error bound about doubles them. GLU_PATH_LENGTH and GLU_PARAMETRIC_ERROR
//   count pixels, so a bigger picture gets more triangles; the object-space
//   methods and GLU_DOMAIN_DISTANCE do not care how big the picture is.
// Try: in methods press [t] and [T]: which counts change about 4x per step?
//   In picture_size press [z]: which row's counts follow the zoom?
// Keys: [t]/[T] finer/coarser  [w]/[W] weight  [z]/[Z] zoom (picture_size)
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: methods, picture_size
// Reference: reference_images/23_nurbs_sampling__*.png

#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_arrays.h"
#include "gl/glu_errors.h"
#include "gl/nurbs_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

namespace spline = gllab::spline;
using gllab::draw_panel_caption;
using gllab::fmt;
using gllab::Panel;
using gllab::State;

// Lab data (edit me) -------------------------------------------------------
// Lab 21's hill: a 5 x 5 net over [-2, 2]^2, i along u, row by row; weight 1
// but P(2, 2)'s; bicubic on clamped uniform knots.
const spline::Vec3 kNet[25] = {
    {-2, -2, 0.0}, {-2, -1, 0.3}, {-2, 0, 0.5}, {-2, 1, 0.3}, {-2, 2, 0.0},
    {-1, -2, 0.3}, {-1, -1, 1.4}, {-1, 0, 1.8}, {-1, 1, 1.2}, {-1, 2, 0.4},
    {0, -2, 0.5},  {0, -1, 1.9},  {0, 0, 2.6},  {0, 1, 1.5},  {0, 2, 0.6},
    {1, -2, 0.2},  {1, -1, 1.0},  {1, 0, 1.4},  {1, 1, 0.4},  {1, 2, -0.4},
    {2, -2, 0.0},  {2, -1, 0.2},  {2, 0, 0.3},  {2, 1, -0.5}, {2, 2, -1.0}};
constexpr int kMiddle = 2 * 5 + 2;
GLfloat kKnots[9] = {0, 0, 0, 0, .5f, 1, 1, 1, 1};
const GLint kKnotCount = GLint(std::size(kKnots));
// The sampling methods, each with the parameter that holds its tolerance, the
// GLU property that takes it, and its unit.
struct Method { GLenum method, property; const char* param; const char* unit; };
const Method kMethods[] = {
    {GLU_PATH_LENGTH, GLU_SAMPLING_TOLERANCE, "path_px", "px per edge"},
    {GLU_PARAMETRIC_ERROR, GLU_PARAMETRIC_TOLERANCE, "error_px", "px off"},
    {GLU_DOMAIN_DISTANCE, GLU_U_STEP, "steps", "steps per unit"},  // and GLU_V_STEP
    {GLU_OBJECT_PATH_LENGTH, GLU_SAMPLING_TOLERANCE, "object_length", "units per edge"},
    {GLU_OBJECT_PARAMETRIC_ERROR, GLU_PARAMETRIC_TOLERANCE, "object_error", "units off"}};
const gllab::Rgb kGlu{0.95f, 0.6f, 0.25f}, kWire{0.1f, 0.1f, 0.1f};

// One GLU NURBS object per method, made in init(). An object keeps what it
// sampled with: switched from GLU_DOMAIN_DISTANCE to an object-space method,
// one object went on drawing the domain grid (measured, GLU 9.0.2).
GLUnurbs* g_nurbs[5] = {};

// GLU calls this inside the failing call (never exit(0), as the Red Book does).
void GLAPIENTRY on_nurbs_error(GLenum code) { gllab::report_glu_error(code, "the hill"); }

// The hill through GLU ----------------------------------------------------------
// GL_MAP2_VERTEX_4 takes every point premultiplied by its weight, (w x, w y, w z, w).
std::vector<GLfloat> rational_net(const State& s) {
  std::vector<GLfloat> ctl;
  for (int k = 0; k < 25; ++k) {
    const double w = k == kMiddle ? s.get("weight") : 1.0;
    const spline::Vec3 p = kNet[k];
    ctl.insert(ctl.end(), {GLfloat(w * p.x), GLfloat(w * p.y), GLfloat(w * p.z), GLfloat(w)});
  }
  return ctl;
}

// Method k's tolerance ([t]/[T] halve or double every one; the steps double).
double tolerance(const State& s, int k) {
  const double finer = std::pow(2.0, s.get("finer"));
  return k == 2 ? s.get(kMethods[k].param) * finer : s.get(kMethods[k].param) / finer;
}

void draw_hill(const State& s, int k, GLenum display_mode) {
  GLUnurbs* nurb = g_nurbs[k];
  std::vector<GLfloat> ctl = rational_net(s);
  gluNurbsProperty(nurb, kMethods[k].property, GLfloat(tolerance(s, k)));
  // GLU 9.0.2 reads the steps for GLU_PATH_LENGTH too (lab 21): they are set for all.
  gluNurbsProperty(nurb, GLU_U_STEP, GLfloat(tolerance(s, 2)));
  gluNurbsProperty(nurb, GLU_V_STEP, GLfloat(tolerance(s, 2)));
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLfloat(display_mode));
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, kKnotCount, kKnots, kKnotCount, kKnots, 5 * 4, 4, ctl.data(), 4, 4,
                  GL_MAP2_VERTEX_4);
  gluEndSurface(nurb);
}

// How many triangles method k makes of the hill under the current matrices,
// read back from GLU's tessellator (gl/glu_nurbs.h: not the lesson).
std::string triangles(const State& s, int k) {
  const std::vector<GLfloat> ctl = rational_net(s);
  const spline::BsplineSurface S =
      gllab::core_surface(kKnotCount, kKnots, kKnotCount, kKnots, 5 * 4, 4, ctl.data(), 4, 4,
                          GL_MAP2_VERTEX_4);
  const gllab::GluNurbsProperties p = gllab::GluNurbsProperties::of(g_nurbs[k]);
  return std::to_string(gllab::glu_triangle_count(S, p, "hill")) + " triangles";
}

// Drawing -------------------------------------------------------------------
// One panel's camera: lab 21's, the net's square tilted 60° towards us.
void camera(const State& s, const Panel& p, double zoom = 1) {
  gllab::ortho_fit(p.width, p.height, 3.1 / zoom, 2.9 / zoom, 20);
  gllab::enable_headlight();
  gllab::apply_orbit(s);
  glRotatef(-60.f, 1.f, 0.f, 0.f);
  glRotatef(-30.f, 0.f, 0.f, 1.f);
}

// GLU's hill lit in its colour, its triangles' edges on top.
void draw_glu(const State& s, int k) {
  glColor3f(kGlu.r, kGlu.g, kGlu.b);
  gllab::fill_then_edges([&](GLenum mode) { draw_hill(s, k, mode); }, kWire);
}

void draw_methods(const State& s) {
  for (int k = 0; k < 5; ++k) {
    const Panel p = gllab::enter_panel(k % 2, k / 2, 2, 3, s.width, s.height);
    camera(s, p);
    draw_glu(s, k);
    draw_panel_caption(p, 0, gllab::glu_enum_name(kMethods[k].method));
    draw_panel_caption(p, 1, fmt("%g ", tolerance(s, k)) + kMethods[k].unit);
    draw_panel_caption(p, -1, triangles(s, k));  // under the same matrices
  }
  gllab::leave_panels(s.width, s.height);
}

// The same edge length in pixels and in object units, each at zoom 1 and at
// `zoom`: only the pixels follow the picture.
void draw_picture_size(const State& s) {
  const double zooms[2] = {1, s.get("zoom")};
  for (int row = 0; row < 2; ++row) {
    const int k = row == 0 ? 0 : 3;  // GLU_PATH_LENGTH, GLU_OBJECT_PATH_LENGTH
    for (int col = 0; col < 2; ++col) {
      const Panel p = gllab::enter_panel(col, row, 2, 2, s.width, s.height);
      camera(s, p, zooms[col]);
      draw_glu(s, k);
      draw_panel_caption(p, 0, gllab::glu_enum_name(kMethods[k].method));
      draw_panel_caption(p, -2, fmt("%g ", tolerance(s, k)) + kMethods[k].unit);
      draw_panel_caption(p, -1, fmt("zoom %g: ", zooms[col]) + triangles(s, k));
    }
  }
  gllab::leave_panels(s.width, s.height);
}

// init / shutdown ------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  glEnable(GL_AUTO_NORMAL);  // else GLU sends no normals (lab 21)
  for (int k = 0; k < 5; ++k) {
    g_nurbs[k] = gluNewNurbsRenderer();
    gluNurbsCallback(g_nurbs[k], GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_nurbs_error));
    // An object-space method turns GLU_AUTO_LOAD_MATRIX off: it samples without
    // the GL matrices, in object units.
    gluNurbsProperty(g_nurbs[k], GLU_SAMPLING_METHOD, GLfloat(kMethods[k].method));
  }
}

void shutdown() { for (GLUnurbs* nurb : g_nurbs) gluDeleteNurbsRenderer(nurb); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "23_nurbs_sampling",
      "lab 23 · GLU's sampling methods",
      {{"methods", "the five GLU_SAMPLING_METHODs with their tolerances and triangle counts",
        draw_methods, kOrbit},
       {"picture_size", "GLU_PATH_LENGTH and GLU_OBJECT_PATH_LENGTH at zoom 1 and zoomed in",
        draw_picture_size, kOrbit}},
      {{"weight", 2, 0.25, 10, "weight of the middle control point P(2, 2)"},
       {"path_px", 40, 1, 200, "GLU_PATH_LENGTH: longest edge, pixels"},
       {"error_px", 2, 0.05, 20, "GLU_PARAMETRIC_ERROR: distance to the surface, pixels"},
       {"steps", 8, 1, 100, "GLU_DOMAIN_DISTANCE: GLU_U_STEP = GLU_V_STEP, per unit"},
       {"object_length", 1, 0.01, 2, "GLU_OBJECT_PATH_LENGTH: longest edge, object units"},
       {"object_error", 0.03, 0.0005, 1, "GLU_OBJECT_PARAMETRIC_ERROR: distance, object units"},
       {"finer", 0, -3, 3, "every tolerance / 2^finer, steps x 2^finer"},
       {"zoom", 1.5, 1, 4, "picture_size: the right column's zoom"}},
      {{'t', "finer sampling (tolerances / 2)", "finer", +1}, {'T', "coarser (x 2)", "finer", -1},
       {'w', "weight of P(2, 2) +0.5", "weight", +0.5}, {'W', "weight -0.5", "weight", -0.5},
       {'z', "zoom +0.5 (picture_size)", "zoom", +0.5}, {'Z', "zoom -0.5", "zoom", -0.5}},
      init};
  lab.shutdown = shutdown;
  return lab;
}
