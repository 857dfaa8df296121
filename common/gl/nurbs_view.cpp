// common/gl/nurbs_view.cpp — see nurbs_view.h.
#include "gl/nurbs_view.h"

#include "gl/gl.h"
#include "gl/scene.h"
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

void fill_then_edges(const std::function<void(GLenum display_mode)>& draw, std::optional<Rgb> edges) {
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_POLYGON_BIT | GL_EVAL_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.f, 1.f);
  draw(GLU_FILL);
  glDisable(GL_POLYGON_OFFSET_FILL);
  if (edges) {
    glColor3f(edges->r, edges->g, edges->b);
    glDisable(GL_LIGHTING);
    draw(GLU_OUTLINE_POLYGON);
  }
  glPopAttrib();
}

std::size_t glu_triangle_count(const spline::BsplineSurface& surface, GluNurbsProperties properties,
                               const std::string& name) {
  properties.display_mode = GLU_FILL;
  return GluNurbs(properties).capture_surface(surface, name).mesh.triangles.size();
}

void draw_trim_domain(const Panel& panel, const std::vector<spline::TrimLoop>& loops) {
  const Rgb pwl{1.f, 1.f, 1.f}, trim2{0.4f, 0.9f, 0.4f}, trim3{0.45f, 0.7f, 1.f};
  ortho_fit(panel.width, panel.height, 0.62, 0.62);
  glTranslated(-0.5, -0.5, 0);
  draw_polyline({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0.5f, 0.5f, 0.55f}, 1.f, true);
  draw_trim_loops(loops, pwl, trim2, trim3);
  draw_panel_caption(panel, -3, "gluPwlCurve", pwl);
  draw_panel_caption(panel, -2, "gluNurbsCurve GLU_MAP1_TRIM_2", trim2);
  draw_panel_caption(panel, -1, "gluNurbsCurve GLU_MAP1_TRIM_3", trim3);
}

void draw_mesh_pair(const State& s, const spline::SurfaceEvaluator& surface, const spline::Mesh meshes[2],
                    const std::string titles[2][2], bool trims, double tilt_degrees,
                    const std::function<void(const Panel&)>& camera) {
  const Rgb colours[2] = {{0.95f, 0.6f, 0.25f}, {0.35f, 0.65f, 0.95f}}, wire{0.1f, 0.1f, 0.1f};
  for (int k = 0; k < 2; ++k) {
    const Panel p = enter_panel(k, 0, 2, 1, s.width, s.height);
    camera(p);
    glColor3f(colours[k].r, colours[k].g, colours[k].b);
    draw_mesh_with_edges(meshes[k], wire);
    const spline::MeshFidelity f = spline::mesh_fidelity(meshes[k], surface, tilt_degrees);
    const int last = trims ? -3 : -2;
    draw_panel_caption(p, 0, titles[k][0]);
    draw_panel_caption(p, 1, titles[k][1]);
    draw_panel_caption(p, last, std::to_string(meshes[k].triangles.size()) + " triangles");
    draw_panel_caption(p, last + 1, "max deviation " + fmt("%.2e", f.max_deviation));
    if (trims) draw_panel_caption(p, -1, "along trims " + fmt("%.2e", f.max_trim_deviation));
  }
  leave_panels(s.width, s.height);
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
