// lab 09 · glut shapes                                        difficulty: ★☆☆☆
// freeglut's ready-made shapes, the convenience functions of lecture notes ch. 1,
// §1.3 Polygon rendering with OpenGL (glutSolidTetrahedron, glutSolidCube, ...),
// and glutSolidSphere beside gluSphere, the two spheres of §1.4 Quadric surfaces.
// Each cell calls gllab::draw_glut_shape, not glut*: the headless programs that
// render the reference images have no X display, and freeglut needs one
// (glutInit). In the window it makes the glut call named in kCalls; headless it
// replays the GL calls freeglut made for exactly those arguments
// (common/gl/README.md, "glut shapes headless").
// Notice: at the same slices and stacks gluSphere and glutSolidSphere still make
//   different triangles, and their first slices point different ways.
// Try: in glu_vs_glut_sphere press [g] until the wires meet. At which slices?
//   Then press [f]: does smooth shading hide the difference?
// Keys: [g]/[G] sphere stacks  [f] flat shading
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: glut_solid, glut_wire, glu_vs_glut_sphere
// Reference: reference_images/09_glut_shapes__*.png

#include <cmath>
#include <iterator>
#include <string>

#include "gl/gl.h"
#include "gl/glu_errors.h"
#include "gl/glut_shapes.h"
#include "gl/scene.h"
#include "gl/shape_grid.h"
#include "gl/text.h"
#include "harness/lab.h"

namespace {

using gllab::GlutShape, gllab::kOrbit, gllab::State;

// Lab data (edit me) -------------------------------------------------------
// The nine shapes, row by row, and the freeglut calls they stand for, with the
// arguments recorded for the headless replay (gl/glut_shapes.h): sphere (radius,
// slices, stacks), cube (edge), cone (base radius, height, slices, stacks), torus
// (inner radius, outer radius, sides, rings), teapot (size). The dodecahedron's
// radius is √3, the other three solids' 1.
struct GlutCall { GlutShape shape; const char* solid; const char* wire; const char* args; };
const GlutCall kCalls[] = {
    {GlutShape::kSphere, "glutSolidSphere", "glutWireSphere", "(0.9, 24, 12)"},
    {GlutShape::kCube, "glutSolidCube", "glutWireCube", "(1.2)"},
    {GlutShape::kCone, "glutSolidCone", "glutWireCone", "(0.7, 1.4, 24, 6)"},
    {GlutShape::kTorus, "glutSolidTorus", "glutWireTorus", "(0.25, 0.65, 12, 24)"},
    {GlutShape::kTetrahedron, "glutSolidTetrahedron", "glutWireTetrahedron", "()"},
    {GlutShape::kOctahedron, "glutSolidOctahedron", "glutWireOctahedron", "()"},
    {GlutShape::kDodecahedron, "glutSolidDodecahedron", "glutWireDodecahedron", "()"},
    {GlutShape::kIcosahedron, "glutSolidIcosahedron", "glutWireIcosahedron", "()"},
    {GlutShape::kTeapot, "glutSolidTeapot", "glutWireTeapot", "(0.6)"}};
const GLfloat kColours[][3] = {{0.95f, 0.55f, 0.2f}, {0.3f, 0.75f, 0.35f}, {0.3f, 0.6f, 0.95f},
                               {0.85f, 0.35f, 0.65f}, {0.9f, 0.8f, 0.25f}};  // taken in turn
constexpr float kTilt = -60.f;  // about x: each shape's z axis leans up and towards us
const GLfloat kBackground[] = {0.12f, 0.13f, 0.16f};
const GLfloat kGluInk[] = {1.f, 0.6f, 0.2f}, kGlutInk[] = {0.3f, 0.85f, 1.f};

GLUquadric* g_q = nullptr;  // for gluSphere, made in init()
void GLAPIENTRY on_quadric_error(GLenum code) { gllab::report_glu_error(code, "gluSphere"); }

// Drawing -------------------------------------------------------------------
void begin_view(const State& s, bool lit) {
  gllab::ortho_fit(s.width, s.height, 3.3, 3.3);
  if (lit) gllab::enable_headlight();  // wires unlit: one colour whichever line wins
  gllab::apply_orbit(s);              // right-drag, wheel, [0]: s.camera
}

// The nine shapes in a 3 x 3 grid, turned so that corners face us, not faces.
void draw_glut(const State& s, bool solid) {
  begin_view(s, solid);
  const std::string prefix = solid ? "glutSolid" : "glutWire";
  for (std::size_t i = 0; i < std::size(kCalls); ++i) {
    const GlutShape shape = kCalls[i].shape;
    const double x = -2.2 + 2.2 * (i % 3), y = 2.0 - 2.0 * (i / 3);
    gllab::enter_cell(x, y, 0.7, kTilt);
    glRotatef(35.f, 0.f, 0.f, 1.f);
    if (shape == GlutShape::kCone) glTranslatef(0.f, 0.f, -0.7f);  // base at z = 0
    if (shape == GlutShape::kDodecahedron) glScalef(0.577f, 0.577f, 0.577f);  // radius √3
    if (shape == GlutShape::kTeapot) glRotatef(90.f, 1.f, 0.f, 0.f);  // its up is y, not z
    if (!solid) {  // hidden lines: the solid in the background colour, pushed back
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.f, 1.f);
      glColor3fv(kBackground);
      gllab::draw_glut_shape(shape, true);
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
    glColor3fv(kColours[i % std::size(kColours)]);
    gllab::draw_glut_shape(shape, solid);  // kCalls[i].solid or .wire, with .args
    glPopMatrix();
    const std::string call = solid ? kCalls[i].solid : kCalls[i].wire;
    gllab::draw_caption(x, y - 0.8, call.substr(prefix.size()), kCalls[i].args);
  }
  gllab::draw_caption(0, 3.1, prefix + "<Shape>(arguments)");
}

void draw_glut_solid(const State& s) { draw_glut(s, true); }
void draw_glut_wire(const State& s) { draw_glut(s, false); }

// gluSphere and glutSolidSphere, radius 1, at the same slices (2 x stacks).
void draw_glu_vs_glut(const State& s) {
  const int st = s.integer("glut_stacks"), sl = 2 * st;
  const double xs[] = {-2.2, 0.0, 2.2};
  begin_view(s, true);
  gluQuadricDrawStyle(g_q, GLU_FILL);
  glShadeModel(s.flag("flat") ? GL_FLAT : GL_SMOOTH);
  for (int c = 0; c < 3; c += 2) {  // row 1, lit: GLU left, freeglut right
    gllab::enter_cell(xs[c], 1.45, 0.85, kTilt);
    glColor3fv(kColours[0]);
    if (c == 0) gluSphere(g_q, 1.0, sl, st);
    else gllab::draw_glut_sphere(sl, st, true);  // glutSolidSphere(1, sl, st)
    glPopMatrix();
  }
  // Row 2, wireframes with hidden lines removed: first a background-coloured
  // fill of the same shape, pushed back by glPolygonOffset, then the lines.
  // The middle fill is shrunk to lie inside both polyhedra.
  glDisable(GL_LIGHTING);
  glPolygonOffset(1.f, 1.f);
  const double inner = 0.98 * std::cos(M_PI / sl) * std::cos(M_PI / (2 * st));
  for (int c = 0; c < 3; ++c) {
    gllab::enter_cell(xs[c], -0.75, 0.85, kTilt);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glColor3fv(kBackground);
    if (c == 2) gllab::draw_glut_sphere(sl, st, true);
    else gluSphere(g_q, c == 0 ? 1.0 : inner, sl, st);
    glDisable(GL_POLYGON_OFFSET_FILL);
    gluQuadricDrawStyle(g_q, GLU_LINE);
    glColor3fv(kGluInk);
    if (c < 2) gluSphere(g_q, 1.0, sl, st);
    glColor3fv(kGlutInk);
    // Where both wires run along the same edge their depths tie, and which
    // one wins would hang on the last bit of rounding. A hair nearer (depth
    // range shrunk by 1e-5), glut's wire wins every tie in every renderer.
    glDepthRange(0.0, 1.0 - 1e-5);
    if (c > 0) gllab::draw_glut_sphere(sl, st, false);  // glutWireSphere(1, sl, st)
    glDepthRange(0.0, 1.0);
    gluQuadricDrawStyle(g_q, GLU_FILL);
    glPopMatrix();
  }
  const std::string args = gllab::format_text("(1, %d, %d)", sl, st);
  gllab::draw_caption(-2.2, 2.65, "gluSphere", args);
  gllab::draw_caption(2.2, 2.65, "glutSolidSphere", args);
  gllab::draw_caption(0, 0.55, "both wires");
  // freeglut does not call GLU: it makes its own vertices and normals.
  gllab::draw_text_panel(8, 424, {"freeglut makes its own vertices:",
                                  "GLU slice 0 points to +y, glut's to +x",
                                  "(same only if slices % 4 == 0); glut cuts",
                                  "each quad into 2 triangles, GLU keeps quads"},
                         gllab::Rgb{1.f, 1.f, 1.f});
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(kBackground[0], kBackground[1], kBackground[2], 1.f);
  g_q = gluNewQuadric();
  gluQuadricCallback(g_q, GLU_ERROR, reinterpret_cast<_GLUfuncptr>(on_quadric_error));
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "09_glut_shapes",
      "lab 09 · glut shapes",
      {{"glut_solid", "the nine glutSolid* shapes", draw_glut_solid, kOrbit},
       {"glut_wire", "the nine glutWire* shapes, hidden lines removed", draw_glut_wire, kOrbit},
       {"glu_vs_glut_sphere", "gluSphere and glutSolidSphere at the same slices/stacks",
        draw_glu_vs_glut, kOrbit}},
      {{"glut_stacks", 5, 2, 24, "glu_vs_glut_sphere: stacks; slices = 2 x stacks"},
       {"flat", 1, 0, 1, "glu_vs_glut_sphere: glShadeModel(GL_FLAT) in the lit row"}},
      {{'g', "sphere stacks +1", "glut_stacks", +1},
       {'G', "sphere stacks -1", "glut_stacks", -1},
       {'f', "flat shading on/off", "flat"}},
      init};
  lab.shutdown = [] { gluDeleteQuadric(g_q); };
  return lab;
}
