// lab 08 · blobby objects                                       difficulty: ★★☆☆
// An object as the iso-surface {x : sum_i f(|x - P_i|) = c} of blobs (lecture notes
// ch. 1, §1.5 Blobby objects): the density f(t) = a H0(t / b) and its four conditions,
// two blobs that merge as their centres approach, a molecule, and one blob's surface
// over the gluSphere of the radius the density predicts. The core samples the field
// and extracts the surface (field/marching_cubes.h); the lab draws it.
// Notice: the surfaces join the moment the field at the midpoint reaches c, and the
//   join is smooth (C^1), never a crease.
// Try: in two_blobs, press [d] until they touch: what distance does the caption
//   predict? Does [c] or [b] move the merge distance, and which way?
// Keys: [d]/[D] distance  [c]/[C] iso-value  [b]/[B] radius  [g]/[G] grid
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: density, two_blobs, merging, molecule, vs_glu_sphere
// Reference: reference_images/08_blobby_objects__*.png

#include <cmath>
#include <string>
#include <vector>

#include "field/density.h"
#include "field/grid.h"
#include "field/marching_cubes.h"
#include "field/marching_squares.h"
#include "field/mesh_measures.h"
#include "gl/field_view.h"
#include "gl/gl.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

namespace fd = gllab::field;
using gllab::kOrbit, gllab::State, gllab::Rgb;

// Lab data (edit me) -------------------------------------------------------
constexpr double kA = 1.0;  // f(0): every blob's density at its centre
// A methane-like molecule: carbon in the middle, four hydrogens on a tetrahedron.
const fd::Blob kMolecule[] = {{{0, 0, 0}, 1.0, 1.3},     {{.6, .6, .6}, 1.0, .8},
                              {{.6, -.6, -.6}, 1.0, .8}, {{-.6, .6, -.6}, 1.0, .8},
                              {{-.6, -.6, .6}, 1.0, .8}};
const double kApproach[] = {1.35, 1.1, 1.02, 0.97, 0.6, 0.0};  // merging: d / d*
const Rgb kSurface{.95f, .6f, .25f}, kText{1, 1, 1}, kIso{.1f, .1f, .1f}, kGlu{.35f, .6f, .9f};

GLUquadric* g_q = nullptr;  // for gluSphere, made in init()

// Two blobs d apart on the x axis, with the State's radius b.
fd::BlobField two_blobs(const State& s, double d) {
  const fd::Blob left{{-d / 2, 0, 0}, kA, s.get("radius")}, right{{d / 2, 0, 0}, kA, left.b};
  return {{left, right}, fd::Density::kHermite};
}

// The iso-surface: the field sampled on grid^3 points over the cube [-h, h]^3,
// then marching cubes.
gllab::IndexedMesh surface(const State& s, const fd::BlobField& f, double h) {
  const int n = s.integer("grid");
  auto field = [&](const fd::Vec3& x) { return f.value(x); };
  return fd::marching_cubes(fd::sample(field, {-h, -h, -h}, {h, h, h}, n, n, n), s.get("iso")).mesh;
}

// Drawing -------------------------------------------------------------------
// The notes' density beside Wyvill's and Blinn's, with the four conditions.
void draw_density(const State& s) {
  const double b = s.get("radius"), c = s.get("iso");
  gllab::ortho_fit(s.width, s.height, .85 * b, .7);
  glTranslated(-.7 * b, -.45, 0);
  gllab::draw_plot_axes(0, 1.45 * b, 0, 1.05, .25, .25, kText);
  double (*const densities[])(double, double, double) = {fd::blinn_density, fd::wyvill_density,
                                                         fd::hermite_density};
  const Rgb colours[] = {{.5f, .7f, 1.f}, {.5f, .9f, .5f}, kSurface};
  for (int k = 0; k < 3; ++k) {
    glLineWidth(k == 2 ? 3.f : 1.f);
    glColor3f(colours[k].r, colours[k].g, colours[k].b);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 290; ++i) glVertex2d(i * b / 200, densities[k](i * b / 200, kA, b));
    glEnd();
  }
  glLineWidth(1.f);
  glColor3f(kText.r, kText.g, kText.b);
  glBegin(GL_LINES);  // the slopes f'(0) = 0 and f'(b) = 0, the iso-value c
  glVertex2d(0, kA), glVertex2d(.2 * b, kA), glVertex2d(.85 * b, 0), glVertex2d(1.15 * b, 0);
  glVertex2d(0, c), glVertex2d(1.4 * b, c);
  glEnd();
  const double r = fd::iso_radius(fd::Density::kHermite, kA, b, c);
  glPointSize(7.f);
  glBegin(GL_POINTS);
  glVertex2d(0, kA), glVertex2d(b, 0), glVertex2d(r, c);
  glEnd();
  gllab::draw_label(.3 * b, kA, 0, "f(0) = a, f'(0) = 0", kText, 60, -10);
  gllab::draw_label(b, 0, 0, "f(b) = 0, f'(b) = 0", kText, 0, -30);
  gllab::draw_label(r, c, 0, "f(r) = c: r = " + gllab::fmt("%.4f", r), kText, 70, -12);
  gllab::draw_label(.75 * b, .25, 0, "decreasing", kSurface, 50, 0);
  gllab::draw_text_panel(8, 8, {"f(t) = a H0(t/b) = a (1 - 3s^2 + 2s^3), s = t/b (thick)",
      "Wyvill et al. 1986 (green), Blinn 1982 exp (blue): never 0",
      gllab::format_text("a = %.1f, b = %.2f, c = %.2f", kA, b, c)}, kText);
}

// Two blobs: the surface on the left, the slice z = 0 coloured by value with
// its iso-curve (marching squares) on the right.
void draw_two_blobs(const State& s) {
  const double d = s.get("distance"), b = s.get("radius"), c = s.get("iso");
  const fd::BlobField f = two_blobs(s, d);
  const double h = 1.1 * b + d / 2;
  const gllab::IndexedMesh m = surface(s, f, h);
  const gllab::Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  gllab::field_camera(s, left.width, left.height, .8 * h);
  glColor3f(kSurface.r, kSurface.g, kSurface.b);
  gllab::draw_iso_mesh(m);
  const gllab::Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  gllab::ortho_fit(right.width, right.height, h, h);
  auto slice = [&](double x, double y) { return f.value({x, y, 0}); };
  gllab::draw_field_slice(slice, -h, -h, h, h, 0, 120, 0, c, 2 * kA);
  const int n = s.integer("grid");
  gllab::draw_iso_curves(fd::marching_squares(fd::sample(slice, -h, -h, h, h, n, n), c), 0.1, kIso,
                         2.f);
  gllab::leave_panels(s.width, s.height);
  const double merge = fd::merge_distance(fd::Density::kHermite, kA, b, c);
  gllab::draw_panel_caption(left, -1, "surface: " + gllab::component_text(m), kText);
  gllab::draw_panel_caption(right, -1, "slice z = 0, iso-curve", kText);
  gllab::draw_text_panel(8, 8, {gllab::format_text("d = %.2f, they merge at d* = %.4f", d, merge),
                                gllab::format_text("(2 f(d*/2) = c = %.2f)", c)}, kText);
}

// The notes' sequence: the centres approach until they coincide.
void draw_merging(const State& s) {
  const double merge = fd::merge_distance(fd::Density::kHermite, kA, s.get("radius"), s.get("iso"));
  const double h = 1.1 * s.get("radius") + merge * kApproach[0] / 2;
  for (int k = 0; k < 6; ++k) {
    const gllab::IndexedMesh m = surface(s, two_blobs(s, kApproach[k] * merge), h);
    const gllab::Panel p = gllab::enter_panel(k % 3, k / 3, 3, 2, s.width, s.height);
    gllab::field_camera(s, p.width, p.height, .75 * h);
    glColor3f(kSurface.r, kSurface.g, kSurface.b);
    gllab::draw_iso_mesh(m);
    gllab::draw_panel_caption(p, -2, gllab::format_text("d = %.2f d*", kApproach[k]), kText);
    gllab::draw_panel_caption(p, -1, gllab::component_text(m), kText);
  }
  gllab::leave_panels(s.width, s.height);
}

void draw_molecule(const State& s) {
  const fd::BlobField f{{std::begin(kMolecule), std::end(kMolecule)}, fd::Density::kHermite};
  const gllab::IndexedMesh m = surface(s, f, 1.6);
  gllab::field_camera(s, s.width, s.height, 1.6);
  glColor3f(kSurface.r, kSurface.g, kSurface.b);
  gllab::draw_iso_mesh(m);
  const std::string counts = gllab::fmt("%g triangles, ", m.triangle_count());
  gllab::draw_text_panel(8, 8, {"a molecule of 5 blobs (C: b = 1.3, H: b = 0.8)",
                                counts + gllab::component_text(m)}, kText);
}

// One blob: its extracted mesh (lines) over gluSphere(r), r from f(r) = c.
void draw_vs_glu_sphere(const State& s) {
  const double b = s.get("radius"), c = s.get("iso");
  const double r = fd::iso_radius(fd::Density::kHermite, kA, b, c);
  const gllab::IndexedMesh m = surface(s, {{{{0, 0, 0}, kA, b}}, fd::Density::kHermite}, 1.05 * b);
  const auto [lo, hi] = gllab::distance_range(m, {0, 0, 0});
  gllab::field_camera(s, s.width, s.height, 1.25 * r);
  glColor3f(kGlu.r, kGlu.g, kGlu.b);
  gluSphere(g_q, r * 0.995, 48, 24);  // just inside, so the mesh's lines show
  gllab::draw_mesh_edges(m, kSurface);
  const std::string sphere = gllab::format_text("gluSphere(q, r = %.4f, 48, 24): f(r) = c", r);
  gllab::draw_text_panel(8, 8, {sphere, gllab::format_text("vertices %.4f .. %.4f from the centre "
                                "(grid %d^3)", lo, hi, s.integer("grid"))}, kText);
}

// init / shutdown -------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  g_q = gluNewQuadric();
}
void shutdown() { gluDeleteQuadric(g_q); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "08_blobby_objects",
      "lab 08 · blobby objects",
      {{"density", "f(t) = a H0(t/b) with its four conditions, Wyvill's and Blinn's", draw_density},
       {"two_blobs", "two blobs d apart: the surface and the field's slice z = 0", draw_two_blobs,
        kOrbit},
       {"merging", "the centres approach until they coincide: the moment they merge", draw_merging,
        kOrbit},
       {"molecule", "five blobs: a methane-like molecule", draw_molecule, kOrbit},
       {"vs_glu_sphere", "one blob's mesh over gluSphere of the predicted radius",
        draw_vs_glu_sphere, kOrbit}},
      {{"distance", 1.4, 0, 3, "distance d of the two centres"},
       {"iso", 0.5, 0.05, 0.95, "iso-value c (0 < c < a = 1)"},
       {"radius", 1, 0.5, 2, "blob radius b"}, {"grid", 40, 8, 96, "grid points per axis"}},
      {{'d', "centres closer (-0.05)", "distance", -0.05},
       {'D', "centres apart (+0.05)", "distance", +0.05},
       {'c', "iso-value down (-0.05)", "iso", -0.05}, {'C', "iso-value up (+0.05)", "iso", +0.05},
       {'b', "radius down (-0.05)", "radius", -0.05}, {'B', "radius up (+0.05)", "radius", +0.05},
       {'g', "coarser grid (-4)", "grid", -4}, {'G', "finer grid (+4)", "grid", +4}},
      init};
  lab.shutdown = shutdown;
  return lab;
}
