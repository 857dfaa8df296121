// lab 35 · quadric coordinates                                difficulty: ★★☆☆
// A sphere from the notes' spherical coordinates (x = ρ sin φ cos θ, y = ρ sin φ sin θ,
// z = ρ cos φ: lecture notes "B-Spline Polynomials", "Conversions"), a cylinder from
// cylindrical (r, θ, z), by glBegin/glNormal/glVertex beside gluSphere and gluCylinder (ch. 1,
// §1.4 Quadric surfaces); the slices a sphere needs on screen (§1.1 Overview, level of detail).
// Notice: GLU starts its slices at +y and turns clockwise, so the lab's θ runs
//   90° − 360° i / slices. The overlay is green only where both agree.
// Try: start θ at 0 in own_sphere. What does the overlay show, and why does it agree
//   again at 20 slices? In level_of_detail, zoom with the wheel: which counts change?
// Keys: [s]/[S] slices  [t]/[T] stacks  [e]/[E] error in pixels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: spherical_vs_glu, cylindrical_vs_glu, level_of_detail
// Reference: reference_images/35_quadric_coordinates__*.png

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "gl/gl.h"
#include "gl/glu_errors.h"
#include "gl/scene.h"
#include "gl/shape_grid.h"
#include "gl/text.h"
#include "harness/lab.h"
#include "mesh/coordinates.h"
#include "mesh/level_of_detail.h"

namespace {

using gllab::kOrbit, gllab::State, gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
constexpr double kRadius = 0.9, kHeight = 1.4;   // sphere radius; cylinder radius 0.6
const GLfloat kOwn[] = {0.3f, 0.75f, 0.35f}, kGlu[] = {0.95f, 0.55f, 0.2f};
// level_of_detail: spheres of radius 0.5, each twice as far as the one before, seen
// through gluPerspective(kFovy, ...), kScreenX pixels right of the centre.
constexpr double kFovy = 40, kLodRadius = 0.5, kNearest = 4.5;
const double kScreenX[] = {-165, -30, 65, 140, 210};
constexpr int kGluMaxSlices = 239;  // GLU clamps slices and stacks here

GLUquadric* g_q = nullptr;  // made in init()
std::string g_call;         // what the GLU error callback reports (gl/glu_errors.h)
void GLAPIENTRY on_quadric_error(GLenum code) { gllab::report_glu_error(code, g_call); }

// One GL_QUAD_STRIP per stack, as GLU sends it: stack j from φ = π j / stacks (φ = 0:
// the north pole, +z) to π (j + 1) / stacks. ρ = 1 gives the normal, ρ = r the vertex.
void own_sphere(double r, int slices, int stacks) {
  for (int j = 0; j < stacks; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double theta = M_PI / 2 - 2 * M_PI * i / slices;  // GLU: from +y, clockwise
      for (int k : {j + 1, j}) {  // lower ring first: counter-clockwise from outside
        const Vec3 n = gllab::spherical_to_cartesian({1, theta, M_PI * k / stacks});
        glNormal3d(n.x, n.y, n.z);
        glVertex3d(r * n.x, r * n.y, r * n.z);
      }
    }
    glEnd();
  }
}

// The open tube from cylindrical coordinates (r, θ, z), z from 0 to h as gluCylinder.
void own_cylinder(double r, double h, int slices, int stacks) {
  for (int j = 0; j < stacks; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double theta = M_PI / 2 - 2 * M_PI * i / slices;
      for (int k : {j, j + 1}) {  // lower ring first, as GLU
        const Vec3 p = gllab::cylindrical_to_cartesian({r, theta, h * k / stacks});
        glNormal3d(p.x / r, p.y / r, 0);  // (cos θ, sin θ, 0)
        glVertex3d(p.x, p.y, p.z);
      }
    }
    glEnd();
  }
}

// Drawing -------------------------------------------------------------------
// Three cells: own and GLU lit with their facets' edges, then the overlay: GLU
// unlit in orange, own on top in green where the depths agree (orange = differ).
void three_cells(const State& s, void (*own)(int, int), void (*glu)(int, int),
                 const char* coordinates, const char* glu_name, double lift = 0) {
  const int sl = s.integer("slices"), st = s.integer("stacks");
  g_call = gllab::glu_quadric_note(glu_name, sl, "stacks", st);
  gllab::ortho_fit(s.width, s.height, 3.3, 3.3);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: s.camera
  for (int c = 0; c < 3; ++c) {
    gllab::enter_cell(-2.2 + 2.2 * c, 0.5, 1.0, -60.f);  // z axis up and towards us
    glTranslated(0, 0, lift);
    if (c < 2) {
      glColor3fv(c ? kGlu : kOwn);
      gllab::wire_over_fill([&](bool wire) {  // GLU_FILL both; glPolygonMode draws the wire
        glPolygonMode(GL_FRONT_AND_BACK, wire ? GL_LINE : GL_FILL);
        c ? glu(sl, st) : own(sl, st);
      }, {0.1f, 0.1f, 0.1f});
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    } else {
      glDisable(GL_LIGHTING);
      glColor3fv(kGlu);
      glu(sl, st);
      glColor3fv(kOwn);
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(-1.f, -2.f);  // float rounding passes, a misplaced facet does not
      own(sl, st);
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
    glPopMatrix();
  }
  gllab::draw_caption(-2.2, -0.85, "own quad strips", coordinates);
  gllab::draw_caption(0, -0.85, glu_name, gllab::format_text("slices %d, stacks %d", sl, st));
  gllab::draw_caption(2.2, -0.85, "overlay", "green: own = GLU");
}

void draw_spherical(const State& s) {
  three_cells(s, [](int sl, int st) { own_sphere(kRadius, sl, st); },
              [](int sl, int st) { gluSphere(g_q, kRadius, sl, st); }, "from (rho,theta,phi)",
              "gluSphere");
}

void draw_cylindrical(const State& s) {  // both start at z = 0: lifted by -h/2 to the centre
  three_cells(s, [](int sl, int st) { own_cylinder(0.6, kHeight, sl, st); },
              [](int sl, int st) { gluCylinder(g_q, 0.6, 0.6, kHeight, sl, st); },
              "from (r, theta, z)", "gluCylinder", -kHeight / 2);
}

// Row 1: the State's slices at every depth d. Row 2: the fewest with sagitta r_px (1 - cos(π/n))
// <= error_px, r_px = r f / d (f: the projection's focal length in pixels, zoom included).
void draw_level_of_detail(const State& s) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(kFovy, double(s.width) / s.height, 1, 200);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // the wheel zooms: the counts follow; right-drag turns about the eye
  GLdouble proj[16], mv[16];
  glGetDoublev(GL_PROJECTION_MATRIX, proj);
  glGetDoublev(GL_MODELVIEW_MATRIX, mv);
  const double f = proj[5] * s.height / 2, f0 = gllab::focal_length_px(kFovy, s.height);
  const double e = s.get("error_px");
  const int sl = s.integer("slices"), st0 = s.integer("stacks");  // the fixed row
  for (int row = 0; row < 2; ++row) {
    int triangles = 0;
    for (std::size_t k = 0; k < std::size(kScreenX); ++k) {
      const double d0 = kNearest * std::pow(2.0, double(k));  // depth at the lab's camera
      const double c[3] = {kScreenX[k] * d0 / f0, (row ? -130 : 110) * d0 / f0, -d0};
      const double d = -(mv[2] * c[0] + mv[6] * c[1] + mv[10] * c[2] + mv[14]);
      const double r_px = gllab::projected_length(kLodRadius, d, f);
      const int fit = std::min(gllab::segments_for_chord_error(r_px, e, 4), kGluMaxSlices);
      const int n = row ? fit : sl, st = row ? (n + 1) / 2 : st0;  // meridians: the same sagitta
      triangles += 2 * n * (st - 1);  // two pole fans plus two per quad
      glPushMatrix();
      glTranslated(c[0], c[1], c[2]);  // the axis towards the eye: the silhouette is an n-gon
      glColor3fv(row ? kOwn : kGlu);
      gluSphere(g_q, kLodRadius, n, st);
      glPopMatrix();
      const double err = gllab::chord_error(r_px, n);
      gllab::draw_label(c[0], c[1] - kLodRadius, c[2], gllab::format_text("n=%d", n),
                        {1, 1, 1}, 0, 14);
      gllab::draw_label(c[0], c[1] - kLodRadius, c[2], gllab::format_text("%.2f px", err),
                        err > e ? gllab::Rgb{1, 0.4f, 0.4f} : gllab::Rgb{0.7f, 0.9f, 0.7f}, 0, 30);
    }
    const std::string rule = row ? gllab::format_text("n from sagitta <= %.2f px: ", e)
                                 : gllab::format_text("fixed %dx%d: ", sl, st0);
    const std::string total = rule + std::to_string(triangles) + " triangles";
    gllab::draw_text(8, row ? s.height / 2 + 12 : 8, total, {1, 1, 1});
  }
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  g_q = gluNewQuadric();  // GLU's defaults: GLU_FILL, GLU_SMOOTH, GLU_OUTSIDE
  gluQuadricCallback(g_q, GLU_ERROR, reinterpret_cast<_GLUfuncptr>(on_quadric_error));
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "35_quadric_coordinates",
      "lab 35 · quadric coordinates",
      {{"spherical_vs_glu", "sphere from (rho, theta, phi) vs gluSphere", draw_spherical, kOrbit},
       {"cylindrical_vs_glu", "cylinder from (r, theta, z) vs gluCylinder", draw_cylindrical,
        kOrbit},
       {"level_of_detail", "fixed slices vs sagitta <= error_px", draw_level_of_detail, kOrbit}},
      {{"slices", 18, 2, 64, "slices of both quadrics and of level_of_detail's fixed row"},
       {"stacks", 9, 1, 64, "stacks of both quadrics and of level_of_detail's fixed row"},
       {"error_px", 0.5, 0.25, 4, "level_of_detail: largest sagitta on screen, pixels"}},
      {{'s', "slices +2", "slices", +2}, {'S', "slices -2", "slices", -2},
       {'t', "stacks +1", "stacks", +1}, {'T', "stacks -1", "stacks", -1},
       {'e', "error +0.25 px", "error_px", +0.25}, {'E', "error -0.25 px", "error_px", -0.25}},
      init};
  lab.shutdown = [] { gluDeleteQuadric(g_q); };
  return lab;
}
