// common/space/bsp.h — binary space-partitioning trees over convex polygons
// (lecture notes ch. 1, §1.8 Space partitioning, "BSP trees": a cell is split
// in two at an arbitrary plane; for visibility the space is split until each
// region holds at most one object, and the regions' order as seen from the
// viewpoint sorts the objects by depth). Fuchs, Kedem and Naylor 1980, "On
// visible surface generation by a priori tree structures".
//
// A polygon that a plane cuts is split into its front and back pieces; the
// pieces keep the polygon's id. Three rules choose the plane of a node, so
// that they can be compared:
//  - kOwnPlane: the plane of the node's first polygon (Fuchs et al.'s
//    auto-partition);
//  - kFewestSplits: among the node's polygons' planes, the one that cuts the
//    fewest polygons, ties broken by the better balance |front - back|, then
//    by the lower index;
//  - kPca: across the main axis e_1 of the PCA of the polygons' vertices
//    (pca.h; the notes' "ideal choice of dividing planes"), at the median of
//    the objects' centres along e_1 (midway between the two middle ones, so
//    that both sides get objects); e_2, then e_3 when the centres coincide
//    along e_1; the own-plane rule when they coincide along all three.
// Recursion stops when all polygons of a node share one object id: each
// leaf region then holds one object. A node keeps the polygons lying in its
// plane. Known limit: when a plane (a PCA plane that falls back to the own
// plane in the 2-D case) leaves several objects all in the node's plane,
// those objects stay together in that node, so "at most one object per
// region" is not guaranteed for every scene (it holds for lab 31's).
#pragma once

#include <cstddef>
#include <vector>

#include "space/box.h"

namespace gllab::space {

/// A convex planar polygon, counter-clockwise seen from the side its normal
/// points to. `id` names the original polygon (pieces keep it); `object` the
/// object it belongs to (the stop rule: a region holds one object).
struct Polygon3 {
  std::vector<Vec3> points;
  int id = 0;
  int object = 0;
};

/// n . x = d, n unit: front where n . x > d.
struct Plane {
  Vec3 n;
  double d;
  double distance(Vec3 p) const { return dot(n, p) - d; }
};

/// The plane of a polygon (Newell's method for the normal), or false when
/// its area is below 1e-12 times its squared extent (degenerate).
bool polygon_plane(const Polygon3& polygon, Plane& plane);
double polygon_area(const Polygon3& polygon);

/// Points within eps of the plane count as on it.
struct SplitResult {
  enum Side { kFront, kBack, kCoplanar, kSpanning } side;
  Polygon3 front, back;  // both set for kSpanning; the polygon itself on its side otherwise
};
SplitResult split_polygon(const Polygon3& polygon, const Plane& plane, double eps = 1e-9);

enum class SplitRule { kOwnPlane, kFewestSplits, kPca };
const char* split_rule_name(SplitRule rule);  // "own plane", "fewest splits", "PCA"

struct BspNode {
  Plane plane{};
  std::vector<Polygon3> on;   // polygons (pieces) in the plane; a leaf's polygons
  int front = -1, back = -1;  // children, -1 none
  bool leaf = false;          // a region with one object (its pieces in `on`)
};

struct BspStats {
  std::size_t polygons = 0;            // given
  std::size_t degenerate_skipped = 0;  // zero area or fewer than 3 points: skipped, counted
  std::size_t splits = 0;              // polygons cut in two
  std::size_t fragments = 0;           // pieces in the tree
  std::size_t nodes = 0;
  int depth = 0;  // the deepest node's (root 0)
};

class BspTree {
 public:
  /// Throws std::invalid_argument naming the polygon for a non-finite point.
  BspTree(const std::vector<Polygon3>& polygons, SplitRule rule, double eps = 1e-9);

  const std::vector<BspNode>& nodes() const { return nodes_; }  // nodes()[0] the root (if any)
  const BspStats& stats() const { return stats_; }
  /// Every piece, farthest first as seen from `eye`: at each node the far
  /// side, then the node's own polygons, then the near side (eye in the
  /// plane: either order). Drawn in this order with the depth test off,
  /// nearer pieces cover farther ones.
  std::vector<const Polygon3*> back_to_front(Vec3 eye) const;

 private:
  std::vector<BspNode> nodes_;
  BspStats stats_;
};

}  // namespace gllab::space
