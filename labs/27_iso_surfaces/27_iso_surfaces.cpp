// lab 27 · iso-curves and iso-surfaces                          difficulty: ★★★☆
// Marching squares and marching cubes (lecture notes ch. 1, §1.7 Surface
// representations, "Iso-curves" and "Iso-surfaces"): a bilinear field's iso-curves
// with its saddle cells joined naively and by the asymptotic decider (Nielson and
// Hamann 1991); Lorensen and Cline's 15 base cases; the hole their table leaves
// where two cells decide one face differently; a surface coloured by case; and a
// CT-like volume (the Shepp-Logan head phantom) cut open with glClipPlane.
// Notice: a saddle face has two inside corners on a diagonal; only its four values
//   say whether they are joined. Deciding by the face, both cells agree.
// Try: in squares, press [c]: at which iso-value do the two panels agree again?
//   In ct_phantom, step [t] from 0.1 to 0.3: which structures appear?
// Keys: [c]/[C] iso-value  [t]/[T] CT iso-value  [g]/[G] phantom grid  [k] clip plane
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: squares, cube_cases, ambiguous_face, cases_coloured, ct_phantom
// Reference: reference_images/27_iso_surfaces__*.png

#include <string>
#include <vector>

#include "field/grid.h"
#include "field/marching_cubes.h"
#include "field/marching_squares.h"
#include "field/mesh_measures.h"
#include "field/phantom.h"
#include "gl/field_view.h"
#include "gl/gl.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

namespace fd = gllab::field;
using gllab::kOrbit, gllab::State, gllab::Rgb;

// Lab data (edit me) -------------------------------------------------------
// A bilinear field on 5 x 5 values, rows j = 0..4 from the bottom; three of its
// cells are saddles at c = 0.5 (diagonal corners above c, the other two below).
// The decider joins three of them (saddle value above c) and separates one.
const double kSquares[5][5] = {{0.1, 0.3, 0.2, 0.4, 0.1},
                               {0.2, 0.9, 0.1, 0.8, 0.3},
                               {0.3, 0.2, 0.95, 0.2, 0.2},
                               {0.1, 0.8, 0.3, 0.6, 0.1},
                               {0.0, 0.2, 0.1, 0.3, 0.2}};
// Two cells sharing the face x = 2 of a 5 x 4 x 4 grid (0 elsewhere): inside
// corners (2,1,1) and (2,2,2) on its diagonal; the cell on the right has all four
// corners at x = 3 inside as well. Left: case 3 (2 inside), right: 6 inside.
struct Corner {
  int i, j, k;
  float value;
};
const Corner kAmbiguous[] = {{2, 1, 1, 1.f}, {2, 2, 2, 1.f}, {2, 2, 1, .2f}, {3, 1, 1, 1.f},
                             {3, 2, 1, 1.f}, {3, 1, 2, 1.f}, {3, 2, 2, 1.f}};
constexpr int kTorusGrid = 20;  // cases_coloured: coarse, so that cells show
const Rgb kText{1, 1, 1}, kCurve{.1f, .1f, .1f}, kExact{.2f, .6f, .2f}, kSaddle{1, .85f, .2f},
    kSurface{.95f, .6f, .25f}, kHole{1, .2f, .2f};
// One colour per Lorensen-Cline base case 0..14.
const Rgb kCaseColours[15] = {{.5, .5, .5},    {.9, .4, .3},  {.3, .7, .4},   {.3, .5, .9},
                              {.9, .8, .3},    {.7, .4, .8},  {.3, .8, .8},   {.95, .6, .7},
                              {.6, .8, .3},    {.8, .55, .3}, {.45, .45, .8}, {.8, .3, .5},
                              {.55, .75, .95}, {1, .95, .6},  {.4, .6, .5}};

fd::Grid2 squares_grid() {
  fd::Grid2 g{5, 5, 0, 0, 1, 1, {}};
  for (const auto& row : kSquares) g.values.insert(g.values.end(), std::begin(row), std::end(row));
  return g;
}

// Drawing -------------------------------------------------------------------
// Left: saddle cells separated (naive table); right: the asymptotic decider.
// Green underneath: the bilinear interpolant's true iso-curve, traced finely.
void draw_squares(const State& s) {
  const fd::Grid2 g = squares_grid();
  const double c = s.get("iso");
  auto bilinear = [&](double x, double y) { return g.bilinear(x, y); };
  const fd::IsoCurves exact = fd::marching_squares(fd::sample(bilinear, 0, 0, 4, 4, 161, 161), c);
  const char* names[] = {"naive: saddles separated", "asymptotic decider"};
  const fd::Saddle rules[] = {fd::Saddle::kNaive, fd::Saddle::kDecider};
  for (int p = 0; p < 2; ++p) {
    const gllab::Panel panel = gllab::enter_panel(p, 0, 2, 1, s.width, s.height);
    gllab::ortho_fit(panel.width, panel.height, 2.6, 2.6);
    glTranslated(-2, -2, 0);
    gllab::draw_field_slice(bilinear, 0, 0, 4, 4, -0.5, 80, 0, c, 1);
    const fd::IsoCurves curves = fd::marching_squares(g, c, rules[p]);
    glColor3f(kSaddle.r, kSaddle.g, kSaddle.b);
    for (const auto& cell : curves.cells)  // saddle cells outlined
      if (cell.saddle) {
        glBegin(GL_LINE_LOOP);
        glVertex2i(cell.i, cell.j), glVertex2i(cell.i + 1, cell.j);
        glVertex2i(cell.i + 1, cell.j + 1), glVertex2i(cell.i, cell.j + 1);
        glEnd();
      }
    gllab::draw_iso_curves(exact, 0, kExact, 1.f);
    gllab::draw_iso_curves(curves, 0.1, kCurve, 3.f);
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i)
        gllab::draw_label(i, j, .2, gllab::fmt("%.1f", g.at(i, j)), kText);
    gllab::draw_panel_caption(panel, 0, names[p], kText);
    gllab::draw_panel_caption(
        panel, -1, gllab::format_text("%zu polylines at c = %.2f", curves.polylines().size(), c),
        kText);
  }
  gllab::leave_panels(s.width, s.height);
}

// Lorensen and Cline's 15 base cases, one cell each, as their 1987 table cuts them.
void draw_cube_cases(const State& s) {
  for (int k = 0; k < 15; ++k) {
    const std::uint8_t mask = fd::base_case_mask(k);
    fd::Grid3 g{2, 2, 2, {0, 0, 0}, {1, 1, 1}, std::vector<float>(8)};
    for (int a = 0; a < 8; ++a) g.values[a] = float(mask >> a & 1);
    const fd::McResult r = fd::marching_cubes(g, 0.5, {fd::FaceRule::kLorensenCline});
    const gllab::Panel p = gllab::enter_panel(k % 5, k / 5, 5, 3, s.width, s.height);
    gllab::field_camera(s, p.width, p.height, 1.0, -110);
    glTranslated(-.5, -.5, -.5);
    gllab::draw_unit_cell(mask, kHole);  // inside corners red
    glColor3f(kSurface.r, kSurface.g, kSurface.b);
    gllab::draw_iso_mesh(r.mesh);
    const std::size_t n = r.mesh.triangle_count();
    gllab::draw_panel_caption(p, 0, gllab::format_text("case %d", k), kText);
    const std::string count = gllab::format_text("%zu triangle%s", n, n == 1 ? "" : "s");
    gllab::draw_panel_caption(p, -1, count, kText);
  }
  gllab::leave_panels(s.width, s.height);
}

// The two cells of kAmbiguous, by Lorensen and Cline's table and by the decider.
void draw_ambiguous_face(const State& s) {
  fd::Grid3 g{5, 4, 4, {0, 0, 0}, {1, 1, 1}, std::vector<float>(80, 0.f)};
  for (const Corner& v : kAmbiguous) g.values[(v.k * 4 + v.j) * 5 + v.i] = v.value;
  const char* names[] = {"Lorensen and Cline 1987", "asymptotic decider on the face"};
  const fd::FaceRule rules[] = {fd::FaceRule::kLorensenCline, fd::FaceRule::kDecider};
  for (int p = 0; p < 2; ++p) {
    const fd::McResult r = fd::marching_cubes(g, 0.5, {rules[p]});
    const gllab::Panel panel = gllab::enter_panel(p, 0, 2, 1, s.width, s.height);
    gllab::field_camera(s, panel.width, panel.height, 2.0, 63);  // from -x: the face x = 2
    glTranslated(-2.5, -1.5, -1.5);
    glColor3f(kSurface.r, kSurface.g, kSurface.b);
    gllab::draw_iso_mesh(r.mesh);
    gllab::draw_mesh_edges(r.mesh, kCurve);
    gllab::draw_open_edges(r.mesh, kHole, 3.f);
    const fd::MeshTopology t = fd::topology(r.mesh);
    gllab::draw_panel_caption(panel, 0, names[p], kText);
    gllab::draw_panel_caption(panel, -1,
                              gllab::format_text("%zu open edges: %s", t.boundary_edges,
                                                 t.boundary_edges ? "a hole" : "closed"),
                              kText);
  }
  gllab::leave_panels(s.width, s.height);
}

// A torus sampled coarsely; each triangle in its cell's base-case colour.
void draw_cases_coloured(const State& s) {
  const int n = kTorusGrid;
  const fd::Grid3 g = fd::sample([](const fd::Vec3& x) { return fd::torus_field(x, 1, .45); },
                                 {-1.6, -1.6, -.6}, {1.6, 1.6, .6}, n, n, (n + 2) / 3);
  const fd::McResult r = fd::marching_cubes(g, 0, {fd::FaceRule::kDecider, true, true});
  std::vector<Rgb> colours(r.mesh.triangle_count());
  int used[15] = {};
  for (const fd::McCell& cell : r.cells) {
    ++used[cell.base];
    for (std::uint32_t t = 0; t < cell.triangle_count; ++t)
      colours[cell.first_triangle + t] = kCaseColours[cell.base];
  }
  gllab::field_camera(s, s.width, s.height, 1.9);
  gllab::draw_iso_mesh(r.mesh, colours);
  std::vector<std::string> legend{
      gllab::format_text("torus, %d x %d x %d grid: cells by case", n, n, (n + 2) / 3)};
  std::vector<Rgb> legend_colours{kText};
  for (int k = 1; k < 15; ++k)
    if (used[k])
      legend.push_back(gllab::format_text("case %d: %d cells", k, used[k])),
          legend_colours.push_back(kCaseColours[k]);
  gllab::draw_text_panel(8, 8, legend, legend_colours);
}

// The phantom's iso-surface, its front half cut away by a clip plane.
void draw_ct_phantom(const State& s) {
  const fd::Grid3 g = fd::shepp_logan_phantom(s.integer("grid"));
  const fd::McResult r = fd::marching_cubes(g, s.get("ct_iso"));
  gllab::field_camera(s, s.width, s.height, 1.1);
  const GLdouble plane[4] = {0, 1, 0, 0};  // keeps y >= 0: the back half
  glClipPlane(GL_CLIP_PLANE0, plane);
  if (s.flag("clip")) glEnable(GL_CLIP_PLANE0);
  glColor3f(.9f, .85f, .75f);
  gllab::draw_iso_mesh(r.mesh);
  glDisable(GL_CLIP_PLANE0);
  gllab::draw_text_panel(8, 8,
                         {gllab::format_text("Shepp-Logan phantom, %d^3 samples, iso %.2f",
                                             s.integer("grid"), s.get("ct_iso")),
                          gllab::format_text("%zu triangles", r.mesh.triangle_count())},
                         kText);
}

void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"27_iso_surfaces",
          "lab 27 · iso-curves and iso-surfaces",
          {{"squares", "marching squares: saddle cells naive and by the decider", draw_squares},
           {"cube_cases", "Lorensen and Cline's 15 base cases", draw_cube_cases, kOrbit},
           {"ambiguous_face", "one face decided two ways by two cells: a hole", draw_ambiguous_face,
            kOrbit},
           {"cases_coloured", "a torus, each triangle coloured by its cell's case",
            draw_cases_coloured, kOrbit},
           {"ct_phantom", "a CT-like volume cut open with glClipPlane", draw_ct_phantom, kOrbit}},
          {{"iso", 0.5, 0.05, 0.95, "iso-value c of the squares field"},
           {"ct_iso", 0.1, 0.05, 0.95, "iso-value of the phantom"},
           {"grid", 48, 8, 128, "phantom samples per axis"},
           {"clip", 1, 0, 1, "clip plane on/off"}},
          {{'c', "iso-value down (-0.05)", "iso", -0.05},
           {'C', "iso-value up (+0.05)", "iso", +0.05},
           {'t', "CT iso-value down (-0.05)", "ct_iso", -0.05},
           {'T', "CT iso-value up (+0.05)", "ct_iso", +0.05},
           {'g', "coarser grid (-4)", "grid", -4},
           {'G', "finer grid (+4)", "grid", +4},
           {'k', "clip plane on/off", "clip"}},
          init};
}
