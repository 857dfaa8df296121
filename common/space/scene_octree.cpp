// common/space/scene_octree.cpp — an octree of triangles for ray queries
// (scene_octree.h).
#include "space/scene_octree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "space/internal.h"

namespace gllab::space {

bool ray_triangle(const Ray& ray, Vec3 a, Vec3 b, Vec3 c, double& t, double& u, double& v) {
  // Möller and Trumbore 1997, "Fast, minimum storage ray-triangle intersection": solve
  // origin + t d = (1 - u - v) a + u b + v c by Cramer's rule.
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (det == 0) return false;  // parallel to the plane, or no area
  const double inv = 1 / det;
  const Vec3 s = ray.origin - a;
  const double uu = dot(s, p) * inv;
  if (uu < 0 || uu > 1) return false;
  const Vec3 q = cross(s, e1);
  const double vv = dot(ray.direction, q) * inv;
  if (vv < 0 || uu + vv > 1) return false;
  const double tt = dot(e2, q) * inv;
  if (!(tt >= 0)) return false;
  t = tt, u = uu, v = vv;
  return true;
}

namespace {

Vec3 vertex(const IndexedMesh& m, std::size_t triangle, int corner) {
  const float* p = &m.positions[3 * std::size_t(m.indices[3 * triangle + corner])];
  return {p[0], p[1], p[2]};
}

/// Keeps the nearer hit; on equal t the lower triangle index (the brute force's order).
void keep(Hit& best, double t, double u, double v, std::uint32_t triangle) {
  if (!best.hit || t < best.t || (t == best.t && triangle < best.triangle))
    best = {true, t, triangle, u, v};
}

/// Akenine-Möller 2001, "Fast 3D triangle-box overlap testing": the separating-axis
/// theorem over the box's three normals, the triangle's normal and the nine cross
/// products of the edges with the box's axes. Boundaries count as overlapping.
bool triangle_overlaps_box(Vec3 a, Vec3 b, Vec3 c, const Box3& box) {
  const Vec3 centre = box.centre(), half = 0.5 * box.size();
  const Vec3 v[3] = {a - centre, b - centre, c - centre};
  const double h[3] = {half.x, half.y, half.z};
  const auto comp = [](Vec3 p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; };
  for (int k = 0; k < 3; ++k) {  // the box's normals: the triangle's bounding box
    const double lo = std::min({comp(v[0], k), comp(v[1], k), comp(v[2], k)});
    const double hi = std::max({comp(v[0], k), comp(v[1], k), comp(v[2], k)});
    if (lo > h[k] || hi < -h[k]) return false;
  }
  const Vec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  const auto separated = [&](Vec3 axis) {
    const double p0 = dot(v[0], axis), p1 = dot(v[1], axis), p2 = dot(v[2], axis);
    const double r = h[0] * std::abs(axis.x) + h[1] * std::abs(axis.y) + h[2] * std::abs(axis.z);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
  };
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const Vec3& edge : e)
    for (const Vec3& axis : axes)
      if (separated(cross(edge, axis))) return false;
  return !separated(cross(e[0], e[1]));  // the triangle's plane
}

}  // namespace

Hit first_hit_brute_force(const IndexedMesh& mesh, const Ray& ray, RayStats* stats) {
  Hit best;
  const std::size_t n = mesh.triangle_count();
  for (std::size_t i = 0; i < n; ++i) {
    double t, u, v;
    if (ray_triangle(ray, vertex(mesh, i, 0), vertex(mesh, i, 1), vertex(mesh, i, 2), t, u, v))
      keep(best, t, u, v, std::uint32_t(i));
  }
  if (stats) {
    stats->triangles_tested += n;
    stats->cells_visited += 1;
  }
  return best;
}

struct SceneOctree::Impl {
  struct Node {
    Box3 box;
    std::int32_t first_child;    // -1: a leaf
    std::uint32_t first, count;  // a leaf's triangles: refs[first .. first + count)
    int depth;
  };
  struct Triangle {
    Vec3 a, b, c;
  };
  std::vector<Node> nodes;
  /// What a ray query reads of a node, 12 bytes (Node's box is 48 more): the walk carries
  /// each node's box on its stack, computed by Box3::child exactly as the build did.
  struct Hot {
    std::int32_t first_child;
    std::uint32_t first, count;
  };
  std::vector<Hot> hot;
  std::vector<std::uint32_t> refs;
  std::vector<Triangle> triangles;
  int depth = 0;
};

SceneOctree::SceneOctree(const IndexedMesh& mesh, SceneOctreeOptions options) {
  internal::require_valid_mesh(mesh, "SceneOctree");
  if (options.max_depth < 0 || options.max_depth > 12)
    throw std::invalid_argument("SceneOctree: max_depth = " + std::to_string(options.max_depth) +
                                " (must be 0..12)");
  if (options.leaf_size < 1)
    throw std::invalid_argument("SceneOctree: leaf_size = " + std::to_string(options.leaf_size) +
                                " (must be at least 1)");
  auto impl = std::make_shared<Impl>();
  const std::size_t n = mesh.triangle_count();
  impl->triangles.resize(n);
  Vec3 lo{1e300, 1e300, 1e300}, hi = -1 * lo;
  for (std::size_t i = 0; i < n; ++i) {
    Impl::Triangle& t = impl->triangles[i];
    t = {vertex(mesh, i, 0), vertex(mesh, i, 1), vertex(mesh, i, 2)};
    for (const Vec3& p : {t.a, t.b, t.c}) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  if (n == 0) lo = hi = {0, 0, 0};
  // The bounding cube of the vertices, grown by a relative 1e-9.
  const Vec3 c = 0.5 * (lo + hi);
  const double half = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300}) / 2 * (1 + 1e-9);
  const Box3 root{c - Vec3{half, half, half}, c + Vec3{half, half, half}};
  // Depth first with an explicit stack of (node, its triangles).
  struct Work {
    std::size_t node;
    std::vector<std::uint32_t> triangles;
  };
  std::vector<std::uint32_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = std::uint32_t(i);
  impl->nodes.push_back({root, -1, 0, 0, 0});
  std::vector<Work> stack;
  stack.push_back({0, std::move(all)});
  while (!stack.empty()) {
    Work w = std::move(stack.back());
    stack.pop_back();
    Impl::Node node = impl->nodes[w.node];
    impl->depth = std::max(impl->depth, node.depth);
    if (w.triangles.size() <= std::size_t(options.leaf_size) || node.depth >= options.max_depth) {
      impl->nodes[w.node].first = std::uint32_t(impl->refs.size());
      impl->nodes[w.node].count = std::uint32_t(w.triangles.size());
      impl->refs.insert(impl->refs.end(), w.triangles.begin(), w.triangles.end());
      continue;
    }
    const std::size_t first = impl->nodes.size();
    impl->nodes[w.node].first_child = std::int32_t(first);
    for (int k = 0; k < 8; ++k)
      impl->nodes.push_back({node.box.child(k), -1, 0, 0, node.depth + 1});
    for (int k = 0; k < 8; ++k) {
      Work child{first + std::size_t(k), {}};
      for (std::uint32_t t : w.triangles) {
        const Impl::Triangle& tr = impl->triangles[t];
        if (triangle_overlaps_box(tr.a, tr.b, tr.c, impl->nodes[child.node].box))
          child.triangles.push_back(t);
      }
      stack.push_back(std::move(child));
    }
  }
  for (const Impl::Node& n : impl->nodes) impl->hot.push_back({n.first_child, n.first, n.count});
  impl_ = std::move(impl);
}

namespace {
/// The slab test (Kay and Kajiya 1986): the ray's parameter interval inside the box, with
/// 1/d precomputed (an infinite 1/d for a zero component works: the slab is all or nothing,
/// except for an origin exactly on the slab's plane, where 0 * inf gives NaN and std::max /
/// std::min then keep the other bound).
bool slab(const Box3& b, Vec3 o, Vec3 inv, double& t0, double& t1) {
  double lo = 0, hi = std::numeric_limits<double>::infinity();
  const double os[3] = {o.x, o.y, o.z}, is[3] = {inv.x, inv.y, inv.z};
  const double bl[3] = {b.lo.x, b.lo.y, b.lo.z}, bh[3] = {b.hi.x, b.hi.y, b.hi.z};
  for (int k = 0; k < 3; ++k) {
    double a = (bl[k] - os[k]) * is[k], c = (bh[k] - os[k]) * is[k];
    if (a > c) std::swap(a, c);
    if (a > lo) lo = a;  // NaN compares false: the bound stays
    if (c < hi) hi = c;
  }
  t0 = lo, t1 = hi;
  return lo <= hi;
}
}  // namespace

Hit SceneOctree::first_hit(const Ray& ray, RayStats* stats) const {
  const Impl& m = *impl_;
  Hit best;
  // Triangles met in an earlier leaf are not tested again: a stamp per triangle, per thread.
  thread_local std::vector<std::uint32_t> stamp;
  thread_local std::uint32_t ray_number = 0;
  if (stamp.size() < m.triangles.size()) stamp.assign(m.triangles.size(), 0), ray_number = 0;
  if (++ray_number == 0) std::fill(stamp.begin(), stamp.end(), 0), ray_number = 1;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const double inv[3] = {1 / d[0], 1 / d[1], 1 / d[2]};
  struct Entry {
    std::uint32_t node;
    double t0, t1;  // the ray's interval inside the node
    Box3 box;
  };
  Entry stack[4 * 13 + 1];
  int top = 0;
  double t0, t1;
  if (m.nodes.empty() || !slab(m.nodes[0].box, ray.origin, {inv[0], inv[1], inv[2]}, t0, t1))
    return best;
  stack[top++] = {0, t0, t1, m.nodes[0].box};
  while (top > 0) {
    const Entry e = stack[--top];
    if (best.hit && e.t0 > best.t) continue;  // entirely behind the hit found
    const Impl::Hot& n = m.hot[e.node];
    if (n.first_child < 0) {
      if (stats) ++stats->cells_visited;
      for (std::uint32_t r = n.first; r < n.first + n.count; ++r) {
        const std::uint32_t t = m.refs[r];
        if (stamp[t] == ray_number) continue;
        stamp[t] = ray_number;
        if (stats) ++stats->triangles_tested;
        const Impl::Triangle& tr = m.triangles[t];
        double tt, u, v;
        if (ray_triangle(ray, tr.a, tr.b, tr.c, tt, u, v)) keep(best, tt, u, v, t);
      }
      continue;
    }
    // The children the ray passes, in order, from where it crosses the three mid-planes
    // (Revelles, Ureña and Lastra 2000, "An efficient parametric algorithm for octree
    // traversal"): at most four, with no box test. Along axis k the ray is in the upper half
    // after t_k when it runs up the axis, before t_k when it runs down; the child's number
    // flips bit k at t_k.
    const Vec3 mid = e.box.centre();
    const double mids[3] = {mid.x, mid.y, mid.z};
    int child = 0, events = 0;
    double et[3];
    int axis[3];
    for (int k = 0; k < 3; ++k) {
      const double tk = (mids[k] - o[k]) * inv[k];
      const bool upper = d[k] > 0 ? tk <= e.t0 : d[k] < 0 ? !(tk <= e.t0) : o[k] >= mids[k];
      child |= int(upper) << k;
      if (tk > e.t0 && tk < e.t1) {  // a crossing inside the node (NaN is none)
        int i = events++;
        for (; i > 0 && et[i - 1] > tk; --i) et[i] = et[i - 1], axis[i] = axis[i - 1];
        et[i] = tk, axis[i] = k;
      }
    }
    Entry seq[4];
    double start = e.t0;
    for (int i = 0; i < events; ++i) {
      seq[i] = {std::uint32_t(n.first_child + child), start, et[i], e.box.child(child)};
      child ^= 1 << axis[i];
      start = et[i];
    }
    seq[events] = {std::uint32_t(n.first_child + child), start, e.t1, e.box.child(child)};
    for (int i = events; i >= 0; --i)  // farthest first: the nearest is taken next
      if (!(best.hit && seq[i].t0 > best.t)) stack[top++] = seq[i];
  }
  return best;
}

const Box3& SceneOctree::cube() const { return impl_->nodes[0].box; }
std::size_t SceneOctree::node_count() const { return impl_->nodes.size(); }
std::size_t SceneOctree::leaf_count() const {
  std::size_t c = 0;
  for (const Impl::Node& n : impl_->nodes) c += n.first_child < 0;
  return c;
}
std::size_t SceneOctree::references() const { return impl_->refs.size(); }
int SceneOctree::depth() const { return impl_->depth; }
std::size_t SceneOctree::bytes() const {
  return impl_->nodes.size() * (sizeof(Impl::Node) + sizeof(Impl::Hot)) +
         impl_->refs.size() * sizeof(std::uint32_t) +
         impl_->triangles.size() * sizeof(Impl::Triangle);
}

std::vector<Box3> SceneOctree::leaf_boxes() const {
  std::vector<Box3> out;
  for (const Impl::Node& n : impl_->nodes)
    if (n.first_child < 0) out.push_back(n.box);
  return out;
}

std::vector<Box3> SceneOctree::visited_boxes(const Ray& ray) const {
  // The leaves first_hit looks into, in its order: the same walk, recording.
  const Impl& m = *impl_;
  const Hit h = first_hit(ray);
  std::vector<Box3> out;
  const Vec3 inv{1 / ray.direction.x, 1 / ray.direction.y, 1 / ray.direction.z};
  std::vector<std::pair<std::uint32_t, double>> stack;
  double t0, t1;
  if (!slab(m.nodes[0].box, ray.origin, inv, t0, t1)) return out;
  stack.push_back({0, t0});
  while (!stack.empty()) {
    const auto e = stack.back();
    stack.pop_back();
    if (h.hit && e.second > h.t) continue;
    const Impl::Node& n = m.nodes[e.first];
    if (n.first_child < 0) {
      if (n.count > 0) out.push_back(n.box);
      continue;
    }
    std::vector<std::pair<std::uint32_t, double>> hit;
    for (int c = 0; c < 8; ++c)
      if (slab(m.nodes[std::size_t(n.first_child + c)].box, ray.origin, inv, t0, t1) &&
          !(h.hit && t0 > h.t))
        hit.push_back({std::uint32_t(n.first_child + c), t0});
    std::sort(hit.begin(), hit.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    stack.insert(stack.end(), hit.begin(), hit.end());
  }
  return out;
}

}  // namespace gllab::space
