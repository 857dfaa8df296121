// lab 20 · interpolating surfaces                            difficulty: ★★★☆
// Surfaces through given data (lecture notes ch. 1, §1.7 Surface representations, "Lagrange
// surfaces", "Hermite surfaces", "Hermite-Lagrange tensor product", "Interpolating using
// Bézier surfaces"): the Lagrange tensor product, bicubic Hermite patches (corner points,
// partials, twists), the Hermite–Lagrange mix, and the interpolating Bézier surface.
// Lab 26 draws a B-spline scalar field as a terrain with iso-lines.
// Notice: lagrange and interpolating_bezier draw one surface, one polynomial in
//   two bases: its Bézier net floats off the surface, the data points stay on it.
// Try: in hermite, drag a twist handle (at the end of a red arrow): the corner and
//   its tangents stay; what changes?
// Keys: [k] curves  [c] nets and handles  [n] labels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: lagrange, interpolating_bezier, hermite, hermite_lagrange
// Reference: reference_images/20_interpolating_surfaces__*.png

#include <cmath>
#include <functional>
#include <string>
#include <type_traits>
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
using gllab::State;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The notes' example m = 3, n = 2: data c_ij at the nodes s_i x t_j, c[3 i + j].
const std::vector<double> kUs = {0, 1.0 / 3, 2.0 / 3, 1}, kVs = {0, 0.5, 1};
const std::vector<Vec3> kData = {
    {-1.5, -1, 0}, {-1.5, 0, .5}, {-1.5, 1, .2}, {-.5, -1, .5}, {-.5, 0, .8}, {-.5, 1, .4},
    {.5, -1, .1},  {.5, 0, .4},   {.5, 1, .6},   {1.5, -1, .2}, {1.5, 0, .3}, {1.5, 1, .1}};
// Hermite patch: per corner (u, v) = (a, b), K[4 (2a + b) + ...] = h0 the point,
// h1 = h0 +- Xu/3 and h2 = h0 +- Xv/3 (a step into the patch), h3 = h1 + h2 - h0
// +- Xuv/9: where the Bézier points b10, b01, b11 sit (§1.7, "Example: bicubic
// Bézier surface": Xs(0,0) = 3 (b10 - b00), Xst(0,0) = 9 (b11 - b10 - b01 + b00)).
const std::vector<Vec3> kHermite = {
    {-1.5, -1.5, 0}, {-.5, -1.5, .6}, {-1.5, -.5, .5}, {-.5, -.5, 1.4},
    {-1.5, 1.5, .3}, {-.5, 1.5, .8},  {-1.5, .5, .6},  {-.5, .5, 1.1},
    {1.5, -1.5, .2}, {.5, -1.5, .7},  {1.5, -.5, .9},  {.5, -.5, 1},
    {1.5, 1.5, 0},   {.5, 1.5, .4},   {1.5, .5, .3},   {.5, .5, .9}};
// Hermite along u, Lagrange along v at the nodes 0, 0.5, 1: per node L[4 j + ...]:
// 0 X(0, v_j), 1 that point + Xu/3, 2 X(1, v_j), 3 that point - Xu/3.
const std::vector<double> kHermiteLagrangeNodes = {0, 0.5, 1};
const std::vector<Vec3> kHermiteLagrange = {
    {-1.5, -1.5, 0}, {-.5, -1.5, .8}, {1.5, -1.5, .3}, {.5, -1.5, .7},
    {-1.5, 0, .5},   {-.5, 0, .6},    {1.5, 0, .9},    {.5, 0, .3},
    {-1.5, 1.5, 0},  {-.5, 1.5, .2},  {1.5, 1.5, .1},  {.5, 1.5, .9}};
constexpr double kTolerance = 5e-3;  // tessellation, object units
const gllab::Rgb kClay{.85f, .55f, .35f}, kNet{.85f, .5f, .85f}, kFree{1.f, .9f, .3f},
    kCurve{.3f, 1.f, .5f}, kBlue{.4f, .7f, 1.f}, kText{1.f, 1.f, 1.f};

sp::Mesh mesh_of(const sp::SurfaceEvaluator& f, sp::UvDomain domain = {0, 1, 0, 1}) {
  return sp::tessellate_surface(f, domain, sp::TessellationOptions::adaptive(kTolerance));
}
// The Hermite patch has exact normals; Lagrange and Hermite–Lagrange surfaces
// give points only, and the tessellator takes central differences (tessellate.h).
template <class Surface> sp::Mesh mesh_of(const Surface& f) {
  return mesh_of(sp::SurfaceEvaluator([f](double u, double v) {
    sp::SurfaceSample sample{sp::surface_point(f, u, v), {}, {}, {}};
    if constexpr (std::is_same_v<Surface, sp::HermitePatch>)
      sample.normal = sp::surface_normal(f, u, v);
    return sample;
  }));
}

// Drawing ----------------------------------------------------------------------
// One light that stays with the eye, both sides lit; from 25° above.
void camera(const State& s) {
  gllab::ortho_fit(s.width, s.height, 2.5, 2.5);
  gllab::enable_headlight();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gllab::apply_orbit(s);     // right-drag, wheel, [0]: s.camera
  glTranslated(0, -0.3, 0);  // below the text panel
  gllab::look_from_above(25, 30);
}

// A curve on the surface, parameter 0..1 (off with [k], to compare surfaces).
void curve(const State& s, const std::function<Vec3(double)>& c, gllab::Rgb colour) {
  if (s.flag("curves")) gllab::draw_curve(c, 0, 1, colour);
}
void caption(const State& s, const std::vector<std::string>& lines) {
  if (s.flag("labels")) gllab::draw_text_panel(8, 8, lines, kText);
}

void draw_lagrange(const State& s) {
  const sp::LagrangeSurface f{kUs, kVs, s.points("C")};
  camera(s);
  gllab::draw_surface(mesh_of(f), kClay);
  // The curves through each row and column of the data lie on the surface.
  for (double u : kUs) curve(s, [&](double v) { return sp::surface_point(f, u, v); }, kCurve);
  for (double v : kVs) curve(s, [&](double u) { return sp::surface_point(f, u, v); }, kBlue);
  gllab::draw_control_points(s, "C", kFree);
  caption(s, {"f(s, t) = sum c_ij L_i(s) L_j(t), m = 3, n = 2",
              "green c_i(t), blue c_j(s): through the data"});
}

// 1) a curve per column j through c_0j..c_3j (its points a_ij); 2) per row i through a_i.: b_ij
void draw_interpolating_bezier(const State& s) {
  const std::vector<Vec3>& c = s.points("C");
  const sp::BezierSurface b = sp::interpolating_bezier_surface(kUs, kVs, c);
  camera(s);
  gllab::draw_surface(mesh_of(sp::surface_evaluator(b)), kClay);
  for (std::size_t j = 0; j < 3; ++j) {
    const sp::BezierCurve a = sp::bezier_interpolate({c[j], c[3 + j], c[6 + j], c[9 + j]}, kUs);
    if (s.flag("curves")) gllab::draw_dots(a.P, kCurve, 6.f);  // its Bézier points a_ij
    curve(s, [&](double u) { return sp::bezier_point(a, u); }, kCurve);
  }
  if (s.flag("nets")) gllab::draw_control_net(b.P, 4, 3, kNet);
  gllab::draw_control_points(s, "C", kFree);
  caption(s, {"1) green: a curve per column through the data",
              "2) pink: the Bezier net b_ij through those points",
              "   (the same surface as lagrange)"});
}

void draw_hermite(const State& s) {
  const std::vector<Vec3>& k = s.points("K");
  sp::HermitePatch h;  // the corners' data from their handles
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const Vec3* c = &k[std::size_t(4 * (2 * a + b))];
      const double su = a ? -1 : 1, sv = b ? -1 : 1;  // the handles point into the patch
      h.point[a][b] = c[0], h.du[a][b] = 3 * su * (c[1] - c[0]);
      h.dv[a][b] = 3 * sv * (c[2] - c[0]);
      h.twist[a][b] = 9 * su * sv * (c[3] - c[1] - c[2] + c[0]);
    }
  camera(s);
  gllab::draw_surface(mesh_of(h), kClay);
  for (double w : {0.0, 1.0}) {  // the boundary curves: Hermite segments
    curve(s, [&](double v) { return sp::surface_point(h, w, v); }, kCurve);
    curve(s, [&](double u) { return sp::surface_point(h, u, w); }, kCurve);
  }
  if (s.flag("nets"))  // from each corner h0 to h1 and h2
    gllab::draw_handles(s, "K", {{0, 1}, {0, 2}, {4, 5}, {4, 6}, {8, 9}, {8, 10}, {12, 13},
                                 {12, 14}}, kBlue, kFree);
  // The twist: how far h3 misses the parallelogram corner h1 + h2 - h0 (red).
  for (std::size_t c = 0; c < 16 && s.flag("nets"); c += 4) {
    gllab::draw_polyline({k[c + 1], k[c + 3], k[c + 2]}, kNet, 1.f);
    gllab::draw_polyline({k[c + 1] + k[c + 2] - k[c], k[c + 3]}, {1.f, .35f, .3f}, 2.f);
  }
  caption(s, {"corners, Xu/3 and Xv/3 (blue), twist Xuv/9 (red) at each",
              "X = sum H H point + Hbar H Xu + H Hbar Xv + Hbar Hbar Xuv"});
}

void draw_hermite_lagrange(const State& s) {
  const std::vector<Vec3>& l = s.points("L");
  sp::HermiteLagrangeSurface h{kHermiteLagrangeNodes, {}, {}, {}, {}};
  for (std::size_t j = 0; j < 3; ++j) {
    h.p0.push_back(l[4 * j]), h.du0.push_back(3 * (l[4 * j + 1] - l[4 * j]));
    h.p1.push_back(l[4 * j + 2]), h.du1.push_back(3 * (l[4 * j + 2] - l[4 * j + 3]));
  }
  camera(s);
  gllab::draw_surface(mesh_of(h), kClay);
  for (double v : kHermiteLagrangeNodes)  // Hermite segments at the nodes
    curve(s, [&](double u) { return sp::surface_point(h, u, v); }, kCurve);
  for (double u : {0.0, 1.0})  // Lagrange curves through the end points
    curve(s, [&](double v) { return sp::surface_point(h, u, v); }, kBlue);
  if (s.flag("nets"))
    gllab::draw_handles(s, "L", {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {8, 9}, {10, 11}}, kBlue, kFree);
  caption(s, {"Hermite along u (green, with Xu/3 handles)",
              "Lagrange along v (blue) through the nodes 0, 0.5, 1"});
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "20_interpolating_surfaces",
      "lab 20 · interpolating surfaces",
      {{"lagrange", "the Lagrange tensor product through 4 x 3 points", draw_lagrange, kOrbit},
       {"interpolating_bezier", "the Bézier surface through the same points, and its net",
        draw_interpolating_bezier, kOrbit},
       {"hermite", "a bicubic Hermite patch: corners, partials, twists", draw_hermite, kOrbit},
       {"hermite_lagrange", "Hermite along u, Lagrange along v", draw_hermite_lagrange, kOrbit}},
      {{"curves", 1, 0, 1, "curves on the surfaces"}, {"nets", 1, 0, 1, "control nets and handles"},
       {"labels", 1, 0, 1, "formulas and captions"}},
      {{'k', "curves on/off", "curves"},
       {'c', "nets and handles on/off", "nets"}, {'n', "labels on/off", "labels"}},
      init};
  lab.points = {{"C", kData, "data points c_ij", 3}, {"K", kHermite, "Hermite corners, handles", 3},
                {"L", kHermiteLagrange, "Hermite-Lagrange points and handles", 3}};
  return lab;
}
