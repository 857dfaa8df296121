// common/gl/field_view.cpp — see field_view.h.
#include "gl/field_view.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "gl/gl.h"
#include "field/mesh_measures.h"
#include "gl/scene.h"

namespace gllab {

void field_camera(const State& s, int width, int height, double half, double azimuth) {
  ortho_fit(width, height, half, half);
  enable_headlight();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  apply_orbit(s);
  glRotated(-65, 1, 0, 0);
  glRotated(azimuth, 0, 0, 1);
}

std::string component_text(const IndexedMesh& m) {
  const std::size_t n = field::topology(m).components;
  return format_text("%zu component%s", n, n == 1 ? "" : "s");
}

void draw_unit_cell(std::uint8_t mask, Rgb corner_colour) {
  auto corner = [](int b) { glVertex3i(b & 1, b >> 1 & 1, b >> 2); };
  glPushAttrib(GL_ENABLE_BIT | GL_POINT_BIT);
  glDisable(GL_LIGHTING);
  glColor3f(.6f, .6f, .6f);
  glBegin(GL_LINES);
  for (int b = 0; b < 8; ++b)
    for (int axis = 1; axis < 8; axis <<= 1)
      if (!(b & axis)) corner(b), corner(b | axis);  // the 12 edges
  glEnd();
  glPointSize(8.f);
  glColor3f(corner_colour.r, corner_colour.g, corner_colour.b);
  glBegin(GL_POINTS);
  for (int b = 0; b < 8; ++b)
    if (mask >> b & 1) corner(b);
  glEnd();
  glPopAttrib();
}

void draw_iso_mesh(const IndexedMesh& m, const std::vector<Rgb>& triangle_colours) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  if (triangle_colours.empty()) {
    glVertexPointer(3, GL_FLOAT, 0, m.positions.data());
    glNormalPointer(GL_FLOAT, 0, m.normals.data());
    glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, m.indices.data());
  } else {  // a colour per triangle: every corner sent on its own
    const IndexedMesh flat = unshared(m);
    std::vector<float> colours;
    colours.reserve(flat.positions.size());
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
      for (int corner = 0; corner < 3; ++corner)
        colours.insert(colours.end(),
                       {triangle_colours[t].r, triangle_colours[t].g, triangle_colours[t].b});
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, flat.positions.data());
    glNormalPointer(GL_FLOAT, 0, flat.normals.data());
    glColorPointer(3, GL_FLOAT, 0, colours.data());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(flat.vertex_count()));
    glDisableClientState(GL_COLOR_ARRAY);
  }
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

void draw_mesh_edges(const IndexedMesh& m, Rgb colour) {
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_LIGHTING);
  glColor3f(colour.r, colour.g, colour.b);
  glBegin(GL_LINES);
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      glVertex3fv(&m.positions[3 * std::size_t(m.indices[t + e])]);
      glVertex3fv(&m.positions[3 * std::size_t(m.indices[t + (e + 1) % 3])]);
    }
  glEnd();
  glPopAttrib();
}

void draw_open_edges(const IndexedMesh& m, Rgb colour, float width) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;  // undirected edge -> triangles
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = m.indices[t + e], b = m.indices[t + (e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glLineWidth(width);
  glColor3f(colour.r, colour.g, colour.b);
  glBegin(GL_LINES);
  for (const auto& [edge, count] : uses)
    if (count == 1) {
      glVertex3fv(&m.positions[3 * std::size_t(edge.first)]);
      glVertex3fv(&m.positions[3 * std::size_t(edge.second)]);
    }
  glEnd();
  glPopAttrib();
}

Rgb value_colour(double v, double lo, double mid, double hi) {
  const Rgb cold{.15f, .3f, .8f}, white{1.f, 1.f, 1.f}, hot{.85f, .2f, .15f};
  const bool below = v < mid;
  const double s = below ? (mid - v) / (mid - lo) : (v - mid) / (hi - mid);
  const float t = float(std::clamp(s, 0.0, 1.0));
  const Rgb& end = below ? cold : hot;
  return {white.r + t * (end.r - white.r), white.g + t * (end.g - white.g),
          white.b + t * (end.b - white.b)};
}

void draw_field_slice(const std::function<double(double, double)>& f, double x0, double y0,
                      double x1, double y1, double z, int n, double lo, double mid, double hi) {
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_LIGHTING);
  const double hx = (x1 - x0) / n, hy = (y1 - y0) / n;
  glBegin(GL_QUADS);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double cx = x0 + (i + .5) * hx, cy = y0 + (j + .5) * hy;
      const Rgb c = value_colour(f(cx, cy), lo, mid, hi);  // flat per quad: its centre's value
      glColor3f(c.r, c.g, c.b);
      glVertex3d(cx - hx / 2, cy - hy / 2, z);
      glVertex3d(cx + hx / 2, cy - hy / 2, z);
      glVertex3d(cx + hx / 2, cy + hy / 2, z);
      glVertex3d(cx - hx / 2, cy + hy / 2, z);
    }
  glEnd();
  glPopAttrib();
}

void draw_iso_curves(const field::IsoCurves& curves, double z, Rgb colour, float width) {
  glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT);
  glDisable(GL_LIGHTING);
  glLineWidth(width);
  glColor3f(colour.r, colour.g, colour.b);
  glBegin(GL_LINES);
  for (const auto& s : curves.segments)
    for (int end : s) glVertex3d(curves.points[end][0], curves.points[end][1], z);
  glEnd();
  glPopAttrib();
}

std::pair<double, double> distance_range(const IndexedMesh& m, const field::Vec3& centre) {
  double lo = HUGE_VAL, hi = 0;
  for (std::size_t i = 0; i < m.positions.size(); i += 3) {
    const double d = std::hypot(m.positions[i] - centre.x, m.positions[i + 1] - centre.y,
                                m.positions[i + 2] - centre.z);
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  return {lo, hi};
}

void draw_plot_axes(double x0, double x1, double y0, double y1, double dx, double dy, Rgb colour) {
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glColor3f(colour.r, colour.g, colour.b);
  const double tx = (y1 - y0) / 60, ty = (x1 - x0) / 60;  // tick lengths
  glBegin(GL_LINES);
  glVertex2d(x0, 0), glVertex2d(x1, 0), glVertex2d(0, y0), glVertex2d(0, y1);
  for (double x = dx; x <= x1 + 1e-9; x += dx) glVertex2d(x, -tx), glVertex2d(x, tx);
  for (double y = dy; y <= y1 + 1e-9; y += dy) glVertex2d(-ty, y), glVertex2d(ty, y);
  glEnd();
  for (double x = dx; x <= x1 + 1e-9; x += dx) draw_label(x, 0, 0, fmt("%g", x), colour, 0, 12);
  for (double y = dy; y <= y1 + 1e-9; y += dy) draw_label(0, y, 0, fmt("%g", y), colour, -18, 0);
  glPopAttrib();
}

}  // namespace gllab
