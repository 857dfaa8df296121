// lab 19 · OpenGL's Bézier evaluators                        difficulty: ★★☆☆
// OpenGL evaluates Bézier curves and patches itself, as the Red Book's bezcurve.c and
// bezmesh.c show: glMap1f / glMap2f take the control points, glMapGrid and glEvalMesh (or
// glEvalCoord) sample them. Each view puts the evaluator beside the own core's result on the
// same grid: lab 12's curve, lab 17's patch (lecture notes "Higher Order Surfaces", "Rendering
// Bezier Curves", "Rendering Bezier Patches"; ch. 1, §1.6 Spline representations, "Properties
// of Bézier segments", property 5, the Bernstein basis).
// Notice: glEvalMesh1 hits the core's points to the pixel: the same Bernstein
//   form at the same parameters. glMapGrid2f(12, .., 6, ..) gives 12 cells along u
//   and 6 along v; without GL_AUTO_NORMAL glEvalMesh2 sends no normals.
// Try: --set curve_grid=4: is GL's curve still the curve? Swap glMap2f's strides
//   (3 for u, 12 for v): what changes in surface, and what on 12 x 12 cells?
// Keys: [g]/[G] curve grid  [c]/[C] curve source  [m]/[M] surface un  [a] GL_AUTO_NORMAL
//   [n] labels  [mouse] drag  right-drag turn  wheel zoom  [0] reset camera  [h] help
// Views: curve, surface
// Reference: reference_images/19_gl_evaluators__*.png

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/feedback.h"
#include "gl/gl.h"
#include "gl/glu_arrays.h"
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
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// bezcurve.c's ctrlpoints[4][3], here lab 12's polygon (lecture notes ch. 1,
// "Example (de Casteljau algorithm)"): the point list P.
const std::vector<Vec3> kCurve = {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}};
// bezmesh.c's ctrlpoints[4][4][3], here lab 17's hill: b_ij = B[4 i + j], i along u.
const std::vector<Vec3> kPatch = {
    {-1.5, -1.5, 0},    {-1.5, -.5, .42}, {-1.5, .5, .56}, {-1.5, 1.5, 0},
    {-.5, -1.5, .42},   {-.5, -.5, 1.68}, {-.5, .5, 1.4},  {-.5, 1.5, .7},
    {.5, -1.5, .21},    {.5, -.5, 1.26},  {.5, .5, 1.19},  {.5, 1.5, .98},
    {1.5, -1.5, -.14},  {1.5, -.5, .84},  {1.5, .5, .84},  {1.5, 1.5, 1.26}};
const Rgb kText{0.9f, 0.9f, 0.9f}, kOwn{0.3f, 0.8f, 1.f}, kPoints{1.f, 0.8f, 0.3f},
    kGl{1.f, 0.3f, 0.9f}, kClay{.85f, .55f, .35f}, kNet{.75f, .75f, .8f}, kFree{1.f, .9f, .3f},
    kWhite{1.f, 1.f, 1.f}, kGrid{.4f, .22f, .1f};

// The curve -------------------------------------------------------------------
// OpenGL's one-dimensional evaluator: the driver evaluates the same Bernstein
// form in float, at u = 0, 1/grid, ..., 1 (the own samples below).
void gl_evaluator_curve(const State& s, int grid) {
  const std::vector<GLfloat> ctrl = gllab::glu_points(s.points("P"));  // x y z per point
  const GLint order = GLint(ctrl.size() / 3);                           // n + 1 points
  glMap1f(GL_MAP1_VERTEX_3, 0.f, 1.f, 3, order, ctrl.data());           // u in [0, 1], stride 3
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(grid, 0.f, 1.f);
  glEvalMesh1(GL_LINE, 0, grid);  // a line strip through glEvalCoord1f(k / grid), k = 0..grid
}

void draw_curves(const State& s) {
  const sp::BezierCurve c{s.points("P"), 0, 1, 2};
  const int grid = s.integer("curve_grid"), source = s.integer("source");
  const double t = s.get("t");
  std::vector<Vec3> own;
  for (int k = 0; k <= grid; ++k) own.push_back(sp::bezier_point(c, double(k) / grid));
  glDisable(GL_DEPTH_TEST);  // the curves are flat, and drawn in order
  glDisable(GL_LIGHTING);    // (the surface view turns both on)
  gllab::ortho_fit(s.width, s.height, 7, 7);
  gllab::enter_plot({-6.8, -3.8, 6.8, 6.8, -0.8, 11.8, -0.8, 7.2}, true);  // one scale for x, y
  // What GL receives from both, side by side: the largest distance, in pixels.
  const std::vector<Vec3> a =
      gllab::feedback_line_vertices([&] { gllab::draw_polyline(own, kOwn); }, grid);
  const std::vector<Vec3> b =
      gllab::feedback_line_vertices([&] { gl_evaluator_curve(s, grid); }, grid);
  double worst = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    worst = std::max(worst, std::hypot(a[k].x - b[k].x, a[k].y - b[k].y));
  // source 0: own wide underneath, GL thin on top; 1 or 2: one of them alone, in the same ink.
  if (source != 2) gllab::draw_polyline(own, kOwn, source == 0 ? 6.f : 2.f);
  if (source != 2) gllab::draw_dots({sp::bezier_point(c, t)}, kOwn, source == 0 ? 14.f : 9.f);
  if (source != 1) {
    const Rgb ink = source == 0 ? kGl : kOwn;
    glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LINE_BIT | GL_POINT_BIT | GL_EVAL_BIT);
    glColor3f(ink.r, ink.g, ink.b);
    glLineWidth(2.f);
    gl_evaluator_curve(s, grid);
    glPointSize(source == 0 ? 5.f : 9.f);
    glBegin(GL_POINTS);
    glEvalCoord1f(GLfloat(t));  // X(t) by the evaluator
    glEnd();
    glPopAttrib();
  }
  gllab::draw_control_points(s, "P", kPoints, 9.f);  // unnumbered: only the curves differ
  glPopMatrix();
  if (!s.flag("labels")) return;
  const char* shown[] = {"own (wide, blue) and GL (thin, pink)", "own points only",
                         "GL evaluator only"};
  gllab::draw_text_panel_at(
      -6.8, -3.2, 0,
      {format_text("glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, %zu, P)", c.P.size()),
       format_text("glMapGrid1f(%d, 0, 1); glEvalMesh1(GL_LINE, 0, %d)", grid, grid),
       format_text("own bezier_point(k/%d) vs GL, read back by feedback:", grid),
       format_text("  largest distance %.2g px over %zu vertices", worst, b.size()),
       std::string("showing: ") + shown[source], "dot: X(t) (own) and glEvalCoord1f(t) (GL)"},
      {kText});
}

// The surface -----------------------------------------------------------------
// OpenGL's two-dimensional evaluator (bezmesh.c): the 16 points as a map, a
// grid, and normals from the map's derivatives when GL_AUTO_NORMAL is on.
void gl_evaluator_surface(const State& s, int un, int vn) {
  const std::vector<GLfloat> ctrl = gllab::glu_points(s.points("B"));  // b_00, b_01, ..., b_33
  // u (index i) steps over a row of 4 points: stride 12 floats; v steps 3.
  glMap2f(GL_MAP2_VERTEX_3, 0.f, 1.f, 12, 4, 0.f, 1.f, 3, 4, ctrl.data());
  glEnable(GL_MAP2_VERTEX_3);
  if (s.flag("auto_normal")) glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(un, 0.f, 1.f, vn, 0.f, 1.f);  // un cells along u, vn along v
  glPolygonOffset(2.f, 4.f);  // with the grid lines, the fill a little deeper: lines in front
  if (s.flag("grid_lines")) glEnable(GL_POLYGON_OFFSET_FILL);
  // Its strips run clockwise in (u, v) while Xu x Xv points up: tell GL which
  // side is the front, or two-sided lighting lights the back.
  glFrontFace(GL_CW);
  glEvalMesh2(GL_FILL, 0, un, 0, vn);
  glFrontFace(GL_CCW);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_LIGHTING);  // the same grid as lines: u = i / un, i = 0..un, and v = j / vn
  glColor3f(kGrid.r, kGrid.g, kGrid.b);
  if (s.flag("grid_lines")) glEvalMesh2(GL_LINE, 0, un, 0, vn);
  glDisable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_VERTEX_3);
}

// Left: the core's tessellation on un x vn cells; right: glEvalMesh2 on the
// same grid. Each in its own half of the window, under the same matrices.
void draw_patches(const State& s) {
  const sp::BezierSurface p{3, 3, s.points("B")};
  const int un = s.integer("surface_un"), vn = s.integer("surface_vn"), half = s.width / 2;
  glEnable(GL_DEPTH_TEST);
  for (int side = 0; side < 2; ++side) {
    glViewport(side * half, 0, half, s.height);
    gllab::ortho_fit(half, s.height, 2.4, 2.4);
    gllab::enable_headlight();  // one light that stays with the eye, both sides lit
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    gllab::apply_orbit(s);  // right-drag, wheel, [0]: s.camera
    gllab::look_from_above(25, 30);
    glColor3f(kClay.r, kClay.g, kClay.b);
    if (side == 1) gl_evaluator_surface(s, un, vn);
    else gllab::draw_mesh(sp::tessellate_surface(sp::surface_evaluator(p), sp::uv_domain(p),
                                                 sp::TessellationOptions::fixed_steps(un, vn)));
    if (side == 1 || !s.flag("nets")) continue;
    gllab::draw_control_net(p.P, 4, 4, kNet);
    gllab::draw_control_points(s, "B", kFree);
  }
  glViewport(0, 0, s.width, s.height);
  if (!s.flag("labels")) return;
  const std::string cells = format_text("%d x %d cells (u x v)", un, vn);
  const char* normals = s.flag("auto_normal") ? "" : ", no normals";
  gllab::draw_text_panel(8, 8, {"tessellate_surface", cells}, kWhite);
  gllab::draw_text_panel(half + 8, 8, {"glEvalMesh2", cells + normals}, kWhite);
}

// init ----------------------------------------------------------------------
void init() { glClearColor(0.12f, 0.13f, 0.16f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "19_gl_evaluators",
      "lab 19 · OpenGL's Bézier evaluators",
      {{"curve", "the core's points against glMap1f/glEvalMesh1 on one grid", draw_curves},
       {"surface", "tessellate_surface vs glMap2f + glEvalMesh2, same grid", draw_patches,
        kOrbit}},
      {{"t", 0.6, 0, 1, "curve: the dot at X(t), own and glEvalCoord1f"},
       {"curve_grid", 64, 1, 256, "curve: segments of glMapGrid1f and of the own points"},
       {"source", 0, 0, 2, "curve: 0 both, 1 own points only, 2 GL evaluator only"},
       {"surface_un", 12, 1, 64, "surface: glMapGrid2f's un, cells along u"},
       {"surface_vn", 6, 1, 64, "surface: glMapGrid2f's vn, cells along v"},
       {"grid_lines", 1, 0, 1, "surface: glEvalMesh2(GL_LINE) over GL's patch"},
       {"auto_normal", 1, 0, 1, "surface: glEnable(GL_AUTO_NORMAL) for glEvalMesh2"},
       {"nets", 1, 0, 1, "surface: the control net and its draggable points"},
       {"labels", 1, 0, 1, "text panels"}},
      {{'g', "curve grid +8 segments", "curve_grid", +8}, {'G', "curve grid -8", "curve_grid", -8},
       {'c', "curve source: both > own > GL", "source", +1}, {'C', "source back", "source", -1},
       {'m', "surface un +1", "surface_un", +1}, {'M', "surface un -1", "surface_un", -1},
       {'a', "GL_AUTO_NORMAL on/off", "auto_normal"}, {'n', "text panels on/off", "labels"}},
      init};
  lab.points = {{"P", kCurve, "the curve's control points b_0..b_n"},
                {"B", kPatch, "the patch's net b_ij = B[4i + j]", 3}};
  return lab;
}
