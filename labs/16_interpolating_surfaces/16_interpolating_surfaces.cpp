// lab 16 · interpolating surfaces                            difficulty: ★★★☆
// Surfaces through given data (seed 000 §1.7): the Lagrange tensor product,
// bicubic Hermite patches (corner points, partials, twists), the Hermite–
// Lagrange mix, the interpolating Bézier surface, and a bicubic B-spline
// scalar field drawn as a terrain with height colours and iso-lines.
// Notice: lagrange and interpolating_bezier draw the same surface: one
//   polynomial in two bases. Its Bézier net floats off the surface; the data
//   points stay on it.
// Try: in hermite, drag a twist handle (the square at the end of a red
//   arrow). The corner point and both tangents stay; what changes? In terrain,
//   drag a control point up: how far does the hill spread, which iso-lines move?
// Keys: [l]/[L] iso-line spacing  [k] curves  [c] nets and handles  [n] labels
//   [h] help  [Esc] quit
// Views: lagrange, interpolating_bezier, hermite, hermite_lagrange, terrain, terrain_map
// Reference: reference_images/16_interpolating_surfaces__*.png

#include <algorithm>
#include <cmath>
#include <functional>
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
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The seeds' example m = 3, n = 2: data c_ij at the nodes s_i x t_j, c[3 i + j].
const std::vector<double> kUs = {0, 1.0 / 3, 2.0 / 3, 1}, kVs = {0, 0.5, 1};
const std::vector<Vec3> kData = {
    {-1.5, -1, 0},   {-1.5, 0, .5},  {-1.5, 1, .2},  {-.5, -1, .5},  {-.5, 0, .8},  {-.5, 1, .4},
    {.5, -1, .1},    {.5, 0, .4},    {.5, 1, .6},    {1.5, -1, .2},  {1.5, 0, .3},  {1.5, 1, .1}};
// Hermite patch: per corner (u, v) = (a, b), K[4 (2a + b) + ...] = h0 the
// point, h1 = h0 +- Xu/3 and h2 = h0 +- Xv/3 (a step into the patch), h3 =
// h1 + h2 - h0 +- Xuv/9: where the seeds' Bézier points b10, b01, b11 sit
// (seed 000 §1.7, Xs(0,0) = 3 (b10 - b00), Xst(0,0) = 9 (b11 - b10 - b01 + b00)).
const std::vector<Vec3> kHermite = {
    {-1.5, -1.5, 0},  {-.5, -1.5, .6},  {-1.5, -.5, .5},  {-.5, -.5, 1.4},
    {-1.5, 1.5, .3},  {-.5, 1.5, .8},   {-1.5, .5, .6},   {-.5, .5, 1.1},
    {1.5, -1.5, .2},  {.5, -1.5, .7},   {1.5, -.5, .9},   {.5, -.5, 1},
    {1.5, 1.5, 0},    {.5, 1.5, .4},    {1.5, .5, .3},    {.5, .5, .9}};
// Hermite along u, Lagrange along v at the nodes 0, 0.5, 1: per node L[4 j + ...]:
// 0 X(0, v_j), 1 that point + Xu/3, 2 X(1, v_j), 3 that point - Xu/3.
const std::vector<double> kHermiteLagrangeNodes = {0, 0.5, 1};
const std::vector<Vec3> kHermiteLagrange = {
    {-1.5, -1.5, 0},  {-.5, -1.5, .8},  {1.5, -1.5, .3},  {.5, -1.5, .7},
    {-1.5, 0, .5},    {-.5, 0, .6},     {1.5, 0, .9},     {.5, 0, .3},
    {-1.5, 1.5, 0},   {-.5, 1.5, .2},   {1.5, 1.5, .1},   {.5, 1.5, .9}};
// Terrain: a bicubic B-spline height field, 6 x 6 ordinates h_ij over
// [-2, 2]^2 (seed 000 §1.7, "Scalar fields": scalar "points").
const std::vector<double> kKnots = {-2, -2, -2, -2, -2.0 / 3, 2.0 / 3, 2, 2, 2, 2};
const double kHeights[6][6] = {{0, .1, .2, .1, 0, -.2},     {.1, .5, .9, .6, .2, 0},
                               {.2, 1, 1.8, 1.2, .4, .1},   {.1, .6, 1.1, .5, -.3, -.4},
                               {0, .2, .3, -.2, -.6, -.3},  {-.1, 0, .1, 0, -.2, -.1}};
constexpr double kTolerance = 5e-3;  // tessellation, object units
const gllab::Rgb kClay{.85f, .55f, .35f}, kNet{.85f, .5f, .85f}, kFree{1.f, .9f, .3f}, kCurve{.3f, 1.f, .5f},
    kBlue{.4f, .7f, 1.f}, kText{1.f, 1.f, 1.f}, kIso{.1f, .1f, .1f};
// Height colours: water, grass, rock, snow (h, colour), blended in between.
const std::pair<double, gllab::Rgb> kRamp[] = {
    {-.6, {.15f, .3f, .7f}}, {0, {.3f, .6f, .8f}}, {.05, {.3f, .65f, .3f}}, {.9, {.6f, .5f, .3f}}, {1.6, {1.f, 1.f, 1.f}}};

// The surfaces -------------------------------------------------------------------
sp::LagrangeSurface lagrange(const gllab::State& s) { return {kUs, kVs, s.points("C")}; }

sp::HermitePatch hermite(const gllab::State& s) {
  const std::vector<Vec3>& k = s.points("K");
  sp::HermitePatch h;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const Vec3* c = &k[std::size_t(4 * (2 * a + b))];
      const double su = a ? -1 : 1, sv = b ? -1 : 1;  // the handles point into the patch
      h.point[a][b] = c[0], h.du[a][b] = 3 * su * (c[1] - c[0]), h.dv[a][b] = 3 * sv * (c[2] - c[0]);
      h.twist[a][b] = 9 * su * sv * (c[3] - c[1] - c[2] + c[0]);
    }
  return h;
}

sp::HermiteLagrangeSurface hermite_lagrange(const gllab::State& s) {
  const std::vector<Vec3>& l = s.points("L");
  sp::HermiteLagrangeSurface h{kHermiteLagrangeNodes, {}, {}, {}, {}};
  for (std::size_t j = 0; j < 3; ++j) {
    h.p0.push_back(l[4 * j]), h.du0.push_back(3 * (l[4 * j + 1] - l[4 * j]));
    h.p1.push_back(l[4 * j + 2]), h.du1.push_back(3 * (l[4 * j + 2] - l[4 * j + 3]));
  }
  return h;
}

// Control point i of the terrain sits above its Greville abscissae (the knot
// averages (U[i+1] + U[i+2] + U[i+3]) / 3: then x(u, v) = u, y = v, and the
// surface is the graph of the height field); only the heights are data.
double greville(int i) { return (kKnots[i + 1] + kKnots[i + 2] + kKnots[i + 3]) / 3; }
Vec3 above_grid(const std::vector<Vec3>& H, int k) { return {greville(k / 6), greville(k % 6), H[std::size_t(k)].z}; }

sp::BsplineSurface terrain(const gllab::State& s) {
  sp::BsplineSurface t{3, 3, kKnots, kKnots, 6, 6, {}, {}, {}};
  for (int k = 0; k < 36; ++k) t.P.push_back(above_grid(s.points("H"), k));
  return t;
}

// Lagrange and Hermite–Lagrange surfaces give points only: the tessellator
// takes their normals from central differences (tessellate.h).
sp::Mesh mesh_of(const sp::SurfaceEvaluator& f, sp::UvDomain domain = {0, 1, 0, 1}) {
  return sp::tessellate_surface(f, domain, sp::TessellationOptions::adaptive(kTolerance));
}
template <class Surface>
sp::SurfaceEvaluator points_only(const Surface& surface) {
  return [surface](double u, double v) { return sp::SurfaceSample{sp::surface_point(surface, u, v), {}, {}, {}}; };
}

// Drawing ----------------------------------------------------------------------
// A curve on the surface, parameter 0..1 (off with [k], to compare surfaces).
void curve(const gllab::State& s, const std::function<Vec3(double)>& c, gllab::Rgb colour) {
  if (s.flag("curves")) gllab::draw_curve(c, 0, 1, colour);
}

void caption(const gllab::State& s, const std::vector<std::string>& lines) {
  if (s.flag("labels")) gllab::draw_text_panel(8, 8, lines, kText);
}

std::vector<std::size_t> first(std::size_t n) {
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  return all;
}

// Handles: an arrow from point base to its tip, the tip draggable.
void draw_handles(const gllab::State& s, const std::string& list, const std::vector<std::pair<int, int>>& arrows) {
  if (!s.flag("nets")) return;
  const std::vector<Vec3>& p = s.points(list);
  for (auto [base, tip] : arrows) gllab::draw_polyline({p[std::size_t(base)], p[std::size_t(tip)]}, kBlue, 2.f);
  gllab::draw_control_points(s, list, first(p.size()), kFree);
}

void draw_lagrange(const gllab::State& s) {
  const sp::LagrangeSurface f = lagrange(s);
  gllab::draw_surface(mesh_of(points_only(f)), kClay);
  // The curves through each row and column of the data lie on the surface.
  for (double u : kUs) curve(s, [&](double v) { return sp::surface_point(f, u, v); }, kCurve);
  for (double v : kVs) curve(s, [&](double u) { return sp::surface_point(f, u, v); }, kBlue);
  gllab::draw_control_points(s, "C", first(12), kFree);
  caption(s, {"f(s, t) = sum c_ij L_i(s) L_j(t), m = 3, n = 2", "green c_i(t), blue c_j(s): through the data"});
}

// Step 1: a curve per column j through c_0j..c_3j (points a_ij, dashed); step 2:
// a curve per row i through a_i0..a_i2 gives the net b_ij (core).
void draw_interpolating_bezier(const gllab::State& s) {
  const std::vector<Vec3>& c = s.points("C");
  const sp::BezierSurface b = sp::interpolating_bezier_surface(kUs, kVs, c);
  gllab::draw_surface(mesh_of(sp::surface_evaluator(b)), kClay);
  for (std::size_t j = 0; j < 3; ++j) {
    const sp::BezierCurve a = sp::bezier_interpolate({c[j], c[3 + j], c[6 + j], c[9 + j]}, kUs);
    if (s.flag("curves")) gllab::draw_dots(a.P, kCurve, 6.f);  // its Bézier points a_ij
    curve(s, [&](double u) { return sp::bezier_point(a, u); }, kCurve);
  }
  if (s.flag("nets")) gllab::draw_control_net(b.P, 4, 3, kNet);
  gllab::draw_control_points(s, "C", first(12), kFree);
  caption(s, {"1) green: a curve per column through the data", "2) pink: the Bezier net b_ij through those points",
              "   (the same surface as lagrange)"});
}

void draw_hermite(const gllab::State& s) {
  const sp::HermitePatch h = hermite(s);
  gllab::draw_surface(mesh_of([h](double u, double v) {
    return sp::SurfaceSample{sp::surface_point(h, u, v), sp::surface_normal(h, u, v), {}, {}};
  }), kClay);
  for (double w : {0.0, 1.0}) {  // the boundary curves: Hermite segments
    curve(s, [&](double v) { return sp::surface_point(h, w, v); }, kCurve);
    curve(s, [&](double u) { return sp::surface_point(h, u, w); }, kCurve);
  }
  std::vector<std::pair<int, int>> arrows;
  for (int c = 0; c < 4; ++c) arrows.insert(arrows.end(), {{4 * c, 4 * c + 1}, {4 * c, 4 * c + 2}});
  draw_handles(s, "K", arrows);
  // The twist: how far h3 misses the parallelogram corner h1 + h2 - h0 (red).
  const std::vector<Vec3>& k = s.points("K");
  for (std::size_t c = 0; c < 16 && s.flag("nets"); c += 4) {
    gllab::draw_polyline({k[c + 1], k[c + 3], k[c + 2]}, kNet, 1.f);
    gllab::draw_polyline({k[c + 1] + k[c + 2] - k[c], k[c + 3]}, {1.f, .35f, .3f}, 2.f);
  }
  caption(s, {"corners, Xu/3 and Xv/3 (blue), twist Xuv/9 (red) at each",
              "X = sum H H point + Hbar H Xu + H Hbar Xv + Hbar Hbar Xuv"});
}

void draw_hermite_lagrange(const gllab::State& s) {
  const sp::HermiteLagrangeSurface h = hermite_lagrange(s);
  gllab::draw_surface(mesh_of(points_only(h)), kClay);
  for (double v : kHermiteLagrangeNodes)  // Hermite segments at the nodes
    curve(s, [&](double u) { return sp::surface_point(h, u, v); }, kCurve);
  for (double u : {0.0, 1.0})  // Lagrange curves through the end points
    curve(s, [&](double v) { return sp::surface_point(h, u, v); }, kBlue);
  draw_handles(s, "L", {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {8, 9}, {10, 11}});
  caption(s, {"Hermite along u (green, with Xu/3 handles)", "Lagrange along v (blue) through the nodes 0, 0.5, 1"});
}

gllab::Rgb height_colour(double h) {
  std::size_t k = 1;
  while (k + 1 < std::size(kRamp) && h > kRamp[k].first) ++k;
  const auto& [h0, c0] = kRamp[k - 1];
  const auto& [h1, c1] = kRamp[k];
  const float f = float(std::clamp((h - h0) / (h1 - h0), 0.0, 1.0));
  return {c0.r + f * (c1.r - c0.r), c0.g + f * (c1.g - c0.g), c0.b + f * (c1.b - c0.b)};
}

// Height colours per vertex, iso-lines every `iso_step` (core contour_segments
// on the mesh, within its tolerance of the true iso-curves).
void draw_terrain(const gllab::State& s, bool map) {
  const sp::BsplineSurface t = terrain(s);
  const sp::Mesh m = mesh_of(sp::surface_evaluator(t), sp::uv_domain(t));
  std::vector<gllab::Rgb> colours;
  for (const Vec3& p : m.positions) colours.push_back(height_colour(p.z));
  gllab::draw_surface(m, colours);
  const double step = s.get("iso_step");
  for (double level = step * std::floor(-0.6 / step); level < 1.8; level += step)
    gllab::draw_segments(sp::contour_segments(m, {0, 0, 1}, level), kIso, std::fabs(level) < 1e-9 ? 2.f : 1.f);
  // From above the mouse could only move the points sideways: not pickable there.
  if (map) gllab::draw_dots(t.P, kText, 4.f);
  else if (s.flag("nets")) {
    gllab::draw_control_net(t.P, 6, 6, kNet);
    gllab::draw_control_points_at(s, "H", first(36), t.P, kFree);
  }
  caption(s, {"bicubic B-spline height field h(x, y), 6 x 6 ordinates",
              gllab::format_text("iso-lines every %.2f (thick: height 0)", step)});
}

// init / display ----------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

void display(const gllab::State& s) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 2.5, 2.5);
  gllab::enable_headlight();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);  // we see under some of them
  glTranslated(0, -0.3, 0);  // below the text panel
  if (s.view() == "terrain" || s.view() == "terrain_map") glScaled(.85, .85, .85);  // [-2, 2]^2: larger
  if (s.view() == "terrain_map") return draw_terrain(s, true);  // from straight above
  gllab::look_from_above(25, 30);
  if (s.view() == "lagrange") draw_lagrange(s);
  else if (s.view() == "interpolating_bezier") draw_interpolating_bezier(s);
  else if (s.view() == "hermite") draw_hermite(s);
  else if (s.view() == "hermite_lagrange") draw_hermite_lagrange(s);
  else draw_terrain(s, false);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"16_interpolating_surfaces",
                 "lab 16 · interpolating surfaces",
                 {{"lagrange", "the Lagrange tensor product through 4 x 3 points"},
                  {"interpolating_bezier", "the Bézier surface through the same points, and its net"},
                  {"hermite", "a bicubic Hermite patch: corners, partials, twists"},
                  {"hermite_lagrange", "Hermite along u, Lagrange along v"},
                  {"terrain", "a bicubic B-spline height field: colours and iso-lines"},
                  {"terrain_map", "the same terrain from above, as a map"}},
                 {{"iso_step", 0.2, 0.05, 1, "height between iso-lines (terrain)"},
                  {"curves", 1, 0, 1, "curves on the surfaces"}, {"nets", 1, 0, 1, "control nets and handles"},
                  {"labels", 1, 0, 1, "formulas and captions"}},
                 {{'l', "iso-lines closer (step -0.05)", "iso_step", -0.05},
                  {'L', "iso-lines wider (step +0.05)", "iso_step", +0.05},
                  {'k', "curves on/off", "curves"}, {'c', "nets and handles on/off", "nets"},
                  {'n', "labels on/off", "labels"}},
                 init,
                 display};
  std::vector<Vec3> heights;
  for (int k = 0; k < 36; ++k) heights.push_back({greville(k / 6), greville(k % 6), kHeights[k / 6][k % 6]});
  lab.points = {{"H", heights, "terrain ordinates h_ij (only z counts)", 3},
                {"C", kData, "data points c_ij (lagrange, interpolating_bezier)", 3},
                {"K", kHermite, "Hermite corners and handles (hermite)", 3},
                {"L", kHermiteLagrange, "Hermite-Lagrange points and handles", 3}};
  // Ctrl+S saves the terrain, the one surface here given by control points.
  lab.model = [](const gllab::State& s) -> gllab::Model { return terrain(s); };
  return lab;
}
