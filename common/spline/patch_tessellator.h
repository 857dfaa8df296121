// common/spline/patch_tessellator.h — internal: not part of the core's API.
// Include it only from the tessellator's own files; labs and tests use
// tessellate.h (tessellate_surface), which this class implements.
//
// One patch, tessellated. The class holds the state of one run: the lattice,
// the cells, the vertices, the trims and the triangles. Its member functions
// are defined in parts, one file each, in the order run() uses them:
//   tessellate.cpp      run(): the steps, in order; the input checks; what
//                       a pass forgets before the next
//   patch_quadtree.cpp  S on the (u, v) lattice; cells: a grid or the
//                       restricted quadtree; patch-edge samples; lines, vertices
//   patch_trims.cpp     trims: flattened on the surface, edges refined, cut at
//                       the cell lines and given to the leaves; the inside test
//   patch_leaves.cpp    each leaf's part of the trimmed region, its triangles,
//                       and the tolerance check of the ear-clipped ones
//   patch_mesh.cpp      the mesh: points and normals, then sliver flips
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

#include "spline/tessellate.h"
#include "spline/tessellate_detail.h"
#include "spline/trim.h"

namespace gllab::spline::detail {

/// A directed boundary segment between two vertex ids.
struct Seg {
  int a, b;
};

/// A leaf cell of the quadtree (or grid): lattice corners [i0, i1] x [j0, j1].
struct Leaf {
  Index i0, j0, i1, j1;
};

/// A trim segment that lies in a leaf; side >= 0 when it runs along the
/// leaf's side 0 bottom, 1 right, 2 top, 3 left (else -1).
struct LeafTrim {
  Seg seg;
  int side;
};

/// Union-find over leaves (for merging the leaves along one edge segment).
struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

class PatchTessellator {
 public:
  PatchTessellator(const SurfaceEvaluator& surface, UvDomain domain, const TessellationOptions& options)
      : surface_(surface), dom_(domain), opt_(options), adaptive_(options.sampling == Sampling::Adaptive) {}

  Mesh run(const std::vector<TrimLoop>& trims);  // tessellate.cpp

 private:
  const SurfaceEvaluator& surface_;
  UvDomain dom_;
  TessellationOptions opt_;
  bool adaptive_;
  Index nu_ = 1, nv_ = 1;  // lattice size (cells of the finest level along u and v)

  // ---- run (tessellate.cpp) -----------------------------------------------------------

  void check_input() const;
  void reset_pass();

  // ---- evaluation (patch_quadtree.cpp) --------------------------------------------------

  /// (u, v) of a lattice position given in quarter units (4 per lattice cell),
  /// so quarter points of every cell are lattice positions too.
  double u_q(Index i4) const { return lattice_param(dom_.u0, dom_.u1, i4, 4 * nu_); }
  double v_q(Index j4) const { return lattice_param(dom_.v0, dom_.v1, j4, 4 * nv_); }

  Vec2 clamp_uv(Vec2 p) const { return {std::clamp(p.x, dom_.u0, dom_.u1), std::clamp(p.y, dom_.v0, dom_.v1)}; }

  SurfaceSample evaluate(double u, double v) const;

  /// Cached S at a lattice position in quarter units.
  std::unordered_map<std::uint64_t, SurfaceSample> cache_;
  SurfaceSample sample_q(Index i4, Index j4);
  Vec3 point_q(Index i4, Index j4) { return sample_q(i4, j4).point; }

  // ---- cells: grid or restricted quadtree (patch_quadtree.cpp) ------------------------

  struct Node {
    Index i0, j0, size;
    int depth;
    int child = -1;  // first of 4 children: SW, SE, NW, NE
  };
  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;
  std::vector<int> node_leaf_;                      // node -> leaf index (-1: inner node)
  std::vector<int> leaf_node_;                      // leaf index -> node
  std::array<std::vector<Index>, 4> edge_samples_;  // per side (0 bottom, 1 right, 2 top, 3 left), increasing

  void build_grid();
  void split(int n);
  int node_at(Index i, Index j, int depth) const;
  bool cell_is_flat(const Node& c);
  void refine(int n, const std::vector<int>& inside);
  std::pair<Index, Index> side_q(int side, Index k4) const;
  std::vector<Index> sample_edge(int side);
  bool misses_edge_sample(const Node& c, int side) const;
  void grow_quadtree();
  void finish_quadtree();
  void restrict_tree();
  int leaf_at(Index i, Index j) const;

  // ---- lines and vertices (patch_quadtree.cpp) ------------------------------------------

  /// The finest cell lines (every leaf corner lies on them): lattice indices
  /// line_i_[k] with parameters line_u_[k]; the same along v.
  std::vector<Index> line_i_, line_j_;
  std::vector<double> line_u_, line_v_;
  /// Leaf corners on each lattice line: hanging vertices are read from here.
  std::map<Index, std::vector<Index>> corners_on_vline_, corners_on_hline_;

  void collect_lines();

  struct Vertex {
    Vec2 uv;
    Index i4 = -1, j4 = -1;  // lattice position in quarter units, or -1
    bool trim = false;       // a point of the trim polygon
  };
  std::vector<Vertex> verts_;
  std::map<std::pair<double, double>, int> vertex_id_;

  int vertex(Vec2 uv);
  int lattice_vertex(Index i4, Index j4);
  int corner(Index i, Index j) { return lattice_vertex(4 * i, 4 * j); }
  Vec2 uv(int id) const { return verts_[id].uv; }

  // ---- trims (patch_trims.cpp) ------------------------------------------------------------

  bool trimmed_ = false;
  std::vector<TrimPolygon> trim_polygons_;       // validated, refined; runs along the domain edge moved out
  std::vector<std::vector<char>> trim_refined_;  // per point: added by refine_trim_edges
  std::vector<Vec2> trim_points_;                // their points inside the domain (for refine)
  std::vector<std::vector<LeafTrim>> leaf_trims_;
  /// Trim points on each lattice line, as (coordinate along the line, id).
  std::map<Index, std::vector<std::pair<double, int>>> trim_on_vline_, trim_on_hline_;
  /// Non-horizontal trim segments by finest row, for the winding number.
  std::vector<std::vector<Seg>> row_segments_;

  void prepare_trims(const std::vector<TrimLoop>& trims);
  void cut_trims();
  bool outside_domain(Vec2 p) const;
  TrimPolygon move_runs_off_domain_edge(const TrimPolygon& poly) const;
  TrimPolygon refine_trim_edges(const TrimPolygon& poly, std::vector<char>& refined);
  /// Throws when `count` trim points would pass kMaxTrimPoints (tessellate.h).
  void check_trim_points(std::size_t count) const;
  bool chord_within(Vec2 a, Vec2 b) const;
  void register_trim_polygon(const std::vector<Vec2>& poly);
  int winding_row(double y) const;
  bool inside(Vec2 p) const;

  // ---- each leaf's part of the region (patch_leaves.cpp) ----------------------------------

  std::vector<std::array<int, 3>> triangles_;
  /// Triangles [first, last) came from ear clipping the part of these leaves.
  struct Clipped {
    std::size_t first, last;
    std::vector<int> leaves;
  };
  std::vector<Clipped> clipped_;

  /// Leaves finer than their edge segment [lo, hi] on one side.
  struct Strip {
    int side;
    Index lo, hi;
    std::vector<int> leaves;  // sorted along the side
  };

  std::vector<int> side_vertices(const Leaf& f, int side);
  bool leaf_segments(int leaf, std::vector<Seg>& out);
  std::vector<std::vector<int>> link(const std::vector<Seg>& segs) const;
  bool extra_edge_vertex(int id) const;
  Vec3 position(int id);
  void add_triangle(int a, int b, int c);
  void fan_or_split(const Leaf& f, const std::vector<int>& ring);
  bool touches(const Leaf& f, int side) const;
  std::pair<Index, Index> along(const Leaf& f, int side) const;
  int side_vertex(int side, Index k, Index inward);
  void lift_strip(const Strip& st, std::map<int, int>& lifted);
  void triangulate_leaves();
  bool triangle_within(const std::array<int, 3>& t);
  bool split_leaves_of_failing_triangles();

  // ---- the mesh (patch_mesh.cpp) ----------------------------------------------------------

  Mesh assemble();
  void flip_slivers(Mesh& m);
};

}  // namespace gllab::spline::detail
