// common/spline/patch_mesh.cpp — the mesh output of the patch tessellator
// (patch_tessellator.h): a point, a unit normal and a (u, v) on the surface
// for every vertex a triangle uses (assemble), then edge flips against
// slivers (flip_slivers: Lawson's edge swapping, "Software for C1 surface
// interpolation", 1977, with the smallest angle in 3D as the measure).
#include "spline/patch_tessellator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gllab::spline::detail {

/// The mesh: for each vertex a triangle uses (in the order they are first used),
/// its point, unit normal and (u, v); lattice vertices come from the cache.
Mesh PatchTessellator::assemble() {
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

/// Edge flips against slivers (Lawson's edge swapping, 1977, with the
/// smallest angle as the measure). Where a trim line runs close to a cell
/// line, the cut cells leave needle triangles; the edge between such a
/// needle and its neighbour is flipped when that raises the smaller of the
/// two triangles' smallest angles (in 3D), both new triangles stay counter-
/// clockwise in (u, v), and they still meet the tolerance (at their
/// barycentres and the new edge's midpoint). Trim edges and patch edges are
/// boundary edges of the mesh, so they are never flipped.
void PatchTessellator::flip_slivers(Mesh& m) {
  const auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
  };
  std::unordered_map<std::uint64_t, std::array<int, 2>> faces;  // edge -> up to two triangles
  const auto attach = [&](int t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t e = key(m.triangles[t][k], m.triangles[t][(k + 1) % 3]);
      auto& f = faces.try_emplace(e, std::array<int, 2>{-1, -1}).first->second;
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
    for (int id : ids)
      q += m.uv[id] / static_cast<double>(ids.size()), p += m.positions[id] / static_cast<double>(ids.size());
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
    for (const auto& [p, q] : {std::pair{a, d}, std::pair{d, b}, std::pair{b, c}, std::pair{c, a}})
      work.push_back(key(p, q));
  }
}

}  // namespace gllab::spline::detail
