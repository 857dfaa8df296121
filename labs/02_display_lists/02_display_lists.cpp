// lab 02 · display lists                                    difficulty: ★☆☆☆
// Draw calls recorded once in a display list and replayed with glCallList and
// glCallLists (lecture notes ch. 1, §1.3 Polygon rendering with OpenGL, "Display
// lists"): a lit torus and a row of shapes.
// Notice: a list records state changes too, and they outlive the call (state_leak).
//   Replaying a list gives the pixels of the same calls made immediately.
// Try: in state_leak press [f]: which two pairs of calls keep the bar green and in
//   place? In list_vs_immediate press [i], then [+] (GL_COMPILE_AND_EXECUTE).
// Keys: [i] immediate/list  [f] fix the leak  [+]/[-] torus detail  [n] labels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: default, state_leak, list_vs_immediate
// Reference: reference_images/02_display_lists__*.png

#include <cmath>
#include <iterator>
#include <string>

#include "gl/gl.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

// Lab data (edit me) -------------------------------------------------------
// The torus: 2k rings around z, k sides around the tube, 4k^2 triangles.
constexpr int kDefaultDetail = 16;
constexpr double kRingRadius = 1.0, kTubeRadius = 0.4;
// Four shapes, one list each: a regular polygon with this many corners, in this
// colour. Shape 0 is Red Book list.c's list: it sets red, draws, moves right.
struct Shape { int corners; gllab::Rgb colour; };
const Shape kShapes[] = {{3, {1.f, 0.f, 0.f}}, {4, {0.95f, 0.6f, 0.2f}},
                         {5, {0.35f, 0.6f, 1.f}}, {6, {0.85f, 0.4f, 0.8f}}};
constexpr float kAdvance = 1.5f;  // each shape list ends with glTranslatef(kAdvance, 0, 0)
// The row glCallLists draws: offsets added to glListBase, one byte each.
const GLubyte kRow[] = {0, 1, 2, 3, 2, 1, 0};
const gllab::Rgb kLabel{1.f, 1.f, 1.f}, kDim{0.6f, 0.62f, 0.68f};
// The lists: names from glGenLists in init(); the shapes made there, the torus
// at its first call and again when its detail changes. None is made per frame.
GLuint g_shapes = 0, g_torus = 0;  // kShapes lists are g_shapes + 0, + 1, ...; the torus
int g_torus_detail = 0;            // the detail g_torus was compiled with (0: not yet)

// Drawing -------------------------------------------------------------------
// Vertex (i, j): ring i of `rings` around z, side j of `sides` around the tube.
// cos and sin run at every call; a list keeps only the floats they gave.
void torus_vertex(int i, int j, int rings, int sides) {
  const double u = 2 * M_PI * (i % rings) / rings, v = 2 * M_PI * (j % sides) / sides;
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  glColor3f(float(0.55 + 0.4 * cu), float(0.55 + 0.35 * su), float(0.6 - 0.3 * cu));
  glNormal3f(float(cv * cu), float(cv * su), float(sv));  // from the tube's centre
  const double w = kRingRadius + kTubeRadius * cv;
  glVertex3f(float(w * cu), float(w * su), float(kTubeRadius * sv));
}

// Immediate mode, 2k rings and k sides. The same calls compile the list.
void draw_torus_immediate(int k) {
  // The quad (i, j)-(i+1, j+1) as two triangles, counter-clockwise from outside.
  const int corners[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 2 * k; ++i)
    for (int j = 0; j < k; ++j)
      for (const auto& c : corners) torus_vertex(i + c[0], j + c[1], 2 * k, k);
  glEnd();
}

void call_torus_list(int detail) {
  if (detail == g_torus_detail) {
    glCallList(g_torus);
    return;
  }
  // Not made yet, or the data changed and the list is stale. Release its name
  // first; a new list without glDeleteLists leaks one list per change.
  glDeleteLists(g_torus, 1);
  g_torus = glGenLists(1), g_torus_detail = detail;
  // GL_COMPILE_AND_EXECUTE records and draws at once: this frame needs it too.
  glNewList(g_torus, GL_COMPILE_AND_EXECUTE);
  draw_torus_immediate(detail);
  glEndList();
}

void compile_shape(GLuint list, const Shape& shape) {
  // GL_COMPILE only records; nothing is drawn until glCallList.
  glNewList(list, GL_COMPILE);
  glColor3f(shape.colour.r, shape.colour.g, shape.colour.b);
  glBegin(GL_POLYGON);
  for (int c = 0; c < shape.corners; ++c) {
    const double a = M_PI / 2 + 2 * M_PI * c / shape.corners;
    glVertex2d(0.5 + 0.55 * std::cos(a), 0.45 + 0.55 * std::sin(a));
  }
  glEnd();
  glTranslatef(kAdvance, 0.f, 0.f);  // like a font glyph: move on to the next
  glEndList();
}

// The projection, the light and the camera, then the torus at (x, y), tilted.
void draw_lit_torus(const gllab::State& s, float x, float y, float scale) {
  gllab::ortho_fit(s.width, s.height, 5.2, 3.3);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: the camera (common/gl/scene.h)
  glPushMatrix();
  glTranslatef(x, y, 0.f);
  glScalef(scale, scale, scale);
  glRotatef(-55.f, 1.f, 0.f, 0.f);
  if (s.flag("path")) call_torus_list(s.integer("detail"));
  else draw_torus_immediate(s.integer("detail"));
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

void draw_default(const gllab::State& s) {
  draw_lit_torus(s, 0.f, 1.1f, 1.6f);
  const float left = -kAdvance * static_cast<float>(std::size(kRow)) / 2 + 0.25f;
  // The shape lists move the matrix, so keep it for what comes after.
  glPushMatrix();
  glTranslatef(left, -2.3f, 0.f);
  glListBase(g_shapes);  // glCallLists adds this to every offset in kRow
  glCallLists(static_cast<GLsizei>(std::size(kRow)), GL_UNSIGNED_BYTE, kRow);
  glPopMatrix();
  if (!s.flag("labels")) return;
  std::string offsets;
  for (std::size_t i = 0; i < std::size(kRow); ++i) {
    gllab::draw_label(left + kAdvance * i + 0.5f, -2.55f, 0, std::to_string(kRow[i]), kLabel);
    offsets += " " + std::to_string(kRow[i]);
  }
  const std::string row = "glListBase(shapes); glCallLists(" + std::to_string(std::size(kRow));
  gllab::draw_label(0, 3.3, 0, s.flag("path") ? "glCallList(torus)" : "glBegin/glEnd (path=0)",
                    kLabel);
  gllab::draw_label(0, -1.15, 0, row + ", row)", kLabel);
  gllab::draw_label(0, -3.1, 0, "row = offsets" + offsets, kDim);
}

void draw_state_leak(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 5.2, 3.3);
  const float bar[] = {0.f, -1.f, 3.f, -0.5f};  // x0 y0 x1 y1, meant below triangle 0
  glTranslatef(-4.5f, 0.6f, 0.f);
  glColor3f(kDim.r, kDim.g, kDim.b);  // where the bar is meant to be
  glBegin(GL_LINE_LOOP);
  glVertex2f(bar[0], bar[1]), glVertex2f(bar[2], bar[1]);
  glVertex2f(bar[2], bar[3]), glVertex2f(bar[0], bar[3]);
  glEnd();
  glColor3f(0.f, 1.f, 0.f);  // current colour green
  // fix: save the colour and the matrix around the calls, as the default view's row does.
  if (s.flag("fix")) glPushAttrib(GL_CURRENT_BIT), glPushMatrix();
  for (int i = 0; i < 4; ++i) glCallList(g_shapes + 0);
  if (s.flag("fix")) glPopMatrix(), glPopAttrib();
  // Is this bar green, below the first triangle? (Not without fix: the list
  // left the colour red and the matrix 4 x 1.5 to the right.)
  glRectf(bar[0], bar[1], bar[2], bar[3]);
  glLoadIdentity();  // the labels: back to the projection's own coordinates
  if (!s.flag("labels")) return;
  gllab::draw_label(0, 2.7, 0, "glColor3f(green); 4 x glCallList(triangle)", kLabel);
  gllab::draw_label(0, 2.3, 0, "list: glColor3f(red); triangle; glTranslatef(1.5,0,0)", kDim);
  gllab::draw_label(-3.0, -0.75, 0, "meant: green, here", kDim);
  if (!s.flag("fix")) gllab::draw_label(3.0, -0.75, 0, "drawn: red, 4 x 1.5 right", kLabel);
  gllab::draw_label(0, -1.9, 0, "then glRectf(bar): which colour, where?", kLabel);
  gllab::draw_label(0, -2.3, 0, s.flag("fix") ? "fix=1: glPushAttrib/glPushMatrix around the calls"
                                                : "fix=0: the bar took the list's colour and moved",
                    kLabel);
}

void draw_list_vs_immediate(const gllab::State& s) {
  draw_lit_torus(s, 0.f, 0.f, 2.4f);
  if (!s.flag("labels")) return;
  const int k = s.integer("detail"), triangles = 2 * (2 * k) * k;  // 2 per quad
  gllab::draw_label(0, 2.9, 0, "torus: " + std::to_string(triangles) + " triangles", kLabel);
  gllab::draw_label(0, -2.9, 0, "path=0 glBegin/glEnd, path=1 glCallList: same pixels", kLabel);
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  // One contiguous block of names: g_shapes, g_shapes + 1, ... for glCallLists.
  g_shapes = glGenLists(static_cast<GLsizei>(std::size(kShapes)));
  for (std::size_t i = 0; i < std::size(kShapes); ++i) compile_shape(g_shapes + i, kShapes[i]);
  g_torus = glGenLists(1);  // a name only: call_torus_list records it when first drawn
  if (g_shapes == 0 || g_torus == 0) gllab::report_frame_error("glGenLists returned 0");
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"02_display_lists", "lab 02 · display lists",
          {{"default", "a torus from glCallList, shapes from glCallLists", draw_default, kOrbit},
           {"state_leak", "a list's colour and translation leak out", draw_state_leak},
           {"list_vs_immediate", "list or immediate ([i]): same pixels", draw_list_vs_immediate,
            kOrbit}},
          {{"path", 1, 0, 1, "draw the torus from its list (1) or immediately (0)"},
           {"fix", 0, 0, 1, "state_leak: push/pop colour and matrix around the calls"},
           {"detail", kDefaultDetail, 3, 60, "torus sides k: 2k rings, 4k^2 triangles"},
           {"labels", 1, 0, 1, "labels on/off"}},
          {{'i', "torus: display list / immediate mode", "path"},
           {'f', "fix the state leak on/off", "fix"}, {'n', "labels on/off", "labels"},
           {'+', "torus detail +4 (recompiles the list)", "detail", +4},
           {'-', "torus detail -4 (recompiles the list)", "detail", -4}},
          init};
}
