// tests/harness/drag_lab.cpp — a test-only lab with point lists (window and
// headless programs), for tests/harness/drag_test.cpp: the mouse drags a
// point in a flat view and in a tilted 3D view, [p] prints the --set line,
// [Ctrl+S] saves the curve, --load reads it back.
//   left half:  ortho_fit(3, 3) shifted left by 1.5: a quadratic B-spline
//               through the 2D list P (its model, saved by Ctrl+S)
//   right half: the 3D list H, drawn tilted by 60 degrees about x
#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"

namespace {

gllab::spline::BsplineCurve curve_of(const gllab::State& s) {
  return gllab::spline::clamped_curve(s.points("P"), 2, 2);
}

void display(const gllab::State& s) {
  glClearColor(0.1f, 0.1f, 0.12f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
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

}  // namespace

gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"drag_lab", "drag lab (tests)", {{"default", "a curve and a tilted 3D polyline"}}, {}, {},
                 nullptr, display};
  lab.points = {{"P", {{-1, -1, 0}, {0, 1, 0}, {1, -1, 0}}, "control points of the curve"},
                {"H", {{-0.5, 0, 0}, {0.5, 0, 0.5}}, "a 3D polyline", 3}};
  lab.model = [](const gllab::State& s) -> gllab::Model { return curve_of(s); };
  return lab;
}
