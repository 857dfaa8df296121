// common/space/scene_octree.h — an octree over the triangles of a scene, for
// ray queries (lecture notes ch. 1, §1.8 Space partitioning, "Octrees": "the
// state of the cells ... is extended to a data structure that stores a list
// of objects, e.g. polygons, which are contained by the cell. This results in
// a significant performance increase for ... ray tracing").
//
// A cell holding more than `leaf_size` triangles is split into its eight
// children (Box3::child's numbering) while the depth allows; a triangle goes
// into every child cell it overlaps (the separating-axis test of Akenine-
// Möller 2001, "Fast 3D triangle-box overlap testing"). A ray walks the cells
// it passes front to back and stops at the first cell whose nearest hit lies
// inside it. Triangles met in two cells are tested once (a per-ray mark).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "space/box.h"

namespace gllab::space {

/// The first hit of a ray: the smallest t >= 0 over all triangles, the
/// lowest triangle index among equal t.
struct Hit {
  bool hit = false;
  double t = 0;
  std::uint32_t triangle = 0;
  double u = 0, v = 0;  // barycentric: point = (1 - u - v) a + u b + v c
};

/// What one ray query did.
struct RayStats {
  std::size_t triangles_tested = 0;
  std::size_t cells_visited = 0;  // leaves whose triangles were looked at
};

/// Ray against one triangle (Möller and Trumbore 1997), in double; both
/// sides of the triangle count. Writes t, u, v when it hits with t >= 0.
bool ray_triangle(const Ray& ray, Vec3 a, Vec3 b, Vec3 c, double& t, double& u, double& v);

/// The first hit by testing every triangle: the reference.
Hit first_hit_brute_force(const IndexedMesh& mesh, const Ray& ray, RayStats* stats = nullptr);

struct SceneOctreeOptions {
  int max_depth = 8;  // 0..12
  int leaf_size = 8;  // split a cell holding more triangles than this
};

class SceneOctree {
 public:
  /// Builds over the mesh's triangles (the mesh is copied). The root is the
  /// bounding cube of the vertices, grown by a relative 1e-9. Throws
  /// std::invalid_argument naming the value for a bad index, a non-finite
  /// position or an option out of range. Degenerate (zero-area) triangles
  /// are kept: a ray cannot hit them, as in first_hit_brute_force.
  explicit SceneOctree(const IndexedMesh& mesh, SceneOctreeOptions options = {});

  /// The same hit as first_hit_brute_force (the same t, triangle, u, v).
  Hit first_hit(const Ray& ray, RayStats* stats = nullptr) const;

  const Box3& cube() const;
  std::size_t node_count() const;
  std::size_t leaf_count() const;
  std::size_t references() const;  // triangle references in all leaves
  int depth() const;               // the deepest leaf's depth
  std::size_t bytes() const;       // nodes, references and the copied triangles
  /// The leaves' cubes (for drawing), and the leaves a ray visits, in order.
  std::vector<Box3> leaf_boxes() const;
  std::vector<Box3> visited_boxes(const Ray& ray) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace gllab::space
