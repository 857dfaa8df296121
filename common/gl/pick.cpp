// common/gl/pick.cpp — the pick registry (pick.h).
#include "gl/pick.h"

#include <cmath>
#include <vector>

#include "gl/gl.h"

namespace gllab {

namespace {

struct Registry {
  bool enabled = false;
  std::vector<Pickable> items;
};

Registry& registry() {
  static Registry r;
  return r;
}

bool unproject(const Pickable& p, double x, double y, double z, spline::Vec3& out) {
  GLdouble ox = 0, oy = 0, oz = 0;
  if (gluUnProject(x, y, z, p.modelview.data(), p.projection.data(), p.viewport.data(), &ox, &oy, &oz) != GL_TRUE)
    return false;
  out = {ox, oy, oz};
  return std::isfinite(ox) && std::isfinite(oy) && std::isfinite(oz);
}

}  // namespace

void enable_picking(bool on) { registry().enabled = on; }

void clear_pickables() { registry().items.clear(); }

void register_pickable(const std::string& list, std::size_t index, const spline::Vec3& point, int dimension) {
  Registry& r = registry();
  if (!r.enabled) return;
  Pickable p;
  p.list = list;
  p.index = index;
  p.point = point;
  p.dimension = dimension;
  glGetDoublev(GL_MODELVIEW_MATRIX, p.modelview.data());
  glGetDoublev(GL_PROJECTION_MATRIX, p.projection.data());
  glGetIntegerv(GL_VIEWPORT, p.viewport.data());
  if (gluProject(point.x, point.y, point.z, p.modelview.data(), p.projection.data(), p.viewport.data(),
                 &p.window_x, &p.window_y, &p.window_z) != GL_TRUE)
    return;  // behind the eye or a singular matrix: not on screen
  r.items.push_back(std::move(p));
}

std::optional<Pickable> nearest_pickable(double x, double y, double max_pixels) {
  std::optional<Pickable> best;
  double best_distance = max_pixels;
  for (const Pickable& p : registry().items) {
    const double d = std::hypot(p.window_x - x, p.window_y - y);
    if (d <= best_distance) {  // <=: the one drawn last (on top) wins a tie
      best_distance = d;
      best = p;
    }
  }
  return best;
}

std::optional<spline::Vec3> drag_to(const Pickable& picked, double x, double y) {
  spline::Vec3 out;
  if (picked.dimension == 3) {
    if (!unproject(picked, x, y, picked.window_z, out)) return std::nullopt;
    return out;
  }
  // The mouse ray from the near to the far plane, cut with z = point.z.
  spline::Vec3 near_point, far_point;
  if (!unproject(picked, x, y, 0, near_point) || !unproject(picked, x, y, 1, far_point)) return std::nullopt;
  const double dz = far_point.z - near_point.z;
  if (std::abs(dz) < 1e-12) return std::nullopt;  // the plane is edge-on
  const double t = (picked.point.z - near_point.z) / dz;
  out = near_point + t * (far_point - near_point);
  out.z = picked.point.z;  // exactly in the plane
  return out;
}

}  // namespace gllab
