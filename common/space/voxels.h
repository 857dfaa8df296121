// common/space/voxels.h — a regular grid of voxels and the solid
// voxelization of a closed triangle mesh (lecture notes ch. 1, §1.8 Space
// partitioning: "space is divided by a regular equidistant grid ... cube-shaped
// cells, which are called voxels"; like a CT scan).
//
// Voxelization by ray parity: for each column (i, j) a ray parallel to z
// through the voxel centres' (x, y) crosses the surface; a voxel centre is
// inside when an odd number of crossings lie below it. Why parity and not the
// generalized winding number (Jacobson et al. 2013): on a closed, consistently
// oriented mesh both give the same answer, and parity costs one 2-D
// point-in-triangle test per triangle and column (n^2 columns, each triangle
// only over the columns its shadow covers) where the winding number costs a
// solid angle per triangle and voxel (n^3 of them). The winding number's
// strength, open or self-overlapping meshes, is exactly what the voxelizer
// refuses: it checks that the mesh is closed first. A column through a shared
// edge or vertex is counted once by a tie-break rule (voxels.cpp), so
// the crossings of a closed mesh are always even.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "space/box.h"

namespace gllab::space {

/// n x n x n voxels over a cube, one bit each (x fastest). Voxel (i, j, k)
/// is the cube lo + h [i, i+1] x [j, j+1] x [k, k+1], h = edge / n.
class VoxelGrid {
 public:
  VoxelGrid() = default;
  /// Throws std::invalid_argument when n is not in 1..1024 or the box is not
  /// a cube with positive edge ("VoxelGrid: n = 0 (must be 1..1024)").
  VoxelGrid(Box3 cube, int n);

  int n() const { return n_; }
  const Box3& cube() const { return cube_; }
  double voxel_size() const { return h_; }
  Vec3 centre(int i, int j, int k) const;
  bool at(int i, int j, int k) const;
  void set(int i, int j, int k, bool solid);
  std::size_t solid_count() const;
  /// The grid's memory: one bit per voxel, rounded up to whole 64-bit words.
  std::size_t bytes() const { return words_.size() * sizeof(std::uint64_t); }
  /// The voxel holding p (clamped to the grid), or false outside the cube.
  bool contains(Vec3 p) const;

 private:
  Box3 cube_{};
  int n_ = 0;
  double h_ = 0;
  std::vector<std::uint64_t> words_;
};

/// What voxelize found besides the grid.
struct VoxelizeStats {
  std::size_t triangles = 0;           // of the mesh
  std::size_t degenerate_skipped = 0;  // zero-area triangles: skipped, counted
  std::size_t crossings = 0;           // ray-triangle crossings found, all columns
};

/// Solid voxelization of a closed mesh by ray parity (above), into the cube.
/// Throws std::invalid_argument with one line:
///  - the mesh is open: "voxelize: the mesh is not closed: edge (12, 13) has 1
///    triangle (every edge needs 2)" — the first such edge in index order;
///  - an edge is used by more than two triangles, or twice in one direction
///    (the orientation is inconsistent), named the same way;
///  - an index out of range, a non-finite position, n out of 1..1024.
VoxelGrid voxelize(const IndexedMesh& mesh, Box3 cube, int n, VoxelizeStats* stats = nullptr);

/// The first edge of the mesh that does not have exactly one partner
/// triangle running the other way, as "edge (a, b) has k triangle(s)", or ""
/// when the mesh is closed and consistently oriented.
std::string open_edge(const IndexedMesh& mesh);

/// A solid given by a signed distance bound: negative inside, positive
/// outside, and |d(x) - d(y)| <= |x - y| (1-Lipschitz; an exact signed
/// distance is one). The octree classifies whole cubes with it.
using SignedDistance = std::function<double(Vec3)>;

/// The sphere of radius r about c, and the torus about the z axis through
/// `centre` with ring radius R and tube radius r: exact signed distances.
SignedDistance sphere_distance(Vec3 centre, double r);
SignedDistance torus_distance(Vec3 centre, double R, double r);

/// A voxel is solid when its centre is inside (d < 0): the point sampling
/// of a CT scan.
VoxelGrid voxelize(const SignedDistance& solid, Box3 cube, int n);

}  // namespace gllab::space
