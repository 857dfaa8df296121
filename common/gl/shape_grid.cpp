// common/gl/shape_grid.cpp — see shape_grid.h.
#include "gl/shape_grid.h"

#include "gl/gl.h"
#include "gl/scene.h"

namespace gllab {

void enter_cell(double x, double y, double scale, float tilt_degrees, double spin_degrees) {
  glPushMatrix();
  glTranslated(x, y, 0);
  glScaled(scale, scale, scale);
  if (tilt_degrees != 0.f) glRotatef(tilt_degrees, 1.f, 0.f, 0.f);
  if (spin_degrees != 0) glRotated(spin_degrees, 0, 0, 1);
}

void draw_caption(double x, double y, const std::string& first, const std::string& second) {
  const Rgb white{1.f, 1.f, 1.f};
  draw_label(x, y, 0, first, white);
  if (!second.empty()) draw_label(x, y, 0, second, white, 0, kGlyphHeight);
}

void wire_over_fill(const std::function<void(bool wire)>& draw, Rgb wire) {
  glPolygonOffset(1.f, 1.f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  draw(false);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_LIGHTING);
  glColor3f(wire.r, wire.g, wire.b);
  draw(true);
  glEnable(GL_LIGHTING);
}

double pixels_per_unit(int width) {
  GLdouble projection[16];
  glGetDoublev(GL_PROJECTION_MATRIX, projection);
  return projection[0] * width / 2;
}

}  // namespace gllab
