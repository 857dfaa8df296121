// common/gl/ffd_view.h — what lab 29 draws beside its deformed teapot and is
// not its lesson: the lattice's lines, det J as colours with their legend,
// the camera of its panels, and the presets' lattice points. The vertex
// arrays, the lighting and the Jacobian's normals are the lesson: they are in
// the lab.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "deform/ffd.h"
#include "gl/text.h"
#include "harness/lab.h"
#include "mesh/indexed_mesh.h"

namespace gllab {

/// A cube lattice of count^3 points, Bernstein (degree count - 1) when
/// degree is 0, else a B-spline volume of that degree: the identity of the box.
deform::Lattice cube_lattice(const deform::Frame& frame, int count, int degree);

/// The lattice's control points as a lab's point list (P[(i * count + j) *
/// count + k], i along S, j along T, k along U), each moved to move(point).
std::vector<spline::Vec3> lattice_points(const deform::Lattice& lattice,
                                         const std::function<spline::Vec3(spline::Vec3)>& move);

/// The lattice with the point list's points instead of its own; throws
/// std::invalid_argument naming both counts when they differ.
deform::Lattice with_points(deform::Lattice lattice, const std::vector<spline::Vec3>& points);

/// The lines between neighbouring control points, in all three directions,
/// unlit, 1 pixel wide.
void draw_lattice_lines(const std::vector<spline::Vec3>& points, int count, Rgb colour);

/// The colour of det J: white at 1, towards blue as a volume shrinks (det J
/// 1/2 and below full blue), towards red as it grows (2 and above full red),
/// log2 scale; magenta where det J <= 0 (the lattice folds). 3 floats per
/// vertex, for glColorPointer.
std::vector<float> det_colours(const std::vector<float>& det);

/// The legend of det_colours: a bar from 1/2 to 2 with its labels and the
/// fold colour, at window pixel (x, y) from the top-left.
void draw_det_legend(int x, int y);

/// The camera of one panel: an orthographic view `half` wide round the
/// origin, the headlight with a white specular part, the orbit camera, then
/// the scene turned to be seen from `elevation` degrees above, `azimuth`
/// degrees round z, with `centre` at the middle.
void ffd_camera(const State& s, int width, int height, double half, spline::Vec3 centre,
                double elevation = 20, double azimuth = -35);

/// deform::teapot_mesh(resolution), made again only when the resolution
/// changes (the views of one frame share it).
const IndexedMesh& cached_teapot(int resolution);

/// How many vertices of two arrays of floats (3 per vertex) differ by more
/// than `tolerance` in some coordinate: the vertices a lattice moved.
std::size_t moved_vertices(const std::vector<float>& before, const std::vector<float>& after,
                           float tolerance = 1e-6f);

}  // namespace gllab
