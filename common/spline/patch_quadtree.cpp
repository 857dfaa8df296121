// common/spline/patch_quadtree.cpp — the (u, v) quadtree of the patch
// tessellator (patch_tessellator.h): S on the lattice, the cells, the samples
// of the patch edges, and the cell lines and vertices.
//
// A cell is split while the surface is farther than the tolerance from the
// cell's two triangles: the "sufficiently planar" test of the notes "Higher
// Order Surfaces" ("Rendering Bezier Patches"), measured the way tessellate.h
// defines the tolerance. The tree is then restricted: neighbouring leaves
// differ by at most one level (Von Herzen and Barr, "Accurate triangulations
// of deformed, intersecting surfaces", SIGGRAPH 1987), so a leaf side carries
// at most one hanging vertex. The patch edges are sampled from the edge alone,
// so two patches that share an edge share its samples. FixedSteps: a plain
// u_steps x v_steps grid of cells instead.
#include "spline/patch_tessellator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "spline/errors.h"

namespace gllab::spline::detail {

// ---- evaluation ----------------------------------------------------------------------------------

/// S(u, v) with a unit normal (see SurfaceSample).
SurfaceSample PatchTessellator::evaluate(double u, double v) const {
  SurfaceSample s = surface_(u, v);
  // The message is built only when needed: num() is slow.
  const auto finite = [](Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
  const auto require = [&](Vec3 p, const char* name) {
    if (!finite(p)) require_finite(p, "tessellate_surface: at (u, v)=(" + num(u) + ", " + num(v) + ")", name);
  };
  require(s.point, "point");
  require(s.normal, "normal");
  if (norm(s.normal) == 0) s.normal = cross(s.du, s.dv);
  if (norm(s.normal) == 0) {
    // Central differences of the point, one step inwards at the domain edge.
    const double hu = 1e-6 * (dom_.u1 - dom_.u0), hv = 1e-6 * (dom_.v1 - dom_.v0);
    const double ua = std::max(dom_.u0, u - hu), ub = std::min(dom_.u1, u + hu);
    const double va = std::max(dom_.v0, v - hv), vb = std::min(dom_.v1, v + hv);
    s.normal = cross(surface_(ub, v).point - surface_(ua, v).point, surface_(u, vb).point - surface_(u, va).point);
  }
  if (norm(s.normal) == 0) {
    // A pole (a whole edge maps to one point): the normal a little inwards.
    const double uc = (dom_.u0 + dom_.u1) / 2, vc = (dom_.v0 + dom_.v1) / 2;
    const SurfaceSample in = surface_(u + 1e-6 * (uc - u), v + 1e-6 * (vc - v));
    s.normal = norm(in.normal) > 0 ? in.normal : cross(in.du, in.dv);
  }
  require(s.normal, "normal");
  s.normal = normalized(s.normal);
  return s;
}

/// Cached S at a lattice position in quarter units.
SurfaceSample PatchTessellator::sample_q(Index i4, Index j4) {
  const std::uint64_t key = (static_cast<std::uint64_t>(i4) << 32) | static_cast<std::uint64_t>(j4);
  auto it = cache_.find(key);
  if (it == cache_.end()) it = cache_.emplace(key, evaluate(u_q(i4), v_q(j4))).first;
  return it->second;
}

// ---- cells: grid or restricted quadtree ----------------------------------------------------------

void PatchTessellator::build_grid() {
  for (Index j = 0; j < nv_; ++j)
    for (Index i = 0; i < nu_; ++i) leaves_.push_back({i, j, i + 1, j + 1});
  for (int side = 0; side < 4; ++side) {
    const Index n = side % 2 == 0 ? nu_ : nv_;
    for (Index k = 0; k <= n; ++k) edge_samples_[side].push_back(k);
  }
}

void PatchTessellator::split(int n) {
  const Node p = nodes_[n];
  const Index h = p.size / 2;
  nodes_[n].child = static_cast<int>(nodes_.size());
  nodes_.push_back({p.i0, p.j0, h, p.depth + 1});
  nodes_.push_back({p.i0 + h, p.j0, h, p.depth + 1});
  nodes_.push_back({p.i0, p.j0 + h, h, p.depth + 1});
  nodes_.push_back({p.i0 + h, p.j0 + h, h, p.depth + 1});
}

/// The deepest node of depth <= depth that contains lattice cell (i, j).
int PatchTessellator::node_at(Index i, Index j, int depth) const {
  int n = 0;
  while (nodes_[n].depth < depth && nodes_[n].child >= 0) {
    const Node& p = nodes_[n];
    const Index h = p.size / 2;
    n = p.child + (i >= p.i0 + h ? 1 : 0) + (j >= p.j0 + h ? 2 : 0);
  }
  return n;
}

/// the "sufficiently planar" test of the notes "Higher Order Surfaces", measured as the tolerance is
/// defined: S against the cell's two triangles at 11 points.
bool PatchTessellator::cell_is_flat(const Node& c) {
  const Index I = 4 * c.i0, J = 4 * c.j0, S = 4 * c.size;
  const Vec3 p00 = point_q(I, J), p10 = point_q(I + S, J), p01 = point_q(I, J + S), p11 = point_q(I + S, J + S);
  const bool diag02 = norm(p11 - p00) <= norm(p01 - p10);  // split along the shorter diagonal
  // The piecewise-linear interpolant of the two triangles at (s, t) in [0, 1]^2.
  const auto pl = [&](double s, double t) {
    if (diag02) return s >= t ? p00 + s * (p10 - p00) + t * (p11 - p10) : p00 + t * (p01 - p00) + s * (p11 - p01);
    return s + t <= 1 ? p00 + s * (p10 - p00) + t * (p01 - p00) : p11 + (1 - s) * (p01 - p11) + (1 - t) * (p10 - p11);
  };
  const double accept = kFlattenSafety * opt_.tolerance;
  static constexpr double kGrid[9][2] = {{.5, .5}, {.5, 0}, {1, .5}, {.5, 1}, {0, .5},
                                         {.25, .25}, {.75, .25}, {.25, .75}, {.75, .75}};
  for (const auto& g : kGrid) {
    const Vec3 q = point_q(I + static_cast<Index>(g[0] * S), J + static_cast<Index>(g[1] * S));
    if (norm(q - pl(g[0], g[1])) > accept) return false;
  }
  const double b[2][2] = {{diag02 ? 2 / 3.0 : 1 / 3.0, 1 / 3.0}, {diag02 ? 1 / 3.0 : 2 / 3.0, 2 / 3.0}};
  for (const auto& g : b) {
    const double u = u_q(I) + g[0] * (u_q(I + S) - u_q(I)), v = v_q(J) + g[1] * (v_q(J + S) - v_q(J));
    if (norm(evaluate(u, v).point - pl(g[0], g[1])) > accept) return false;
  }
  return true;
}

/// Splits node n until flat; `inside` lists the trim points in it. A leaf
/// holding more than kMaxTrimPointsPerLeaf of them is split too: cut cells
/// then follow the trim at its own spacing, and ear clipping does not have
/// to fan one corner to a long row of trim points (needles).
void PatchTessellator::refine(int n, const std::vector<int>& inside) {
  const Node c = nodes_[n];
  if (c.depth >= opt_.max_depth) return;
  const bool crowded = inside.size() > static_cast<std::size_t>(kMaxTrimPointsPerLeaf);
  if (c.depth >= opt_.min_depth && !crowded && cell_is_flat(c)) return;
  split(n);
  const int first = nodes_[n].child;
  const double um = u_q(4 * (c.i0 + c.size / 2)), vm = v_q(4 * (c.j0 + c.size / 2));
  std::array<std::vector<int>, 4> parts;
  for (int k : inside) parts[(trim_points_[k].x >= um ? 1 : 0) + (trim_points_[k].y >= vm ? 2 : 0)].push_back(k);
  for (int k = 0; k < 4; ++k) refine(first + k, parts[k]);
}

/// Lattice position (quarter units) at k4 quarter units along a side.
std::pair<Index, Index> PatchTessellator::side_q(int side, Index k4) const {
  switch (side) {
    case 0: return {k4, 0};
    case 1: return {4 * nu_, k4};
    case 2: return {k4, 4 * nv_};
    default: return {0, k4};
  }
}

/// Samples of one patch edge from the edge alone: bisect until the edge
/// curve is within the tolerance of its chords (parametric error, three
/// samples as in flatten_curve) and the cross-edge tangent (S_v along a
/// u-edge, S_u along a v-edge) turns little enough that a square cell on the
/// segment keeps its twist error |T(b) - T(a)| h / 4 within the tolerance.
/// Both quantities belong to the edge, so a neighbour patch computes the same.
std::vector<Index> PatchTessellator::sample_edge(int side) {
  const bool along_u = side % 2 == 0;
  const Index n = along_u ? nu_ : nv_;
  const double cross_extent = along_u ? dom_.v1 - dom_.v0 : dom_.u1 - dom_.u0;
  const double accept = kFlattenSafety * opt_.tolerance;
  auto needs_split = [&](Index k0, Index k1) {
    const auto [a0, b0] = side_q(side, 4 * k0);
    const auto [a1, b1] = side_q(side, 4 * k1);
    const SurfaceSample s0 = sample_q(a0, b0), s1 = sample_q(a1, b1);
    for (int q = 1; q <= 3; ++q) {
      const auto [aq, bq] = side_q(side, 4 * k0 + (k1 - k0) * q);
      if (norm(point_q(aq, bq) - lerp(s0.point, s1.point, q / 4.0)) > accept) return true;
    }
    const Vec3 t0 = along_u ? s0.dv : s0.du, t1 = along_u ? s1.dv : s1.du;
    const double h = cross_extent * static_cast<double>(k1 - k0) / static_cast<double>(n);
    return norm(t1 - t0) * h / 4 > accept;
  };
  std::vector<Index> ks{0};
  bisect(0, n, 0, opt_.min_depth, opt_.max_depth, needs_split, ks);
  return ks;
}

/// Does the leaf node n touch side `side` with an edge sample strictly inside its side?
bool PatchTessellator::misses_edge_sample(const Node& c, int side) const {
  const bool touches = (side == 0 && c.j0 == 0) || (side == 1 && c.i0 + c.size == nu_) ||
                       (side == 2 && c.j0 + c.size == nv_) || (side == 3 && c.i0 == 0);
  if (!touches) return false;
  const Index lo = side % 2 == 0 ? c.i0 : c.j0, hi = lo + c.size;
  const auto& s = edge_samples_[side];
  const auto it = std::upper_bound(s.begin(), s.end(), lo);
  return it != s.end() && *it < hi;
}

void PatchTessellator::grow_quadtree() {
  nodes_.push_back({0, 0, nu_, 0});
  std::vector<int> all(trim_points_.size());
  std::iota(all.begin(), all.end(), 0);
  refine(0, all);
  // Patch edges from the edge alone.
  for (int side = 0; side < 4; ++side) edge_samples_[side] = sample_edge(side);
}

/// Leaves along the patch edges split down to the edge samples, the tree
/// restricted, and the leaves listed.
void PatchTessellator::finish_quadtree() {
  std::vector<int> work;
  for (int n = 0; n < static_cast<int>(nodes_.size()); ++n)
    if (nodes_[n].child < 0) work.push_back(n);
  while (!work.empty()) {
    const int n = work.back();
    work.pop_back();
    bool must = false;
    for (int side = 0; side < 4; ++side) must = must || misses_edge_sample(nodes_[n], side);
    if (!must) continue;
    split(n);
    for (int k = 0; k < 4; ++k) work.push_back(nodes_[n].child + k);
  }
  restrict_tree();
  node_leaf_.assign(nodes_.size(), -1);
  leaf_node_.clear();
  for (int n = 0; n < static_cast<int>(nodes_.size()); ++n) {
    const Node& c = nodes_[n];
    if (c.child >= 0) continue;
    node_leaf_[n] = static_cast<int>(leaves_.size());
    leaf_node_.push_back(n);
    leaves_.push_back({c.i0, c.j0, c.i0 + c.size, c.j0 + c.size});
  }
}

/// The restricted quadtree (Von Herzen & Barr 1987): split leaves until
/// neighbours differ by at most one level, so a leaf side carries at most one
/// extra vertex (its midpoint) and the transition fans stay well shaped.
void PatchTessellator::restrict_tree() {
  std::vector<int> work;
  for (int n = 0; n < static_cast<int>(nodes_.size()); ++n)
    if (nodes_[n].child < 0) work.push_back(n);
  // Children of a node on its side facing direction d (0 -x, 1 +x, 2 -y, 3 +y).
  static constexpr int kFacing[4][2] = {{0, 2}, {1, 3}, {0, 1}, {2, 3}};
  while (!work.empty()) {
    const int n = work.back();
    work.pop_back();
    if (nodes_[n].child >= 0) continue;
    const Node c = nodes_[n];
    const Index probe[4][2] = {{c.i0 - 1, c.j0}, {c.i0 + c.size, c.j0}, {c.i0, c.j0 - 1}, {c.i0, c.j0 + c.size}};
    bool must = false;
    std::vector<int> neighbours;
    for (int d = 0; d < 4; ++d) {
      const Index pi = probe[d][0], pj = probe[d][1];
      if (pi < 0 || pj < 0 || pi >= nu_ || pj >= nv_) continue;
      const int m = node_at(pi, pj, c.depth);
      neighbours.push_back(m);
      if (nodes_[m].depth != c.depth || nodes_[m].child < 0) continue;
      // The neighbour's children facing us (d ^ 1 flips -x/+x, -y/+y).
      for (int k : kFacing[d ^ 1])
        if (nodes_[nodes_[m].child + k].child >= 0) must = true;
    }
    if (!must) continue;
    split(n);
    for (int k = 0; k < 4; ++k) work.push_back(nodes_[n].child + k);
    for (int m : neighbours)
      if (nodes_[m].child < 0 && nodes_[m].depth < c.depth) work.push_back(m);
  }
}

/// The leaf that holds lattice cell (i, j).
int PatchTessellator::leaf_at(Index i, Index j) const {
  if (!adaptive_) return static_cast<int>(j * nu_ + i);
  return node_leaf_[node_at(i, j, opt_.max_depth)];
}

// ---- lines and vertices --------------------------------------------------------------------------

void PatchTessellator::collect_lines() {
  Index step_u = nu_, step_v = nv_;
  for (const Leaf& f : leaves_) {
    step_u = std::min(step_u, f.i1 - f.i0);
    step_v = std::min(step_v, f.j1 - f.j0);
    for (Index i : {f.i0, f.i1})
      for (Index j : {f.j0, f.j1}) corners_on_vline_[i].push_back(j), corners_on_hline_[j].push_back(i);
  }
  for (auto* lines : {&corners_on_vline_, &corners_on_hline_})
    for (auto& [line, list] : *lines) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
  for (Index i = 0; i <= nu_; i += step_u) line_i_.push_back(i), line_u_.push_back(u_q(4 * i));
  for (Index j = 0; j <= nv_; j += step_v) line_j_.push_back(j), line_v_.push_back(v_q(4 * j));
}

int PatchTessellator::vertex(Vec2 uv) {
  const auto [it, added] = vertex_id_.emplace(std::make_pair(uv.x, uv.y), static_cast<int>(verts_.size()));
  if (added) verts_.push_back({uv});
  return it->second;
}

int PatchTessellator::lattice_vertex(Index i4, Index j4) {
  const int id = vertex({u_q(i4), v_q(j4)});
  verts_[id].i4 = i4, verts_[id].j4 = j4;
  return id;
}

}  // namespace gllab::spline::detail
