// lab 18 · joining Bézier patches                            difficulty: ★★★☆
// A second bicubic patch joined to lab 17's along the edge u = 1 with C0, C1
// or C2 (lecture notes "Higher Order Surfaces", "Joining Bezier Patches";
// ch. 1, §1.7 Surface representations, "Spline surfaces"): C^k holds when
// every column of the joined nets, read as a Bézier curve along u, is C^k at
// the edge. The neighbour's rows 0..k are then the left patch's columns
// continued beyond u = 1, de Casteljau evaluated outside its interval.
// Notice: row 0 is the shared edge; C1 makes a_3j - a_2j = b_1j - b_0j (each
//   white line runs straight through the edge); C2 also fixes row 2.
//   join_c1_below shows the underside, lit with -N (GL_LIGHT_MODEL_TWO_SIDE).
// Try: in join_c1, drag a point of row 2 of the left patch: which points of
//   the right patch follow, and why only those? In join_c2, drag b_1j: how far
//   do row 2's points move compared with your drag?
// Keys: [c] nets  [n] labels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: join_c0, join_c1, join_c2, join_c1_below
// Reference: reference_images/18_joining_patches__*.png

#include <algorithm>
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
using gllab::Rgb;
using gllab::State;
using sp::BezierSurface;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The left patch over u in [0, 1], lab 17's hill: b_ij = P[4 i + j], i along u (x).
const std::vector<Vec3> kPatch = {
    {-1.5, -1.5, 0},    {-1.5, -.5, .42}, {-1.5, .5, .56}, {-1.5, 1.5, 0},
    {-.5, -1.5, .42},   {-.5, -.5, 1.68}, {-.5, .5, 1.4},  {-.5, 1.5, .7},
    {.5, -1.5, .21},    {.5, -.5, 1.26},  {.5, .5, 1.19},  {.5, 1.5, .98},
    {1.5, -1.5, -.14},  {1.5, -.5, .84},  {1.5, .5, .84},  {1.5, 1.5, 1.26}};
// Rows 1..3 of the neighbour over u in [1, 2], Q[4 (i - 1) + j]; its row 0 is
// the shared edge. The join views ignore the rows they make (1..k).
const std::vector<Vec3> kNext = {
    {2.5, -1.5, .4},   {2.5, -.5, 1.3},  {2.5, .5, .2},  {2.5, 1.5, .5},
    {3.5, -1.5, .1},   {3.5, -.5, .5},   {3.5, .5, .9},  {3.5, 1.5, .3},
    {4.5, -1.5, .2},   {4.5, -.5, .3},   {4.5, .5, .6},  {4.5, 1.5, .1}};
constexpr double kTolerance = 2e-3;  // tessellation, object units (a patch is 3 wide)
const Rgb kClay{.85f, .55f, .35f}, kSea{.35f, .6f, .85f}, kNet{.75f, .75f, .8f},
    kFree{1.f, .9f, .3f}, kMade{.85f, .5f, .85f}, kText{1.f, 1.f, 1.f};

sp::Mesh mesh_of(const BezierSurface& p) {
  return sp::tessellate_surface(sp::surface_evaluator(p), sp::uv_domain(p),
                                sp::TessellationOptions::adaptive(kTolerance));
}

// Drawing -------------------------------------------------------------------
// Both patches in the middle, seen from `elevation` degrees above (below when
// negative); one light that stays with the eye, both sides lit: the back of a
// polygon with -N, so the underside is lit as the light falls on it.
void camera(const State& s, double elevation) {
  gllab::ortho_fit(s.width, s.height, 2.4, 2.4);
  gllab::enable_headlight();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gllab::apply_orbit(s);     // right-drag, wheel, [0]: s.camera
  glTranslated(0, -0.3, 0);  // below the text panel
  gllab::look_from_above(elevation, 30);
  glScaled(0.62, 0.62, 0.62);
  glTranslated(-1.5, 0, 0);
}

// join_ck: the neighbour's rows 0..k continue the left patch's columns (core
// joined_patch), its other rows are the list Q. The construction lines: each
// column's Bézier curve continued beyond u = 1 (de Casteljau at tau = 2).
void draw_join(const State& s, int k, double elevation = 25) {
  const BezierSurface a{3, 3, s.points("P")};
  BezierSurface b = a;  // row 0: any, joined_patch replaces it
  std::copy(s.points("Q").begin(), s.points("Q").end(), b.P.begin() + 4);
  b = sp::joined_patch(a, {3, 3, b.P, 1, 2}, k);  // b over [1, 2] x [0, 1]
  camera(s, elevation);
  gllab::draw_surface(mesh_of(a), kClay);
  gllab::draw_surface(mesh_of(b), kSea);
  if (s.flag("nets")) {
    glDisable(GL_DEPTH_TEST);  // the construction lines run under the surface too
    for (int j = 0; j < 4; ++j) {
      const sp::BezierCurve column{{a.point(0, j), a.point(1, j), a.point(2, j), a.point(3, j)}};
      const sp::BezierContinuation c = sp::continuation_points(column, k, 1);
      for (std::size_t r = 1; r < c.levels.size(); ++r)
        for (std::size_t m = 0; m < c.levels[r].size(); ++m)
          gllab::draw_polyline({c.levels[r - 1][m], c.levels[r - 1][m + 1], c.levels[r][m]},
                               kText, 1.f);
    }
    glEnable(GL_DEPTH_TEST);
    gllab::draw_control_net(b.P, 4, 4, kMade);
    std::vector<std::size_t> free;  // rows k+1..3 of the blue patch: Q[4k..11]
    for (std::size_t i = 4 * std::size_t(k); i < 12; ++i) free.push_back(i);
    gllab::draw_control_points(s, "Q", free, kFree);
    gllab::draw_control_net(a.P, 4, 4, kNet);
    gllab::draw_control_points(s, "P", kFree);
  }
  if (!s.flag("labels")) return;
  const std::string made =
      gllab::format_text("C%d: blue rows 0..%d made from the orange patch", k, k);
  std::vector<std::string> lines = {made, "(each column continued beyond u = 1)"};
  if (elevation < 0) lines.push_back("from below: the underside, lit with -N");
  gllab::draw_text_panel(8, 8, lines, kText);
}

void draw_c0(const State& s) { draw_join(s, 0); }
void draw_c1(const State& s) { draw_join(s, 1); }
void draw_c2(const State& s) { draw_join(s, 2); }
void draw_c1_below(const State& s) { draw_join(s, 1, -60); }  // 60 degrees below

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"18_joining_patches",
                 "lab 18 · joining Bézier patches",
                 {{"join_c0", "a second patch sharing the edge only", draw_c0, kOrbit},
                  {"join_c1", "its row 1 continued: C1", draw_c1, kOrbit},
                  {"join_c2", "rows 1 and 2 continued: C2", draw_c2, kOrbit},
                  {"join_c1_below", "the C1 join from below: the underside lit", draw_c1_below,
                   kOrbit}},
                 {{"nets", 1, 0, 1, "control nets, construction lines and draggable points"},
                  {"labels", 1, 0, 1, "the caption"}},
                 {{'c', "control nets on/off", "nets"}, {'n', "labels on/off", "labels"}},
                 init};
  lab.points = {{"P", kPatch, "the left patch's net a_ij = P[4i + j]", 3},
                {"Q", kNext, "rows 1-3 of the joined patch", 3}};
  // Ctrl+S saves the left patch as a clamped bicubic B-spline surface.
  lab.model = [](const State& s) -> gllab::Model {
    return sp::to_bspline(BezierSurface{3, 3, s.points("P")});
  };
  return lab;
}
