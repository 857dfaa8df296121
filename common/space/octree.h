// common/space/octree.h — the region octree of a solid (lecture notes ch. 1,
// §1.8 Space partitioning, "Octrees"): the root is a cube covering the object
// space; a cube is covered, uncovered or partly covered; a partly covered cube
// is split into eight equal children, numbered by a fixed scheme, down to the
// wanted depth. Leaves hold the state; inner nodes are the partly covered
// cubes.
//
// The numbering (Box3::child): child c has bit 0 set for the upper half in x,
// bit 1 for y, bit 2 for z, so 0 = (lo x, lo y, lo z), 1 = (hi x, lo y, lo z),
// 2 = (lo x, hi y, lo z), ..., 7 = (hi x, hi y, hi z) (Morton order).
//
// At the deepest level a cube is one voxel of the grid at n = 2^depth, and its
// state is the voxel's: the tree then holds exactly what the voxel grid holds,
// in fewer nodes wherever whole cubes are uniform. Eight children of one state
// are merged into their parent, so the tree of a solid is unique.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "space/box.h"
#include "space/voxels.h"

namespace gllab::space {

enum class Coverage : std::uint8_t { kUncovered, kCovered, kPartial };
const char* coverage_name(Coverage c);  // "uncovered", "covered", "partly covered"

struct OctreeNode {
  Coverage state;
  std::uint8_t depth;        // 0 at the root
  std::int32_t first_child;  // index of child 0 in nodes (children are consecutive), -1 for a leaf
};

class RegionOctree {
 public:
  /// From a voxel grid whose n is a power of two (depth = log2 n). Throws
  /// std::invalid_argument when n is not ("region_octree: n = 12 is not a
  /// power of two").
  static RegionOctree from_voxels(const VoxelGrid& grid);
  /// From a signed distance bound (voxels.h), to `depth` (0..10): a cube whose
  /// centre is farther from the surface than its half-diagonal is uniform
  /// and not split; a cube at `depth` takes the state of its centre. Equals
  /// from_voxels(voxelize(solid, cube, 2^depth)) node for node.
  static RegionOctree from_distance(const SignedDistance& solid, Box3 cube, int depth);

  const Box3& cube() const { return cube_; }
  int depth() const { return depth_; }
  const std::vector<OctreeNode>& nodes() const { return nodes_; }  // nodes()[0] is the root
  Box3 box(std::size_t node) const;  // the node's cube (walks from the root)
  /// Every node's cube, in nodes() order (for drawing).
  std::vector<Box3> boxes() const;

  /// Leaves by state, and inner nodes.
  std::size_t count(Coverage state) const;  // leaves of that state; kPartial: inner nodes
  std::size_t leaf_count() const;
  /// The voxels (at n = 2^depth) that covered leaves hold: 8^(depth - d) per leaf.
  std::size_t covered_voxels() const;
  /// Memory: nodes().size() * sizeof(OctreeNode).
  std::size_t bytes() const { return nodes_.size() * sizeof(OctreeNode); }
  /// Whether p lies in a covered leaf (false outside the root cube).
  bool covered(Vec3 p) const;

 private:
  Box3 cube_{};
  int depth_ = 0;
  std::vector<OctreeNode> nodes_;
  std::vector<Box3> boxes_;  // nodes_[i]'s cube (for drawing; not counted in bytes())
};

}  // namespace gllab::space
