// common/spline/patch_subdivision.cpp — see patch_subdivision.h.
#include "spline/patch_subdivision.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spline/bezier.h"
#include "spline/errors.h"
#include "spline/internal.h"

namespace gllab::spline {
namespace {

std::size_t idx(const BezierSurface& s, int i, int j) {
  return static_cast<std::size_t>(i * (s.m + 1) + j);
}
Vec3& at(BezierSurface& s, int i, int j) { return s.P[idx(s, i, j)]; }
Vec3 at(const BezierSurface& s, int i, int j) { return s.P[idx(s, i, j)]; }

// Split along u (along_u) or v: every line of the net in that direction is a
// Bézier curve, split by subdivide (bezier.h).
BezierSurfaceSplit split(const BezierSurface& s, double w, bool along_u, const char* what) {
  validate(s);
  const double lo = along_u ? s.a : s.c, hi = along_u ? s.b : s.d;
  if (!(w > lo && w < hi))
    fail(ErrorCode::kParameterOutsideDomain,
         std::string(what) + ": " + num(w) + " is not inside (" + num(lo) + ", " + num(hi) + ")",
         {{"parameter", w}});
  BezierSurfaceSplit out{s, s};
  const int lines = along_u ? s.m + 1 : s.n + 1, deg = along_u ? s.n : s.m;
  for (int l = 0; l < lines; ++l) {
    BezierCurve c;
    c.a = lo;
    c.b = hi;
    for (int k = 0; k <= deg; ++k) c.P.push_back(along_u ? at(s, k, l) : at(s, l, k));
    if (deg == 0) continue;  // a constant direction: both halves keep the point
    const BezierSplit h = subdivide(c, w);
    for (int k = 0; k <= deg; ++k) {
      (along_u ? at(out.first, k, l) : at(out.first, l, k)) = h.left.P[k];
      (along_u ? at(out.second, k, l) : at(out.second, l, k)) = h.right.P[k];
    }
  }
  if (along_u) {
    out.first.b = w;
    out.second.a = w;
  } else {
    out.first.d = w;
    out.second.c = w;
  }
  return out;
}

void split_rec(const BezierSurface& s, double tol, int depth, int max_depth,
               std::vector<PatchLeaf>& out) {
  if (depth >= max_depth || patch_flatness(s) <= tol) {
    out.push_back({s, depth});
    return;
  }
  const BezierSurfaceSplit hu = split_u(s, 0.5 * (s.a + s.b));
  for (const BezierSurface* h : {&hu.first, &hu.second}) {
    const BezierSurfaceSplit hv = split_v(*h, 0.5 * (h->c + h->d));
    split_rec(hv.first, tol, depth + 1, max_depth, out);
    split_rec(hv.second, tol, depth + 1, max_depth, out);
  }
}

struct Edge {
  Vec2 p0, p1;  // (u, v) end points, axis-parallel
};

// The longest leaf edge that has uv strictly inside it (nullptr when none).
const Edge* longest_edge_through(const std::vector<Edge>& edges, Vec2 uv) {
  const double eps = 1e-12;
  const Edge* best = nullptr;
  double best_len = 0;
  for (const Edge& e : edges) {
    const bool horizontal = e.p0.y == e.p1.y;
    const double along = horizontal ? uv.x : uv.y, fixed = horizontal ? uv.y : uv.x;
    const double lo = horizontal ? std::min(e.p0.x, e.p1.x) : std::min(e.p0.y, e.p1.y);
    const double hi = horizontal ? std::max(e.p0.x, e.p1.x) : std::max(e.p0.y, e.p1.y);
    if (std::abs(fixed - (horizontal ? e.p0.y : e.p0.x)) > eps) continue;
    if (!(along > lo + eps && along < hi - eps)) continue;
    if (hi - lo > best_len) {
      best_len = hi - lo;
      best = &e;
    }
  }
  return best;
}

// The crack-free position of the vertex at uv (see leaf_quads); guard bounds the recursion.
Vec3 placed(const BezierSurface& s, const std::vector<Edge>& edges, Vec2 uv, int guard) {
  const Edge* e = guard > 0 ? longest_edge_through(edges, uv) : nullptr;
  if (!e) return surface_point(s, uv.x, uv.y);
  const bool horizontal = e->p0.y == e->p1.y;
  const double w = horizontal ? (uv.x - e->p0.x) / (e->p1.x - e->p0.x)
                              : (uv.y - e->p0.y) / (e->p1.y - e->p0.y);
  const Vec3 q0 = placed(s, edges, e->p0, guard - 1), q1 = placed(s, edges, e->p1, guard - 1);
  return (1 - w) * q0 + w * q1;
}

}  // namespace

std::vector<LeafQuad> leaf_quads(const BezierSurface& surface, const std::vector<PatchLeaf>& leaves,
                                 bool close_cracks) {
  validate(surface);
  std::vector<Edge> edges;
  std::vector<LeafQuad> out;
  for (const PatchLeaf& l : leaves) {
    LeafQuad q;
    q.depth = l.depth;
    q.uv[0] = {l.patch.a, l.patch.c};
    q.uv[1] = {l.patch.b, l.patch.c};
    q.uv[2] = {l.patch.b, l.patch.d};
    q.uv[3] = {l.patch.a, l.patch.d};
    for (int k = 0; k < 4; ++k) edges.push_back({q.uv[k], q.uv[(k + 1) % 4]});
    out.push_back(q);
  }
  // A guard on placed()'s recursion (each step goes to the end points of an edge that
  // holds the vertex inside it); split_adaptive's quadtrees need far fewer steps.
  const int guard = close_cracks ? 64 : 0;
  for (LeafQuad& q : out)
    for (int k = 0; k < 4; ++k) q.p[k] = placed(surface, edges, q.uv[k], guard);
  return out;
}

BezierSurfaceSplit split_u(const BezierSurface& surface, double u0) {
  return split(surface, u0, true, "split_u");
}
BezierSurfaceSplit split_v(const BezierSurface& surface, double v0) {
  return split(surface, v0, false, "split_v");
}

double patch_flatness(const BezierSurface& surface) {
  validate(surface);
  const Vec3 o = at(surface, 0, 0);
  const Vec3 nrm = cross(at(surface, surface.n, 0) - o, at(surface, 0, surface.m) - o);
  const double len = norm(nrm);
  double worst = 0;
  for (const Vec3& p : surface.P) {
    // No plane (collinear corners): the distance from b_00 bounds the distance from any
    // plane through b_00.
    const double d = len > 0 ? std::abs(dot(p - o, nrm)) / len : norm(p - o);
    worst = std::max(worst, d);
  }
  return worst;
}

std::vector<PatchLeaf> split_adaptive(const BezierSurface& surface, double tolerance,
                                      int max_depth) {
  validate(surface);
  if (!(tolerance > 0))
    fail(ErrorCode::kToleranceNotPositive,
         "split_adaptive: tolerance=" + num(tolerance) + " is not > 0", {{"tolerance", tolerance}});
  if (max_depth < 0 || max_depth > 12)
    fail(ErrorCode::kOutOfRange,
         "split_adaptive: max_depth=" + std::to_string(max_depth) + " is outside [0, 12]",
         {{"max_depth", static_cast<double>(max_depth)}});
  std::vector<PatchLeaf> out;
  split_rec(surface, tolerance, 0, max_depth, out);
  return out;
}

BezierCurve diagonal_curve(const BezierSurface& surface) {
  validate(surface);
  const int n = surface.n, m = surface.m;
  BezierCurve c;
  c.P.assign(static_cast<std::size_t>(n + m + 1), Vec3{});
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      c.P[static_cast<std::size_t>(i + j)] +=
          (internal::binomial(n, i) * internal::binomial(m, j) /
           internal::binomial(n + m, i + j)) * at(surface, i, j);
  return c;
}

Vec3 matrix_form_point(const BezierSurface& surface, double u, double v) {
  validate(surface);
  const int n = surface.n, m = surface.m;
  const double s = (u - surface.a) / (surface.b - surface.a);
  const double t = (v - surface.c) / (surface.d - surface.c);
  const auto Mn = bezier_matrix(n), Mm = bezier_matrix(m);
  // U M_n: row r of M multiplies s^(n - r).
  std::vector<double> uM(static_cast<std::size_t>(n + 1), 0.0);
  std::vector<double> vM(static_cast<std::size_t>(m + 1), 0.0);
  for (int r = 0; r <= n; ++r)
    for (int i = 0; i <= n; ++i) uM[i] += std::pow(s, n - r) * Mn[r][i];
  for (int r = 0; r <= m; ++r)
    for (int j = 0; j <= m; ++j) vM[j] += std::pow(t, m - r) * Mm[r][j];
  Vec3 x{};
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) x += (uM[i] * vM[j]) * at(surface, i, j);
  return x;
}

}  // namespace gllab::spline
