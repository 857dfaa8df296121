// common/gl/morph_view.h — what lab 28 draws beside its textured morph and is
// not its lesson: the unit square placed in a panel, the grid lines of the
// in-between deformation, feature points, the fold warning, and the control
// grid as a State point list. The texture calls, the quad mesh and the blend
// are the lesson: they are in the lab.
#pragma once

#include <cstddef>
#include <vector>

#include "deform/plane.h"
#include "gl/text.h"
#include "spline/vec.h"

namespace gllab {

/// An orthographic view of the unit square [0, 1]^2 in the middle of the
/// current viewport (width x height pixels), `margin` (in square units) left
/// round it. With margin 0 in a 256 x 256 viewport or a 256-wide panel, one
/// pixel per texel of a 256 x 256 picture.
void enter_unit_square(int width, int height, double margin = 0);

/// f(t, x) = (1 - t) x + t f2(x): the notes' in-between geometry.
spline::Vec2 in_between(const deform::PlaneEvaluator& f2, double t, spline::Vec2 x);

/// The inner lines x = k / lines and y = k / lines of the square (k = 1 ..
/// lines - 1), each through 64 points carried to f(t, x): how the
/// deformation bends the plane. The border (which stays) is left out: a line
/// on a pixel boundary is drawn in the column either side of it by different
/// rasterizers. Unlit, 1 pixel wide.
void draw_deformed_grid(const deform::PlaneEvaluator& f2, double t, int lines, Rgb colour);

/// Dots at f(t, x) for each x.
void draw_moved_points(const deform::PlaneEvaluator& f2, double t,
                       const std::vector<spline::Vec2>& x, Rgb colour, float size);

/// When f folds (deform::find_plane_fold), its warning (plane_fold_text) in
/// red at the bottom of a window `height` pixels high; nothing otherwise.
void draw_fold_warning(const deform::PlaneDeformation& f, int height);

/// A count x count grid of control points as a State point list (z = 0) and
/// back: point k of the list is P[k] of the deformation.
std::vector<spline::Vec3> grid_points(const deform::PlaneDeformation& f);
deform::PlaneDeformation grid_deformation(const std::vector<spline::Vec3>& points, int count,
                                          int degree);

/// The inner (count - 2)^2 points of a count x count grid, row by row: the
/// net the mouse moves (draw_control_net), without the border on the
/// square's edges.
std::vector<spline::Vec3> inner_net(const std::vector<spline::Vec3>& points, int count);

/// The indices of the grid's inner points (not on its border), which the
/// mouse may move: the border keeps the square in place.
std::vector<std::size_t> inner_grid_points(int count);

/// The largest |f(from[k]) - to[k]|: how far f misses the feature correspondence.
double feature_miss(const deform::PlaneEvaluator& f, const std::vector<spline::Vec2>& from,
                    const std::vector<spline::Vec2>& to);

}  // namespace gllab
