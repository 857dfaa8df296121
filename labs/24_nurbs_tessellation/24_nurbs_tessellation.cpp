// lab 24 · NURBS tessellation: the own core against GLU         difficulty: ★★★★
// How finely must a surface be cut into triangles (lecture notes ch. 1, §1.2
// Polygonal representation: "What polygonal resolution is required for a
// precise representation?")? The own core's adaptive tessellation
// (spline::tessellate_surface, common/spline/tessellate.h) beside GLU's on lab
// 21's hill: triangles, and how far each mesh strays from the true surface.
// GLU's triangles are read back from its tessellator (capture mode) and drawn
// the same way as the own ones. Lab 25 does the same for trimmed surfaces.
// Notice: at one tolerance the own core needs fewer triangles than GLU, and
//   uses its tolerance more fully. GLU's vertices lie on the surface to float
//   precision; fed (x, y, z, w) instead of (w x, w y, w z, w), they do not.
// Try: press [t] three times: how do both triangle counts grow? In difference
//   press [x]: where is GLU's surface farthest off, and why not at the edges?
// Keys: [t]/[T] finer/coarser  [w]/[W] weight  [x] not premultiplied
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: own_vs_glu, difference
// Reference: reference_images/24_nurbs_tessellation__*.png

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_nurbs.h"
#include "gl/nurbs_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/surface.h"
#include "spline/tessellate.h"

namespace {

namespace sp = gllab::spline;
using gllab::draw_panel_caption;
using gllab::fmt;
using gllab::Panel;
using gllab::State;

// Lab data (edit me) -------------------------------------------------------
// Lab 21's hill: 5 x 5 points over [-2, 2]^2, bicubic on clamped uniform
// knots, every weight 1 but P(2, 2)'s (the `weight` parameter).
const std::vector<sp::Vec3> kNet = {
    {-2, -2, 0.0}, {-2, -1, 0.3}, {-2, 0, 0.5}, {-2, 1, 0.3}, {-2, 2, 0.0},
    {-1, -2, 0.3}, {-1, -1, 1.4}, {-1, 0, 1.8}, {-1, 1, 1.2}, {-1, 2, 0.4},
    {0, -2, 0.5},  {0, -1, 1.9},  {0, 0, 2.6},  {0, 1, 1.5},  {0, 2, 0.6},
    {1, -2, 0.2},  {1, -1, 1.0},  {1, 0, 1.4},  {1, 1, 0.4},  {1, 2, -0.4},
    {2, -2, 0.0},  {2, -1, 0.2},  {2, 0, 0.3},  {2, 1, -0.5}, {2, 2, -1.0}};
constexpr double kAnyTilt = 180;  // mesh_fidelity: no face counts as tilted here

sp::BsplineSurface hill_of(const State& s) {
  const std::vector<double> U = sp::clamped_uniform_knots(4, 3);
  std::vector<double> w(25, 1.0);
  w[2 * 5 + 2] = s.get("weight");
  return {3, 3, U, U, 5, 5, kNet, w, {}};
}

// The meshes ---------------------------------------------------------------------
double finer(const State& s) { return std::pow(2.0, s.get("finer")); }

// The own core's adaptive tessellation: split until every triangle is within
// `tolerance` of the surface (its parametric error), no further.
sp::Mesh own_mesh(const sp::BsplineSurface& S, double tolerance) {
  const auto options = sp::TessellationOptions::adaptive(tolerance);
  return sp::tessellate_surface(sp::surface_evaluator(S), sp::uv_domain(S), options);
}

// GLU's triangles for the same surface, read back from its tessellator
// (gl/glu_nurbs.h). GLU takes the steps for every method (lab 21).
sp::Mesh glu_mesh(const State& s, GLenum method, double tolerance,
                  gllab::RationalFeed feed = gllab::RationalFeed::kPremultiplied) {
  gllab::GluNurbsProperties p;
  p.sampling_method = method;
  p.parametric_tolerance = float(tolerance);
  p.u_step = p.v_step = float(s.get("grid") * finer(s));
  return gllab::GluNurbs(p).capture_surface(hill_of(s), "hill", feed).mesh;
}

// Drawing -------------------------------------------------------------------
// Lab 21's camera: the net's square tilted 60° towards us, turned 30°.
void camera(const State& s, const Panel& p) {
  gllab::ortho_fit(p.width, p.height, 3.1, 2.9, 20);
  gllab::enable_headlight();
  gllab::apply_orbit(s);
  glRotatef(-60.f, 1.f, 0.f, 0.f);
  glRotatef(-30.f, 0.f, 0.f, 1.f);
}

// GLU_OBJECT_PARAMETRIC_ERROR and the own core at the same tolerance.
void draw_own_vs_glu(const State& s) {
  const double tol = s.get("object_error") / finer(s);
  const sp::Mesh meshes[2] = {glu_mesh(s, GLU_OBJECT_PARAMETRIC_ERROR, tol),
                              own_mesh(hill_of(s), tol)};
  const std::string titles[2][2] = {{"GLU_OBJECT_PARAMETRIC_ERROR", fmt("tolerance %g", tol)},
                                    {"own core, tessellate_surface", fmt("tolerance %g", tol)}};
  gllab::draw_mesh_pair(s, sp::surface_evaluator(hill_of(s)), meshes, titles, false, kAnyTilt,
                        [&](const Panel& p) { camera(s, p); });
}

// A distance on a log scale: 1e-8 (blue) to 1e-5 and beyond (red).
gllab::Rgb heat(double d) {
  const double t = std::clamp((std::log10(std::max(d, 1e-12)) + 8) / 3, 0.0, 1.0);
  return {float(std::min(1.0, 2 * t)), float(1 - std::abs(2 * t - 1) * 0.6),
          float(std::max(0.0, 1 - 2 * t))};
}

// Each GLU vertex against the own surface at the (u, v) GLU evaluated there.
void draw_difference(const State& s) {
  const sp::BsplineSurface S = hill_of(s);
  const bool mistake = s.flag("mistake");  // (x, y, z, w) handed to GLU, not premultiplied
  const auto feed = mistake ? gllab::RationalFeed::kMistakeNotPremultiplied
                            : gllab::RationalFeed::kPremultiplied;
  const sp::Mesh m = glu_mesh(s, GLU_DOMAIN_DISTANCE, 0.5, feed);
  std::vector<gllab::Rgb> colours;
  double worst = 0;
  for (std::size_t k = 0; k < m.positions.size(); ++k) {
    const double d = norm(m.positions[k] - sp::surface_point(S, m.uv[k].x, m.uv[k].y));
    worst = std::max(worst, d);
    colours.push_back(heat(d));
  }
  const Panel p = gllab::enter_panel(0, 0, 1, 1, s.width, s.height);
  camera(s, p);
  glDisable(GL_LIGHTING);
  gllab::draw_surface(m, colours);
  gllab::leave_panels(s.width, s.height);
  draw_panel_caption(p, 0, std::string("|GLU vertex - S(u, v)|, ") + (mistake ? "not " : "") +
                               "premultiplied");
  draw_panel_caption(p, -2, "max |GLU - S(u,v)| = " + fmt("%.2e", worst));
  for (int e = 0; e < 4; ++e)  // the colour scale
    gllab::draw_text(s.width / 2 - 136 + 72 * e, s.height - 20, fmt("1e-%g", 8 - e),
                     heat(std::pow(10, e - 8)));
}

void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"24_nurbs_tessellation",
          "lab 24 · NURBS tessellation: the own core against GLU",
          {{"own_vs_glu", "GLU_OBJECT_PARAMETRIC_ERROR vs the own tessellation at one tolerance",
            draw_own_vs_glu, kOrbit},
           {"difference", "GLU's vertices coloured by their distance to the own S(u, v)",
            draw_difference, kOrbit}},
          {{"object_error", 0.03, 0.0005, 1, "own_vs_glu: the tolerance, object units"},
           {"grid", 8, 1, 100, "GLU_U_STEP = GLU_V_STEP (difference: GLU_DOMAIN_DISTANCE)"},
           {"finer", 0, -3, 3, "the tolerance / 2^finer, the steps x 2^finer"},
           {"weight", 2, 0.25, 10, "weight of the middle control point P(2, 2)"},
           {"mistake", 0, 0, 1, "difference: hand GLU (x, y, z, w), not premultiplied"}},
          {{'t', "finer (tolerance / 2, steps x 2)", "finer", +1}, {'T', "coarser", "finer", -1},
           {'w', "weight of P(2, 2) +0.5", "weight", +0.5}, {'W', "weight -0.5", "weight", -0.5},
           {'x', "not premultiplied on/off (difference)", "mistake"}},
          init};
}
