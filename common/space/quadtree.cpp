// common/space/quadtree.cpp — the quadtree of a 2-D scene (quadtree.h).
#include "space/quadtree.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace gllab::space {

bool overlaps(const ConvexPolygon2& polygon, const Box2& box) {
  // The separating-axis theorem for two convex shapes: they are disjoint exactly when
  // their projections on one of the box's axes or the polygon's edge normals are.
  double lo = 1e300, hi = -1e300, lo2 = 1e300, hi2 = -1e300;
  for (Vec2 p : polygon) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  for (Vec2 p : polygon) lo2 = std::min(lo2, p.y), hi2 = std::max(hi2, p.y);
  if (lo > box.hi.x || hi < box.lo.x || lo2 > box.hi.y || hi2 < box.lo.y) return false;
  const Vec2 corners[4] = {box.lo, {box.hi.x, box.lo.y}, box.hi, {box.lo.x, box.hi.y}};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    // Counter-clockwise: the inside is left of a -> b. All corners strictly right: apart.
    bool all_right = true;
    for (Vec2 c : corners) all_right = all_right && cross(b - a, c - a) < 0;
    if (all_right) return false;
  }
  return true;
}

bool contains(const ConvexPolygon2& polygon, Vec2 p) {
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if (cross(b - a, p - a) < 0) return false;
  }
  return true;
}

Quadtree::Quadtree(const std::vector<ConvexPolygon2>& objects, Box2 root, int max_depth)
    : objects_(objects) {
  if (max_depth < 0 || max_depth > 16)
    throw std::invalid_argument("quadtree: max_depth = " + std::to_string(max_depth) +
                                " (must be 0..16)");
  if (!(root.hi.x > root.lo.x) || !(root.hi.y > root.lo.y))
    throw std::invalid_argument("quadtree: the root box is empty");
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const ConvexPolygon2& P = objects[o];
    const std::string name = "quadtree: object " + std::to_string(o);
    if (P.size() < 3)
      throw std::invalid_argument(name + " has " + std::to_string(P.size()) +
                                  " points (at least 3)");
    for (std::size_t i = 0; i < P.size(); ++i)
      if (!std::isfinite(P[i].x) || !std::isfinite(P[i].y))
        throw std::invalid_argument(name + ": point " + std::to_string(i) + " is not finite");
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Vec2 a = P[(i + P.size() - 1) % P.size()], b = P[i], c = P[(i + 1) % P.size()];
      if (!(cross(b - a, c - b) > 0))
        throw std::invalid_argument(name + " is not convex and counter-clockwise at point " +
                                    std::to_string(i));
    }
  }
  // Depth first; a cell's four children are consecutive (reserved together).
  nodes_.push_back({root, 0, -1, {}});
  for (std::size_t o = 0; o < objects.size(); ++o)
    if (overlaps(objects[o], root)) nodes_[0].objects.push_back(int(o));
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    if (nodes_[i].objects.size() <= 1 || nodes_[i].depth >= max_depth) continue;
    const std::size_t first = nodes_.size();
    nodes_[i].first_child = int(first);
    for (int c = 0; c < 4; ++c) {
      QuadNode child{nodes_[i].box.child(c), nodes_[i].depth + 1, -1, {}};
      for (int o : nodes_[i].objects)
        if (overlaps(objects_[std::size_t(o)], child.box)) child.objects.push_back(o);
      nodes_.push_back(std::move(child));
    }
    nodes_[i].objects.clear();  // inner cells hold none; their leaves do
    for (int c = 3; c >= 0; --c) stack.push_back(first + std::size_t(c));
  }
}

std::size_t Quadtree::leaf_count() const {
  std::size_t c = 0;
  for (const QuadNode& n : nodes_) c += n.first_child < 0;
  return c;
}

int Quadtree::depth() const {
  int d = 0;
  for (const QuadNode& n : nodes_) d = std::max(d, n.depth);
  return d;
}

std::size_t Quadtree::crowded_leaves() const {
  std::size_t c = 0;
  for (const QuadNode& n : nodes_) c += n.first_child < 0 && n.objects.size() > 1;
  return c;
}

int Quadtree::locate(Vec2 p) const {
  if (!nodes_[0].box.contains(p)) return -1;
  int i = 0;
  while (nodes_[std::size_t(i)].first_child >= 0) {
    const int first = nodes_[std::size_t(i)].first_child;
    int next = first + 3;
    for (int c = 0; c < 4; ++c)
      if (nodes_[std::size_t(first + c)].box.contains(p)) {
        next = first + c;
        break;
      }
    i = next;
  }
  return i;
}

int Quadtree::object_at(Vec2 p) const {
  const int leaf = locate(p);
  if (leaf < 0) return -1;
  int best = -1;
  for (int o : nodes_[std::size_t(leaf)].objects)
    if (contains(objects_[std::size_t(o)], p) && (best < 0 || o < best)) best = o;
  return best;
}

}  // namespace gllab::space
