// lab 26 · scalar fields: a height map                          difficulty: ★★☆☆
// A surface whose control points are scalars (lecture notes ch. 1, §1.7 Surface
// representations, "Scalar fields": "scalar valued 'points' (ordinates)", shown
// as a graph over the domain, like a terrain model): a bicubic B-spline height
// field h(x, y) from 6 x 6 ordinates, coloured by height, with its iso-lines
// ("Iso-curves"), in 3D and from straight above as a map.
// Notice: each ordinate sits above its Greville abscissae, so x(u, v) = u and
//   y(u, v) = v: the heights are the only data. An iso-line is where the
//   surface crosses a plane z = c.
// Try: in terrain, drag a point up: which iso-lines move, and how far away?
//   Press [l] a few times: where do the lines crowd together, and why?
// Keys: [l]/[L] iso-line spacing  [c] net and points  [n] labels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: terrain, terrain_map
// Reference: reference_images/26_scalar_fields__*.png

#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/surface.h"
#include "spline/tessellate.h"

namespace {

namespace sp = gllab::spline;
using gllab::State;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// A bicubic B-spline height field, 6 x 6 ordinates h_ij over [-2, 2]^2.
const std::vector<double> kKnots = {-2, -2, -2, -2, -2.0 / 3, 2.0 / 3, 2, 2, 2, 2};
const double kHeights[6][6] = {{0, .1, .2, .1, 0, -.2},    {.1, .5, .9, .6, .2, 0},
                               {.2, 1, 1.8, 1.2, .4, .1},  {.1, .6, 1.1, .5, -.3, -.4},
                               {0, .2, .3, -.2, -.6, -.3}, {-.1, 0, .1, 0, -.2, -.1}};
constexpr double kTolerance = 5e-3;  // tessellation, object units
const gllab::Rgb kNet{.85f, .5f, .85f}, kFree{1.f, .9f, .3f}, kText{1.f, 1.f, 1.f},
    kIso{.1f, .1f, .1f};
// Height colours: water, grass, rock, snow (h, colour), blended in between.
const std::vector<gllab::HeightColour> kRamp = {{-.6, {.15f, .3f, .7f}}, {0, {.3f, .6f, .8f}},
    {.05, {.3f, .65f, .3f}}, {.9, {.6f, .5f, .3f}}, {1.6, {1.f, 1.f, 1.f}}};

// Ordinate i sits above its Greville abscissae (U[i+1] + U[i+2] + U[i+3]) / 3:
// then x(u, v) = u, y = v, and the surface is the graph of the heights.
double greville(int i) { return (kKnots[i + 1] + kKnots[i + 2] + kKnots[i + 3]) / 3; }
Vec3 above_grid(int k, double height) { return {greville(k / 6), greville(k % 6), height}; }

// The field from the dragged points: only their heights count.
sp::BsplineSurface terrain(const State& s) {
  sp::BsplineSurface t{3, 3, kKnots, kKnots, 6, 6, {}, {}, {}};
  for (int k = 0; k < 36; ++k) t.P.push_back(above_grid(k, s.points("H")[k].z));
  return t;
}

// Drawing ----------------------------------------------------------------------
// One light that stays with the eye, both sides lit; from 25° above, or from
// straight above for the map.
void camera(const State& s, bool map) {
  gllab::ortho_fit(s.width, s.height, 2.5, 2.5);
  gllab::enable_headlight();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gllab::apply_orbit(s);     // right-drag, wheel, [0]: s.camera
  glTranslated(0, -0.3, 0);  // below the text panel
  glScaled(.85, .85, .85);   // [-2, 2]^2 fits
  if (!map) gllab::look_from_above(25, 30);
}

// Height colours per vertex; iso-lines every `iso_step` (the core's
// contour_segments on the mesh: where each triangle crosses z = level).
void draw_field(const State& s, bool map) {
  const sp::BsplineSurface t = terrain(s);
  camera(s, map);
  const sp::Mesh m = sp::tessellate_surface(sp::surface_evaluator(t), sp::uv_domain(t),
                                            sp::TessellationOptions::adaptive(kTolerance));
  gllab::draw_surface(m, gllab::height_colours(kRamp, m));
  const double step = s.get("iso_step");
  for (double level = step * std::floor(-0.6 / step); level < 1.8; level += step)
    gllab::draw_segments(sp::contour_segments(m, {0, 0, 1}, level), kIso,
                         std::fabs(level) < 1e-9 ? 2.f : 1.f);
  // From above the mouse could only move the points sideways: not pickable there.
  if (map) gllab::draw_dots(t.P, kText, 4.f);
  else if (s.flag("nets")) {
    gllab::draw_control_net(t.P, 6, 6, kNet);
    gllab::draw_control_points_at(s, "H", t.P, kFree);  // each above its grid point
  }
  const std::string title = "bicubic B-spline height field h(x, y), 6 x 6 ordinates";
  const std::string iso = gllab::format_text("iso-lines every %.2f (thick: height 0)", step);
  if (s.flag("labels")) gllab::draw_text_panel(8, 8, {title, iso}, kText);
}

void draw_terrain(const State& s) { draw_field(s, false); }
void draw_map(const State& s) { draw_field(s, true); }

void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "26_scalar_fields",
      "lab 26 · scalar fields: a height map",
      {{"terrain", "a bicubic B-spline height field: colours and iso-lines", draw_terrain, kOrbit},
       {"terrain_map", "the same terrain from above, as a map", draw_map, kOrbit}},
      {{"iso_step", 0.2, 0.05, 1, "height between iso-lines"},
       {"nets", 1, 0, 1, "control net and points"},
       {"labels", 1, 0, 1, "caption"}},
      {{'l', "iso-lines closer (step -0.05)", "iso_step", -0.05},
       {'L', "iso-lines wider (step +0.05)", "iso_step", +0.05},
       {'c', "net and points on/off", "nets"}, {'n', "labels on/off", "labels"}},
      init};
  std::vector<Vec3> heights;
  for (int k = 0; k < 36; ++k) heights.push_back(above_grid(k, kHeights[k / 6][k % 6]));
  lab.points = {{"H", heights, "ordinates h_ij (only z counts)", 3}};
  lab.model = [](const State& s) -> gllab::Model { return terrain(s); };  // for Ctrl+S
  return lab;
}
