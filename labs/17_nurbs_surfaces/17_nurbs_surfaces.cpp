// lab 17 · NURBS surfaces with gluNurbsSurface                 difficulty: ★★★☆
// A rational B-spline hill drawn by GLU's NURBS renderer (seed 000 §1.6
// "Displaying B-spline surfaces with OpenGL"), bicubic and biquadratic, lit
// with GL_AUTO_NORMAL; GLU's display modes, its five sampling methods with the
// triangles each makes (read back in capture mode), a display list beside the
// direct call, and the own spline core's tessellation beside GLU's.
// Notice: without GL_AUTO_NORMAL the surface gets one normal and looks flat.
//   GLU_PATH_LENGTH counts pixels, so a bigger picture gets more triangles; a
//   display list keeps the triangles it was compiled with (the seed's caution):
//   zoom in and only the direct call gets finer.
// Try: in sampling press [t] and [T]: which counts change about 4x per step?
//   Raise the weight to 10: where does the surface go? In difference,
//   --set mistake=1 feeds GLU (x, y, z, w) unmultiplied: how far off is it?
// Keys: [d]/[D] degree  [c] control net  [w]/[W] weight  [t]/[T] finer/coarser
//   sampling  [z]/[Z] zoom  [x] not premultiplied  [h] help  [Esc] quit
// Views: default, display_modes, sampling, display_list, own_vs_glu, difference
// Reference: reference_images/17_nurbs_surfaces__*.png

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/nurbs_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/surface.h"

namespace {

using gllab::GluNurbsProperties;
using gllab::fmt;
using gllab::Panel;
using gllab::State;
using gllab::spline::BsplineSurface;

// Lab data (edit me) -------------------------------------------------------
// A 5 x 5 control net over [-2, 2]^2, P(i, j) = (i - 2, j - 2, height) with i
// along u and j along v, row by row as BsplineSurface::P stores it (P[i * 5 + j]).
constexpr int kN = 5;
const std::vector<gllab::spline::Vec3> kNet = {
    {-2, -2, 0.0}, {-2, -1, 0.3}, {-2, 0, 0.5}, {-2, 1, 0.3}, {-2, 2, 0.0},
    {-1, -2, 0.3}, {-1, -1, 1.4}, {-1, 0, 1.8}, {-1, 1, 1.2}, {-1, 2, 0.4},
    {0, -2, 0.5},  {0, -1, 1.9},  {0, 0, 2.6},  {0, 1, 1.5},  {0, 2, 0.6},
    {1, -2, 0.2},  {1, -1, 1.0},  {1, 0, 1.4},  {1, 1, 0.4},  {1, 2, -0.4},
    {2, -2, 0.0},  {2, -1, 0.2},  {2, 0, 0.3},  {2, 1, -0.5}, {2, 2, -1.0}};
constexpr int kMiddle = 2 * kN + 2;  // P(2, 2): its weight is the `weight` parameter
const GLenum kMethods[] = {GLU_PATH_LENGTH, GLU_PARAMETRIC_ERROR, GLU_DOMAIN_DISTANCE, GLU_OBJECT_PATH_LENGTH,
                           GLU_OBJECT_PARAMETRIC_ERROR};
const char* kTolerances[] = {"path_px", "error_px", "steps", "object_length", "object_error"};  // their parameters
const char* kUnits[] = {"px per edge", "px off", "steps per unit", "units per edge", "units off"};
const gllab::Rgb kGlu{0.95f, 0.6f, 0.25f}, kOwn{0.35f, 0.65f, 0.95f}, kNetInk{0.9f, 0.9f, 0.5f},
    kWire{0.1f, 0.1f, 0.1f}, kText{1.f, 1.f, 1.f};

// The surface: degree p = q on clamped uniform knots, the dragged points,
// weight 1 everywhere but P(2, 2). Always rational: GLU gets GL_MAP2_VERTEX_4.
BsplineSurface surface_of(const State& s, int degree) {
  const std::vector<double> U = gllab::spline::clamped_uniform_knots(kN - 1, degree);
  std::vector<double> w(kN * kN, 1.0);
  w[kMiddle] = s.get("weight");
  return {degree, degree, U, U, kN, kN, s.points("P"), w, {}};  // no trims
}

// Drawing -------------------------------------------------------------------
// One panel's camera: the net's square tilted 60° towards us, turned 30°.
void camera(const Panel& p, double zoom = 1) {
  gllab::ortho_fit(p.width, p.height, 3.1 / zoom, 2.9 / zoom, 20);
  gllab::enable_headlight();  // a direction in eye space: set before the turns
  glRotatef(-60.f, 1.f, 0.f, 0.f);
  glRotatef(-30.f, 0.f, 0.f, 1.f);
}

void caption(const Panel& p, int line, const std::string& text) { gllab::draw_panel_caption(p, line, text, kText); }

// Sampling method k with its tolerance ([t]/[T] halve or double them all),
// and that tolerance as text.
GluNurbsProperties sampling(const State& s, int k, std::string* text = nullptr, GLenum mode = GLU_FILL) {
  const double finer = std::pow(2.0, s.get("finer"));
  const double value = k == 2 ? s.get(kTolerances[k]) * finer : s.get(kTolerances[k]) / finer;
  GluNurbsProperties p;
  p.sampling_method = kMethods[k];
  p.display_mode = mode;
  (k == 0 || k == 3 ? p.sampling_tolerance : p.parametric_tolerance) = float(value);
  p.u_step = p.v_step = float(s.get("steps") * finer);
  if (text) *text = fmt("%g ", value) + kUnits[k];
  return p;
}

// GLU draws in the current colour; the edges of its triangles on top.
void draw_glu(const BsplineSurface& S, const GluNurbsProperties& p, bool edges = true, bool auto_normal = true) {
  glColor3f(kGlu.r, kGlu.g, kGlu.b);
  gllab::draw_glu_surface(S, p, "hill", edges ? std::optional(kWire) : std::nullopt, auto_normal);
}

void draw_default(const State& s) {
  for (int degree : {3, 2}) {
    const Panel p = gllab::enter_panel(3 - degree, 0, 2, 1, s.width, s.height);
    camera(p);
    const BsplineSurface S = surface_of(s, degree);
    std::string tolerance;
    const GluNurbsProperties props = sampling(s, 0, &tolerance);
    draw_glu(S, props, false);
    const std::size_t n = gllab::glu_triangle_count(S, props, "hill");  // under the same matrices
    if (s.flag("net")) gllab::draw_control_net(S.P, kN, kN, kNetInk), gllab::draw_control_points(s, "P", kNetInk);
    std::string knots;
    for (double u : S.U) knots += fmt(" %.2g", u);
    caption(p, 0, degree == 3 ? "bicubic, p = q = 3" : "biquadratic, p = q = 2");
    caption(p, 1, "U = V =" + knots);
    caption(p, -2, "GLU_PATH_LENGTH " + tolerance);
    caption(p, -1, std::to_string(n) + " triangles");
  }
  gllab::leave_panels(s.width, s.height);
}

void draw_display_modes(const State& s, const BsplineSurface& S) {
  const GLenum modes[] = {GLU_FILL, GLU_OUTLINE_POLYGON, GLU_OUTLINE_PATCH, GLU_FILL};
  for (int k = 0; k < 4; ++k) {
    const Panel p = gllab::enter_panel(k % 2, k / 2, 2, 2, s.width, s.height);
    camera(p);
    draw_glu(S, sampling(s, 0, nullptr, modes[k]), false, k != 3);  // the last one without GL_AUTO_NORMAL
    caption(p, 0, gllab::glu_enum_name(modes[k]) + (k == 3 ? ", no GL_AUTO_NORMAL" : ""));
  }
  gllab::leave_panels(s.width, s.height);
}

void draw_sampling(const State& s, const BsplineSurface& S) {
  for (int k = 0; k < 5; ++k) {
    const Panel p = gllab::enter_panel(k % 2, k / 2, 2, 3, s.width, s.height);
    camera(p);
    std::string tolerance;
    const GluNurbsProperties props = sampling(s, k, &tolerance);
    draw_glu(S, props);
    caption(p, 0, gllab::glu_enum_name(kMethods[k]));
    caption(p, 1, tolerance);
    caption(p, -1, std::to_string(gllab::glu_triangle_count(S, props, "hill")) + " triangles");
  }
  gllab::leave_panels(s.width, s.height);
}

// The display list: compiled for the data it draws, never for the camera.
GLuint g_list = 0;
std::string g_list_key;  // the state it was compiled from (all but the zoom)
std::size_t g_list_triangles = 0;

void compile_list_if_stale(const State& s, const BsplineSurface& S, const GluNurbsProperties& props) {
  State unzoomed = s;  // the key: every parameter and point but the zoom, and the window size
  unzoomed.set("zoom", 1);
  const std::string key = unzoomed.as_arguments() + fmt(" %g", s.width) + fmt("x%g", s.height);
  if (key == g_list_key) return;
  g_list_key = key;
  g_list_triangles = gllab::glu_triangle_count(S, props, "hill");
  glNewList(g_list, GL_COMPILE);  // GLU samples now, under these matrices
  draw_glu(S, props);
  glEndList();
}

void draw_display_list(const State& s, const BsplineSurface& S) {
  const GluNurbsProperties props = sampling(s, 0);
  const double zoom = s.get("zoom");
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  camera(left, zoom);
  draw_glu(S, props);  // GLU samples again, at this zoom
  const std::size_t direct = gllab::glu_triangle_count(S, props, "hill");
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(right);
  compile_list_if_stale(s, S, props);
  camera(right, zoom);
  glCallList(g_list);
  gllab::leave_panels(s.width, s.height);
  caption(left, 0, "gluNurbsSurface, zoom " + fmt("%g", zoom));
  caption(left, -1, "direct call: " + std::to_string(direct) + " triangles");
  caption(right, 0, "glCallList, zoom " + fmt("%g", zoom));
  caption(right, 1, "(compiled at zoom 1)");
  caption(right, -1, "display list: " + std::to_string(g_list_triangles) + " triangles");
}

void draw_own_vs_glu(const State& s, const BsplineSurface& S) {
  const GluNurbsProperties props = sampling(s, 4);  // GLU_OBJECT_PARAMETRIC_ERROR
  const double tol = props.parametric_tolerance;
  const auto surface = gllab::spline::surface_evaluator(S);
  const gllab::spline::Mesh own = gllab::spline::tessellate_surface(
      surface, gllab::spline::uv_domain(S), gllab::spline::TessellationOptions::adaptive(tol));
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  camera(left);
  draw_glu(S, props);
  const gllab::spline::Mesh glu = gllab::GluNurbs(props).capture_surface(S, "hill").mesh;
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  camera(right);
  glColor3f(kOwn.r, kOwn.g, kOwn.b);
  gllab::draw_mesh_with_edges(own, kWire);
  gllab::leave_panels(s.width, s.height);
  const std::pair<const gllab::spline::Mesh*, Panel> sides[] = {{&glu, left}, {&own, right}};
  for (const auto& [mesh, p] : sides) {
    caption(p, 0, mesh == &glu ? "GLU_OBJECT_PARAMETRIC_ERROR" : "own core, tessellate_surface");
    caption(p, 1, fmt("tolerance %g", tol));
    caption(p, -2, std::to_string(mesh->triangles.size()) + " triangles");
    const double off = gllab::spline::mesh_fidelity(*mesh, surface, 180).max_deviation;  // tessellate.h's measure
    caption(p, -1, "max deviation " + fmt("%.2e", off));
  }
}

// A distance on a log scale: 1e-8 (blue) to 1e-5 and beyond (red).
gllab::Rgb heat(double d) {
  const double t = std::clamp((std::log10(std::max(d, 1e-12)) + 8) / 3, 0.0, 1.0);
  return {float(std::min(1.0, 2 * t)), float(1 - std::abs(2 * t - 1) * 0.6), float(std::max(0.0, 1 - 2 * t))};
}

void draw_difference(const State& s, const BsplineSurface& S) {
  const Panel p = gllab::enter_panel(0, 0, 1, 1, s.width, s.height);
  camera(p);
  const bool mistake = s.flag("mistake");
  const auto feed = mistake ? gllab::RationalFeed::kMistakeNotPremultiplied : gllab::RationalFeed::kPremultiplied;
  const gllab::spline::Mesh m = gllab::GluNurbs(sampling(s, 2)).capture_surface(S, "hill", feed).mesh;
  // Each GLU vertex against the own surface at the (u, v) GLU evaluated there.
  double worst = 0;
  glDisable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  for (const auto& t : m.triangles)
    for (int k : t) {
      const double d = norm(m.positions[k] - gllab::spline::surface_point(S, m.uv[k].x, m.uv[k].y));
      worst = std::max(worst, d);
      const gllab::Rgb c = heat(d);
      glColor3f(c.r, c.g, c.b);
      glVertex3d(m.positions[k].x, m.positions[k].y, m.positions[k].z);
    }
  glEnd();
  gllab::leave_panels(s.width, s.height);
  caption(p, 0, std::string("|GLU vertex - S(u, v)|, ") + (mistake ? "not premultiplied" : "premultiplied"));
  caption(p, -2, "max |GLU - S(u,v)| = " + fmt("%.2e", worst));
  for (int e = 0; e < 4; ++e)  // the colour scale
    gllab::draw_text(s.width / 2 - 136 + 72 * e, s.height - 20, fmt("1e-%g", 8 - e), heat(std::pow(10, e - 8)));
}

// init / display ----------------------------------------------------------
void init() {
  g_list = glGenLists(1);  // one name for the program's life
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

void display(const State& s) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const BsplineSurface S = surface_of(s, s.integer("degree"));
  const std::string& v = s.view();
  if (v == "display_modes") draw_display_modes(s, S);
  else if (v == "sampling") draw_sampling(s, S);
  else if (v == "display_list") draw_display_list(s, S);
  else if (v == "own_vs_glu") draw_own_vs_glu(s, S);
  else if (v == "difference") draw_difference(s, S);
  else draw_default(s);
}

void shutdown() { glDeleteLists(g_list, 1); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"17_nurbs_surfaces",
                 "lab 17 · NURBS surfaces with gluNurbsSurface",
                 {{"default", "bicubic and biquadratic gluNurbsSurface, GL_AUTO_NORMAL, control net, triangle counts"},
                  {"display_modes", "the three GLU_DISPLAY_MODEs, and GLU_FILL without GL_AUTO_NORMAL"},
                  {"sampling", "the five GLU_SAMPLING_METHODs with their tolerances and triangle counts"},
                  {"display_list", "direct call vs a display list compiled at zoom 1, both zoomed"},
                  {"own_vs_glu", "GLU_OBJECT_PARAMETRIC_ERROR vs the own tessellation at the same tolerance"},
                  {"difference", "GLU's vertices coloured by their distance to the own S(u, v)"}},
                 {{"degree", 3, 2, 3, "degree p = q of every view but default: 3 bicubic, 2 biquadratic"},
                  {"weight", 2, 0.25, 10, "weight of the middle control point P(2, 2)"},
                  {"net", 1, 0, 1, "default: show the control net"},
                  {"path_px", 40, 1, 200, "GLU_PATH_LENGTH: longest edge, pixels"},
                  {"error_px", 2, 0.05, 20, "GLU_PARAMETRIC_ERROR: distance to the surface, pixels"},
                  {"steps", 8, 1, 100, "GLU_DOMAIN_DISTANCE: GLU_U_STEP = GLU_V_STEP, samples per unit"},
                  {"object_length", 1, 0.01, 2, "GLU_OBJECT_PATH_LENGTH: longest edge, object units"},
                  {"object_error", 0.03, 0.0005, 1, "GLU_OBJECT_PARAMETRIC_ERROR, and own_vs_glu's tolerance"},
                  {"finer", 0, -3, 3, "every tolerance / 2^finer, steps x 2^finer"},
                  {"zoom", 3, 1, 8, "display_list: camera zoom (the list was compiled at 1)"},
                  {"mistake", 0, 0, 1, "difference: feed GLU (x, y, z, w) not premultiplied"}},
                 {{'d', "degree +1 (bicubic)", "degree", +1}, {'D', "degree -1 (biquadratic)", "degree", -1},
                  {'c', "control net on/off (default)", "net"}, {'x', "not premultiplied (difference)", "mistake"},
                  {'w', "weight of P(2, 2) +0.5", "weight", +0.5}, {'W', "weight of P(2, 2) -0.5", "weight", -0.5},
                  {'t', "finer sampling (tolerances / 2)", "finer", +1}, {'T', "coarser (x 2)", "finer", -1},
                  {'z', "zoom +1 (display_list)", "zoom", +1}, {'Z', "zoom -1 (display_list)", "zoom", -1}},
                 init,
                 display};
  lab.shutdown = shutdown;
  lab.points = {{"P", kNet, "control points P(i, j), row by row (i along u)", 3}};
  lab.model = [](const State& s) -> gllab::Model { return surface_of(s, s.integer("degree")); };
  return lab;
}
