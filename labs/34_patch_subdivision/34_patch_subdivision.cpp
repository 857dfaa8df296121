// lab 34 · splitting Bézier patches                              difficulty: ★★★☆
// A bicubic patch split for drawing (lecture notes "Higher Order Surfaces",
// "Rendering Bezier Patches": "Patch Splitting", "Splitting Termination",
// "Patch Cracking"): each direction is split on its own by de Casteljau; a
// piece stops when its control vertices lie within a tolerance of the plane
// through three of its corners, or at a maximum depth. Each piece is drawn as
// the flat quad of its corners; where a fine piece meets a coarse one its
// corner is off the coarse quad's straight edge: a crack (the magenta
// background shows through). Closing: the finer side's corner on a shared
// edge is snapped onto the coarser quad's edge line.
// Notice: the cracks run only where the depth changes; cracks_closed has none.
// Try: lower the tolerance [t]: do the cracks get narrower, and why never zero?
// Keys: [t]/[T] flatness tolerance  [c] control nets
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: cracks, cracks_closed, diagonal_curve, subdivision_net
// Reference: reference_images/34_patch_subdivision__*.png

#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bezier.h"
#include "spline/patch_subdivision.h"
#include "spline/surface.h"

namespace {

namespace sp = gllab::spline;
using gllab::Rgb;
using gllab::State;
using sp::BezierSurface;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// A bicubic patch, b_ij = P[4 i + j]: a fan whose v-lines are arcs in the plane (flat, so
// its pieces stop early, with straight edges under the arcs), and one corner pulled up high,
// so that quarter needs deeper splits whose corners lie on the arcs: a crack you can see.
const std::vector<Vec3> kPatch = {
    {-1.15, -0.78, 0.0}, {-0.75, -0.31, 0.0}, {-0.75, 0.31, 0.0}, {-1.15, 0.78, 0.0},
    {-0.80, -1.39, 0.0}, {-0.10, -0.55, 0.0}, {-0.10, 0.55, 0.0}, {-0.80, 1.39, 0.0},
    {-0.45, -1.99, 0.0}, {0.56, -0.79, 0.0}, {0.56, 0.79, 0.3}, {-0.45, 1.99, 0.6},
    {-0.10, -2.60, 0.0}, {1.22, -1.03, 0.2}, {1.22, 1.03, 1.2}, {-0.10, 2.60, 2.0}};
constexpr int kMaxDepth = 4;  // the termination guarantee: at most 4^4 pieces
const Rgb kNet{.6f, .6f, .65f}, kCurve{.4f, .65f, 1.f}, kText{1.f, 1.f, 1.f};
// Piece colours by depth 0..4 (the flatness test's answer).
const GLfloat kDepthColour[5][3] = {
    {.95f, .95f, .5f}, {.5f, .9f, .5f}, {.5f, .85f, .95f}, {.95f, .65f, .3f}, {.9f, .9f, .9f}};

// Drawing -------------------------------------------------------------------
void camera(const State& s) {
  gllab::ortho_fit(s.width, s.height, 3.0, 3.0);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: s.camera
  gllab::look_from_above(60, -90);
  glTranslated(0, 0, -0.8);
}

BezierSurface patch(const State& s) { return {3, 3, s.points("P")}; }

// Each piece a flat lit quad of its four corner points, coloured by its depth.
void draw_pieces(const State& s, bool close_cracks) {
  const BezierSurface p = patch(s);
  const double tol = s.get("tolerance");
  const auto quads = sp::leaf_quads(p, sp::split_adaptive(p, tol, kMaxDepth), close_cracks);
  glClearColor(1.f, 0.f, 1.f, 1.f);  // magenta: shows through every crack
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);  // the other views' background again
  camera(s);
  glEnable(GL_LIGHTING);
  glEnable(GL_COLOR_MATERIAL);
  glBegin(GL_QUADS);
  for (const sp::LeafQuad& q : quads) {
    const Vec3 n = sp::normalized(sp::cross(q.p[2] - q.p[0], q.p[3] - q.p[1]));
    glColor3fv(kDepthColour[q.depth]);
    glNormal3d(n.x, n.y, n.z);
    for (const Vec3& v : q.p) glVertex3d(v.x, v.y, v.z);
  }
  glEnd();
  glDisable(GL_LIGHTING);
  if (s.flag("nets")) gllab::draw_control_net(p.P, 4, 4, kNet);
  gllab::draw_text_panel(8, 8,
                         {gllab::format_text("tolerance %.3f, max depth %d: %zu pieces", tol,
                                             kMaxDepth, quads.size()),
                          close_cracks ? "T-junctions snapped onto the coarse edge"
                                       : "pieces drawn as they are: cracks"},
                         kText);
}

void draw_cracks(const State& s) { draw_pieces(s, false); }
void draw_cracks_closed(const State& s) { draw_pieces(s, true); }

// The curve u = v: a Bézier curve of degree 3 + 3 = 6 (core diagonal_curve),
// drawn with its 7 control points over the patch's iso-lines.
void draw_diagonal(const State& s) {
  const BezierSurface p = patch(s);
  const sp::BezierCurve d = sp::diagonal_curve(p);
  camera(s);
  for (int k = 0; k <= 8; ++k) {  // iso-lines u = k/8 and v = k/8
    glColor3f(.4f, .4f, .45f);
    for (int dir = 0; dir < 2; ++dir) {
      glBegin(GL_LINE_STRIP);
      for (int l = 0; l <= 32; ++l) {
        const double a = k / 8.0, b = l / 32.0;
        const Vec3 x = dir ? sp::surface_point(p, a, b) : sp::surface_point(p, b, a);
        glVertex3d(x.x, x.y, x.z);
      }
      glEnd();
    }
  }
  gllab::draw_control_net(d.P, 1, static_cast<int>(d.P.size()), kCurve);
  std::vector<Vec3> line;
  for (int l = 0; l <= 64; ++l) line.push_back(sp::bezier_point(d, l / 64.0));
  gllab::draw_polyline(line, {.9f, .1f, .1f}, 3.f);
  gllab::draw_text_panel(8, 8, {"red: X(t, t), a Bezier curve of degree 6", "blue: its 7 points"},
                         kText);
}

// Subdivision nets: the control nets of the pieces after two uniform splits in
// each direction; they already lie close to the surface (they converge to it).
void draw_nets(const State& s) {
  const BezierSurface p = patch(s);
  camera(s);
  for (const sp::PatchLeaf& l : sp::split_adaptive(p, 1e-300, 2)) {
    gllab::draw_control_net(l.patch.P, 4, 4, Rgb{.4f, .7f, 1.f});
  }
  if (s.flag("nets")) gllab::draw_control_net(p.P, 4, 4, kNet);
  gllab::draw_text_panel(8, 8, {"the 16 sub-nets after 2 splits each way"}, kText);
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);  // draw_pieces clears to magenta itself
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"34_patch_subdivision",
                 "lab 34 · splitting Bézier patches",
                 {{"cracks", "pieces split to different depths: cracks", draw_cracks, kOrbit},
                  {"cracks_closed", "the same pieces, T-junctions snapped", draw_cracks_closed,
                   kOrbit},
                  {"diagonal_curve", "the curve u = v, degree 6", draw_diagonal, kOrbit},
                  {"subdivision_net", "the nets after two splits", draw_nets, kOrbit}},
                 {{"tolerance", 0.2, 0.01, 0.5, "flatness tolerance (object units)"},
                  {"nets", 0, 0, 1, "the patch's control net"}},
                 {{'t', "tolerance -0.01", "tolerance", -0.01},
                  {'T', "tolerance +0.01", "tolerance", +0.01},
                  {'c', "control net on/off", "nets"}},
                 init};
  lab.points = {{"P", kPatch, "the patch's net b_ij = P[4i + j]", 3}};
  return lab;
}
