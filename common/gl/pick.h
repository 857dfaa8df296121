// common/gl/pick.h — what the mouse can grab in the window.
//
// While display() runs, draw_control_points (spline_draw.h) registers each
// point of a State point list where it lands on screen, together with the
// matrices it was drawn under. The window runner picks the registered point
// nearest the mouse and moves it by un-projecting the mouse under those same
// matrices: picking works in any cell of a side-by-side view, and in 3D.
// Only the window runner enables it; headless, registering does nothing.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "spline/vec.h"

namespace gllab {

struct Pickable {
  std::string list;        // the State point list
  std::size_t index = 0;   // the point in it
  spline::Vec3 point;      // where it was drawn (lab coordinates)
  int dimension = 2;       // 2: moves in its plane z = point.z; 3: parallel to the screen
  double window_x = 0, window_y = 0, window_z = 0;  // GL window coordinates (y up)
  std::array<double, 16> modelview{}, projection{};
  std::array<int, 4> viewport{};
};

/// The window runner turns picking on; every frame starts with clear_pickables().
void enable_picking(bool on);
void clear_pickables();

/// Records where point `index` of `list` lands under the current GL matrices.
void register_pickable(const std::string& list, std::size_t index, const spline::Vec3& point, int dimension);

/// The pickable nearest (x, y) (window pixels, y up) within max_pixels, the
/// one drawn last when two are equally near; none when nothing is that close.
std::optional<Pickable> nearest_pickable(double x, double y, double max_pixels);

/// Where the mouse at (x, y) puts the picked point, under its matrices:
/// dimension 2 on the plane z = point.z, dimension 3 at the point's depth.
/// None when that plane is seen edge-on.
std::optional<spline::Vec3> drag_to(const Pickable& picked, double x, double y);

}  // namespace gllab
