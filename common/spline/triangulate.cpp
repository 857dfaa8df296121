// common/spline/triangulate.cpp — ear clipping of polygons with holes:
// triangulate_polygon (tessellate.h), and triangulate_loops, which the patch
// tessellator uses for its cut cells (tessellate_detail.h).
//
// Every simple polygon with more than three vertices has two ears that do not
// overlap (Meisters, "Polygons have ears", 1975), so cutting one ear at a time
// triangulates it. The steps follow Eberly, "Triangulation by Ear Clipping"
// (2002): holes are first joined to the outer loop by bridges (§3), then ears
// are cut. Which ear first is this code's own choice: the one whose triangle
// has the largest smallest angle, which avoids most slivers.
#include "spline/tessellate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "spline/errors.h"
#include "spline/tessellate_detail.h"

namespace gllab::spline {

using detail::orient;

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
std::vector<int> bridge_holes(const std::vector<Vec2>& pt, std::vector<int> outer,
                              std::vector<std::vector<int>> holes) {
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

}  // namespace

namespace detail {

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

}  // namespace detail

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

}  // namespace gllab::spline
