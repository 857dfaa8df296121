// common/gl/mesh_view.cpp — see mesh_view.h.
#include "gl/mesh_view.h"

#include <cmath>

#include "gl/gl.h"
#include "gl/scene.h"

namespace gllab {

void draw_vertex_normals(const IndexedMesh& m, float length) {
  glDisable(GL_LIGHTING);
  glColor3f(1.f, 1.f, 1.f);
  glBegin(GL_LINES);
  for (std::size_t i = 0; i < m.positions.size(); i += 3) {
    const float *p = &m.positions[i], *n = &m.normals[i];
    glVertex3fv(p);
    glVertex3f(p[0] + length * n[0], p[1] + length * n[1], p[2] + length * n[2]);
  }
  glEnd();
  glEnable(GL_LIGHTING);
}

void draw_profile_section(double x, double y, double scale,
                          const std::vector<ProfilePoint>& profile, double a, double b,
                          int samples) {
  glPushMatrix();
  glTranslated(x, y, 0);
  glScaled(scale, scale, scale);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1.f, .3f, .2f);
  glBegin(GL_TRIANGLE_FAN);
  for (int i = 0; i < samples; ++i)
    glVertex2d(a * std::cos(2 * M_PI * i / samples), b * std::sin(2 * M_PI * i / samples));
  glEnd();
  glColor3f(.3f, .55f, .35f);
  glBegin(GL_TRIANGLE_FAN);  // the section is convex: a fan covers it
  for (const ProfilePoint& p : profile) glVertex2d(p.r, p.z);
  for (auto p = profile.rbegin() + 1; p + 1 != profile.rend(); ++p) glVertex2d(-p->r, p->z);
  glEnd();
  glColor3f(.6f, 1.f, .65f);
  glPointSize(5.f);
  glBegin(GL_POINTS);
  for (const ProfilePoint& p : profile)
    for (double sign : {-1.0, 1.0}) glVertex2d(sign * p.r, p.z);
  glEnd();
  glPopAttrib();
  glPopMatrix();
}

void draw_mesh_numbers(const PolygonMesh& m) {
  GLdouble mv[16];
  glGetDoublev(GL_MODELVIEW_MATRIX, mv);
  for (std::size_t p = 0; p < m.polygons.size(); ++p) {
    const Polygon& poly = m.polygons[p];
    if (mv[2] * poly.normal.x + mv[6] * poly.normal.y + mv[10] * poly.normal.z <= 0) continue;
    Vec3 centre;
    for (std::size_t v : poly.vertices) {
      centre += m.vertices[v].position / double(poly.vertices.size());
      const Vec3 q = 1.2 * m.vertices[v].position;  // just outside the corner
      draw_label(q.x, q.y, q.z, std::to_string(v), {1.f, 1.f, 1.f});
    }
    draw_label(centre.x, centre.y, centre.z, "p" + std::to_string(p), {1.f, 1.f, .6f});
  }
}

std::vector<std::string> mesh_counts(const PolygonMesh& m, const IndexedMesh& arrays) {
  return {std::to_string(m.polygons.size()) + " polygons",
          std::to_string(m.vertices.size()) + " vertices stored",
          std::to_string(arrays.vertex_count()) + " sent to GL"};
}

std::vector<std::string> data_structure_counts(const PolygonMesh& m, const IndexedMesh& arrays,
                                               std::size_t edge) {
  const auto str = [](std::size_t n) { return std::to_string(n); };
  std::string surfaces = str(m.surfaces.size()) + " surfaces: ";
  for (std::size_t i = 0; i < m.surfaces.size(); ++i)
    surfaces += (i ? ", " : "") + m.surfaces[i].name + " " + str(m.surfaces[i].polygons.size()) +
                (i ? "" : " polygons");
  const std::size_t v = m.vertices.size(), e = m.edges.size(), f = m.polygons.size();
  const Edge& shared = m.edges.at(edge);
  std::string users;
  for (std::size_t k = 0; k < shared.polygons.size(); ++k)
    users += (k ? " and " : "") + str(shared.polygons[k]);
  return {surfaces,
          "V " + str(v) + "  E " + str(e) + "  F " + str(f) +
              "  V-E+F = " + std::to_string(long(v + f) - long(e)),
          str(m.count(EdgeType::kFeature)) + " feature edges (orange), " +
              str(m.count(EdgeType::kVirtual)) + " virtual (blue, dashed)",
          "edge " + str(shared.v0) + "-" + str(shared.v1) + " is used by polygons " + users,
          str(arrays.vertex_count()) + " vertices sent to GL: one per corner and smoothing group"};
}

}  // namespace gllab
