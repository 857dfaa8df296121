// lab 25 · trimmed tessellation: the own core against GLU       difficulty: ★★★★
// Lab 22's trimmed hill cut into triangles by the own core
// (spline::tessellate_surface with trim loops, common/spline/tessellate.h) and by
// GLU (lecture notes ch. 1, §1.7 Surface representations, "Trimming"): how far
// each mesh strays from the surface inside and along the trims, and GLU's
// slivers along a coarse gluPwlCurve. GLU's triangles are read back from its
// tessellator (capture mode) and drawn the same way as the own ones.
// Notice: GLU samples NURBS trim curves but never refines a gluPwlCurve edge:
//   a coarse square gets long slivers fanned from its corners across the hill,
//   5-30 % too much area. The own core refines trim edges to its tolerance.
// Try: in slivers press [E] until the square has 1 point per edge: which
//   numbers of the second panel change? Press [s]: does a finer GLU grid help?
// Keys: [t]/[T] finer/coarser  [s]/[S] GLU steps  [e]/[E] polyline points per edge
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: own_vs_glu, slivers
// Reference: reference_images/25_trimmed_tessellation__*.png

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_arrays.h"
#include "gl/glu_nurbs.h"
#include "gl/nurbs_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/nurbs.h"
#include "spline/surface.h"
#include "spline/tessellate.h"

namespace {

namespace sp = gllab::spline;
using gllab::draw_panel_caption;
using gllab::fmt;
using gllab::Panel;
using gllab::State;

// Lab data (edit me) -------------------------------------------------------
// Lab 22's hill (the Red Book's surface.c), one bicubic Bézier patch, and its
// five trim loops: outer boundary, round hole, trim.c's hole, a rectangular
// hole and the island in it.
const std::vector<sp::Vec3> kHill = {
    {-3, -3, -3}, {-3, -1, -3}, {-3, 1, -3}, {-3, 3, -3}, {-1, -3, -3}, {-1, -1, 3},
    {-1, 1, 3},   {-1, 3, -3},  {1, -3, -3}, {1, -1, 3},  {1, 1, 3},    {1, 3, -3},
    {3, -3, -3},  {3, -1, -3},  {3, 1, -3},  {3, 3, -3}};
const std::vector<sp::Vec3> kOuter = {{.5, .03, 0}, {.97, .03, 0}, {.97, .5, 0}, {.97, .97, 0},
    {.5, .97, 0}, {.03, .97, 0}, {.03, .5, 0}, {.03, .03, 0}, {.5, .03, 0}};
const std::vector<sp::Vec3> kArch = {{.61, .7, 0}, {.61, .81, 0}, {.83, .81, 0}, {.83, .7, 0}};
const std::vector<sp::Vec2> kArchBase = {{.83, .7}, {.72, .59}, {.61, .7}};
const std::vector<sp::Vec2> kRectangle = {{.15, .12}, {.15, .45}, {.85, .45}, {.85, .12},
                                          {.15, .12}};
// slivers: a 5-point square, counter-clockwise, as coarse as trim.c's.
const std::vector<sp::Vec2> kSquare = {{.1, .1}, {.9, .1}, {.9, .9}, {.1, .9}, {.1, .1}};
constexpr double kTiltDegrees = 20;  // a face this far from the surface's normal is a sliver
const gllab::Rgb kGlu{0.95f, 0.6f, 0.25f}, kOwn{0.35f, 0.65f, 0.95f}, kWire{0.1f, 0.1f, 0.1f},
    kSliver{1.f, 0.25f, 0.25f}, kDim{0.25f, 0.26f, 0.3f};

// A polyline with `per_edge` points per edge, as lab 22 hands it to GLU.
sp::TrimPiece pwl(const std::vector<sp::Vec2>& p, int per_edge) {
  const std::vector<GLfloat> uv = gllab::densified_pwl(p, per_edge);
  return gllab::core_pwl(GLint(uv.size() / 2), uv.data(), 2, GLU_MAP1_TRIM_2);
}
sp::TrimPiece curve(sp::BsplineCurve c) { return {{}, std::move(c)}; }

// The hill with lab 22's five loops, or with the slivers view's square.
enum class Trims { kLoops, kCoarseSquare, kDenseSquare };
sp::BsplineSurface hill_of(const State& s, Trims trims) {
  const int n = s.integer("per_edge");
  const std::vector<double> U = {0, 0, 0, 0, 1, 1, 1, 1};
  sp::BsplineSurface S{3, 3, U, U, 4, 4, kHill, {}, {}};
  if (trims != Trims::kLoops) {
    S.trims = {{{pwl(kSquare, trims == Trims::kDenseSquare ? n : 1)}}};
    return S;
  }
  S.trims = {{{curve(sp::clamped_curve(kOuter, 2, 2))}},
             {{curve(sp::reversed(sp::circle({0.27, 0.7, 0}, 0.13)))}},  // clockwise: a hole
             {{curve(sp::clamped_curve(kArch, 3, 2)), pwl(kArchBase, n)}},
             {{pwl(kRectangle, n)}},
             {{curve(sp::circle({0.5, 0.285, 0}, 0.1))}}};  // the island: counter-clockwise
  return S;
}

// The meshes ---------------------------------------------------------------------
double finer(const State& s) { return std::pow(2.0, s.get("finer")); }
double own_tolerance(const State& s) { return s.get("tol") / finer(s); }
double glu_steps(const State& s) { return s.get("steps") * finer(s); }

// The own core's tessellation: trim edges are refined like the inside, until
// every piece is within the tolerance of the surface.
sp::Mesh own_mesh(const sp::BsplineSurface& S, const State& s) {
  const auto options = sp::TessellationOptions::adaptive(own_tolerance(s));
  return sp::tessellate_surface(sp::surface_evaluator(S), sp::uv_domain(S), options, S.trims);
}

// GLU's triangles, GLU_DOMAIN_DISTANCE, read back from its tessellator (gl/glu_nurbs.h).
sp::Mesh glu_mesh(const sp::BsplineSurface& S, const State& s) {
  gllab::GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;
  p.u_step = p.v_step = float(glu_steps(s));
  return gllab::GluNurbs(p).capture_surface(S, "trimmed hill").mesh;
}

// Drawing -------------------------------------------------------------------
// Lab 22's camera: the hill from above, tilted 30°; `extent` from centre to edge.
void camera(const State& s, const Panel& p, double extent = 3.4) {
  gllab::ortho_fit(p.width, p.height, extent, extent, 20);
  gllab::enable_headlight();
  gllab::apply_orbit(s);
  glTranslated(0, 0.12 * extent, 0);  // up a little: the numbers go below
  glRotatef(-30.f, 1.f, 0.f, 0.f);
}

void draw_own_vs_glu(const State& s) {
  const sp::BsplineSurface S = hill_of(s, Trims::kLoops);
  const sp::Mesh meshes[2] = {glu_mesh(S, s), own_mesh(S, s)};
  const std::string titles[2][2] = {{"GLU_DOMAIN_DISTANCE", fmt("%g steps", glu_steps(s))},
                                    {"own core", "tolerance " + fmt("%g", own_tolerance(s))}};
  gllab::draw_mesh_pair(s, sp::surface_evaluator(S), meshes, titles, true, kTiltDegrees,
                        [&](const Panel& p) { camera(s, p); });
}

// GLU fed the coarse square and the dense one, the own core, and GLU's coarse
// triangles in (u, v): the fans from the corners. The numbers measure each
// mesh against the true trimmed surface (tessellate.h: surface_area, mesh_fidelity).
void draw_slivers(const State& s) {
  const sp::BsplineSurface coarse = hill_of(s, Trims::kCoarseSquare);
  const auto surface = sp::surface_evaluator(coarse);
  const sp::Mesh own = own_mesh(coarse, s);
  const double area = sp::surface_area(surface, own);  // over the own (u, v) triangles
  const sp::Mesh dense = glu_mesh(hill_of(s, Trims::kDenseSquare), s);
  const sp::Mesh meshes[3] = {glu_mesh(coarse, s), dense, own};
  const char* titles[3] = {"GLU, 5-point gluPwlCurve", "GLU, densified polyline", "own core"};
  glShadeModel(GL_FLAT);  // every triangle shows
  for (int k = 0; k < 3; ++k) {
    const Panel p = gllab::enter_panel(k % 2, k / 2, 2, 2, s.width, s.height);
    camera(s, p, 5.2);
    const sp::MeshFidelity f = sp::mesh_fidelity(meshes[k], surface, kTiltDegrees);
    const gllab::Rgb c = k < 2 ? kGlu : kOwn;
    glColor3f(c.r, c.g, c.b);
    if (k < 2) gllab::draw_mesh_with_edges(meshes[k], kWire);
    else gllab::draw_mesh(own);  // no edges: its triangles are too small to see
    gllab::draw_mesh_faces(meshes[k], f.tilted, kSliver, 2.f);
    const double percent = 100 * (sp::mesh_area(meshes[k]) - area) / area;
    draw_panel_caption(p, 0, titles[k]);
    draw_panel_caption(p, -3, "area " + fmt("%+.2f %%", percent));
    draw_panel_caption(p, -2, "faces tilted > 20°: " + std::to_string(f.tilted_faces),
                       f.tilted_faces ? kSliver : gllab::Rgb{1.f, 1.f, 1.f});
    draw_panel_caption(p, -1, "along trims " + fmt("%.2e", f.max_trim_deviation));
  }
  const Panel p = gllab::enter_panel(1, 1, 2, 2, s.width, s.height);
  sp::Mesh flat = meshes[0];  // GLU's coarse triangles laid out in (u, v)
  for (std::size_t k = 0; k < flat.positions.size(); ++k)
    flat.positions[k] = {flat.uv[k].x, flat.uv[k].y, 0};
  gllab::ortho_fit(p.width, p.height, 0.62, 0.62);
  glTranslated(-0.5, -0.5, 0);
  gllab::draw_mesh_wireframe(flat, kDim);
  const auto tilted = sp::mesh_fidelity(meshes[0], surface, kTiltDegrees).tilted;
  gllab::draw_mesh_faces(flat, tilted, kSliver, 2.f);
  gllab::leave_panels(s.width, s.height);
  draw_panel_caption(p, 0, "the same triangles in (u, v)");
}

void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"25_trimmed_tessellation",
          "lab 25 · trimmed tessellation: the own core against GLU",
          {{"own_vs_glu", "lab 22's trimmed hill: GLU and the own core, inside and along the trims",
            draw_own_vs_glu, kOrbit},
           {"slivers", "a 5-point gluPwlCurve square: GLU's slivers, a dense one, the own core",
            draw_slivers, kOrbit}},
          {{"tol", 0.02, 0.0005, 0.5, "the own tessellation's tolerance, object units"},
           {"steps", 24, 2, 100, "GLU_DOMAIN_DISTANCE: GLU_U_STEP = GLU_V_STEP per unit"},
           {"finer", 0, -3, 3, "tol / 2^finer, steps x 2^finer"},
           {"per_edge", 16, 1, 64, "points per edge of the densified polylines"}},
          {{'t', "finer (tol / 2, steps x 2)", "finer", +1}, {'T', "coarser", "finer", -1},
           {'s', "GLU steps +4", "steps", +4}, {'S', "GLU steps -4", "steps", -4},
           {'e', "polyline points per edge +4", "per_edge", +4},
           {'E', "points per edge -4", "per_edge", -4}},
          init};
}
