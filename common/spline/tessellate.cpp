// common/spline/tessellate.cpp — see tessellate.h.
//
// Reading order: curve flattening; ear clipping; then the patch tessellator,
// whose run() lists its steps in order; then welding and mesh measures.
#include "spline/tessellate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "spline/bspline.h"
#include "spline/errors.h"

namespace gllab::spline {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Lattice positions: integer k in [0, n] stands for a + (b - a) k / n. The end
/// k == n is b itself, so a patch's last sample is exactly its neighbour's first.
using Index = std::int64_t;
double lattice_param(double a, double b, Index k, Index n) {
  return k == n ? b : a + (b - a) * (static_cast<double>(k) / static_cast<double>(n));
}

/// Recursive bisection of the lattice interval [k0, k1] (notes "Higher Order Surfaces": subdivide
/// until flat enough or small enough). Appends the right end of every accepted
/// interval, so a caller that starts `out` with k0 gets all breakpoints.
template <class NeedsSplit>
void bisect(Index k0, Index k1, int depth, int min_depth, int max_depth, NeedsSplit& needs_split,
            std::vector<Index>& out) {
  if (depth < max_depth && (depth < min_depth || needs_split(k0, k1))) {
    const Index km = k0 + (k1 - k0) / 2;
    bisect(k0, km, depth + 1, min_depth, max_depth, needs_split, out);
    bisect(km, k1, depth + 1, min_depth, max_depth, needs_split, out);
  } else {
    out.push_back(k1);
  }
}

/// The error of the curve point q against the chord p0-p1 (f: q's fraction of the interval).
double chord_error(Vec3 q, Vec3 p0, Vec3 p1, double f, ChordError kind) {
  if (kind == ChordError::Parametric) return norm(q - lerp(p0, p1, f));
  const Vec3 d = p1 - p0;
  const double len2 = dot(d, d);
  const double s = len2 > 0 ? std::clamp(dot(q - p0, d) / len2, 0.0, 1.0) : 0.0;
  return norm(q - (p0 + s * d));
}

double orient(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

}  // namespace

// ---- curves ----------------------------------------------------------------------

std::vector<CurveSample> flatten_curve(const std::function<Vec3(double)>& curve, double a, double b,
                                       const FlattenOptions& options) {
  const std::string what = "flatten_curve";
  if (!curve) fail(what + ": no curve given");
  require_finite(a, what, "a");
  require_finite(b, what, "b");
  if (a > b) fail(what + ": a=" + num(a) + " > b=" + num(b));
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    fail(what + ": tolerance=" + num(options.tolerance) + " must be > 0");
  if (options.min_depth < 0 || options.min_depth > options.max_depth || options.max_depth > 30)
    fail(what + ": need 0 <= min_depth=" + std::to_string(options.min_depth) +
         " <= max_depth=" + std::to_string(options.max_depth) + " <= 30");

  const auto evaluate = [&](double t) {
    const Vec3 p = curve(t);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) require_finite(p, what, "C(" + num(t) + ")");
    return p;
  };
  if (a == b) return {{a, evaluate(a)}, {b, evaluate(b)}};

  // Points at lattice positions k / 2^max_depth, each evaluated once: the three
  // test samples of an interval become breakpoints when it is split.
  const Index n = Index{1} << options.max_depth;
  std::unordered_map<Index, Vec3> cache;
  const auto at = [&](Index k) {
    const auto it = cache.find(k);
    if (it != cache.end()) return it->second;
    const Vec3 p = evaluate(lattice_param(a, b, k, n));
    cache.emplace(k, p);
    return p;
  };
  const double accept = kFlattenSafety * options.tolerance;
  auto needs_split = [&](Index k0, Index k1) {
    const Vec3 p0 = at(k0), p1 = at(k1);
    const double t0 = lattice_param(a, b, k0, n), t1 = lattice_param(a, b, k1, n);
    for (int q = 1; q <= 3; ++q) {
      const double f = q / 4.0;
      const Index kq = k0 + (k1 - k0) * q / 4;
      const bool on_lattice = (k1 - k0) * q % 4 == 0;
      const Vec3 s = on_lattice ? at(kq) : evaluate(t0 + (t1 - t0) * f);
      if (chord_error(s, p0, p1, f, options.error) > accept) return true;
    }
    return false;
  };
  std::vector<Index> ks{0};
  bisect(0, n, 0, options.min_depth, options.max_depth, needs_split, ks);
  std::vector<CurveSample> out;
  out.reserve(ks.size());
  for (Index k : ks) out.push_back({lattice_param(a, b, k, n), at(k)});
  return out;
}

// ---- ear clipping ------------------------------------------------------------------

namespace {

/// Smallest angle (radians) of the triangle a b c.
double min_angle(Vec2 a, Vec2 b, Vec2 c) {
  const auto angle = [](Vec2 p, Vec2 q, Vec2 r) {  // at p
    return std::atan2(std::abs(cross(q - p, r - p)), dot(q - p, r - p));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

/// Joins each hole to the outer loop by a bridge (Eberly, "Triangulation by
/// Ear Clipping", §3): take the hole's rightmost point M, cast a ray towards
/// +x, find the outer edge it hits first and the visible vertex P there;
/// splice  ... P, M, (hole from M around to M), M, P ...  into the outer loop.
/// Holes are taken rightmost first, so later holes see earlier bridges.
std::vector<int> bridge_holes(const std::vector<Vec2>& pt, std::vector<int> outer, std::vector<std::vector<int>> holes) {
  const auto rightmost = [&](const std::vector<int>& loop) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < loop.size(); ++i) {
      const Vec2 p = pt[loop[i]], q = pt[loop[best]];
      if (p.x > q.x || (p.x == q.x && p.y < q.y)) best = i;
    }
    return best;
  };
  std::sort(holes.begin(), holes.end(), [&](const std::vector<int>& h1, const std::vector<int>& h2) {
    return pt[h1[rightmost(h1)]].x > pt[h2[rightmost(h2)]].x;
  });
  for (const std::vector<int>& hole : holes) {
    const std::size_t mi = rightmost(hole);
    const Vec2 m = pt[hole[mi]];
    // The nearest outer edge crossed by the ray y = m.y, x >= m.x.
    double best_x = std::numeric_limits<double>::infinity();
    std::size_t best_edge = outer.size();
    const std::size_t n = outer.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = pt[outer[i]], b = pt[outer[(i + 1) % n]];
      if ((a.y > m.y) == (b.y > m.y) && !(a.y == m.y || b.y == m.y)) continue;
      if (a.y == b.y) {  // horizontal edge on the ray: its nearer end
        if (a.y != m.y) continue;
        const double x = std::min(a.x, b.x);
        if (x >= m.x && x < best_x) best_x = x, best_edge = i;
        continue;
      }
      const double x = a.x + (m.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x >= m.x && x < best_x) best_x = x, best_edge = i;
    }
    if (best_edge == outer.size()) continue;  // not inside: cannot happen for valid input
    const Vec2 hit{best_x, m.y};
    std::size_t pi = pt[outer[best_edge]].x >= pt[outer[(best_edge + 1) % n]].x ? best_edge : (best_edge + 1) % n;
    if (pt[outer[best_edge]] == hit) pi = best_edge;
    if (pt[outer[(best_edge + 1) % n]] == hit) pi = (best_edge + 1) % n;
    // A reflex vertex inside the triangle (m, hit, P) could hide P: take the
    // one closest in angle to the ray instead.
    const Vec2 p = pt[outer[pi]];
    double best_angle = std::numeric_limits<double>::infinity(), best_dist = best_angle;
    for (std::size_t i = 0; i < n && p != hit; ++i) {
      const Vec2 r = pt[outer[i]];
      if (i == pi) continue;
      const Vec2 prev = pt[outer[(i + n - 1) % n]], next = pt[outer[(i + 1) % n]];
      if (orient(prev, r, next) > 0) continue;  // convex: cannot block
      const double s1 = orient(m, hit, r), s2 = orient(hit, p, r), s3 = orient(p, m, r);
      const bool inside = (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
      if (!inside || r.x < m.x) continue;
      const double ang = std::atan2(std::abs(r.y - m.y), r.x - m.x), dist = norm(r - m);
      if (ang < best_angle || (ang == best_angle && dist < best_dist)) best_angle = ang, best_dist = dist, pi = i;
    }
    std::vector<int> merged(outer.begin(), outer.begin() + static_cast<std::ptrdiff_t>(pi) + 1);
    for (std::size_t k = 0; k <= hole.size(); ++k) merged.push_back(hole[(mi + k) % hole.size()]);
    merged.push_back(outer[pi]);
    merged.insert(merged.end(), outer.begin() + static_cast<std::ptrdiff_t>(pi) + 1, outer.end());
    outer = std::move(merged);
  }
  return outer;
}

/// Ear clipping of one (weakly) simple counter-clockwise loop of indices into pt.
void clip_ears(const std::vector<Vec2>& pt, const std::vector<int>& loop, std::vector<std::array<int, 3>>& out) {
  std::size_t n = loop.size();
  if (n < 3) return;
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  std::vector<char> alive(n, 1);
  const auto P = [&](std::size_t i) { return pt[loop[i]]; };
  const auto convex = [&](std::size_t i) { return orient(P(prev[i]), P(i), P(next[i])) > 0; };
  // An ear: convex, and no other vertex inside or on the triangle. A vertex
  // ON an edge counts: cutting past it would leave a T-junction there.
  // Vertices at the same place as a corner (bridges, pinches) are skipped.
  const auto is_ear = [&](std::size_t i) {
    if (!convex(i)) return false;
    const Vec2 a = P(prev[i]), b = P(i), c = P(next[i]);
    for (std::size_t j = next[next[i]]; j != prev[i]; j = next[j]) {
      const Vec2 r = P(j);
      if (r == a || r == b || r == c) continue;
      if (orient(a, b, r) >= 0 && orient(b, c, r) >= 0 && orient(c, a, r) >= 0) return false;
    }
    return true;
  };
  std::vector<char> ear(n);
  std::vector<double> quality(n);
  const auto update = [&](std::size_t i) {
    ear[i] = is_ear(i);
    quality[i] = ear[i] ? min_angle(P(prev[i]), P(i), P(next[i])) : -1;
  };
  for (std::size_t i = 0; i < n; ++i) update(i);
  std::size_t start = 0;
  while (n > 3) {
    // The best ear: the one whose triangle has the largest smallest angle.
    std::size_t best = n + loop.size(), i = start;
    double best_q = -1;
    do {
      if (ear[i] && quality[i] > best_q) best_q = quality[i], best = i;
      i = next[i];
    } while (i != start);
    if (best > loop.size()) {
      // No ear (round-off in a degenerate polygon): cut the widest convex corner.
      double best_area = 0;
      i = start;
      do {
        const double area = orient(P(prev[i]), P(i), P(next[i]));
        if (area > best_area) best_area = area, best = i;
        i = next[i];
      } while (i != start);
      if (best > loop.size()) return;  // only zero-area corners left
    }
    out.push_back({loop[prev[best]], loop[best], loop[next[best]]});
    const std::size_t p = prev[best], q = next[best];
    next[p] = q, prev[q] = p, alive[best] = 0, --n;
    start = p;
    update(p);
    update(q);
  }
  if (orient(P(prev[start]), P(start), P(next[start])) > 0)
    out.push_back({loop[prev[start]], loop[start], loop[next[start]]});
}

/// Outer loop plus holes (indices into pt) -> triangles.
std::vector<std::array<int, 3>> ear_clip(const std::vector<Vec2>& pt, const std::vector<int>& outer,
                                         const std::vector<std::vector<int>>& holes) {
  std::vector<std::array<int, 3>> out;
  clip_ears(pt, holes.empty() ? outer : bridge_holes(pt, outer, holes), out);
  return out;
}

/// Signed area of a loop of indices.
double loop_area(const std::vector<Vec2>& pt, const std::vector<int>& loop) {
  double twice = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) twice += cross(pt[loop[i]], pt[loop[(i + 1) % loop.size()]]);
  return twice / 2;
}

/// Sorts loops into outer loops (counter-clockwise) with the holes
/// (clockwise) that lie in them, and ear-clips each.
void triangulate_loops(const std::vector<Vec2>& pt, const std::vector<std::vector<int>>& loops,
                       std::vector<std::array<int, 3>>& out) {
  std::vector<std::size_t> outers, holes;
  std::vector<double> area(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    area[l] = loop_area(pt, loops[l]);
    if (area[l] > 0) outers.push_back(l);
    if (area[l] < 0) holes.push_back(l);
  }
  std::vector<std::vector<std::vector<int>>> holes_of(loops.size());
  for (std::size_t h : holes) {
    // The smallest outer loop that contains a point of the hole not on it.
    std::size_t owner = loops.size();
    for (std::size_t o : outers) {
      TrimPolygon poly;
      for (int id : loops[o]) poly.push_back(pt[id]);
      bool inside = false;
      for (int id : loops[h]) {
        const Vec2 q = pt[id];
        if (std::find(poly.begin(), poly.end(), q) != poly.end()) continue;
        inside = winding_number(poly, q) != 0;
        break;
      }
      if (inside && (owner == loops.size() || area[o] < area[owner])) owner = o;
    }
    if (owner != loops.size()) holes_of[owner].push_back(loops[h]);
  }
  for (std::size_t o : outers) {
    const auto tris = ear_clip(pt, loops[o], holes_of[o]);
    out.insert(out.end(), tris.begin(), tris.end());
  }
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<std::vector<Vec2>>& loops) {
  std::vector<Vec2> pt;
  std::vector<std::vector<int>> index_loops;
  for (const auto& loop : loops) {
    std::vector<int> ids;
    for (const Vec2& p : loop) {
      require_finite(p, "triangulate_polygon", "point");
      ids.push_back(static_cast<int>(pt.size()));
      pt.push_back(p);
    }
    index_loops.push_back(std::move(ids));
  }
  if (index_loops.empty()) return {};
  const std::vector<std::vector<int>> holes(index_loops.begin() + 1, index_loops.end());
  return ear_clip(pt, index_loops[0], holes);
}

// ---- the patch tessellator --------------------------------------------------------------

namespace {

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

  Mesh run(const std::vector<TrimLoop>& trims) {
    check_input();
    nu_ = nv_ = Index{1} << opt_.max_depth;
    if (!adaptive_) nu_ = opt_.u_steps, nv_ = opt_.v_steps;
    // 1. Trims: validate, flatten curve pieces on the surface, refine edges.
    if (!trims.empty()) prepare_trims(trims);
    // 2. Cells: a fixed grid, or a quadtree refined until flat (and until no
    //    leaf holds many trim points), with patch edges sampled from the edge
    //    alone.
    if (adaptive_) {
      grow_quadtree();
    } else {
      build_grid();
    }
    for (int pass = 0;; ++pass) {
      if (adaptive_) finish_quadtree();  // restricted, leaves listed
      collect_lines();
      if (trimmed_) cut_trims();
      // 3. Each leaf's part of the trimmed region, merged along edge segments
      //    where leaves are finer than the edge samples; then triangles.
      triangulate_leaves();
      // Verify and refine: ear-clipped triangles (cut cells) were never
      // tested against the surface. Where one misses the tolerance, split its
      // leaves and cut again.
      if (!adaptive_ || !split_leaves_of_failing_triangles()) break;
      reset_pass();
    }
    // 4. Points and normals on the surface; then slivers flipped away.
    Mesh mesh = assemble();
    if (adaptive_) flip_slivers(mesh);
    return mesh;
  }

 private:
  const SurfaceEvaluator& surface_;
  UvDomain dom_;
  TessellationOptions opt_;
  bool adaptive_;
  Index nu_ = 1, nv_ = 1;  // lattice size (cells of the finest level along u and v)

  // ---- evaluation ------------------------------------------------------------------

  /// (u, v) of a lattice position given in quarter units (4 per lattice cell),
  /// so quarter points of every cell are lattice positions too.
  double u_q(Index i4) const { return lattice_param(dom_.u0, dom_.u1, i4, 4 * nu_); }
  double v_q(Index j4) const { return lattice_param(dom_.v0, dom_.v1, j4, 4 * nv_); }

  Vec2 clamp_uv(Vec2 p) const { return {std::clamp(p.x, dom_.u0, dom_.u1), std::clamp(p.y, dom_.v0, dom_.v1)}; }

  /// S(u, v) with a unit normal (see SurfaceSample).
  SurfaceSample evaluate(double u, double v) const {
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
  std::unordered_map<std::uint64_t, SurfaceSample> cache_;
  SurfaceSample sample_q(Index i4, Index j4) {
    const std::uint64_t key = (static_cast<std::uint64_t>(i4) << 32) | static_cast<std::uint64_t>(j4);
    auto it = cache_.find(key);
    if (it == cache_.end()) it = cache_.emplace(key, evaluate(u_q(i4), v_q(j4))).first;
    return it->second;
  }
  Vec3 point_q(Index i4, Index j4) { return sample_q(i4, j4).point; }

  void check_input() const {
    const std::string what = "tessellate_surface";
    if (!surface_) fail(what + ": no surface evaluator given");
    if (!std::isfinite(dom_.u0) || !std::isfinite(dom_.u1) || !std::isfinite(dom_.v0) || !std::isfinite(dom_.v1) ||
        !(dom_.u0 < dom_.u1) || !(dom_.v0 < dom_.v1))
      fail(what + ": domain " + to_string(dom_) + " is empty or not finite");
    if (adaptive_) {
      if (!(opt_.tolerance > 0) || !std::isfinite(opt_.tolerance))
        fail(what + ": tolerance=" + num(opt_.tolerance) + " must be > 0");
      if (opt_.min_depth < 0 || opt_.min_depth > opt_.max_depth || opt_.max_depth > kMaxQuadtreeDepthLimit)
        fail(what + ": need 0 <= min_depth=" + std::to_string(opt_.min_depth) + " <= max_depth=" +
             std::to_string(opt_.max_depth) + " <= " + std::to_string(kMaxQuadtreeDepthLimit));
    } else if (opt_.u_steps < 1 || opt_.v_steps < 1 || opt_.u_steps > (1 << 20) || opt_.v_steps > (1 << 20)) {
      fail(what + ": u_steps=" + std::to_string(opt_.u_steps) + ", v_steps=" + std::to_string(opt_.v_steps) +
           " (each must be 1..1048576)");
    }
  }

  // ---- cells: grid or restricted quadtree ---------------------------------------------

  struct Node {
    Index i0, j0, size;
    int depth;
    int child = -1;  // first of 4 children: SW, SE, NW, NE
  };
  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;
  std::vector<int> node_leaf_;                     // node -> leaf index (-1: inner node)
  std::vector<int> leaf_node_;                     // leaf index -> node
  std::array<std::vector<Index>, 4> edge_samples_;  // per side (0 bottom, 1 right, 2 top, 3 left), increasing

  void build_grid() {
    for (Index j = 0; j < nv_; ++j)
      for (Index i = 0; i < nu_; ++i) leaves_.push_back({i, j, i + 1, j + 1});
    for (int side = 0; side < 4; ++side) {
      const Index n = side % 2 == 0 ? nu_ : nv_;
      for (Index k = 0; k <= n; ++k) edge_samples_[side].push_back(k);
    }
  }

  void split(int n) {
    const Node p = nodes_[n];
    const Index h = p.size / 2;
    nodes_[n].child = static_cast<int>(nodes_.size());
    nodes_.push_back({p.i0, p.j0, h, p.depth + 1});
    nodes_.push_back({p.i0 + h, p.j0, h, p.depth + 1});
    nodes_.push_back({p.i0, p.j0 + h, h, p.depth + 1});
    nodes_.push_back({p.i0 + h, p.j0 + h, h, p.depth + 1});
  }

  /// The deepest node of depth <= depth that contains lattice cell (i, j).
  int node_at(Index i, Index j, int depth) const {
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
  bool cell_is_flat(const Node& c) {
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
  void refine(int n, const std::vector<int>& inside) {
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
  std::pair<Index, Index> side_q(int side, Index k4) const {
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
  std::vector<Index> sample_edge(int side) {
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
  bool misses_edge_sample(const Node& c, int side) const {
    const bool touches = (side == 0 && c.j0 == 0) || (side == 1 && c.i0 + c.size == nu_) ||
                         (side == 2 && c.j0 + c.size == nv_) || (side == 3 && c.i0 == 0);
    if (!touches) return false;
    const Index lo = side % 2 == 0 ? c.i0 : c.j0, hi = lo + c.size;
    const auto& s = edge_samples_[side];
    const auto it = std::upper_bound(s.begin(), s.end(), lo);
    return it != s.end() && *it < hi;
  }

  void grow_quadtree() {
    nodes_.push_back({0, 0, nu_, 0});
    std::vector<int> all(trim_points_.size());
    std::iota(all.begin(), all.end(), 0);
    refine(0, all);
    // Patch edges from the edge alone.
    for (int side = 0; side < 4; ++side) edge_samples_[side] = sample_edge(side);
  }

  /// Leaves along the patch edges split down to the edge samples, the tree
  /// restricted, and the leaves listed.
  void finish_quadtree() {
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
  void restrict_tree() {
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
  int leaf_at(Index i, Index j) const {
    if (!adaptive_) return static_cast<int>(j * nu_ + i);
    return node_leaf_[node_at(i, j, opt_.max_depth)];
  }

  // ---- lines and vertices ---------------------------------------------------------------

  /// The finest cell lines (every leaf corner lies on them): lattice indices
  /// line_i_[k] with parameters line_u_[k]; the same along v.
  std::vector<Index> line_i_, line_j_;
  std::vector<double> line_u_, line_v_;
  /// Leaf corners on each lattice line: hanging vertices are read from here.
  std::map<Index, std::vector<Index>> corners_on_vline_, corners_on_hline_;

  void collect_lines() {
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

  struct Vertex {
    Vec2 uv;
    Index i4 = -1, j4 = -1;  // lattice position in quarter units, or -1
    bool trim = false;       // a point of the trim polygon
  };
  std::vector<Vertex> verts_;
  std::map<std::pair<double, double>, int> vertex_id_;

  int vertex(Vec2 uv) {
    const auto [it, added] = vertex_id_.emplace(std::make_pair(uv.x, uv.y), static_cast<int>(verts_.size()));
    if (added) verts_.push_back({uv});
    return it->second;
  }
  int lattice_vertex(Index i4, Index j4) {
    const int id = vertex({u_q(i4), v_q(j4)});
    verts_[id].i4 = i4, verts_[id].j4 = j4;
    return id;
  }
  int corner(Index i, Index j) { return lattice_vertex(4 * i, 4 * j); }
  Vec2 uv(int id) const { return verts_[id].uv; }

  // ---- trims --------------------------------------------------------------------------------

  bool trimmed_ = false;
  std::vector<TrimPolygon> trim_polygons_;  // validated, refined; runs along the domain edge moved out
  std::vector<std::vector<char>> trim_refined_;  // per point: added by refine_trim_edges
  std::vector<Vec2> trim_points_;           // their points inside the domain (for refine)
  std::vector<std::vector<LeafTrim>> leaf_trims_;
  /// Trim points on each lattice line, as (coordinate along the line, id).
  std::map<Index, std::vector<std::pair<double, int>>> trim_on_vline_, trim_on_hline_;
  /// Non-horizontal trim segments by finest row, for the winding number.
  std::vector<std::vector<Seg>> row_segments_;

  static double snap(double x, const std::vector<double>& lines, double eps) {
    const auto it = std::lower_bound(lines.begin(), lines.end(), x);
    if (it != lines.end() && *it - x <= eps) return *it;
    if (it != lines.begin() && x - *(it - 1) <= eps) return *(it - 1);
    return x;
  }
  static int line_index(const std::vector<double>& lines, double x) {
    const auto it = std::lower_bound(lines.begin(), lines.end(), x);
    return it != lines.end() && *it == x ? static_cast<int>(it - lines.begin()) : -1;
  }
  /// The finest row (column) whose half-open interval [Y_k, Y_k+1) holds y.
  static int band(const std::vector<double>& lines, double y) {
    const auto k = static_cast<int>(std::upper_bound(lines.begin(), lines.end(), y) - lines.begin()) - 1;
    return std::clamp(k, 0, static_cast<int>(lines.size()) - 2);
  }

  void prepare_trims(const std::vector<TrimLoop>& trims) {
    trimmed_ = true;
    // Piece-level checks with trim.h's messages (closure, domain, curves).
    validate_trim_loops(trims, dom_, kTrimFlattenTolerance * std::max(dom_.u1 - dom_.u0, dom_.v1 - dom_.v0));

    // Curve pieces: flattened on the surface (3D chordal error), or for fixed
    // steps in (u, v) to a small fraction of a cell.
    const double cell = std::min((dom_.u1 - dom_.u0) / static_cast<double>(nu_), (dom_.v1 - dom_.v0) / static_cast<double>(nv_));
    const TrimCurveFlattener flatten_piece = [&](const BsplineCurve& c) {
      const ParamInterval d = domain(c);
      const auto uv_at = [&](double t) {
        const Vec3 p = curve_point(c, t);
        return clamp_uv({p.x, p.y});
      };
      FlattenOptions fo;
      fo.error = ChordError::Chordal;
      std::vector<CurveSample> samples;
      if (adaptive_) {
        fo.tolerance = opt_.tolerance;
        samples = flatten_curve([&](double t) { const Vec2 q = uv_at(t); return evaluate(q.x, q.y).point; }, d.a, d.b, fo);
      } else {
        fo.tolerance = 1e-3 * cell;
        samples = flatten_curve([&](double t) { const Vec2 q = uv_at(t); return Vec3{q.x, q.y, 0}; }, d.a, d.b, fo);
      }
      std::vector<Vec2> points;
      for (const CurveSample& s : samples) points.push_back(uv_at(s.t));
      return points;
    };
    const double eps_u = 1e-10 * (dom_.u1 - dom_.u0), eps_v = 1e-10 * (dom_.v1 - dom_.v0);
    const std::vector<double> edges_u{dom_.u0, dom_.u1}, edges_v{dom_.v0, dom_.v1};
    std::vector<TrimPolygon> polygons;
    for (std::size_t l = 0; l < trims.size(); ++l) {
      TrimPolygon poly = flatten_trim_loop(trims[l], flatten_piece, l);
      for (Vec2& p : poly) p = clamp_uv({snap(p.x, edges_u, eps_u), snap(p.y, edges_v, eps_v)});
      polygons.push_back(std::move(poly));
    }
    validate_trim_polygons(polygons, dom_);
    for (TrimPolygon& poly : polygons) {
      poly = move_runs_off_domain_edge(poly);
      std::vector<char> refined(poly.size(), 0);
      if (adaptive_) poly = refine_trim_edges(poly, refined);
      for (const Vec2& p : poly)
        if (!outside_domain(p)) trim_points_.push_back(p);
      trim_refined_.push_back(std::move(refined));
    }
    trim_polygons_ = std::move(polygons);
  }

  void cut_trims() {
    const double eps_u = 1e-10 * (dom_.u1 - dom_.u0), eps_v = 1e-10 * (dom_.v1 - dom_.v0);
    std::vector<TrimPolygon> polygons = trim_polygons_;
    // Cut every trim edge at the finest cell lines, so each piece lies in one
    // leaf (or on a line between two). Points within a hair of a line are moved
    // onto it first: a trim vertex at u = 0.25 on a line at 0.25000000000000006
    // would otherwise leave a sliver.
    leaf_trims_.assign(leaves_.size(), {});
    row_segments_.assign(line_v_.size(), {});  // the last: above the domain
    for (std::size_t l = 0; l < polygons.size(); ++l) {
      TrimPolygon& poly = polygons[l];
      for (Vec2& p : poly) p = {snap(p.x, line_u_, eps_u), snap(p.y, line_v_, eps_v)};
      // What made each point: the loop (kept), refinement (may go), a cell line (kept).
      constexpr char kGiven = 0, kRefined = 1, kCrossing = 2;
      std::vector<Vec2> cut;
      std::vector<char> kind;
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const Vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
        std::vector<std::pair<double, Vec2>> hits;
        if (a.x != b.x) {
          const auto lo = std::upper_bound(line_u_.begin(), line_u_.end(), std::min(a.x, b.x));
          for (auto it = lo; it != line_u_.end() && *it < std::max(a.x, b.x); ++it) {
            const double t = (*it - a.x) / (b.x - a.x);
            hits.push_back({t, {*it, snap(a.y + t * (b.y - a.y), line_v_, eps_v)}});
          }
        }
        if (a.y != b.y) {
          const auto lo = std::upper_bound(line_v_.begin(), line_v_.end(), std::min(a.y, b.y));
          for (auto it = lo; it != line_v_.end() && *it < std::max(a.y, b.y); ++it) {
            const double t = (*it - a.y) / (b.y - a.y);
            hits.push_back({t, {snap(a.x + t * (b.x - a.x), line_u_, eps_u), *it}});
          }
        }
        std::sort(hits.begin(), hits.end(), [](const auto& h1, const auto& h2) { return h1.first < h2.first; });
        cut.push_back(a);
        // A point on a cell line is a crossing, whatever made it.
        const bool on_line = line_index(line_u_, a.x) >= 0 || line_index(line_v_, a.y) >= 0;
        kind.push_back(on_line ? kCrossing : trim_refined_[l][k] ? kRefined : kGiven);
        for (const auto& h : hits) cut.push_back(h.second), kind.push_back(kCrossing);
      }
      // Drop repeats (two crossings at one corner; a point on a line). A
      // refinement point a hair from a crossing would leave a tiny trim
      // segment, and a needle on it: it lies on a straight (u, v) edge, so
      // dropping it changes nothing in (u, v); drop it when the longer chord
      // still meets the tolerance.
      std::vector<Vec2> clean;
      std::vector<char> clean_kind;
      const std::size_t n = cut.size();
      for (std::size_t k = 0; k < n; ++k) {
        if (!clean.empty() && cut[k] == clean.back()) {  // one point: a crossing if either is
          char& merged = clean_kind.back();
          merged = merged == kCrossing || kind[k] == kCrossing ? kCrossing : std::min(merged, kind[k]);
          continue;
        }
        if (adaptive_ && kind[k] == kRefined && !clean.empty()) {
          const Vec2 prev = clean.back(), next = cut[(k + 1) % n];
          const bool near_prev = clean_kind.back() == kCrossing && norm(cut[k] - prev) < 0.25 * norm(next - cut[k]);
          const bool near_next = kind[(k + 1) % n] == kCrossing && norm(next - cut[k]) < 0.25 * norm(cut[k] - prev);
          if ((near_prev || near_next) && chord_within(prev, next)) continue;
        }
        clean.push_back(cut[k]);
        clean_kind.push_back(kind[k]);
      }
      while (clean.size() > 1 && clean.back() == clean.front()) clean.pop_back();
      register_trim_polygon(clean);
    }
    for (auto* lines : {&trim_on_vline_, &trim_on_hline_})
      for (auto& [line, list] : *lines) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
      }
  }

  bool outside_domain(Vec2 p) const { return p.x < dom_.u0 || p.x > dom_.u1 || p.y < dom_.v0 || p.y > dom_.v1; }

  /// Trim edges that run along the domain's edge only repeat it (the Red
  /// Book's outer loop is the domain square). Each maximal run of such edges,
  /// p_i ... p_j, is replaced by a detour outside the domain: p_i, p_i', ...,
  /// p_j', p_j, every point pushed out by the domain's size. Inside the domain
  /// the winding numbers, hence the trimmed region, are unchanged; but no trim
  /// point is left on the patch edge except where a loop really leaves it, so
  /// the edge keeps its own samples (and stays crack-free).
  TrimPolygon move_runs_off_domain_edge(const TrimPolygon& poly) const {
    const double push = std::max(dom_.u1 - dom_.u0, dom_.v1 - dom_.v0);
    // Bit k of sides(p): p lies on side k (0 bottom, 1 right, 2 top, 3 left).
    const auto sides = [&](Vec2 p) {
      return (p.y == dom_.v0 ? 1 : 0) | (p.x == dom_.u1 ? 2 : 0) | (p.y == dom_.v1 ? 4 : 0) | (p.x == dom_.u0 ? 8 : 0);
    };
    const auto pushed = [&](Vec2 p, int run_sides) {
      if (run_sides & 1) p.y -= push;
      if (run_sides & 2) p.x += push;
      if (run_sides & 4) p.y += push;
      if (run_sides & 8) p.x -= push;
      return p;
    };
    const std::size_t n = poly.size();
    std::vector<int> run(n);  // run[k]: the side bits edge k (poly[k] -> poly[k+1]) runs along
    bool any_run = false, all_run = true;
    for (std::size_t k = 0; k < n; ++k) {
      run[k] = sides(poly[k]) & sides(poly[(k + 1) % n]);
      any_run = any_run || run[k];
      all_run = all_run && run[k];
    }
    if (!any_run) return poly;
    TrimPolygon out;
    if (all_run) {
      for (std::size_t k = 0; k < n; ++k) out.push_back(pushed(poly[k], run[(k + n - 1) % n] | run[k]));
      return out;
    }
    // Start after a run ends, so that runs are not cut in two by the wrap-around.
    std::size_t start = 0;
    while (!(run[(start + n - 1) % n] == 0)) ++start;
    for (std::size_t s = 0; s < n; ++s) {
      const std::size_t k = (start + s) % n, prev = (k + n - 1) % n;
      const Vec2 p = poly[k];
      const bool ends_run = run[prev] != 0, starts_run = run[k] != 0;
      if (ends_run && starts_run) {
        out.push_back(pushed(p, run[prev] | run[k]));  // inside a run: only the detour
      } else if (starts_run) {
        out.push_back(p);
        out.push_back(pushed(p, run[k]));
      } else if (ends_run) {
        out.push_back(pushed(p, run[prev]));
        out.push_back(p);
      } else {
        out.push_back(p);
      }
    }
    return out;
  }

  /// Splits each trim edge until its image on the surface is within the
  /// tolerance (parametric error): GLU leaves gluPwlCurve edges alone and fans
  /// slivers across the trimmed region (docs/glu.md); this is the fix.
  TrimPolygon refine_trim_edges(const TrimPolygon& poly, std::vector<char>& refined) {
    TrimPolygon out;
    refined.clear();
    FlattenOptions fo;
    fo.tolerance = opt_.tolerance;
    fo.error = ChordError::Parametric;
    fo.min_depth = 0;
    fo.max_depth = opt_.max_depth;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
      out.push_back(a);
      refined.push_back(0);
      if (outside_domain(a) || outside_domain(b)) continue;  // a detour of move_runs_off_domain_edge
      const auto at = [&](double s) { return clamp_uv(a + s * (b - a)); };
      const auto samples = flatten_curve([&](double s) { const Vec2 q = at(s); return evaluate(q.x, q.y).point; }, 0, 1, fo);
      for (std::size_t i = 1; i + 1 < samples.size(); ++i) out.push_back(at(samples[i].t)), refined.push_back(1);
    }
    return out;
  }

  /// Is the chord a-b (a straight (u, v) segment) within the tolerance on the
  /// surface? The parametric test of flatten_curve at 1/4, 1/2, 3/4.
  bool chord_within(Vec2 a, Vec2 b) const {
    const Vec3 pa = evaluate(a.x, a.y).point, pb = evaluate(b.x, b.y).point;
    for (double f : {0.25, 0.5, 0.75}) {
      const Vec2 q = clamp_uv(a + f * (b - a));
      if (norm(evaluate(q.x, q.y).point - lerp(pa, pb, f)) > kFlattenSafety * opt_.tolerance) return false;
    }
    return true;
  }

  /// Gives each cut trim segment to the leaf it lies in (both leaves when it
  /// runs along the line between them), and records trim points on lines.
  void register_trim_polygon(const std::vector<Vec2>& poly) {
    std::vector<int> ids;
    for (const Vec2& p : poly) {
      const int id = vertex(p);
      verts_[id].trim = true;
      ids.push_back(id);
      if (outside_domain(p)) continue;  // on a detour (move_runs_off_domain_edge)
      const int vi = line_index(line_u_, p.x), hj = line_index(line_v_, p.y);
      if (vi >= 0) trim_on_vline_[line_i_[vi]].push_back({p.y, id});
      if (hj >= 0) trim_on_hline_[line_j_[hj]].push_back({p.x, id});
    }
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const Seg s{ids[k], ids[(k + 1) % ids.size()]};
      const Vec2 p = uv(s.a), q = uv(s.b), m = (p + q) / 2;
      // Rays from the domain go towards +u: they meet detours right of it
      // too, and a ray along the top edge v = v1 meets those above it.
      if (m.y < dom_.v0) continue;
      if (p.y != q.y) row_segments_[winding_row(m.y)].push_back(s);
      if (outside_domain(m)) continue;
      const int row = band(line_v_, m.y);
      const int vi = p.x == q.x ? line_index(line_u_, p.x) : -1;
      const int hj = p.y == q.y ? line_index(line_v_, p.y) : -1;
      const int col = band(line_u_, m.x);
      const Index ci = line_i_[col], rj = line_j_[row];
      if (vi >= 0) {
        const Index li = line_i_[vi];
        const int left = li > 0 ? leaf_at(li - 1, rj) : -1, right = li < nu_ ? leaf_at(li, rj) : -1;
        if (left == right) {
          leaf_trims_[left].push_back({s, -1});
        } else {
          if (left >= 0) leaf_trims_[left].push_back({s, 1});
          if (right >= 0) leaf_trims_[right].push_back({s, 3});
        }
      } else if (hj >= 0) {
        const Index lj = line_j_[hj];
        const int below = lj > 0 ? leaf_at(ci, lj - 1) : -1, above = lj < nv_ ? leaf_at(ci, lj) : -1;
        if (below == above) {
          leaf_trims_[below].push_back({s, -1});
        } else {
          if (below >= 0) leaf_trims_[below].push_back({s, 2});
          if (above >= 0) leaf_trims_[above].push_back({s, 0});
        }
      } else {
        leaf_trims_[leaf_at(ci, rj)].push_back({s, -1});
      }
    }
  }

  /// Rows of the winding buckets: the finest rows, and one more above v1.
  int winding_row(double y) const {
    return y > dom_.v1 || y == dom_.v1 ? static_cast<int>(line_v_.size()) - 1 : band(line_v_, y);
  }

  /// The winding rule of trim.h (inside_trimmed), reading only the trim
  /// segments of p's row: they are cut at every row line, so no other
  /// segment can cross the ray from p.
  bool inside(Vec2 p) const {
    if (!trimmed_) return true;
    int w = 0;
    for (const Seg& s : row_segments_[winding_row(p.y)]) w += edge_winding(uv(s.a), uv(s.b), p);
    return w > 0;
  }

  // ---- each leaf's part of the region ------------------------------------------------

  /// Vertices along one side of a leaf, in counter-clockwise order: its
  /// corners, the corners of smaller neighbours (hanging vertices) and trim
  /// points on the side. Every leaf sharing the side lists the same ones.
  std::vector<int> side_vertices(const Leaf& f, int side) {
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
  bool leaf_segments(int leaf, std::vector<Seg>& out) {
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
  std::vector<std::vector<int>> link(const std::vector<Seg>& segs) const {
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
  bool extra_edge_vertex(int id) const {
    const Vertex& x = verts_[id];
    if (x.trim || x.i4 < 0 || x.i4 % 4 != 0 || x.j4 % 4 != 0) return false;
    const Index i = x.i4 / 4, j = x.j4 / 4;
    const auto missing = [&](int side, Index k) {
      return !std::binary_search(edge_samples_[side].begin(), edge_samples_[side].end(), k);
    };
    return (j == 0 && missing(0, i)) || (i == nu_ && missing(1, j)) || (j == nv_ && missing(2, i)) ||
           (i == 0 && missing(3, j));
  }

  std::vector<std::array<int, 3>> triangles_;
  /// Triangles [first, last) came from ear clipping the part of these leaves.
  struct Clipped {
    std::size_t first, last;
    std::vector<int> leaves;
  };
  std::vector<Clipped> clipped_;

  /// Is triangle t within the tolerance (kFlattenSafety) at its barycentre
  /// and edge midpoints? The test tessellate.h defines the tolerance by.
  bool triangle_within(const std::array<int, 3>& t) {
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
  bool split_leaves_of_failing_triangles() {
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

  /// Forgets everything a pass built from the leaves (not the tree, the
  /// trims or the surface samples).
  void reset_pass() {
    leaves_.clear();
    line_i_.clear(), line_j_.clear(), line_u_.clear(), line_v_.clear();
    corners_on_vline_.clear(), corners_on_hline_.clear();
    verts_.clear(), vertex_id_.clear();
    leaf_trims_.clear(), trim_on_vline_.clear(), trim_on_hline_.clear(), row_segments_.clear();
    triangles_.clear(), clipped_.clear();
  }

  Vec3 position(int id) {
    const Vertex& x = verts_[id];
    return x.i4 >= 0 ? point_q(x.i4, x.j4) : evaluate(x.uv.x, x.uv.y).point;
  }

  /// Appends the triangle a b c, turned counter-clockwise in (u, v).
  void add_triangle(int a, int b, int c) {
    if (orient(uv(a), uv(b), uv(c)) < 0) std::swap(b, c);
    triangles_.push_back({a, b, c});
  }

  /// A whole leaf, given as its ring of vertices (counter-clockwise): four
  /// corners -> two triangles along the shorter diagonal (as cell_is_flat
  /// assumed); more (a smaller neighbour's corner on a side) -> a fan from
  /// the centre: the transition triangles of the restricted quadtree.
  void fan_or_split(const Leaf& f, const std::vector<int>& ring) {
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

  /// Does leaf f touch patch side `side`? Its extent along that side.
  bool touches(const Leaf& f, int side) const {
    return (side == 0 && f.j0 == 0) || (side == 1 && f.i1 == nu_) || (side == 2 && f.j1 == nv_) ||
           (side == 3 && f.i0 == 0);
  }
  std::pair<Index, Index> along(const Leaf& f, int side) const {
    return side % 2 == 0 ? std::make_pair(f.i0, f.i1) : std::make_pair(f.j0, f.j1);
  }
  /// Vertex at position k (lattice units) along a side, `inward` quarter units inside.
  int side_vertex(int side, Index k, Index inward) {
    switch (side) {
      case 0: return lattice_vertex(4 * k, inward);
      case 1: return lattice_vertex(4 * nu_ - inward, 4 * k);
      case 2: return lattice_vertex(4 * k, 4 * nv_ - inward);
      default: return lattice_vertex(inward, 4 * k);
    }
  }

  /// Leaves finer than their edge segment [lo, hi] on one side.
  struct Strip {
    int side;
    Index lo, hi;
    std::vector<int> leaves;  // sorted along the side
  };

  /// The edge band of a strip. The patch edge keeps only its edge samples A
  /// and B, but the leaves along it are smaller. Their corners E_k on the edge
  /// are lifted half the smallest leaf inwards (E'_k) and a band of triangles
  /// joins A B to the lifted row: (A, B, E'_m) in the middle, fans from A and
  /// B to either half. Each band triangle is at most half a cell deep, so its
  /// error is the edge chord's (at most kFlattenSafety tol along A B) plus a
  /// quarter of a cell's cross-edge curvature term. (Without the lift, a
  /// triangle on A B reaching a whole cell inwards adds both in full.)
  void lift_strip(const Strip& st, std::map<int, int>& lifted) {
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

  void triangulate_leaves() {
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
      for (auto& [key, st] : strips)
        std::sort(st.leaves.begin(), st.leaves.end(), [&](int a, int b) {
          return along(leaves_[a], st.side).first < along(leaves_[b], st.side).first;
        });
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

  // ---- the mesh ----------------------------------------------------------------------------

  /// Edge flips against slivers (Lawson's edge swapping, 1977, with the
  /// smallest angle as the measure). Where a trim line runs close to a cell
  /// line, the cut cells leave needle triangles; the edge between such a
  /// needle and its neighbour is flipped when that raises the smaller of the
  /// two triangles' smallest angles (in 3D), both new triangles stay counter-
  /// clockwise in (u, v), and they still meet the tolerance (at their
  /// barycentres and the new edge's midpoint). Trim edges and patch edges are
  /// boundary edges of the mesh, so they are never flipped.
  void flip_slivers(Mesh& m) {
    const auto key = [](int a, int b) {
      return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
    };
    std::unordered_map<std::uint64_t, std::array<int, 2>> faces;  // edge -> up to two triangles
    const auto attach = [&](int t) {
      for (int k = 0; k < 3; ++k) {
        auto& f = faces.try_emplace(key(m.triangles[t][k], m.triangles[t][(k + 1) % 3]), std::array<int, 2>{-1, -1}).first->second;
        (f[0] < 0 ? f[0] : f[1]) = t;
      }
    };
    const auto detach = [&](int t) {
      for (int k = 0; k < 3; ++k) {
        auto& f = faces[key(m.triangles[t][k], m.triangles[t][(k + 1) % 3])];
        if (f[0] == t) f[0] = f[1];
        f[1] = -1;
      }
    };
    const auto smallest_angle = [&](int a, int b, int c) {
      const Vec3 P[3] = {m.positions[a], m.positions[b], m.positions[c]};
      double least = kPi;
      for (int k = 0; k < 3; ++k) {
        const Vec3 e1 = P[(k + 1) % 3] - P[k], e2 = P[(k + 2) % 3] - P[k];
        least = std::min(least, std::atan2(norm(cross(e1, e2)), dot(e1, e2)));
      }
      return least;
    };
    const double accept = kFlattenSafety * opt_.tolerance;
    const auto within = [&](std::initializer_list<int> ids) {
      Vec2 q;
      Vec3 p;
      for (int id : ids) q += m.uv[id] / static_cast<double>(ids.size()), p += m.positions[id] / static_cast<double>(ids.size());
      return norm(evaluate(q.x, q.y).point - p) <= accept;
    };
    const int n = static_cast<int>(m.triangles.size());
    std::vector<std::uint64_t> work;
    for (int t = 0; t < n; ++t) {
      const auto& tri = m.triangles[t];
      if (smallest_angle(tri[0], tri[1], tri[2]) < kSliverAngle)
        for (int k = 0; k < 3; ++k) work.push_back(key(tri[k], tri[(k + 1) % 3]));
    }
    if (work.empty()) return;
    faces.reserve(3 * m.triangles.size() / 2 + 16);
    for (int t = 0; t < n; ++t) attach(t);
    for (std::size_t budget = 4 * m.triangles.size() + 16; !work.empty() && budget > 0; --budget) {
      const std::uint64_t e = work.back();
      work.pop_back();
      const auto it = faces.find(e);
      if (it == faces.end() || it->second[1] < 0) continue;  // a boundary edge
      const int t1 = it->second[0], t2 = it->second[1];
      // t1 = (a, b, c) with a -> b; t2 runs b -> a and has d opposite.
      int k1 = 0;
      while (key(m.triangles[t1][k1], m.triangles[t1][(k1 + 1) % 3]) != e) ++k1;
      const int a = m.triangles[t1][k1], b = m.triangles[t1][(k1 + 1) % 3], c = m.triangles[t1][(k1 + 2) % 3];
      int d = -1;
      for (int k = 0; k < 3; ++k)
        if (m.triangles[t2][k] != a && m.triangles[t2][k] != b) d = m.triangles[t2][k];
      if (orient(m.uv[a], m.uv[d], m.uv[c]) <= 0 || orient(m.uv[d], m.uv[b], m.uv[c]) <= 0) continue;  // not convex
      const double before = std::min(smallest_angle(a, b, c), smallest_angle(b, a, d));
      const double after = std::min(smallest_angle(a, d, c), smallest_angle(d, b, c));
      if (after <= before * (1 + 1e-9)) continue;
      if (!within({c, d}) || !within({a, d, c}) || !within({d, b, c})) continue;
      detach(t1), detach(t2);
      faces.erase(e);
      m.triangles[t1] = {a, d, c};
      m.triangles[t2] = {d, b, c};
      attach(t1), attach(t2);
      for (const auto& [p, q] : {std::pair{a, d}, std::pair{d, b}, std::pair{b, c}, std::pair{c, a}}) work.push_back(key(p, q));
    }
  }

  Mesh assemble() {
    Mesh mesh;
    std::vector<int> index(verts_.size(), -1);
    for (const auto& t : triangles_) {
      std::array<int, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        const int id = t[k];
        if (index[id] < 0) {
          const Vertex& x = verts_[id];
          const SurfaceSample s = x.i4 >= 0 ? sample_q(x.i4, x.j4) : evaluate(x.uv.x, x.uv.y);
          index[id] = static_cast<int>(mesh.positions.size());
          mesh.positions.push_back(s.point);
          mesh.normals.push_back(s.normal);
          mesh.uv.push_back(x.uv);
        }
        tri[k] = index[id];
      }
      mesh.triangles.push_back(tri);
    }
    return mesh;
  }
};

}  // namespace

TessellationOptions TessellationOptions::adaptive(double tolerance) {
  TessellationOptions o;
  o.sampling = Sampling::Adaptive;
  o.tolerance = tolerance;
  return o;
}

TessellationOptions TessellationOptions::fixed_steps(int u_steps, int v_steps) {
  TessellationOptions o;
  o.sampling = Sampling::FixedSteps;
  o.u_steps = u_steps;
  o.v_steps = v_steps;
  return o;
}

Mesh tessellate_surface(const SurfaceEvaluator& surface, UvDomain domain, const TessellationOptions& options,
                        const std::vector<TrimLoop>& trims) {
  return PatchTessellator(surface, domain, options).run(trims);
}

// ---- welding and measures ---------------------------------------------------------------------

Mesh weld(const std::vector<Mesh>& meshes, double weld_tolerance) {
  if (!(weld_tolerance >= 0) || !std::isfinite(weld_tolerance))
    fail("weld: weld_tolerance=" + num(weld_tolerance) + " must be >= 0");
  Mesh out;
  // A hash grid of cell size weld_tolerance: a vertex can only merge with one
  // in its own or a neighbouring cell.
  const double cell = weld_tolerance > 0 ? weld_tolerance : 1.0;
  std::map<std::array<std::int64_t, 3>, std::vector<int>> grid;
  const auto key = [&](Vec3 p) {
    const auto k = [&](double x) {
      const double c = std::floor(x / cell);
      return static_cast<std::int64_t>(std::clamp(c, -9e15, 9e15));
    };
    return std::array<std::int64_t, 3>{k(p.x), k(p.y), k(p.z)};
  };
  for (const Mesh& m : meshes) {
    std::vector<int> remap(m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const Vec3 p = m.positions[i];
      const auto c = key(p);
      int found = -1;
      for (int dx = -1; dx <= 1 && found < 0; ++dx)
        for (int dy = -1; dy <= 1 && found < 0; ++dy)
          for (int dz = -1; dz <= 1 && found < 0; ++dz) {
            const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == grid.end()) continue;
            for (int j : it->second)
              if (norm(out.positions[j] - p) <= weld_tolerance) {
                found = j;
                break;
              }
          }
      if (found < 0) {
        found = static_cast<int>(out.positions.size());
        out.positions.push_back(p);
        out.normals.push_back(i < m.normals.size() ? m.normals[i] : Vec3{});
        out.uv.push_back(i < m.uv.size() ? m.uv[i] : Vec2{});
        grid[c].push_back(found);
      }
      remap[i] = found;
    }
    for (const auto& t : m.triangles) {
      const std::array<int, 3> r{remap[t[0]], remap[t[1]], remap[t[2]]};
      if (r[0] != r[1] && r[1] != r[2] && r[2] != r[0]) out.triangles.push_back(r);
    }
  }
  return out;
}

Mesh tessellate_patches(const std::vector<Patch>& patches, const TessellationOptions& options, double weld_tolerance) {
  std::vector<Mesh> meshes;
  for (std::size_t k = 0; k < patches.size(); ++k) {
    try {
      meshes.push_back(tessellate_surface(patches[k].surface, patches[k].domain, options, patches[k].trims));
    } catch (const std::invalid_argument& e) {
      fail("patch " + std::to_string(k) + ": " + e.what());
    }
  }
  return weld(meshes, weld_tolerance);
}

double mesh_area(const Mesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles)
    area += norm(cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]])) / 2;
  return area;
}

std::vector<std::array<int, 2>> boundary_edges(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::vector<std::array<int, 2>> out;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (uses[std::minmax(t[k], t[(k + 1) % 3])] == 1) out.push_back({t[k], t[(k + 1) % 3]});
  return out;
}

std::vector<std::array<Vec3, 2>> contour_segments(const Mesh& mesh, Vec3 direction, double level) {
  const std::string what = "contour_segments";
  require_finite(direction, what, "direction");
  require_finite(level, what, "level");
  if (norm(direction) == 0) fail(what + ": direction is the zero vector");
  std::vector<double> h;  // height above the level, per vertex
  for (const Vec3& p : mesh.positions) h.push_back(dot(p, direction) - level);
  const auto below = [&h](int k) { return h[static_cast<std::size_t>(k)] < 0; };
  // The point where h = 0 on edge (i, j), one end below and one at or above:
  // always interpolated from the lower index, so both triangles get the same point.
  const auto crossing = [&](int i, int j) {
    if (i > j) std::swap(i, j);
    const double hi = h[static_cast<std::size_t>(i)], hj = h[static_cast<std::size_t>(j)];
    return lerp(mesh.positions[static_cast<std::size_t>(i)], mesh.positions[static_cast<std::size_t>(j)],
                hi / (hi - hj));
  };
  std::vector<std::array<Vec3, 2>> out;
  for (const auto& t : mesh.triangles) {
    Vec3 ends[2];
    int found = 0;
    for (int k = 0; k < 3; ++k)
      if (below(t[k]) != below(t[(k + 1) % 3])) ends[found++] = crossing(t[k], t[(k + 1) % 3]);
    // A vertex at the level with both neighbours below crosses "twice" at itself: no segment.
    if (found == 2 && ends[0] != ends[1]) out.push_back({ends[0], ends[1]});
  }
  return out;
}

namespace {

void check_mesh(const Mesh& mesh, const char* what) {
  if (mesh.uv.size() != mesh.positions.size())
    fail(std::string(what) + ": the mesh has " + std::to_string(mesh.uv.size()) + " (u, v) for " +
         std::to_string(mesh.positions.size()) + " vertices");
  const auto n = static_cast<int>(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k : mesh.triangles[t])
      if (k < 0 || k >= n)
        fail(std::string(what) + ": triangle " + std::to_string(t) + " uses vertex " + std::to_string(k) +
             " of " + std::to_string(n));
}

}  // namespace

double surface_area(const SurfaceEvaluator& surface, const Mesh& mesh) {
  check_mesh(mesh, "surface_area");
  // Radon's rule (Stroud T2:5-1): the centroid, weight 9/40, and the points
  // with barycentric coordinates (a, a, 1 - 2a) and their permutations,
  // a = (6 -+ sqrt 15) / 21 with weight (155 -+ sqrt 15) / 1200.
  const double r15 = std::sqrt(15.0);
  const double a1 = (6 - r15) / 21, a2 = (6 + r15) / 21;
  const double w1 = (155 - r15) / 1200, w2 = (155 + r15) / 1200;
  const double rule[7][4] = {{1.0 / 3, 1.0 / 3, 1.0 / 3, 9.0 / 40},
                             {a1, a1, 1 - 2 * a1, w1}, {a1, 1 - 2 * a1, a1, w1}, {1 - 2 * a1, a1, a1, w1},
                             {a2, a2, 1 - 2 * a2, w2}, {a2, 1 - 2 * a2, a2, w2}, {1 - 2 * a2, a2, a2, w2}};
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.uv[t[0]], b = mesh.uv[t[1]], c = mesh.uv[t[2]];
    double sum = 0;
    for (const auto& r : rule) {
      const Vec2 q = r[0] * a + r[1] * b + r[2] * c;
      const SurfaceSample s = surface(q.x, q.y);
      sum += r[3] * norm(cross(s.du, s.dv));
    }
    area += std::abs(cross(b - a, c - a)) / 2 * sum;
  }
  return area;
}

MeshFidelity mesh_fidelity(const Mesh& mesh, const SurfaceEvaluator& surface, double tilt_degrees,
                           double weld_tolerance) {
  check_mesh(mesh, "mesh_fidelity");
  if (!(tilt_degrees >= 0 && tilt_degrees <= 180))
    fail("mesh_fidelity: tilt_degrees=" + num(tilt_degrees) + " must be in [0, 180]");
  const double kDegrees = 180 / std::acos(-1.0);
  MeshFidelity f;
  // Barycentre and edge midpoints, as tessellate.h measures its tolerance.
  const double samples[4][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const Vec3 P[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    const Vec2 Q[3] = {mesh.uv[t[0]], mesh.uv[t[1]], mesh.uv[t[2]]};
    for (const auto& b : samples) {
      const Vec2 q = b[0] * Q[0] + b[1] * Q[1] + b[2] * Q[2];
      const Vec3 p = b[0] * P[0] + b[1] * P[1] + b[2] * P[2];
      f.max_deviation = std::max(f.max_deviation, norm(surface(q.x, q.y).point - p));
    }
    const Vec3 face = cross(P[1] - P[0], P[2] - P[0]);
    if (norm(face) == 0) continue;
    const Vec2 centre = (Q[0] + Q[1] + Q[2]) / 3;
    const Vec3 n = surface(centre.x, centre.y).normal;
    const double tilt = std::atan2(norm(cross(face, n)), dot(face, n)) * kDegrees;
    f.max_tilt_degrees = std::max(f.max_tilt_degrees, tilt);
    if (tilt > tilt_degrees) f.tilted.push_back(i);
  }
  f.tilted_faces = f.tilted.size();
  const Mesh welded = weld({mesh}, weld_tolerance);
  for (const auto& e : boundary_edges(welded))
    for (double s : {0.25, 0.5, 0.75}) {
      const Vec2 q = (1 - s) * welded.uv[e[0]] + s * welded.uv[e[1]];
      const Vec3 p = lerp(welded.positions[e[0]], welded.positions[e[1]], s);
      f.max_trim_deviation = std::max(f.max_trim_deviation, norm(surface(q.x, q.y).point - p));
    }
  return f;
}

}  // namespace gllab::spline
