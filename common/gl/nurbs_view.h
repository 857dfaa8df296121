// common/gl/nurbs_view.h — GLU's surface and the own tessellation drawn the
// same way, for the NURBS labs' side-by-side views.
//
// Both are lit (the caller sets the light and the colour) and pushed back a
// little (glPolygonOffset(1, 1)), so that their edges, drawn unlit on top,
// show: GLU's with GLU_OUTLINE_POLYGON, the mesh's with draw_mesh_wireframe.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gl/glu_nurbs.h"
#include "gl/panels.h"
#include "gl/text.h"
#include "harness/lab.h"
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

/// A surface drawn by the caller's own GLU calls, twice: `draw(GLU_FILL)` in
/// the current colour and lighting, pushed back a little (glPolygonOffset(1, 1)),
/// then, when `edges` is given, `draw(GLU_OUTLINE_POLYGON)` unlit in that
/// colour on top: GLU's triangles. `draw` sets GLU_DISPLAY_MODE to its argument
/// and makes the GLU calls. GL_AUTO_NORMAL is the caller's (a lit GLU surface
/// needs it). The polygon offset, lighting and the colour are as before afterwards.
void fill_then_edges(const std::function<void(GLenum display_mode)>& draw, std::optional<Rgb> edges);

/// The (u, v) square [0, 1]^2 in the middle of `panel` (its viewport current:
/// enter_panel) with a surface's trim loops drawn by draw_trim_loops, each
/// piece in the colour of the GLU call that takes it, and that legend in the
/// panel's last three caption lines: gluPwlCurve white, gluNurbsCurve
/// GLU_MAP1_TRIM_2 green, GLU_MAP1_TRIM_3 blue. Leaves the square's matrices.
void draw_trim_domain(const Panel& panel, const std::vector<spline::TrimLoop>& loops);

/// Two meshes of one surface side by side, GLU's on the left (orange), the own
/// core's on the right (blue), each lit with its edges (draw_mesh_with_edges)
/// under the matrices `camera(panel)` sets, titled with two caption lines; below
/// each, its triangles, its largest deviation from `surface` (spline::mesh_fidelity
/// with tilt `tilt_degrees`) and, when `trims`, that along the trim loops.
void draw_mesh_pair(const State& s, const spline::SurfaceEvaluator& surface, const spline::Mesh meshes[2],
                    const std::string titles[2][2], bool trims, double tilt_degrees,
                    const std::function<void(const Panel&)>& camera);

/// The mesh lit in the current colour (draw_mesh), pushed back, and its edges.
void draw_mesh_with_edges(const spline::Mesh& mesh, Rgb edges);

}  // namespace gllab
