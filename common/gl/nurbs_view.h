// common/gl/nurbs_view.h — GLU's surface and the own tessellation drawn the
// same way, for the NURBS labs' side-by-side views.
//
// Both are lit (the caller sets the light and the colour) and pushed back a
// little (glPolygonOffset(1, 1)), so that their edges, drawn unlit on top,
// show: GLU's with GLU_OUTLINE_POLYGON, the mesh's with draw_mesh_wireframe.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "gl/glu_nurbs.h"
#include "gl/text.h"
#include "spline/tessellate.h"
#include "spline/types.h"

namespace gllab {

/// gluNurbsSurface with `properties` in the current colour. GLU_FILL is lit
/// with glEnable(GL_AUTO_NORMAL) (off: GLU sends no normals and every vertex
/// keeps the current one, set here to +z: the flat look of that mistake), then
/// the outline in `edges` if given. The outline display modes are drawn as
/// unlit lines in the current colour. GL_AUTO_NORMAL, the polygon offset and
/// lighting are as before afterwards.
void draw_glu_surface(const spline::BsplineSurface& surface, GluNurbsProperties properties, const std::string& name,
                      std::optional<Rgb> edges = std::nullopt, bool auto_normal = true);

/// How many triangles GLU makes of the surface with these properties under
/// the current matrices (capture mode, GLU_FILL): what draw_glu_surface draws.
std::size_t glu_triangle_count(const spline::BsplineSurface& surface, GluNurbsProperties properties,
                               const std::string& name);

/// The mesh lit in the current colour (draw_mesh), pushed back, and its edges.
void draw_mesh_with_edges(const spline::Mesh& mesh, Rgb edges);

}  // namespace gllab
