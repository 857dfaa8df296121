// common/space/octree.cpp — the region octree (octree.h).
#include "space/octree.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gllab::space {

const char* coverage_name(Coverage c) {
  switch (c) {
    case Coverage::kCovered:
      return "covered";
    case Coverage::kUncovered:
      return "uncovered";
    case Coverage::kPartial:
      return "partly covered";
  }
  return "?";
}

namespace {

/// The builder of both constructors; classify(box, depth) says kCovered or kUncovered for
/// a uniform cube, kPartial otherwise.
template <typename Classify>
void build_tree(std::vector<OctreeNode>& nodes, std::vector<Box3>& boxes, Box3 cube,
                const Classify& classify) {
  // Depth first with an explicit stack. A partly covered node reserves its eight children
  // at the end of `nodes` (consecutive); when the last of a node's children is done and all
  // eight are leaves of one state, they are the last eight nodes and are taken back.
  nodes.assign(1, {Coverage::kPartial, 0, -1});
  boxes.assign(1, cube);
  struct Frame {
    std::size_t node;
    int next;  // the next child to build; 8: done
  };
  std::vector<Frame> stack;
  const auto open = [&](std::size_t node) {
    const Coverage s = classify(boxes[node], nodes[node].depth);
    nodes[node].state = s;
    if (s != Coverage::kPartial) return false;
    nodes[node].first_child = std::int32_t(nodes.size());
    for (int c = 0; c < 8; ++c) {
      nodes.push_back({Coverage::kPartial, std::uint8_t(nodes[node].depth + 1), -1});
      boxes.push_back(boxes[node].child(c));
    }
    stack.push_back({node, 0});
    return true;
  };
  open(0);
  while (!stack.empty()) {
    Frame& f = stack.back();
    if (f.next < 8) {
      const std::size_t child = std::size_t(nodes[f.node].first_child) + std::size_t(f.next++);
      open(child);
      continue;
    }
    const std::size_t node = f.node, first = std::size_t(nodes[node].first_child);
    stack.pop_back();
    bool uniform = first + 8 == nodes.size();
    for (int c = 0; c < 8 && uniform; ++c)
      uniform = nodes[first + c].first_child < 0 && nodes[first + c].state == nodes[first].state;
    if (uniform) {  // eight leaves of one state: the node is that leaf
      nodes[node].state = nodes[first].state;
      nodes[node].first_child = -1;
      nodes.resize(first);
      boxes.resize(first);
    }
  }
}

}  // namespace

RegionOctree RegionOctree::from_voxels(const VoxelGrid& grid) {
  const int n = grid.n();
  int depth = 0;
  while ((1 << depth) < n) ++depth;
  if ((1 << depth) != n)
    throw std::invalid_argument("region_octree: n = " + std::to_string(n) +
                                " is not a power of two");
  RegionOctree t;
  t.cube_ = grid.cube();
  t.depth_ = depth;
  const double h = grid.voxel_size();
  // A cube's voxels: [i0, i0 + m)^3 from its corner. Uniform when all share one state.
  build_tree(t.nodes_, t.boxes_, t.cube_, [&](const Box3& b, int d) {
    const int m = 1 << (depth - d);
    const int i0 = int(std::lround((b.lo.x - t.cube_.lo.x) / h));
    const int j0 = int(std::lround((b.lo.y - t.cube_.lo.y) / h));
    const int k0 = int(std::lround((b.lo.z - t.cube_.lo.z) / h));
    const bool first = grid.at(i0, j0, k0);
    for (int k = k0; k < k0 + m; ++k)
      for (int j = j0; j < j0 + m; ++j)
        for (int i = i0; i < i0 + m; ++i)
          if (grid.at(i, j, k) != first) return Coverage::kPartial;
    return first ? Coverage::kCovered : Coverage::kUncovered;
  });
  return t;
}

RegionOctree RegionOctree::from_distance(const SignedDistance& solid, Box3 cube, int depth) {
  if (depth < 0 || depth > 10)
    throw std::invalid_argument("region_octree: depth " + std::to_string(depth) +
                                " (must be 0..10)");
  const Vec3 e = cube.size();
  if (!(e.x > 0) || e.x != e.y || e.x != e.z)
    throw std::invalid_argument("region_octree: the root box is not a cube with a positive edge");
  RegionOctree t;
  t.cube_ = cube;
  t.depth_ = depth;
  build_tree(t.nodes_, t.boxes_, cube, [&](const Box3& b, int d) {
    const double value = solid(b.centre());
    if (d == depth) return value < 0 ? Coverage::kCovered : Coverage::kUncovered;
    // |d(p) - d(centre)| <= |p - centre| <= half the diagonal for p in the cube.
    const double half_diagonal = norm(b.size()) / 2;
    if (value > half_diagonal) return Coverage::kUncovered;
    if (value < -half_diagonal) return Coverage::kCovered;
    return Coverage::kPartial;
  });
  return t;
}

Box3 RegionOctree::box(std::size_t node) const { return boxes_.at(node); }
std::vector<Box3> RegionOctree::boxes() const { return boxes_; }

std::size_t RegionOctree::count(Coverage state) const {
  std::size_t c = 0;
  for (const OctreeNode& n : nodes_)
    c += state == Coverage::kPartial ? n.first_child >= 0 : n.first_child < 0 && n.state == state;
  return c;
}

std::size_t RegionOctree::leaf_count() const {
  std::size_t c = 0;
  for (const OctreeNode& n : nodes_) c += n.first_child < 0;
  return c;
}

std::size_t RegionOctree::covered_voxels() const {
  std::size_t c = 0;
  for (const OctreeNode& n : nodes_)
    if (n.first_child < 0 && n.state == Coverage::kCovered)
      c += std::size_t(1) << (3 * (depth_ - n.depth));
  return c;
}

bool RegionOctree::covered(Vec3 p) const {
  if (nodes_.empty() || !cube_.contains(p)) return false;
  std::size_t i = 0;
  while (nodes_[i].first_child >= 0) {
    const Vec3 m = boxes_[i].centre();
    const int c = (p.x >= m.x) | (p.y >= m.y) << 1 | (p.z >= m.z) << 2;
    i = std::size_t(nodes_[i].first_child) + std::size_t(c);
  }
  return nodes_[i].state == Coverage::kCovered;
}

}  // namespace gllab::space
