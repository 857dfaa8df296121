// common/gl/field_view.h — what labs 08 and 27 draw beside their scalar
// fields and is not their lesson: an iso-surface mesh through vertex arrays,
// a slice of a field coloured by value, iso-curves as lines, a plot frame.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "field/marching_squares.h"
#include "gl/text.h"
#include "harness/lab.h"
#include "mesh/indexed_mesh.h"

namespace gllab {

/// The 3D camera of the field views: ortho_fit to `half`, the headlight,
/// both sides lit (a cut or a hole shows the back faces), the orbit camera,
/// then the scene's z axis tilted 65 degrees towards the eye and turned by
/// `azimuth` degrees about it.
void field_camera(const State& s, int width, int height, double half, double azimuth = -30);

/// "1 component", "2 components": the mesh's parts connected through edges.
std::string component_text(const IndexedMesh& m);

/// The unit cube [0, 1]^3's 12 edges in grey and its corners whose bit is
/// set in `mask` as dots (corner b at (b & 1, b >> 1 & 1, b >> 2)), unlit.
void draw_unit_cell(std::uint8_t mask, Rgb corner_colour);

/// The mesh's triangles with its positions and normals as vertex arrays
/// (glDrawElements, lab 03), in the current colour; per-triangle colours
/// instead when `triangle_colours` has one Rgb per triangle (then unshared
/// corners are sent: glDrawArrays).
void draw_iso_mesh(const IndexedMesh& m, const std::vector<Rgb>& triangle_colours = {});

/// The mesh's edges as lines (unlit, `colour`), e.g. over a gluSphere.
void draw_mesh_edges(const IndexedMesh& m, Rgb colour);

/// The edges that only one triangle uses (a hole's rim, the mesh's border),
/// as lines `width` pixels wide, unlit, over everything (no depth test).
void draw_open_edges(const IndexedMesh& m, Rgb colour, float width);

/// Value v in [lo, hi] on a blue - white - red ramp (white at `mid`).
Rgb value_colour(double v, double lo, double mid, double hi);

/// The field over the rectangle [x0, x1] x [y0, y1] of the plane z = `z` as
/// n x n quads coloured by value (value_colour), unlit.
void draw_field_slice(const std::function<double(double, double)>& f, double x0, double y0,
                      double x1, double y1, double z, int n, double lo, double mid, double hi);

/// The iso-curves' segments as lines at height z, unlit, `width` pixels.
void draw_iso_curves(const field::IsoCurves& curves, double z, Rgb colour, float width);

/// The least and greatest distance of the mesh's vertices from `centre`.
std::pair<double, double> distance_range(const IndexedMesh& m, const field::Vec3& centre);

/// Axes of a plot over [x0, x1] x [y0, y1] in the current (2-D) coordinates,
/// with tick marks every `dx`, `dy` and their numbers.
void draw_plot_axes(double x0, double x1, double y0, double y1, double dx, double dy, Rgb colour);

}  // namespace gllab
