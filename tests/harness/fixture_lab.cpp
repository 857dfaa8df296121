// tests/harness/fixture_lab.cpp — a test-only lab (headless program only).
//
// It draws the kind of scene the labs draw: lit, smoothly shaded polygons,
// one-pixel lines, points and bitmap text. Its `mistake` parameter reproduces
// three errors a student makes, so the image tolerance can be shown to pass
// renderer noise (softpipe vs llvmpipe) and to fail real mistakes:
//   mistake=1  wrong colour: one shape's glColor has red and blue swapped
//   mistake=2  missing primitive: one triangle of the fan is not drawn
//   mistake=3  moved vertex: one vertex off by 1% of the 512-pixel frame
// and `gl_error=1` makes draw() raise GL_INVALID_ENUM on purpose;
// `throws=1` makes it throw std::invalid_argument half-way, with a matrix and
// an attribute group still pushed (as the spline core does on bad input).
// `throw_after_text=1` throws from draw() after its text is drawn.
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "gl/gl.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

constexpr float kHalfBox = 3.f;                     // ortho_fit half size: the box is 6 units
constexpr float kOnePercent = 0.01f * 2 * kHalfBox;  // 1% of the box, ~5 px at 512 px

void draw(const gllab::State& s) {
  const int mistake = s.integer("mistake");
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, kHalfBox, kHalfBox);
  gllab::enable_headlight();

  // A lit fan of 8 triangles (a disc) on the left.
  glColor3f(mistake == 1 ? 0.2f : 0.95f, 0.55f, mistake == 1 ? 0.95f : 0.2f);
  glBegin(GL_TRIANGLES);
  constexpr int kSlices = 8;
  for (int k = 0; k < kSlices; ++k) {
    if (mistake == 2 && k == 3) continue;
    const double a0 = 2 * M_PI * k / kSlices, a1 = 2 * M_PI * (k + 1) / kSlices;
    glNormal3f(0, 0, 1);
    glVertex2f(-1.5f, 1.2f);
    glNormal3d(0.6 * std::cos(a0), 0.6 * std::sin(a0), 1);
    glVertex2d(-1.5 + 1.2 * std::cos(a0), 1.2 + 1.2 * std::sin(a0));
    glNormal3d(0.6 * std::cos(a1), 0.6 * std::sin(a1), 1);
    glVertex2d(-1.5 + 1.2 * std::cos(a1), 1.2 + 1.2 * std::sin(a1));
  }
  glEnd();

  // A lit quad strip on the right; mistake 3 moves its top-right vertex.
  glColor3f(0.3f, 0.6f, 0.95f);
  const float strip[][2] = {{0.3f, 2.2f}, {0.3f, 0.3f}, {1.3f, 2.4f}, {1.3f, 0.2f}, {2.6f, 2.2f}, {2.6f, 0.4f}};
  glBegin(GL_QUAD_STRIP);
  for (std::size_t k = 0; k < std::size(strip); ++k) {
    const float dx = (mistake == 3 && k == 4) ? kOnePercent : 0.f;
    glNormal3f(0.3f * strip[k][0] - 0.4f, 0.2f * strip[k][1], 1.f);
    glVertex2f(strip[k][0] + dx, strip[k][1]);
  }
  glEnd();

  // Unlit one-pixel lines and points, where renderers disagree most.
  glDisable(GL_LIGHTING);
  glColor3f(0.9f, 0.9f, 0.3f);
  glBegin(GL_LINE_STRIP);
  for (int k = 0; k <= 40; ++k) glVertex2d(-2.7 + 5.4 * k / 40, -1.6 + 0.9 * std::sin(k * 0.45));
  glEnd();
  glPointSize(5.f);
  glBegin(GL_POINTS);
  for (int k = 0; k <= 40; k += 5) glVertex2d(-2.7 + 5.4 * k / 40, -1.6 + 0.9 * std::sin(k * 0.45));
  glEnd();
  gllab::draw_label(0, -2.6, 0, "GL_QUAD_STRIP and GL_TRIANGLES", {1.f, 1.f, 1.f});

  if (s.flag("gl_error")) glEnable(GL_TRUE);  // GL_TRUE is no capability: GL_INVALID_ENUM
  if (s.flag("throws")) {
    glPushMatrix();
    glPushAttrib(GL_CURRENT_BIT);
    throw std::invalid_argument("fixture: thrown in draw() on purpose");
  }
  if (s.flag("throw_after_text")) throw std::invalid_argument("draw() gave up after its label");
}

}  // namespace

gllab::Lab gllab::define_lab() {
  return {"fixture_lab",
          "test fixture · mistakes students make",
          {{"default", "lit polygons, lines, points and text", draw}},
          {{"mistake", 0, 0, 3, "0 none, 1 wrong colour, 2 missing triangle, 3 moved vertex"},
           {"gl_error", 0, 0, 1, "raise GL_INVALID_ENUM in draw()"},
           {"throws", 0, 0, 1, "throw std::invalid_argument in draw()"},
           {"throw_after_text", 0, 0, 1, "throw std::invalid_argument from draw() after drawing text"}},
          {},
          [] { glEnable(GL_DEPTH_TEST); }};
}
