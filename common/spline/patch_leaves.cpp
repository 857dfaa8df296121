// common/spline/patch_leaves.cpp — each leaf's part of the trimmed region,
// and its triangles (patch_tessellator.h).
//
// In plain words (no paper): a leaf keeps the trim segments inside it and the
// stretches of its own boundary whose midpoints are inside (the winding rule);
// they are chained into loops, taking the leftmost turn where several leave a
// vertex, and ear-clipped (triangulate.cpp). A whole leaf becomes two
// triangles, or with a smaller neighbour's corner on a side a fan from its
// centre: the transition triangles of the restricted quadtree. Leaves finer
// than their segment of the patch edge get a band of thin triangles
// (lift_strip), so that the edge stays one mesh edge. The ear-clipped
// triangles are checked against the tolerance afterwards; where one misses
// it, its leaves are split and run() cuts again.
#include "spline/patch_tessellator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "spline/errors.h"

namespace gllab::spline::detail {

// ---- the leaf's part of the region ---------------------------------------------------------------

/// Vertices along one side of a leaf, in counter-clockwise order: its
/// corners, the corners of smaller neighbours (hanging vertices) and trim
/// points on the side. Every leaf sharing the side lists the same ones.
std::vector<int> PatchTessellator::side_vertices(const Leaf& f, int side) {
  const bool horizontal = side % 2 == 0;
  const Index line = side == 0 ? f.j0 : side == 1 ? f.i1 : side == 2 ? f.j1 : f.i0;
  const Index lo = horizontal ? f.i0 : f.j0, hi = horizontal ? f.i1 : f.j1;
  std::vector<std::pair<double, int>> along;  // (coordinate, id)
  const auto add_corner = [&](Index k) {
    const int id = horizontal ? corner(k, line) : corner(line, k);
    along.push_back({horizontal ? uv(id).x : uv(id).y, id});
  };
  add_corner(lo);
  const auto& corners = horizontal ? corners_on_hline_[line] : corners_on_vline_[line];
  for (auto it = std::upper_bound(corners.begin(), corners.end(), lo); it != corners.end() && *it < hi; ++it)
    add_corner(*it);
  add_corner(hi);
  if (trimmed_) {
    auto& trims = horizontal ? trim_on_hline_ : trim_on_vline_;
    const auto found = trims.find(line);
    if (found != trims.end()) {
      const double a = along.front().first, b = along.back().first;
      for (const auto& [x, id] : found->second)
        if (x > a && x < b) along.push_back({x, id});
    }
  }
  std::sort(along.begin(), along.end());
  std::vector<int> ids;
  for (const auto& [x, id] : along)
    if (ids.empty() || ids.back() != id) ids.push_back(id);
  if (side >= 2) std::reverse(ids.begin(), ids.end());
  return ids;
}

/// The boundary of (leaf ∩ trimmed region) as directed segments, region on
/// the left: the trim segments inside the leaf, plus each stretch of the
/// leaf's boundary whose midpoint is inside (winding rule). A trim segment
/// along the leaf's side is kept when it runs counter-clockwise around the
/// leaf (the region it keeps is this leaf's side) and replaces that stretch.
/// Returns true when the result is the whole leaf.
bool PatchTessellator::leaf_segments(int leaf, std::vector<Seg>& out) {
  const Leaf& f = leaves_[leaf];
  std::set<std::pair<int, int>> covered;
  bool any_trim = false;
  if (trimmed_) {
    for (const LeafTrim& t : leaf_trims_[leaf]) {
      any_trim = true;
      if (t.side < 0) {
        out.push_back(t.seg);
        continue;
      }
      covered.insert(std::minmax(t.seg.a, t.seg.b));
      const Vec2 d = uv(t.seg.b) - uv(t.seg.a);
      const bool ccw = (t.side == 0 && d.x > 0) || (t.side == 1 && d.y > 0) || (t.side == 2 && d.x < 0) ||
                       (t.side == 3 && d.y < 0);
      if (ccw) out.push_back(t.seg);
    }
  }
  std::array<std::vector<int>, 4> sides;
  bool trim_on_side = false;
  for (int s = 0; s < 4; ++s) {
    sides[s] = side_vertices(f, s);
    for (std::size_t k = 1; k + 1 < sides[s].size(); ++k) trim_on_side = trim_on_side || verts_[sides[s][k]].trim;
  }
  // No trim touches the leaf: one winding number at its centre decides.
  const bool simple = !any_trim && !trim_on_side;
  const bool keep_all = simple && inside((uv(sides[0].front()) + uv(sides[2].front())) / 2);
  if (simple && !keep_all) return false;
  for (int s = 0; s < 4; ++s)
    for (std::size_t k = 0; k + 1 < sides[s].size(); ++k) {
      const Seg g{sides[s][k], sides[s][k + 1]};
      if (covered.count(std::minmax(g.a, g.b))) continue;
      if (keep_all || inside((uv(g.a) + uv(g.b)) / 2)) out.push_back(g);
    }
  return keep_all;
}

/// Chains directed segments into closed loops. Where several segments leave
/// one vertex (a trim touching a cell side), take the leftmost turn: with
/// the region on the left, that follows one face and keeps pinched parts apart.
std::vector<std::vector<int>> PatchTessellator::link(const std::vector<Seg>& segs) const {
  std::unordered_map<int, std::vector<int>> leaving;
  for (int s = 0; s < static_cast<int>(segs.size()); ++s) leaving[segs[s].a].push_back(s);
  std::vector<char> used(segs.size(), 0);
  std::vector<std::vector<int>> loops;
  for (int s0 = 0; s0 < static_cast<int>(segs.size()); ++s0) {
    if (used[s0]) continue;
    used[s0] = 1;
    std::vector<int> loop{segs[s0].a};
    for (int cur = s0;;) {
      const int v = segs[cur].b;
      const Vec2 d_in = uv(v) - uv(segs[cur].a);
      int best = -1;
      double best_turn = -10;
      for (int s : leaving[v]) {
        if (used[s] && s != s0) continue;
        const Vec2 d_out = uv(segs[s].b) - uv(v);
        double turn = std::atan2(cross(d_in, d_out), dot(d_in, d_out));
        if (turn >= kPi) turn = -kPi;  // a U-turn only as the last resort
        if (turn > best_turn) best_turn = turn, best = s;
      }
      if (best < 0)
        throw std::logic_error("tessellate_surface: open boundary chain at (u, v)=" + num(uv(v)) +
                               " (trim clipping bug)");
      if (best == s0) break;
      used[best] = 1;
      loop.push_back(v);
      cur = best;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

/// Is vertex id a cell corner on the patch edge that is not an edge sample?
bool PatchTessellator::extra_edge_vertex(int id) const {
  const Vertex& x = verts_[id];
  if (x.trim || x.i4 < 0 || x.i4 % 4 != 0 || x.j4 % 4 != 0) return false;
  const Index i = x.i4 / 4, j = x.j4 / 4;
  const auto missing = [&](int side, Index k) {
    return !std::binary_search(edge_samples_[side].begin(), edge_samples_[side].end(), k);
  };
  return (j == 0 && missing(0, i)) || (i == nu_ && missing(1, j)) || (j == nv_ && missing(2, i)) ||
         (i == 0 && missing(3, j));
}

// ---- triangles -----------------------------------------------------------------------------------

Vec3 PatchTessellator::position(int id) {
  const Vertex& x = verts_[id];
  return x.i4 >= 0 ? point_q(x.i4, x.j4) : evaluate(x.uv.x, x.uv.y).point;
}

/// Appends the triangle a b c, turned counter-clockwise in (u, v).
void PatchTessellator::add_triangle(int a, int b, int c) {
  if (orient(uv(a), uv(b), uv(c)) < 0) std::swap(b, c);
  triangles_.push_back({a, b, c});
}

/// A whole leaf, given as its ring of vertices (counter-clockwise): four
/// corners -> two triangles along the shorter diagonal (as cell_is_flat
/// assumed); more (a smaller neighbour's corner on a side) -> a fan from
/// the centre: the transition triangles of the restricted quadtree.
void PatchTessellator::fan_or_split(const Leaf& f, const std::vector<int>& ring) {
  if (ring.size() == 4) {
    if (norm(position(ring[2]) - position(ring[0])) <= norm(position(ring[3]) - position(ring[1]))) {
      add_triangle(ring[0], ring[1], ring[2]);
      add_triangle(ring[0], ring[2], ring[3]);
    } else {
      add_triangle(ring[0], ring[1], ring[3]);
      add_triangle(ring[1], ring[2], ring[3]);
    }
    return;
  }
  const int centre = lattice_vertex(2 * (f.i0 + f.i1), 2 * (f.j0 + f.j1));
  for (std::size_t k = 0; k < ring.size(); ++k) add_triangle(centre, ring[k], ring[(k + 1) % ring.size()]);
}

/// Does leaf f touch patch side `side`?
bool PatchTessellator::touches(const Leaf& f, int side) const {
  return (side == 0 && f.j0 == 0) || (side == 1 && f.i1 == nu_) || (side == 2 && f.j1 == nv_) ||
         (side == 3 && f.i0 == 0);
}

/// Leaf f's extent along side `side` (lattice units).
std::pair<Index, Index> PatchTessellator::along(const Leaf& f, int side) const {
  return side % 2 == 0 ? std::make_pair(f.i0, f.i1) : std::make_pair(f.j0, f.j1);
}

/// Vertex at position k (lattice units) along a side, `inward` quarter units inside.
int PatchTessellator::side_vertex(int side, Index k, Index inward) {
  switch (side) {
    case 0: return lattice_vertex(4 * k, inward);
    case 1: return lattice_vertex(4 * nu_ - inward, 4 * k);
    case 2: return lattice_vertex(4 * k, 4 * nv_ - inward);
    default: return lattice_vertex(inward, 4 * k);
  }
}

/// The edge band of a strip. The patch edge keeps only its edge samples A
/// and B, but the leaves along it are smaller. Their corners E_k on the edge
/// are lifted half the smallest leaf inwards (E'_k) and a band of triangles
/// joins A B to the lifted row: (A, B, E'_m) in the middle, fans from A and
/// B to either half. Each band triangle is at most half a cell deep, so its
/// error is the edge chord's (at most kFlattenSafety tol along A B) plus a
/// quarter of a cell's cross-edge curvature term. (Without the lift, a
/// triangle on A B reaching a whole cell inwards adds both in full.)
void PatchTessellator::lift_strip(const Strip& st, std::map<int, int>& lifted) {
  Index smallest = st.hi - st.lo;
  for (int l : st.leaves) smallest = std::min(smallest, leaves_[l].i1 - leaves_[l].i0);
  const Index inward = 2 * smallest;  // half the smallest leaf, in quarter units
  std::vector<int> row;                // E'_1 .. E'_{n-1}
  for (std::size_t k = 1; k < st.leaves.size(); ++k) {
    const Index x = along(leaves_[st.leaves[k]], st.side).first;
    const int e = side_vertex(st.side, x, 0), lifted_e = side_vertex(st.side, x, inward);
    lifted[e] = lifted_e;
    row.push_back(lifted_e);
  }
  const int A = side_vertex(st.side, st.lo, 0), B = side_vertex(st.side, st.hi, 0);
  const std::size_t n = row.size(), m = n / 2;  // the middle lifted vertex: row[m]
  add_triangle(A, B, row[m]);
  for (std::size_t k = 0; k < m; ++k) add_triangle(A, row[k], row[k + 1]);
  for (std::size_t k = m; k + 1 < n; ++k) add_triangle(B, row[k], row[k + 1]);
}

void PatchTessellator::triangulate_leaves() {
  const int n = static_cast<int>(leaves_.size());
  std::vector<std::vector<Seg>> segs(n);
  std::vector<char> whole(n);
  for (int l = 0; l < n; ++l) whole[l] = leaf_segments(l, segs[l]);

  // Strips: leaves along one edge segment, when they are finer than it.
  // Strips that share a corner leaf are handled together (union-find).
  std::map<std::pair<int, Index>, Strip> strips;
  std::vector<char> in_strip(n, 0);
  UnionFind groups(leaves_.size());
  if (adaptive_) {
    for (int l = 0; l < n; ++l)
      for (int side = 0; side < 4; ++side) {
        if (!touches(leaves_[l], side)) continue;
        const auto [lo, hi] = along(leaves_[l], side);
        const auto& s = edge_samples_[side];
        const Index seg_lo = *(std::upper_bound(s.begin(), s.end(), lo) - 1);
        const Index seg_hi = *std::lower_bound(s.begin(), s.end(), hi);
        if (seg_lo == lo && seg_hi == hi) continue;
        Strip& st = strips[{side, seg_lo}];
        st.side = side, st.lo = seg_lo, st.hi = seg_hi;
        if (!st.leaves.empty()) groups.unite(l, st.leaves.front());
        st.leaves.push_back(l);
        in_strip[l] = 1;
      }
    for (auto& entry : strips) {
      // Named, not a structured binding: C++17 lambdas cannot capture those (clang rejects it).
      const int side = entry.second.side;
      std::sort(entry.second.leaves.begin(), entry.second.leaves.end(), [&](int a, int b) {
        return along(leaves_[a], side).first < along(leaves_[b], side).first;
      });
    }
  }
  std::map<int, std::vector<int>> members;
  std::map<int, std::vector<const Strip*>> strips_of;
  for (int l = 0; l < n; ++l) members[groups.find(l)].push_back(l);
  for (const auto& [key, st] : strips) strips_of[groups.find(st.leaves.front())].push_back(&st);

  const auto ring_of = [&](int l) {
    std::vector<int> ring;
    for (const Seg& g : segs[l]) ring.push_back(g.a);
    return ring;
  };
  std::vector<Vec2> pts;  // uv of every vertex, for the ear clipper
  for (const auto& [root, list] : members) {
    const bool all_whole = std::all_of(list.begin(), list.end(), [&](int l) { return whole[l] != 0; });
    if (list.size() == 1 && !in_strip[list[0]] && all_whole) {
      fan_or_split(leaves_[list[0]], ring_of(list[0]));
      continue;
    }
    if (all_whole) {
      // Untrimmed strips: the lifted band, then each leaf with its edge corners lifted.
      std::map<int, int> lifted;
      for (const Strip* st : strips_of[root]) lift_strip(*st, lifted);
      for (int l : list) {
        std::vector<int> ring = ring_of(l);
        for (int& id : ring) {
          const auto it = lifted.find(id);
          if (it != lifted.end()) id = it->second;
        }
        fan_or_split(leaves_[l], ring);
      }
      continue;
    }
    // Cut by a trim (one leaf, or a strip with a trimmed member): the union
    // of the parts — a segment and its reverse, on a side two members
    // share, cancel — chained into loops, without the cell corners on the
    // patch edge that no edge sample put there, and ear-clipped. These
    // triangles are checked against the tolerance afterwards (run()).
    std::vector<Seg> all;
    for (int l : list) all.insert(all.end(), segs[l].begin(), segs[l].end());
    if (all.empty()) continue;
    std::map<std::pair<int, int>, int> count;
    for (const Seg& g : all) ++count[{g.a, g.b}];
    std::vector<Seg> boundary;
    for (const auto& [ab, c] : count) {
      const auto rev = count.find({ab.second, ab.first});
      const int keep = c - (rev == count.end() ? 0 : rev->second);
      for (int k = 0; k < keep; ++k) boundary.push_back({ab.first, ab.second});
    }
    auto loops = link(boundary);
    for (auto& loop : loops) {
      std::vector<int> kept;
      const std::size_t m = loop.size();
      for (std::size_t k = 0; k < m; ++k) {
        const int id = loop[k];
        if (extra_edge_vertex(id) && orient(uv(loop[(k + m - 1) % m]), uv(id), uv(loop[(k + 1) % m])) == 0) continue;
        kept.push_back(id);
      }
      loop = std::move(kept);
    }
    if (pts.size() != verts_.size()) {
      pts.resize(verts_.size());
      for (std::size_t i = 0; i < verts_.size(); ++i) pts[i] = verts_[i].uv;
    }
    const std::size_t first = triangles_.size();
    triangulate_loops(pts, loops, triangles_);
    clipped_.push_back({first, triangles_.size(), list});
  }
}

// ---- the check of the ear-clipped triangles ------------------------------------------------------

/// Is triangle t within the tolerance (kFlattenSafety) at its barycentre
/// and edge midpoints? The test tessellate.h defines the tolerance by.
bool PatchTessellator::triangle_within(const std::array<int, 3>& t) {
  const Vec3 P[3] = {position(t[0]), position(t[1]), position(t[2])};
  const Vec2 Q[3] = {uv(t[0]), uv(t[1]), uv(t[2])};
  static constexpr double kW[4][3] = {{1 / 3.0, 1 / 3.0, 1 / 3.0}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
  for (const auto& w : kW) {
    const Vec2 q = clamp_uv(w[0] * Q[0] + w[1] * Q[1] + w[2] * Q[2]);
    if (norm(evaluate(q.x, q.y).point - (w[0] * P[0] + w[1] * P[1] + w[2] * P[2])) > kFlattenSafety * opt_.tolerance)
      return false;
  }
  return true;
}

/// Splits the leaves (above max_depth) whose ear-clipped triangles miss
/// the tolerance. False when none were split.
bool PatchTessellator::split_leaves_of_failing_triangles() {
  std::set<int> to_split;
  for (const Clipped& c : clipped_) {
    bool fails = false;
    for (std::size_t t = c.first; t < c.last && !fails; ++t) fails = !triangle_within(triangles_[t]);
    if (!fails) continue;
    for (int l : c.leaves)
      if (nodes_[leaf_node_[l]].depth < opt_.max_depth) to_split.insert(leaf_node_[l]);
  }
  for (int n : to_split) split(n);
  return !to_split.empty();
}

}  // namespace gllab::spline::detail
