// lab 01 · immediate mode                                   difficulty: ★☆☆☆
// The six polygon primitives of glBegin/glEnd, lit with glNormal3f (lecture
// notes ch. 1, §1.3 Polygon rendering with OpenGL).
// Notice: a strip or fan reuses vertices; GL_POLYGON is only defined for
//   convex, planar outlines.
// Try: press [f] to mirror the scene. Why do the filled faces turn into
//   outlines in vertex_order? Then move a vertex of the U so it is convex.
// Keys: [l] lighting  [r]/[R] spin  [f] flip winding  [n] labels  [h] help  [Esc] quit
//   right-drag turn  wheel zoom  [0] reset the camera
// Views: default, wireframe, vertex_order, invalid_polygons
// Reference: reference_images/01_immediate_mode__*.png

#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

// Lab data (edit me) -------------------------------------------------------
struct Vertex {
  float x, y;
};

struct Primitive {
  GLenum mode;
  const char* name;
  gllab::Rgb colour;
  std::vector<Vertex> vertices;  // counter-clockwise seen from the front
};

// One cell each, coordinates within [-1, 1]. Each list is in the order the
// primitive needs: read it together with the comment above it.
const Primitive kPrimitives[] = {
    // A convex outline: GL_POLYGON fills it as one face.
    {GL_POLYGON, "GL_POLYGON", {0.95f, 0.55f, 0.2f},
     {{0.f, .85f}, {-.8f, .25f}, {-.5f, -.7f}, {.5f, -.7f}, {.8f, .25f}}},
    // Every 3 vertices make one triangle: 6 vertices, 2 triangles.
    {GL_TRIANGLES, "GL_TRIANGLES", {0.3f, 0.75f, 0.35f},
     {{-.85f, -.7f}, {-.05f, -.7f}, {-.45f, .75f}, {.15f, -.7f}, {.85f, .55f}, {.15f, .75f}}},
    // Vertex k >= 2 makes a triangle with the two before it: 6 vertices, 4 triangles.
    {GL_TRIANGLE_STRIP, "GL_TRIANGLE_STRIP", {0.3f, 0.6f, 0.95f},
     {{-.85f, -.2f}, {-.75f, -.75f}, {-.25f, .15f}, {-.05f, -.45f}, {.45f, .55f}, {.8f, .05f}}},
    // Every vertex after the 2nd makes a triangle with the first and the one before.
    {GL_TRIANGLE_FAN, "GL_TRIANGLE_FAN", {0.85f, 0.35f, 0.65f},
     {{0.f, -.6f}, {.85f, -.3f}, {.7f, .35f}, {.2f, .8f}, {-.35f, .75f}, {-.75f, .35f},
      {-.85f, -.3f}}},
    // Every 4 vertices make one quad: 8 vertices, 2 quads.
    {GL_QUADS, "GL_QUADS", {0.9f, 0.8f, 0.25f},
     {{-.85f, -.75f}, {-.1f, -.75f}, {-.1f, 0.f}, {-.85f, .1f},
      {0.f, -.1f}, {.85f, 0.f}, {.75f, .8f}, {.05f, .65f}}},
    // Pairs of vertices make quads with the pair before: 8 vertices, 3 quads.
    // Quad i is 2i, 2i+1, 2i+3, 2i+2, so top, bottom, top, bottom runs
    // counter-clockwise (not around the quad as in GL_QUADS).
    {GL_QUAD_STRIP, "GL_QUAD_STRIP", {0.35f, 0.8f, 0.8f},
     {{-.85f, .3f}, {-.85f, -.6f}, {-.3f, .55f}, {-.3f, -.75f},
      {.3f, .75f}, {.3f, -.6f}, {.85f, .6f}, {.85f, -.3f}}},
};

// A non-convex outline (a U), counter-clockwise.
const Vertex kU[] = {{-.8f, -.7f}, {.8f, -.7f}, {.8f, .7f}, {.4f, .7f},
                     {.4f, -.3f},  {-.4f, -.3f}, {-.4f, .7f}, {-.8f, .7f}};
// Its triangulation by ear clipping, done by hand: n - 2 = 6 triangles.
const int kUTriangles[][3] = {{0, 1, 4}, {1, 2, 3}, {1, 3, 4}, {0, 4, 5}, {0, 5, 6}, {0, 6, 7}};

// A non-planar hexagon: its corners go up and down by this much in z.
constexpr float kHexRadius = 0.8f, kHexLift = 0.45f;
constexpr int kHexCorners = 6;

const gllab::Rgb kLabel{1.f, 1.f, 1.f}, kOutline{1.f, 1.f, 1.f};

// Drawing -------------------------------------------------------------------
// Normals tilt outwards like a dome, so the lighting shows each shape's form.
void dome_normal(Vertex v) { glNormal3f(0.6f * v.x, 0.6f * v.y, 1.f); }

// The cell of primitive i: 3 columns by 2 rows.
void enter_cell(std::size_t i, const gllab::State& s) {
  glPushMatrix();
  glTranslatef(-2.2f + 2.2f * static_cast<float>(i % 3), i < 3 ? 1.15f : -1.25f, 0.f);
  glRotated(s.get("spin"), 0, 1, 0);
  glScalef(s.flag("flip") ? -0.95f : 0.95f, 0.95f, 0.95f);
}

void draw_primitive(const Primitive& p, bool colour_by_order) {
  const std::size_t n = p.vertices.size();
  glColor3f(p.colour.r, p.colour.g, p.colour.b);
  glBegin(p.mode);
  for (std::size_t k = 0; k < n; ++k) {
    // vertex_order: a ramp from blue (first vertex) to red (last).
    const float t = static_cast<float>(k) / static_cast<float>(n - 1);
    if (colour_by_order) glColor3f(t, 0.25f, 1.f - t);
    dome_normal(p.vertices[k]);
    glVertex2f(p.vertices[k].x, p.vertices[k].y);
  }
  glEnd();
}

void draw_vertex_numbers(const Primitive& p) {
  for (std::size_t k = 0; k < p.vertices.size(); ++k) {
    const Vertex v = p.vertices[k];
    // Push each number a little away from the cell centre so it sits outside.
    const float r = std::hypot(v.x, v.y) + 1e-6f;
    gllab::draw_label(v.x + 0.17f * v.x / r, v.y + 0.17f * v.y / r, 0, std::to_string(k), kLabel);
  }
}

// The three views of the six primitives differ only in how they are drawn.
enum class Style { kLit, kWireframe, kVertexOrder };

void draw_primitives(const gllab::State& s, Style style) {
  const bool order = style == Style::kVertexOrder;
  gllab::ortho_fit(s.width, s.height, 3.3, 2.5);
  if (style == Style::kWireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  // Filled front faces, outlined back faces: the winding shows.
  if (order) glPolygonMode(GL_BACK, GL_LINE);
  if (s.flag("lighting") && style == Style::kLit) gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: the camera (common/gl/scene.h)
  glShadeModel(GL_SMOOTH);
  for (std::size_t i = 0; i < std::size(kPrimitives); ++i) {
    enter_cell(i, s);
    draw_primitive(kPrimitives[i], order);
    if (style == Style::kWireframe) {  // the vertices themselves
      glPointSize(5.f);
      glBegin(GL_POINTS);
      for (const Vertex& v : kPrimitives[i].vertices) glVertex2f(v.x, v.y);
      glEnd();
    }
    if (order) draw_vertex_numbers(kPrimitives[i]);
    if (s.flag("labels")) gllab::draw_label(0, -1.f, 0, kPrimitives[i].name, kLabel, 0, 10);
    glPopMatrix();
  }
}

void draw_default(const gllab::State& s) { draw_primitives(s, Style::kLit); }
void draw_wireframe(const gllab::State& s) { draw_primitives(s, Style::kWireframe); }
void draw_vertex_order(const gllab::State& s) { draw_primitives(s, Style::kVertexOrder); }

Vertex hex_corner(int k) {
  const double a = 2 * M_PI * k / kHexCorners;
  return {kHexRadius * float(std::cos(a)), kHexRadius * float(std::sin(a))};
}
float hex_z(int k) { return k % 2 ? -kHexLift : kHexLift; }

// The U as GL_POLYGON (left) and as triangles (right), the outline on top.
void draw_non_convex(bool as_polygon) {
  glColor3f(0.95f, 0.55f, 0.2f);
  glNormal3f(0, 0, 1);
  if (as_polygon) {
    // Wrong: GL_POLYGON is undefined for a non-convex outline. Does the fill
    // stay inside the white outline? (No: Mesa fans it from vertex 0.)
    glBegin(GL_POLYGON);
    for (const Vertex& v : kU) glVertex2f(v.x, v.y);
  } else {
    glBegin(GL_TRIANGLES);
    for (const auto& t : kUTriangles)
      for (int k : t) glVertex2f(kU[k].x, kU[k].y);
  }
  glEnd();
  glDisable(GL_LIGHTING);
  glColor3f(kOutline.r, kOutline.g, kOutline.b);
  glBegin(GL_LINE_LOOP);
  for (const Vertex& v : kU) glVertex3f(v.x, v.y, 0.01f);
  glEnd();
  glEnable(GL_LIGHTING);
}

// The hexagon as one GL_POLYGON with one normal (left), and as a fan of
// triangles around its centre, each with its own normal (right).
void draw_non_planar(bool as_polygon) {
  glColor3f(0.3f, 0.6f, 0.95f);
  if (as_polygon) {
    // Wrong: the corners are not in one plane, so no single normal is right.
    glBegin(GL_POLYGON);
    glNormal3f(0, 0, 1);
    for (int k = 0; k < kHexCorners; ++k) glVertex3f(hex_corner(k).x, hex_corner(k).y, hex_z(k));
    glEnd();
    return;
  }
  glBegin(GL_TRIANGLES);
  for (int k = 0; k < kHexCorners; ++k) {
    const Vertex a = hex_corner(k), b = hex_corner((k + 1) % kHexCorners);
    const float az = hex_z(k), bz = hex_z(k + 1);
    // Normal = a x b for the triangle (centre, a, b) with the centre at the origin.
    glNormal3f(a.y * bz - az * b.y, az * b.x - a.x * bz, a.x * b.y - a.y * b.x);
    glVertex3f(0, 0, 0);
    glVertex3f(a.x, a.y, az);
    glVertex3f(b.x, b.y, bz);
  }
  glEnd();
}

void draw_invalid_polygons(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 3.3, 2.5);
  if (s.flag("lighting")) gllab::enable_headlight();
  gllab::apply_orbit(s);
  for (int row = 0; row < 2; ++row) {
    for (int col = 0; col < 2; ++col) {
      glPushMatrix();
      glTranslatef(col ? 1.4f : -1.4f, row ? -1.3f : 1.3f, 0.f);
      glRotated(s.get("spin"), 0, 1, 0);
      if (row == 1) glRotatef(-55.f, 1.f, 0.f, 0.f);  // look at the hexagon from aside
      if (row == 0) draw_non_convex(col == 0);
      else draw_non_planar(col == 0);
      glPopMatrix();
      const char* verdict = col ? "6 triangles (correct)" : "GL_POLYGON (undefined)";
      gllab::draw_label(col ? 1.4 : -1.4, row ? -2.35 : 0.3, 0, verdict, kLabel);
    }
  }
  gllab::draw_label(0, 2.35, 0, "non-convex outline", kLabel);
  gllab::draw_label(0, -0.1, 0, "non-planar outline", kLabel);
}

// init ----------------------------------------------------------------------
// Before every frame the runner clears the colour and depth buffers with this
// colour; then it calls the view's draw function (the lab definition below).
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"01_immediate_mode",
          "lab 01 · immediate mode",
          {{"default", "the six primitives, lit with glNormal3f", draw_default, gllab::kOrbit},
           {"wireframe", "the same as outlines: the triangles and quads GL made", draw_wireframe,
            gllab::kOrbit},
           {"vertex_order", "vertices numbered and coloured in the order sent", draw_vertex_order,
            gllab::kOrbit},
           {"invalid_polygons", "non-convex and non-planar GL_POLYGON vs triangles",
            draw_invalid_polygons, gllab::kOrbit}},
          {{"lighting", 1, 0, 1, "light the shapes (default, invalid_polygons)"},
           {"spin", 0, -180, 180, "turn each shape about its vertical axis, degrees"},
           {"flip", 0, 0, 1, "mirror each shape in x: reverses the winding"},
           {"labels", 1, 0, 1, "name each primitive"}},
          {{'l', "lighting on/off", "lighting"},
           {'r', "spin +15 degrees", "spin", +15},
           {'R', "spin -15 degrees", "spin", -15},
           {'f', "flip winding (mirror in x)", "flip"},
           {'n', "primitive names on/off", "labels"}},
          init};
}
