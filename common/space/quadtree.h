// common/space/quadtree.h — the quadtree of a 2-D scene (lecture notes ch. 1,
// §1.8 Space partitioning, "Quadtrees": the plane's case of the octree, four
// children per inner node; "sub-division of the 2-D space until each cell
// contains maximally one object").
//
// Objects are convex polygons. A cell is split into four (Box2::child's
// numbering: 0 lower left, 1 lower right, 2 upper left, 3 upper right) while
// more than one object overlaps it (the separating-axis test, exact for
// convex shapes) and the depth allows. Objects that touch or overlap cannot
// be separated by any cell: their cells stop at max_depth and are counted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "space/box.h"

namespace gllab::space {

/// A convex polygon, counter-clockwise, at least 3 points.
using ConvexPolygon2 = std::vector<Vec2>;

/// Whether the convex polygon and the box share a point (boundaries count).
bool overlaps(const ConvexPolygon2& polygon, const Box2& box);
/// Whether p lies in the convex polygon (boundary counts).
bool contains(const ConvexPolygon2& polygon, Vec2 p);

struct QuadNode {
  Box2 box;
  int depth = 0;
  int first_child = -1;      // index of child 0 (the four are consecutive), -1 for a leaf
  std::vector<int> objects;  // leaves: the objects overlapping the cell
};

class Quadtree {
 public:
  /// Throws std::invalid_argument with one line for an object with fewer
  /// than 3 points, not convex and counter-clockwise ("quadtree: object 2 is
  /// not convex and counter-clockwise at point 3"), a non-finite point, an
  /// empty root box or max_depth outside 0..16.
  Quadtree(const std::vector<ConvexPolygon2>& objects, Box2 root, int max_depth);

  const std::vector<QuadNode>& nodes() const { return nodes_; }  // nodes()[0] is the root
  const std::vector<ConvexPolygon2>& objects() const { return objects_; }
  std::size_t leaf_count() const;
  int depth() const;  // the deepest leaf's
  /// Leaves with more than one object (only where objects touch or overlap).
  std::size_t crowded_leaves() const;
  /// The leaf holding p (the first of the children, by number, whose box
  /// holds it when p lies on a border), or -1 outside the root.
  int locate(Vec2 p) const;
  /// The object containing p, found through locate(): the lowest index among
  /// the leaf's objects that contain p, or -1. Equals the brute-force answer.
  int object_at(Vec2 p) const;

 private:
  std::vector<ConvexPolygon2> objects_;
  std::vector<QuadNode> nodes_;
};

}  // namespace gllab::space
