// tests/harness/drag_lab.cpp — a test-only lab with point lists (window and
// headless programs), for tests/harness/drag_test.cpp: the mouse drags a
// point in a flat view and in a tilted 3D view, [p] prints the --set line,
// [Ctrl+S] saves the curve, --load reads it back.
//   left half:  ortho_fit(3, 3) shifted left by 1.5: a quadratic B-spline
//               through the 2D list P (its model, saved by Ctrl+S)
//   right half: the 3D list H, drawn tilted by 60 degrees about x
// and a 3D view (kOrbit) for the orbit camera: a lit box with faces of six
// colours, turned by the right mouse button and zoomed by the wheel.
#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"

namespace {

gllab::spline::BsplineCurve curve_of(const gllab::State& s) {
  return gllab::spline::clamped_curve(s.points("P"), 2, 2);
}

void draw_default(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 3, 3);
  glPushMatrix();
  glTranslatef(-1.5f, 0.f, 0.f);
  gllab::draw_curve(curve_of(s), {0.3f, 0.8f, 1.f});
  gllab::draw_control_points(s, "P", {1.f, 0.8f, 0.3f});
  glPopMatrix();
  glPushMatrix();
  glTranslatef(1.5f, 0.f, 0.f);
  glRotatef(-60.f, 1.f, 0.f, 0.f);
  gllab::draw_polyline(s.points("H"), {0.6f, 0.6f, 0.6f});
  gllab::draw_control_points(s, "H", {0.4f, 1.f, 0.4f});
  glPopMatrix();
}

// A box 2 x 1.4 x 1 about the origin, one colour per face, seen from above
// the front; apply_orbit turns it on top of that.
void draw_box(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 2, 2);
  gllab::enable_headlight();
  gllab::apply_orbit(s);
  glRotatef(-30.f, 1.f, 0.f, 0.f);
  glRotatef(25.f, 0.f, 1.f, 0.f);
  glEnable(GL_DEPTH_TEST);
  const float x = 1.f, y = 0.7f, z = 0.5f;
  const float faces[6][6] = {  // normal, colour
      {1, 0, 0, 0.9f, 0.3f, 0.3f}, {-1, 0, 0, 0.3f, 0.9f, 0.3f}, {0, 1, 0, 0.3f, 0.4f, 0.9f},
      {0, -1, 0, 0.9f, 0.9f, 0.3f}, {0, 0, 1, 0.9f, 0.5f, 0.9f}, {0, 0, -1, 0.4f, 0.9f, 0.9f}};
  glBegin(GL_QUADS);
  for (const auto& f : faces) {
    glColor3f(f[3], f[4], f[5]);
    glNormal3f(f[0], f[1], f[2]);
    // Four corners on the face: the two axes across it, in counter-clockwise order.
    const int a = f[0] != 0 ? 0 : f[1] != 0 ? 1 : 2;
    const float n = f[0] + f[1] + f[2];
    const float half[3] = {x, y, z};
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    const float su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
      float p[3];
      p[a] = n * half[a];
      p[u] = su[k] * half[u] * n;
      p[v] = sv[k] * half[v];
      glVertex3fv(p);
    }
  }
  glEnd();
}

}  // namespace

gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"drag_lab",
                 "drag lab (tests)",
                 {{"default", "a curve and a tilted 3D polyline", draw_default},
                  {"box", "a lit box under the orbit camera", draw_box, gllab::kOrbit}},
                 {},
                 {},
                 [] { glClearColor(0.1f, 0.1f, 0.12f, 1.f); }};
  lab.points = {{"P", {{-1, -1, 0}, {0, 1, 0}, {1, -1, 0}}, "control points of the curve"},
                {"H", {{-0.5, 0, 0}, {0.5, 0, 0.5}}, "a 3D polyline", 3}};
  lab.model = [](const gllab::State& s) -> gllab::Model { return curve_of(s); };
  return lab;
}
