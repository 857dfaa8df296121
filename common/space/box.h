// common/space/box.h — axis-aligned boxes and rays, shared by the voxel
// grid, the octrees, the quadtree and the BSP tree. Header only.
#pragma once

#include <algorithm>

#include "spline/vec.h"

namespace gllab::space {

using spline::Vec2;
using spline::Vec3;

struct Box3 {
  Vec3 lo, hi;
  Vec3 centre() const { return 0.5 * (lo + hi); }
  Vec3 size() const { return hi - lo; }
  bool contains(Vec3 p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  /// Child c of the octree's fixed numbering (octree.h): bit 0 of c the upper
  /// half in x, bit 1 in y, bit 2 in z.
  Box3 child(int c) const {
    const Vec3 m = centre();
    return {{c & 1 ? m.x : lo.x, c & 2 ? m.y : lo.y, c & 4 ? m.z : lo.z},
            {c & 1 ? hi.x : m.x, c & 2 ? hi.y : m.y, c & 4 ? hi.z : m.z}};
  }
};

struct Box2 {
  Vec2 lo, hi;
  Vec2 centre() const { return 0.5 * (lo + hi); }
  bool contains(Vec2 p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
  /// Child c of the quadtree's numbering: bit 0 the upper half in x, bit 1 in y
  /// (0 lower left, 1 lower right, 2 upper left, 3 upper right).
  Box2 child(int c) const {
    const Vec2 m = centre();
    return {{c & 1 ? m.x : lo.x, c & 2 ? m.y : lo.y}, {c & 1 ? hi.x : m.x, c & 2 ? hi.y : m.y}};
  }
};

/// origin + t direction, t >= 0 (direction need not be unit).
struct Ray {
  Vec3 origin, direction;
};

}  // namespace gllab::space
