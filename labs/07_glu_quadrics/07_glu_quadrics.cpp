// lab 07 · GLU quadrics                                       difficulty: ★★☆☆
// Spheres, cylinders, cones and disks from one gluNewQuadric object (lecture notes
// ch. 1, §1.4 Quadric surfaces): its draw style, normals, orientation, texture
// coordinates and error callback, and the slices a sphere needs on screen.
// Notice: GLU_FLAT looks flat only with glShadeModel(GL_FLAT); glScale
//   stretches the normals unless GL_NORMALIZE is on.
// Try: --set slices=-4. What does the error callback report? In resolution,
//   press [E] and [e]: which sphere's slice count changes most, and why?
// Keys: [s]/[S] slices  [t]/[T] stacks  [e]/[E] edge pixels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: default, draw_styles, normals_orientation, texture, ellipsoid_normalize, resolution
// Reference: reference_images/07_glu_quadrics__*.png

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "gl/gl.h"
#include "gl/glu_errors.h"
#include "gl/scene.h"
#include "gl/shape_grid.h"
#include "gl/texture.h"
#include "harness/lab.h"

namespace {

using gllab::kOrbit, gllab::State;

// Lab data (edit me) -------------------------------------------------------
enum Kind { kSphere, kCylinder, kCone, kDisk, kPartialDisk };  // index into kShapes
struct Shape { const char* call; const char* note; GLfloat colour[3]; };
const Shape kShapes[] = {{"gluSphere", "radius 0.9", {0.95f, 0.55f, 0.2f}},
                         {"gluCylinder", "open tube", {0.3f, 0.75f, 0.35f}},
                         {"gluCylinder", "top radius 0", {0.3f, 0.6f, 0.95f}},
                         {"gluDisk", "inner radius 0.3", {0.85f, 0.35f, 0.65f}},
                         {"gluPartialDisk", "30 deg + 240", {0.9f, 0.8f, 0.25f}}};
constexpr int kLoops = 3;       // rings of a disk
constexpr float kTilt = -60.f;  // about x: each quadric's z axis leans up and towards us
const double kRadii[] = {0.1, 0.2, 0.4, 0.75};  // resolution view, world units
constexpr int kGluMaxSlices = 239;              // GLU clamps slices and stacks here

GLUquadric* g_q = nullptr;  // one quadric object and the checker texture, made in init()
GLuint g_checker = 0;

// GLU hands its error callback only a code, so each call first notes what it is
// and its counts; the report names the count GLU rejects (gl/glu_errors.h).
std::string g_call;
void GLAPIENTRY on_quadric_error(GLenum code) { gllab::report_glu_error(code, g_call); }

// One of the five shapes; a sphere's radius is r.
void draw_quadric(Kind kind, int slices, int stacks, double r = 0.9) {
  const bool disk = kind == kDisk || kind == kPartialDisk;
  g_call = gllab::glu_quadric_note(kShapes[kind].call, slices, disk ? "loops" : "stacks",
                                   disk ? kLoops : stacks);
  if (kind == kSphere) {
    gluSphere(g_q, r, slices, stacks);
  } else if (!disk) {               // a cone is a cylinder with top radius 0
    glTranslatef(0.f, 0.f, -0.7f);  // it starts at z = 0: centre it
    gluCylinder(g_q, 0.6, kind == kCone ? 0.0 : 0.6, 1.4, slices, stacks);
  } else if (kind == kDisk) {
    gluDisk(g_q, 0.3, 0.9, slices, kLoops);
  } else {  // angles in degrees, clockwise from +y
    gluPartialDisk(g_q, 0.3, 0.9, slices, kLoops, 30.0, 240.0);
  }
}
void draw_quadric(const State& s, Kind kind, double r = 0.9) {  // the State's slices, stacks
  draw_quadric(kind, s.integer("slices"), s.integer("stacks"), r);
}

// Drawing -------------------------------------------------------------------
// Every view: projection, headlight, orbit camera, the quadric with GLU's defaults.
void begin_view(const State& s) {
  gllab::ortho_fit(s.width, s.height, 3.3, 3.3);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: s.camera
  gluQuadricDrawStyle(g_q, GLU_FILL);
  gluQuadricNormals(g_q, GLU_SMOOTH);
  gluQuadricOrientation(g_q, GLU_OUTSIDE);
  gluQuadricTexture(g_q, GL_FALSE);
}

void draw_default(const State& s) {
  begin_view(s);
  for (std::size_t i = 0; i < std::size(kShapes); ++i) {
    const double x = i < 3 ? -2.2 + 2.2 * i : -1.1 + 2.2 * (i - 3), y = i < 3 ? 1.4 : -1.2;
    gllab::enter_cell(x, y, 1.0, kTilt);
    glColor3fv(kShapes[i].colour);
    draw_quadric(s, Kind(i));
    glPopMatrix();
    gllab::draw_caption(x, y - 1.15, kShapes[i].call, kShapes[i].note);
  }
}

void draw_styles(const State& s) {
  const GLenum styles[] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
  const char* names[] = {"GLU_FILL", "GLU_LINE", "GLU_SILHOUETTE", "GLU_POINT"};
  const Kind rows[] = {kSphere, kCylinder, kDisk};
  begin_view(s);
  glPointSize(3.f);
  for (int c = 0; c < 4; ++c) {
    gluQuadricDrawStyle(g_q, styles[c]);
    // Lines and points unlit: one colour, whichever of two crossing lines wins.
    if (styles[c] != GLU_FILL) glDisable(GL_LIGHTING);
    for (int r = 0; r < 3; ++r) {
      gllab::enter_cell(-2.4 + 1.6 * c, 1.9 - 1.95 * r, 0.8, kTilt);
      glColor3fv(kShapes[r == 2 ? 3 : r].colour);
      draw_quadric(s, rows[r]);
      glPopMatrix();
    }
    gllab::draw_caption(-2.4 + 1.6 * c, 3.05, names[c]);
  }
}

void draw_normals(const State& s) {
  begin_view(s);
  // Row 1: gluQuadricNormals. GLU_NONE sends none: every vertex keeps the current
  // one. GLU_FLAT sends a facet's normal at one corner only; GL_SMOOTH would blend
  // in the normals its other corners keep. Row 2: GLU_INSIDE reverses normals and
  // winding. Which tube wall is lit right? An inside-out sphere, back faces culled: a bowl.
  const GLenum normals[] = {GLU_NONE, GLU_FLAT, GLU_SMOOTH, GLU_SMOOTH, GLU_SMOOTH, GLU_SMOOTH};
  const char* names[] = {"GLU_NONE",    "GLU_FLAT",   "GLU_SMOOTH",
                         "GLU_OUTSIDE", "GLU_INSIDE", "GLU_INSIDE+cull"};
  for (int i = 0; i < 6; ++i) {
    const bool tube = i == 3 || i == 4;
    gluQuadricNormals(g_q, normals[i]);
    gluQuadricOrientation(g_q, i < 4 ? GLU_OUTSIDE : GLU_INSIDE);
    glNormal3f(0.f, 0.f, 1.f);  // the one GLU_NONE leaves every vertex
    glShadeModel(normals[i] == GLU_FLAT ? GL_FLAT : GL_SMOOTH);
    if (i == 5) glEnable(GL_CULL_FACE);  // glCullFace(GL_BACK) is the default
    gllab::enter_cell(-2.2 + 2.2 * (i % 3), i < 3 ? 1.45 : -1.2, 1.0, kTilt);
    glColor3fv(kShapes[tube ? 1 : 0].colour);
    draw_quadric(s, tube ? kCylinder : kSphere);
    glPopMatrix();
    gllab::draw_caption(-2.2 + 2.2 * (i % 3), i < 3 ? 0.35 : -2.4, names[i]);
  }
}

void draw_texture(const State& s) {
  begin_view(s);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, g_checker);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);  // texel x lit colour
  const Kind kinds[] = {kSphere, kCylinder, kDisk, kPartialDisk};
  for (int r = 0; r < 2; ++r) {
    // Row 2 without texture coordinates: each vertex keeps the current one (one texel).
    gluQuadricTexture(g_q, r == 0 ? GL_TRUE : GL_FALSE);
    glTexCoord2f(0.05f, 0.05f);
    for (int c = 0; c < 4; ++c) {
      gllab::enter_cell(-2.4 + 1.6 * c, r ? -1.15 : 1.55, 0.8, kTilt);
      glColor3f(1.f, 1.f, 1.f);
      draw_quadric(s, kinds[c]);
      glPopMatrix();
    }
    gllab::draw_caption(0, r ? -2.4 : 0.4, r ? "gluQuadricTexture(q, GL_FALSE)"
                                             : "gluQuadricTexture(q, GL_TRUE)");
  }
}

void draw_ellipsoids(const State& s) {
  begin_view(s);
  glDisable(GL_NORMALIZE);  // enable_headlight turned it on
  // GL_NORMALIZE makes every normal unit length again; GL_RESCALE_NORMAL only
  // divides by one factor taken from the matrix: right for a uniform scale.
  const GLenum fixes[] = {GL_NORMALIZE, 0, GL_RESCALE_NORMAL};
  const char* names[] = {"GL_NORMALIZE", "neither", "GL_RESCALE_NORMAL"};
  const char* verdicts[2][3] = {{"right", "wrong: too bright", "right"},
                                {"right", "wrong: too bright", "wrong: dark ends"}};
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) {
      if (fixes[c]) glEnable(fixes[c]);
      // Down the pole (no tilt): the centre pixel has the pole's normal (0, 0, 1).
      gllab::enter_cell(-2.2 + 2.2 * c, r ? -1.0 : 1.35, 1.0, 0.f);
      glColor3fv(kShapes[2].colour);
      // Row 1 scales uniformly by 1/2, row 2 only y and z: an ellipsoid. glScale
      // scales normals by the inverse (here 2): lighting uses their length.
      glScalef(r == 0 ? 0.5f : 1.f, 0.5f, 0.5f);
      draw_quadric(s, kSphere, r == 0 ? 1.8 : 1.0);
      glPopMatrix();
      if (fixes[c]) glDisable(fixes[c]);
      gllab::draw_caption(-2.2 + 2.2 * c, r ? -1.85 : 0.2, verdicts[r][c]);
      if (r == 0) gllab::draw_caption(-2.2 + 2.2 * c, 2.6, names[c]);
    }
  }
  gllab::draw_caption(0, -2.7, "row 1: glScalef(.5, .5, .5)", "row 2: glScalef(1, .5, .5)");
}

void draw_resolution(const State& s) {
  begin_view(s);
  const double px_per_unit = gllab::pixels_per_unit(s.width);  // (gl/shape_grid.h)
  for (int row = 0; row < 2; ++row) {
    int triangles = 0;
    for (std::size_t i = 0; i < std::size(kRadii); ++i) {
      const double r_px = kRadii[i] * px_per_unit, x = -2.5 + 1.65 * i, y = row ? -1.35 : 1.5;
      // Row 2: slices so that an equator edge is at most edge_px pixels long on screen.
      const int fit = int(std::ceil(2 * M_PI * r_px / s.get("edge_px")));
      const int sl = row ? std::clamp(fit, 3, kGluMaxSlices) : s.integer("slices");
      const int st = row ? std::max(2, sl / 2) : s.integer("stacks");
      triangles += 2 * sl * (st - 1);  // two pole fans plus two per quad
      gllab::enter_cell(x, y, 1.0, kTilt);
      glColor3fv(kShapes[0].colour);
      gllab::wire_over_fill([&](bool wire) {  // the wire on top, hidden lines removed
        gluQuadricDrawStyle(g_q, wire ? GLU_LINE : GLU_FILL);
        draw_quadric(kSphere, sl, st, kRadii[i]);
      }, {0.1f, 0.1f, 0.1f});
      glPopMatrix();
      const double edge = 2 * r_px * std::sin(M_PI / sl);  // on screen: a chord of the equator
      gllab::draw_caption(x, y - 0.95, gllab::format_text("%dx%d", sl, st),
                          gllab::format_text("%.1f px", edge));
    }
    const std::string rule = row ? gllab::format_text("edge <= %g px: ", s.get("edge_px"))
                                 : std::string("same slices/stacks: ");
    gllab::draw_caption(0, row ? -0.1 : 2.85, rule + std::to_string(triangles) + " triangles");
  }
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  g_q = gluNewQuadric();
  gluQuadricCallback(g_q, GLU_ERROR, reinterpret_cast<_GLUfuncptr>(on_quadric_error));
  const GLubyte light[] = {240, 230, 210}, dark[] = {40, 90, 200};
  g_checker = gllab::make_checker_texture(64, 8, light, dark);  // 8 x 8 squares (gl/texture.h)
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "07_glu_quadrics",
      "lab 07 · GLU quadrics",
      {{"default", "sphere, cylinder, cone, disk and partial disk, lit", draw_default, kOrbit},
       {"draw_styles", "GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT", draw_styles, kOrbit},
       {"normals_orientation", "GLU_NONE/FLAT/SMOOTH; GLU_OUTSIDE/INSIDE", draw_normals, kOrbit},
       {"texture", "gluQuadricTexture on a checker, GL_TRUE and GL_FALSE", draw_texture, kOrbit},
       {"ellipsoid_normalize", "GL_NORMALIZE, neither, GL_RESCALE_NORMAL", draw_ellipsoids, kOrbit},
       {"resolution", "same slices at every size vs edges of edge_px", draw_resolution, kOrbit}},
      {{"slices", 24, -8, 64, "slices of the GLU quadrics (below 2: GLU_INVALID_VALUE)"},
       {"stacks", 12, -8, 64, "stacks of the GLU quadrics (below 1: GLU_INVALID_VALUE)"},
       {"edge_px", 12, 2, 40, "resolution: longest edge on screen in the adaptive row, pixels"}},
      {{'s', "slices +2", "slices", +2}, {'S', "slices -2", "slices", -2},
       {'t', "stacks +1", "stacks", +1}, {'T', "stacks -1", "stacks", -1},
       {'e', "edge +2 px (resolution)", "edge_px", +2}, {'E', "edge -2 px", "edge_px", -2}},
      init};
  lab.shutdown = [] { gluDeleteQuadric(g_q); glDeleteTextures(1, &g_checker); };
  return lab;
}
