// common/gl/nurbs_view.cpp — see nurbs_view.h.
#include "gl/nurbs_view.h"

#include "gl/gl.h"
#include "gl/spline_draw.h"

namespace gllab {

void draw_glu_surface(const spline::BsplineSurface& surface, GluNurbsProperties properties, const std::string& name,
                      std::optional<Rgb> edges, bool auto_normal) {
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_POLYGON_BIT | GL_EVAL_BIT);
  if (properties.display_mode == GLU_FILL) {
    if (auto_normal) glEnable(GL_AUTO_NORMAL);
    glNormal3f(0.f, 0.f, 1.f);  // every vertex's normal when GLU sends none
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.f, 1.f);
    GluNurbs(properties).draw_surface(surface, name);
    glDisable(GL_POLYGON_OFFSET_FILL);
    if (edges) {
      glColor3f(edges->r, edges->g, edges->b);
      properties.display_mode = GLU_OUTLINE_POLYGON;
    }
  }
  if (properties.display_mode != GLU_FILL) {
    glDisable(GL_LIGHTING);
    GluNurbs(properties).draw_surface(surface, name);
  }
  glPopAttrib();
}

std::size_t glu_triangle_count(const spline::BsplineSurface& surface, GluNurbsProperties properties,
                               const std::string& name) {
  properties.display_mode = GLU_FILL;
  return GluNurbs(properties).capture_surface(surface, name).mesh.triangles.size();
}

void draw_mesh_with_edges(const spline::Mesh& mesh, Rgb edges) {
  glPushAttrib(GL_POLYGON_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.f, 1.f);
  draw_mesh(mesh);
  glPopAttrib();
  draw_mesh_wireframe(mesh, edges);
}

}  // namespace gllab
