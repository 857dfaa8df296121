// common/gl/mesh_view.h — what lab 06 shows beside its polygon mesh
// (mesh/polygon_mesh.h), and is not its lesson: the normals sent to GL as
// lines, a profile's cross-section over the true curve, the indices of the
// polygons and vertices in view, and the counts its captions print.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "mesh/polygon_mesh.h"

namespace gllab {

/// Short white lines along the normals of the arrays, one per render vertex,
/// `length` long, unlit (lighting is on again afterwards).
void draw_vertex_normals(const IndexedMesh& m, float length);

/// A profile of a surface of revolution flat in the xy-plane (x = r, y = z),
/// mirrored for the left half, filled in green over the true ellipse
/// (x/a)^2 + (y/b)^2 = 1 (a fan of `samples` points) in red, so the red that
/// shows is shape the polygons miss; the profile points as dots. Centred at
/// (x, y) and scaled by `scale` under the current modelview (as it was
/// afterwards). Unlit, no depth test; the enable bits are restored. The
/// profile must be convex.
void draw_profile_section(double x, double y, double scale,
                          const std::vector<ProfilePoint>& profile, double a, double b,
                          int samples);

/// Numbers the polygons that face the eye under the current modelview (their
/// normal's eye-space z > 0): "p<k>" at the polygon's centre in light yellow,
/// and each of its vertices' indices in white just outside the corner (1.2
/// times its position, for an object centred at the origin).
void draw_mesh_numbers(const PolygonMesh& m);

/// {"<n> polygons", "<n> vertices stored", "<n> sent to GL"}: the mesh's
/// polygons and stored vertices, and the arrays' vertices.
std::vector<std::string> mesh_counts(const PolygonMesh& m, const IndexedMesh& arrays);

/// The five lines of lab 06's data_structure panel: the surfaces and their
/// polygon counts, V, E, F and V − E + F, the feature and virtual edges, the
/// polygons that use edge `edge`, and the vertices the arrays send to GL.
std::vector<std::string> data_structure_counts(const PolygonMesh& m, const IndexedMesh& arrays,
                                               std::size_t edge);

}  // namespace gllab
