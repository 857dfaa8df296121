// common/gl/scene.cpp
#include "gl/scene.h"

#include <cmath>

#include "gl/gl.h"
#include "harness/lab.h"

namespace gllab {

void apply_orbit(const State& s) {
  const Camera& c = s.camera;
  if (c == Camera{}) return;  // the lab's camera, untouched: the reference images
  GLint mode = 0;
  glGetIntegerv(GL_MATRIX_MODE, &mode);
  glMatrixMode(GL_PROJECTION);
  glScaled(c.zoom, c.zoom, 1);  // x and y only: the depth range stays the lab's
  glMatrixMode(GL_MODELVIEW);
  glRotated(c.pitch, 1, 0, 0);
  glRotated(c.yaw, 0, 1, 0);
  glMatrixMode(static_cast<GLenum>(mode));
}

void ortho_fit(int width, int height, double half_width, double half_height, double depth) {
  const double aspect = static_cast<double>(width) / height;
  double hw = half_width, hh = half_height;
  if (hw / hh < aspect) hw = hh * aspect;  // window wider than the box
  else hh = hw / aspect;                   // window taller than the box
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-hw, hw, -hh, hh, -depth, depth);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void enable_headlight() {
  const GLfloat direction[] = {-0.35f, 0.45f, 1.f, 0.f};  // w = 0: a direction
  const GLfloat white[] = {1.f, 1.f, 1.f, 1.f};
  const GLfloat ambient[] = {0.2f, 0.2f, 0.2f, 1.f};
  glLightfv(GL_LIGHT0, GL_POSITION, direction);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_NORMALIZE);
}

void look_from_above(double elevation, double azimuth) {
  glRotated(elevation - 90, 1, 0, 0);  // z was towards the eye; now it leans up
  glRotated(-azimuth, 0, 0, 1);
}

bool window_pixel(double x, double y, double z, int& px, int& py) {
  GLdouble model[16], projection[16];
  GLint viewport[4];
  glGetDoublev(GL_MODELVIEW_MATRIX, model);
  glGetDoublev(GL_PROJECTION_MATRIX, projection);
  glGetIntegerv(GL_VIEWPORT, viewport);
  GLdouble wx = 0, wy = 0, wz = 0;
  if (gluProject(x, y, z, model, projection, viewport, &wx, &wy, &wz) != GL_TRUE) return false;
  px = static_cast<int>(std::lround(wx));
  py = viewport[3] - static_cast<int>(std::lround(wy));
  return true;
}

void draw_label(double x, double y, double z, const std::string& text, Rgb colour, int dx, int dy) {
  int px = 0, py = 0;
  if (window_pixel(x, y, z, px, py)) draw_text(px - text_width(text) / 2 + dx, py - kGlyphHeight / 2 + dy, text, colour);
}

void draw_text_panel_at(double x, double y, double z, const std::vector<std::string>& lines,
                        const std::vector<Rgb>& colours) {
  int px = 0, py = 0;
  if (window_pixel(x, y, z, px, py)) draw_text_panel(px, py, lines, colours);
}

}  // namespace gllab
