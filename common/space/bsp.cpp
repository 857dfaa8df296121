// common/space/bsp.cpp — BSP trees over convex polygons (bsp.h).
#include "space/bsp.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "space/pca.h"

namespace gllab::space {
namespace {

/// Newell's method: the normal of a planar polygon as the sum over its edges, twice its
/// area in length (exact for a planar polygon, robust for a nearly planar one).
Vec3 newell_normal(const std::vector<Vec3>& P) {
  Vec3 n{};
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec3 a = P[i], b = P[(i + 1) % P.size()];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

Vec3 centroid(const std::vector<Vec3>& P) {
  Vec3 c{};
  for (const Vec3& p : P) c += p / double(P.size());
  return c;
}

/// Keeps `p` unless it repeats the last point kept (a vertex on the plane, met twice).
void add(std::vector<Vec3>& out, Vec3 p) {
  if (out.empty() || out.back() != p) out.push_back(p);
}

}  // namespace

bool polygon_plane(const Polygon3& polygon, Plane& plane) {
  if (polygon.points.size() < 3) return false;
  const Vec3 n = newell_normal(polygon.points);
  Vec3 lo = polygon.points[0], hi = lo;
  for (const Vec3& p : polygon.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double extent = norm(hi - lo);
  if (!(norm(n) / 2 > 1e-12 * extent * extent)) return false;
  plane.n = normalized(n);
  plane.d = dot(plane.n, centroid(polygon.points));
  return true;
}

double polygon_area(const Polygon3& polygon) {
  return polygon.points.size() < 3 ? 0 : norm(newell_normal(polygon.points)) / 2;
}

SplitResult split_polygon(const Polygon3& polygon, const Plane& plane, double eps) {
  SplitResult r{
      SplitResult::kCoplanar, {{}, polygon.id, polygon.object}, {{}, polygon.id, polygon.object}};
  const std::size_t n = polygon.points.size();
  std::vector<double> d(n);
  bool front = false, back = false;
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = plane.distance(polygon.points[i]);
    front = front || d[i] > eps;
    back = back || d[i] < -eps;
  }
  if (!front && !back) return r;  // kCoplanar; the pieces stay empty
  if (!back) {
    r.side = SplitResult::kFront;
    r.front = polygon;
    return r;
  }
  if (!front) {
    r.side = SplitResult::kBack;
    r.back = polygon;
    return r;
  }
  // Both sides (Sutherland and Hodgman 1974, one plane): walk the edges; a vertex goes to
  // its side (both when on the plane), an edge that crosses adds the crossing to both.
  r.side = SplitResult::kSpanning;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const Vec3 a = polygon.points[i], b = polygon.points[j];
    if (d[i] >= -eps) add(r.front.points, a);
    if (d[i] <= eps) add(r.back.points, a);
    if ((d[i] > eps && d[j] < -eps) || (d[i] < -eps && d[j] > eps)) {
      const double t = d[i] / (d[i] - d[j]);
      const Vec3 x = a + t * (b - a);
      add(r.front.points, x);
      add(r.back.points, x);
    }
  }
  for (std::vector<Vec3>* P : {&r.front.points, &r.back.points})
    if (P->size() > 1 && P->front() == P->back()) P->pop_back();
  return r;
}

const char* split_rule_name(SplitRule rule) {
  switch (rule) {
    case SplitRule::kOwnPlane:
      return "own plane";
    case SplitRule::kFewestSplits:
      return "fewest splits";
    case SplitRule::kPca:
      return "PCA";
  }
  return "?";
}

namespace {

/// Fewest splits looks at this many candidate planes per node at most (evenly spaced among
/// the node's polygons): every plane against every polygon is O(n^2) per node.
constexpr std::size_t kCandidates = 64;
/// Deeper than this, a PCA node falls back to the own-plane rule (a chain of PCA planes
/// that keeps cutting the same objects).
constexpr int kPcaDepthLimit = 64;

struct Count {
  std::size_t front = 0, back = 0, spanning = 0;
};
Count count_sides(const std::vector<Polygon3>& L, const Plane& p, double eps) {
  Count c;
  for (const Polygon3& q : L) {
    bool f = false, b = false;
    for (const Vec3& x : q.points) {
      const double d = p.distance(x);
      f = f || d > eps;
      b = b || d < -eps;
    }
    c.spanning += f && b;
    c.front += f && !b;
    c.back += b && !f;
  }
  return c;
}

/// The PCA rule's plane: across e1 (then e2, e3) at the median of the objects' centres.
bool pca_plane(const std::vector<Polygon3>& L, Plane& plane) {
  std::vector<Vec3> points;
  for (const Polygon3& q : L) points.insert(points.end(), q.points.begin(), q.points.end());
  if (points.size() < 2) return false;
  const Pca a = pca(points);
  // Each object's centre: the mean of its pieces' vertices.
  std::vector<std::pair<int, Vec3>> sums;  // object, sum; and counts
  std::vector<double> counts;
  for (const Polygon3& q : L) {
    std::size_t k = 0;
    while (k < sums.size() && sums[k].first != q.object) ++k;
    if (k == sums.size()) sums.push_back({q.object, {}}), counts.push_back(0);
    for (const Vec3& x : q.points) sums[k].second += x;
    counts[k] += double(q.points.size());
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (a.variance[axis] <= 0) break;
    std::vector<double> s;
    for (std::size_t k = 0; k < sums.size(); ++k)
      s.push_back(dot(a.axis[axis], sums[k].second / counts[k]));
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    if (s.size() < 2) continue;
    const std::size_t m = s.size() / 2;  // between the two middle centres
    plane = {a.axis[axis], (s[m - 1] + s[m]) / 2};
    return true;
  }
  return false;
}

}  // namespace

BspTree::BspTree(const std::vector<Polygon3>& polygons, SplitRule rule, double eps) {
  stats_.polygons = polygons.size();
  std::vector<Polygon3> kept;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    for (std::size_t k = 0; k < polygons[i].points.size(); ++k) {
      const Vec3 p = polygons[i].points[k];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        char text[160];
        std::snprintf(text, sizeof text, "bsp: polygon %zu, point %zu = (%g, %g, %g) is not finite",
                      i, k, p.x, p.y, p.z);
        throw std::invalid_argument(text);
      }
    }
    Plane unused;
    if (polygon_plane(polygons[i], unused))
      kept.push_back(polygons[i]);
    else
      ++stats_.degenerate_skipped;
  }
  if (kept.empty()) return;
  struct Work {
    std::size_t node;
    int depth;
    std::vector<Polygon3> polygons;
  };
  nodes_.push_back({});
  std::vector<Work> stack;
  stack.push_back({0, 0, std::move(kept)});
  while (!stack.empty()) {
    Work w = std::move(stack.back());
    stack.pop_back();
    stats_.depth = std::max(stats_.depth, w.depth);
    const std::vector<Polygon3>& L = w.polygons;
    const bool one_object =
        std::all_of(L.begin(), L.end(), [&](const Polygon3& q) { return q.object == L[0].object; });
    if (one_object) {  // a region with one object: a leaf
      BspNode& leaf = nodes_[w.node];
      polygon_plane(L[0], leaf.plane);
      leaf.on = L;
      leaf.leaf = true;
      stats_.fragments += L.size();
      continue;
    }
    Plane plane{};
    bool chosen = false;
    std::size_t own = L.size();  // the polygon whose plane was chosen: it stays in the node
    if (rule == SplitRule::kPca && w.depth < kPcaDepthLimit && pca_plane(L, plane)) {
      // Progress: some object must lie wholly on one side, or the pieces would only multiply.
      std::vector<int> cut;
      for (const Polygon3& q : L) {
        const SplitResult::Side side = split_polygon(q, plane, eps).side;
        if (side == SplitResult::kSpanning || side == SplitResult::kCoplanar)
          cut.push_back(q.object);
      }
      std::vector<int> objects;
      for (const Polygon3& q : L) objects.push_back(q.object);
      std::sort(cut.begin(), cut.end());
      std::sort(objects.begin(), objects.end());
      chosen = std::unique(cut.begin(), cut.end()) - cut.begin() <
               std::unique(objects.begin(), objects.end()) - objects.begin();
    }
    if (!chosen && rule == SplitRule::kFewestSplits) {
      const std::size_t step = std::max<std::size_t>(1, L.size() / kCandidates);
      std::size_t best_splits = 0, best_balance = 0;
      for (std::size_t i = 0; i < L.size(); i += step) {
        Plane p;
        if (!polygon_plane(L[i], p)) continue;
        const Count c = count_sides(L, p, eps);
        const std::size_t balance = c.front > c.back ? c.front - c.back : c.back - c.front;
        if (!chosen || c.spanning < best_splits ||
            (c.spanning == best_splits && balance < best_balance)) {
          plane = p, best_splits = c.spanning, best_balance = balance, chosen = true, own = i;
        }
      }
    }
    if (!chosen) {  // the own-plane rule, and the others' fallback
      for (own = 0; own < L.size() && !polygon_plane(L[own], plane);) ++own;
    }
    std::vector<Polygon3> front, back;
    BspNode& node = nodes_[w.node];
    node.plane = plane;
    for (std::size_t i = 0; i < L.size(); ++i) {
      const Polygon3& q = L[i];
      if (i == own) {  // in its own plane, even when not quite planar: progress is certain
        node.on.push_back(q);
        continue;
      }
      SplitResult r = split_polygon(q, plane, eps);
      switch (r.side) {
        case SplitResult::kCoplanar:
          node.on.push_back(q);
          break;
        case SplitResult::kFront:
          front.push_back(std::move(r.front));
          break;
        case SplitResult::kBack:
          back.push_back(std::move(r.back));
          break;
        case SplitResult::kSpanning:
          ++stats_.splits;
          front.push_back(std::move(r.front));
          back.push_back(std::move(r.back));
          break;
      }
    }
    stats_.fragments += node.on.size();
    if (!back.empty()) {
      nodes_[w.node].back = int(nodes_.size());
      stack.push_back({nodes_.size(), w.depth + 1, std::move(back)});
      nodes_.push_back({});
    }
    if (!front.empty()) {
      nodes_[w.node].front = int(nodes_.size());
      stack.push_back({nodes_.size(), w.depth + 1, std::move(front)});
      nodes_.push_back({});
    }
  }
  stats_.nodes = nodes_.size();
}

std::vector<const Polygon3*> BspTree::back_to_front(Vec3 eye) const {
  std::vector<const Polygon3*> out;
  if (nodes_.empty()) return out;
  // Iterative in-order walk: a node is visited twice, first to push its far side, then to
  // emit its own polygons and go to its near side.
  struct Visit {
    int node;
    bool expanded;
  };
  std::vector<Visit> stack{{0, false}};
  while (!stack.empty()) {
    const Visit v = stack.back();
    stack.pop_back();
    const BspNode& n = nodes_[std::size_t(v.node)];
    if (n.leaf) {
      for (const Polygon3& q : n.on) out.push_back(&q);
      continue;
    }
    const bool in_front = n.plane.distance(eye) > 0;
    const int far = in_front ? n.back : n.front, near = in_front ? n.front : n.back;
    if (!v.expanded) {
      if (near >= 0) stack.push_back({near, false});
      stack.push_back({v.node, true});
      if (far >= 0) stack.push_back({far, false});
    } else {
      for (const Polygon3& q : n.on) out.push_back(&q);
    }
  }
  return out;
}

}  // namespace gllab::space
