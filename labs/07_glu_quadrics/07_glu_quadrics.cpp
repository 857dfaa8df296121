// lab 07 · GLU quadrics                                       difficulty: ★★☆☆
// Spheres, cylinders, cones and disks from one GLU quadric object (seed §1.4):
// draw styles, normals, orientation, texture coordinates and resolution, and
// freeglut's ready-made glutSolid*/glutWire* shapes beside them.
// Notice: GLU_FLAT looks flat only with glShadeModel(GL_FLAT); glScale
//   stretches the normals unless GL_NORMALIZE is on; at the same slices and
//   stacks gluSphere and glutSolidSphere still make different triangles.
// Try: --set slices=-4. What does the error callback report? In resolution,
//   press [E] and [e]: which sphere's slice count changes most, and why?
// Keys: [s]/[S] slices  [t]/[T] stacks  [e]/[E] edge pixels  [g]/[G] glut stacks
//   [r]/[R] spin  [f] flat shading  [l] lighting  [n] labels  [h] help  [Esc] quit
// Views: default, draw_styles, normals_orientation, texture,
//   ellipsoid_normalize, resolution, glut_solid, glut_wire, glu_vs_glut_sphere
// Reference: reference_images/07_glu_quadrics__*.png

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glut_shapes.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

// Lab data (edit me) -------------------------------------------------------
enum class Kind { kSphere, kCylinder, kCone, kDisk, kPartialDisk };
struct Shape {
  Kind kind;
  const char* name;
  const char* note;  // second label line
  gllab::Rgb colour;
};
const Shape kShapes[] = {
    {Kind::kSphere, "gluSphere", "radius 0.9", {0.95f, 0.55f, 0.2f}},
    {Kind::kCylinder, "gluCylinder", "open tube", {0.3f, 0.75f, 0.35f}},
    {Kind::kCone, "gluCylinder", "top radius 0", {0.3f, 0.6f, 0.95f}},
    {Kind::kDisk, "gluDisk", "inner radius 0.3", {0.85f, 0.35f, 0.65f}},
    {Kind::kPartialDisk, "gluPartialDisk", "30 deg + 240", {0.9f, 0.8f, 0.25f}},
};
constexpr int kLoops = 3;       // rings of a disk
constexpr float kTilt = -60.f;  // about x: the quadrics' z axis leans up and towards us
constexpr int kTexels = 64, kCheck = 8;  // checker texture: 8 x 8 squares of 8 texels
const double kRadii[] = {0.1, 0.2, 0.4, 0.75};  // resolution view, world units
constexpr int kGluMaxSlices = 239;              // GLU clamps slices and stacks here
const gllab::Rgb kText{1.f, 1.f, 1.f}, kGluInk{1.f, 0.6f, 0.2f}, kGlutInk{0.3f, 0.85f, 1.f};
GLuint g_checker = 0;  // texture name, made once in init()

// GLU errors ----------------------------------------------------------------
// GLU hands the callback only an error code, so each call first records what
// it is about to do: the report then names the call and the arguments GLU
// 9.0.2 rejects (quad.c: slices < 2, stacks < 1, loops < 1), or all of them.
std::string g_call, g_args;

void record_call(const char* call, int slices, const char* count_name, int count) {
  const std::string a = "slices=" + std::to_string(slices), b = count_name + ("=" + std::to_string(count));
  const bool a_bad = slices < 2, b_bad = count < 1;
  g_call = call;
  g_args = a_bad == b_bad ? a + " " + b : a_bad ? a : b;
}

void GLAPIENTRY on_glu_error(GLenum code) {
  const char* text = reinterpret_cast<const char*>(gluErrorString(code));
  gllab::report_frame_error(g_call + ": GLU error " + std::to_string(code) + " (" + text + "): " + g_args);
}

std::string fmt(const char* format, double a, double b = 0) {
  char text[80];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

void sphere(GLUquadric* q, double r, int slices, int stacks) {
  record_call("gluSphere", slices, "stacks", stacks);
  gluSphere(q, r, slices, stacks);
}

void draw_quadric(GLUquadric* q, Kind kind, int slices, int stacks) {
  switch (kind) {
    case Kind::kSphere: sphere(q, 0.9, slices, stacks); return;
    case Kind::kCylinder:
    case Kind::kCone: {
      const double top = kind == Kind::kCone ? 0.0 : 0.6;  // a cone is a cylinder with top radius 0
      record_call("gluCylinder", slices, "stacks", stacks);
      glTranslatef(0.f, 0.f, -0.7f);  // it starts at z = 0: centre it
      gluCylinder(q, 0.6, top, 1.4, slices, stacks);
      return;
    }
    case Kind::kDisk:
      record_call("gluDisk", slices, "loops", kLoops);
      gluDisk(q, 0.3, 0.9, slices, kLoops);
      return;
    case Kind::kPartialDisk:  // angles in degrees, clockwise from +y
      record_call("gluPartialDisk", slices, "loops", kLoops);
      gluPartialDisk(q, 0.3, 0.9, slices, kLoops, 30.0, 240.0);
      return;
  }
}

// Drawing -------------------------------------------------------------------
// A cell centred at (x, y), scaled, tilted so the z axis shows, spun about z.
void enter_cell(double x, double y, double scale, const gllab::State& s, bool tilt = true) {
  glPushMatrix();
  glTranslated(x, y, 0);
  glScaled(scale, scale, scale);
  if (tilt) glRotatef(kTilt, 1.f, 0.f, 0.f);
  glRotated(s.get("spin"), 0, 0, 1);
}

void label(double x, double y, const std::string& a, const std::string& b, const gllab::State& s) {
  if (!s.flag("labels")) return;
  gllab::draw_label(x, y, 0, a, kText);
  if (!b.empty()) gllab::draw_label(x, y, 0, b, kText, 0, 16);
}

void colour(gllab::Rgb c) { glColor3f(c.r, c.g, c.b); }

void draw_default(GLUquadric* q, const gllab::State& s) {
  if (s.flag("lighting")) gllab::enable_headlight();
  for (std::size_t i = 0; i < std::size(kShapes); ++i) {
    const double x = i < 3 ? -2.2 + 2.2 * i : -1.1 + 2.2 * (i - 3), y = i < 3 ? 1.4 : -1.2;
    enter_cell(x, y, 1.0, s);
    colour(kShapes[i].colour);
    draw_quadric(q, kShapes[i].kind, s.integer("slices"), s.integer("stacks"));
    glPopMatrix();
    label(x, y - 1.15, kShapes[i].name, kShapes[i].note, s);
  }
}

void draw_styles(GLUquadric* q, const gllab::State& s) {
  const GLenum styles[] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
  const char* names[] = {"GLU_FILL", "GLU_LINE", "GLU_SILHOUETTE", "GLU_POINT"};
  const Kind rows[] = {Kind::kSphere, Kind::kCylinder, Kind::kDisk};
  gllab::enable_headlight();
  glPointSize(3.f);
  for (int c = 0; c < 4; ++c) {
    gluQuadricDrawStyle(q, styles[c]);
    // Lines and points unlit: one colour, so the picture does not depend on
    // which of two crossing lines wins the depth test.
    if (styles[c] != GLU_FILL) glDisable(GL_LIGHTING);
    for (int r = 0; r < 3; ++r) {
      enter_cell(-2.4 + 1.6 * c, 1.9 - 1.95 * r, 0.8, s);
      colour(kShapes[r == 2 ? 3 : r].colour);
      draw_quadric(q, rows[r], s.integer("slices"), s.integer("stacks"));
      glPopMatrix();
    }
    label(-2.4 + 1.6 * c, 3.05, names[c], "", s);
  }
}

void draw_normals(GLUquadric* q, const gllab::State& s) {
  gllab::enable_headlight();
  const int sl = s.integer("slices"), st = s.integer("stacks");
  // Row 1: what gluQuadricNormals sends. GLU_NONE sends no normal at all, so
  // every vertex keeps the current one, set here.
  const GLenum normals[] = {GLU_NONE, GLU_FLAT, GLU_SMOOTH};
  const char* names[] = {"GLU_NONE", "GLU_FLAT", "GLU_SMOOTH"};
  for (int c = 0; c < 3; ++c) {
    gluQuadricNormals(q, normals[c]);
    glNormal3f(0.f, 0.f, 1.f);
    // GLU_FLAT sends each facet's normal once, at one corner; its other corners
    // keep the normals sent for the neighbouring facets, and GL_SMOOTH would
    // blend them. Flat normals need the flat shade model.
    glShadeModel(normals[c] == GLU_FLAT ? GL_FLAT : GL_SMOOTH);
    enter_cell(-2.2 + 2.2 * c, 1.45, 1.0, s);
    colour(kShapes[0].colour);
    sphere(q, 0.9, sl, st);
    glPopMatrix();
    label(-2.2 + 2.2 * c, 0.35, names[c], "", s);
  }
  // Row 2: GLU_INSIDE reverses the normals and the winding. An open tube
  // shows both walls: which one is lit right? Culling back faces of an
  // inside-out sphere leaves its far wall: a bowl seen from inside.
  gluQuadricNormals(q, GLU_SMOOTH);
  glShadeModel(GL_SMOOTH);
  const char* notes[] = {"GLU_OUTSIDE", "GLU_INSIDE", "GLU_INSIDE+cull"};
  for (int c = 0; c < 3; ++c) {
    gluQuadricOrientation(q, c == 0 ? GLU_OUTSIDE : GLU_INSIDE);
    if (c == 2) glEnable(GL_CULL_FACE);  // glCullFace(GL_BACK) is the default
    enter_cell(-2.2 + 2.2 * c, -1.2, 1.0, s);
    colour(kShapes[c == 2 ? 0 : 1].colour);
    draw_quadric(q, c == 2 ? Kind::kSphere : Kind::kCylinder, sl, st);
    glPopMatrix();
    label(-2.2 + 2.2 * c, -2.4, notes[c], "", s);
  }
}

void draw_texture(GLUquadric* q, const gllab::State& s) {
  gllab::enable_headlight();
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, g_checker);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);  // texel x lit colour
  const Kind kinds[] = {Kind::kSphere, Kind::kCylinder, Kind::kDisk, Kind::kPartialDisk};
  for (int r = 0; r < 2; ++r) {
    // Row 2 without texture coordinates: every vertex keeps the current one,
    // so each shape takes the colour of one texel.
    gluQuadricTexture(q, r == 0 ? GL_TRUE : GL_FALSE);
    glTexCoord2f(0.05f, 0.05f);
    for (int c = 0; c < 4; ++c) {
      enter_cell(-2.4 + 1.6 * c, r ? -1.15 : 1.55, 0.8, s);
      glColor3f(1.f, 1.f, 1.f);
      draw_quadric(q, kinds[c], s.integer("slices"), s.integer("stacks"));
      glPopMatrix();
    }
    label(0, r ? -2.4 : 0.4, r ? "gluQuadricTexture(q, GL_FALSE)" : "gluQuadricTexture(q, GL_TRUE)", "", s);
  }
}

void draw_ellipsoids(GLUquadric* q, const gllab::State& s) {
  gllab::enable_headlight();
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
      // Look down the pole, so the centre pixel has the pole's normal (0, 0, 1).
      enter_cell(-2.2 + 2.2 * c, r ? -1.0 : 1.35, 1.0, s, false);
      colour(kShapes[2].colour);
      // Row 1 scales uniformly by 1/2, row 2 only y and z: an ellipsoid. glScale
      // scales normals by the inverse (here 2): lighting uses their length.
      if (r == 0) glScalef(0.5f, 0.5f, 0.5f);
      else glScalef(1.f, 0.5f, 0.5f);
      sphere(q, r == 0 ? 1.8 : 1.0, s.integer("slices"), s.integer("stacks"));
      glPopMatrix();
      if (fixes[c]) glDisable(fixes[c]);
      label(-2.2 + 2.2 * c, r ? -1.85 : 0.2, verdicts[r][c], "", s);
      if (r == 0) label(-2.2 + 2.2 * c, 2.6, names[c], "", s);
    }
  }
  label(0, -2.7, "row 1: glScalef(.5, .5, .5)", "row 2: glScalef(1, .5, .5)", s);
}

// Slices so that an equator edge is at most edge_px pixels long on screen.
int slices_for(double radius_px, double edge_px) {
  const int n = static_cast<int>(std::ceil(2 * M_PI * radius_px / edge_px));
  return std::clamp(n, 3, kGluMaxSlices);
}

void draw_resolution(GLUquadric* q, const gllab::State& s) {
  GLdouble projection[16];
  glGetDoublev(GL_PROJECTION_MATRIX, projection);
  const double px_per_unit = projection[0] * s.width / 2;  // ortho: x scale
  gllab::enable_headlight();
  glPolygonOffset(1.f, 1.f);  // push the fill back so the wire on top shows
  for (int row = 0; row < 2; ++row) {
    int triangles = 0;
    for (std::size_t i = 0; i < std::size(kRadii); ++i) {
      const double r_px = kRadii[i] * px_per_unit, x = -2.5 + 1.65 * i, y = row ? -1.35 : 1.5;
      const int sl = row ? slices_for(r_px, s.get("edge_px")) : s.integer("slices");
      const int st = row ? std::max(2, sl / 2) : s.integer("stacks");
      triangles += 2 * sl * (st - 1);  // two pole fans plus two per quad
      enter_cell(x, y, 1.0, s);
      glEnable(GL_POLYGON_OFFSET_FILL);
      colour(kShapes[0].colour);
      gluQuadricDrawStyle(q, GLU_FILL);
      sphere(q, kRadii[i], sl, st);
      glDisable(GL_POLYGON_OFFSET_FILL);
      glDisable(GL_LIGHTING);
      glColor3f(0.1f, 0.1f, 0.1f);
      gluQuadricDrawStyle(q, GLU_LINE);
      sphere(q, kRadii[i], sl, st);
      glEnable(GL_LIGHTING);
      glPopMatrix();
      // The longest edge on screen: a chord of the equator, in pixels.
      const double edge = 2 * r_px * std::sin(M_PI / sl);
      label(x, y - 0.95, std::to_string(sl) + "x" + std::to_string(st), fmt("%.1f px", edge), s);
    }
    label(0, row ? -0.1 : 2.85, row ? fmt("edge <= %g px: %g triangles", s.get("edge_px"), triangles)
                                    : fmt("same slices/stacks: %g triangles", triangles), "", s);
  }
}

void draw_glut(const gllab::State& s, bool solid) {
  if (solid) gllab::enable_headlight();  // wires unlit, as in draw_styles
  const std::string prefix = solid ? "glutSolid" : "glutWire";
  for (std::size_t i = 0; i < std::size(gllab::kGlutShapes); ++i) {
    const gllab::GlutShape shape = gllab::kGlutShapes[i];
    const double x = -2.2 + 2.2 * (i % 3), y = 2.0 - 2.0 * (i / 3);
    enter_cell(x, y, 0.7, s);
    glRotatef(35.f, 0.f, 0.f, 1.f);  // corners towards us, not faces
    if (shape == gllab::GlutShape::kCone) glTranslatef(0.f, 0.f, -0.7f);  // base at z = 0
    if (shape == gllab::GlutShape::kDodecahedron) glScalef(0.577f, 0.577f, 0.577f);  // radius sqrt 3
    if (shape == gllab::GlutShape::kTeapot) glRotatef(90.f, 1.f, 0.f, 0.f);  // its up is y, not z
    if (!solid) {  // hidden lines: the solid in the background colour, pushed back
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.f, 1.f);
      glColor3f(0.12f, 0.13f, 0.16f);
      gllab::draw_glut_shape(shape, true);
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
    colour(kShapes[i % std::size(kShapes)].colour);
    gllab::draw_glut_shape(shape, solid);
    glPopMatrix();
    // "glutSolidTorus(0.25, 0.65, 12, 24)" as "Torus" over "(0.25, 0.65, 12, 24)"
    const std::string call = gllab::glut_call_text(shape, solid).substr(prefix.size());
    const std::size_t open = call.find('(');
    label(x, y - 0.8, call.substr(0, open), call.substr(open), s);
  }
  label(0, 3.1, prefix + "<Shape>(arguments)", "", s);
}

void draw_glu_vs_glut(GLUquadric* q, const gllab::State& s) {
  const int st = s.integer("glut_stacks"), sl = 2 * st;
  const double xs[] = {-2.2, 0.0, 2.2};
  gllab::enable_headlight();
  glShadeModel(s.flag("flat") ? GL_FLAT : GL_SMOOTH);
  for (int c = 0; c < 3; c += 2) {  // row 1, lit: GLU left, freeglut right
    enter_cell(xs[c], 1.45, 0.85, s);
    colour(kShapes[0].colour);
    if (c == 0) sphere(q, 1.0, sl, st);
    else gllab::draw_glut_sphere(sl, st, true);
    glPopMatrix();
  }
  // Row 2, wireframes with hidden lines removed: first a background-coloured
  // fill of the same shape, pushed back by glPolygonOffset, then the lines.
  // The middle fill is shrunk to lie inside both polyhedra.
  glDisable(GL_LIGHTING);
  glPolygonOffset(1.f, 1.f);
  const double inner = 0.98 * std::cos(M_PI / sl) * std::cos(M_PI / (2 * st));
  for (int c = 0; c < 3; ++c) {
    enter_cell(xs[c], -0.75, 0.85, s);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glColor3f(0.12f, 0.13f, 0.16f);
    if (c == 2) gllab::draw_glut_sphere(sl, st, true);
    else sphere(q, c == 0 ? 1.0 : inner, sl, st);
    glDisable(GL_POLYGON_OFFSET_FILL);
    gluQuadricDrawStyle(q, GLU_LINE);
    colour(kGluInk);
    if (c < 2) sphere(q, 1.0, sl, st);
    colour(kGlutInk);
    // Where both wires run along the same edge their depths tie, and which
    // one wins would hang on the last bit of rounding. A hair nearer (depth
    // range shrunk by 1e-5), glut's wire wins every tie in every renderer.
    glDepthRange(0.0, 1.0 - 1e-5);
    if (c > 0) gllab::draw_glut_sphere(sl, st, false);
    glDepthRange(0.0, 1.0);
    gluQuadricDrawStyle(q, GLU_FILL);
    glPopMatrix();
  }
  const std::string args = "(1, " + std::to_string(sl) + ", " + std::to_string(st) + ")";
  label(-2.2, 2.65, "gluSphere", args, s);
  label(2.2, 2.65, "glutSolidSphere", args, s);
  label(0, 0.55, "both wires", "", s);
  // freeglut does not call GLU: it makes its own vertices and normals.
  if (s.flag("labels"))
    gllab::draw_text_panel(8, 424, {"freeglut makes its own vertices:", "GLU slice 0 points to +y, glut's to +x",
                                    "(same only if slices % 4 == 0); glut cuts", "each quad into 2 triangles, GLU keeps quads"},
                           kText);
}

// init / display ----------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  // A checker made in code: kCheck x kCheck texels per square, two colours.
  std::vector<GLubyte> texels(kTexels * kTexels * 3);
  for (int y = 0; y < kTexels; ++y)
    for (int x = 0; x < kTexels; ++x) {
      const bool dark = ((x / kCheck) + (y / kCheck)) % 2 != 0;
      GLubyte* t = &texels[3 * (y * kTexels + x)];
      t[0] = dark ? 40 : 240, t[1] = dark ? 90 : 230, t[2] = dark ? 200 : 210;
    }
  glGenTextures(1, &g_checker);  // one name for the program's life
  glBindTexture(GL_TEXTURE_2D, g_checker);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, kTexels, kTexels, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

void display(const gllab::State& s) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 3.3, 3.3);
  const std::string& v = s.view();
  if (v == "glut_solid" || v == "glut_wire") return draw_glut(s, v == "glut_solid");
  // One quadric object for the frame; gluDeleteQuadric frees it.
  GLUquadric* q = gluNewQuadric();
  if (!q) return gllab::report_frame_error("gluNewQuadric: out of memory");
  gluQuadricCallback(q, GLU_ERROR, reinterpret_cast<_GLUfuncptr>(on_glu_error));
  if (v == "draw_styles") draw_styles(q, s);
  else if (v == "normals_orientation") draw_normals(q, s);
  else if (v == "texture") draw_texture(q, s);
  else if (v == "ellipsoid_normalize") draw_ellipsoids(q, s);
  else if (v == "resolution") draw_resolution(q, s);
  else if (v == "glu_vs_glut_sphere") draw_glu_vs_glut(q, s);
  else draw_default(q, s);
  gluDeleteQuadric(q);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"07_glu_quadrics",
          "lab 07 · GLU quadrics",
          {{"default", "sphere, cylinder, cone, disk and partial disk, lit"},
           {"draw_styles", "GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT"},
           {"normals_orientation", "GLU_NONE/FLAT/SMOOTH normals; GLU_OUTSIDE vs GLU_INSIDE"},
           {"texture", "gluQuadricTexture with a checker made in code, on and off"},
           {"ellipsoid_normalize", "glScale of a sphere: GL_NORMALIZE, neither, GL_RESCALE_NORMAL"},
           {"resolution", "same slices at every size vs a fixed edge length in pixels"},
           {"glut_solid", "the nine glutSolid* shapes"},
           {"glut_wire", "the nine glutWire* shapes"},
           {"glu_vs_glut_sphere", "gluSphere and glutSolidSphere at the same slices/stacks"}},
          {{"slices", 24, -8, 64, "slices of the GLU quadrics (below 2: GLU_INVALID_VALUE)"},
           {"stacks", 12, -8, 64, "stacks of the GLU quadrics (below 1: GLU_INVALID_VALUE)"},
           {"edge_px", 12, 2, 40, "resolution: longest edge on screen in the adaptive row, pixels"},
           {"glut_stacks", 5, 2, 24, "glu_vs_glut_sphere: stacks; slices = 2 x stacks"},
           {"spin", 0, -180, 180, "turn each shape about its own z axis, degrees"},
           {"flat", 1, 0, 1, "glu_vs_glut_sphere: glShadeModel(GL_FLAT) in the lit row"},
           {"lighting", 1, 0, 1, "light the shapes (default)"},
           {"labels", 1, 0, 1, "names and counts under the shapes"}},
          {{'s', "slices +2", "slices", +2},
           {'S', "slices -2", "slices", -2},
           {'t', "stacks +1", "stacks", +1},
           {'T', "stacks -1", "stacks", -1},
           {'e', "edge pixels +2 (resolution)", "edge_px", +2},
           {'E', "edge pixels -2 (resolution)", "edge_px", -2},
           {'g', "glut sphere stacks +1", "glut_stacks", +1},
           {'G', "glut sphere stacks -1", "glut_stacks", -1},
           {'r', "spin +15 degrees", "spin", +15},
           {'R', "spin -15 degrees", "spin", -15},
           {'f', "flat shading on/off (glu_vs_glut_sphere)", "flat"},
           {'l', "lighting on/off (default)", "lighting"},
           {'n', "labels on/off", "labels"}},
          init,
          display};
}
