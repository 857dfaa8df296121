// common/field/mesh_measures.cpp — topology, area and enclosed volume of a
// triangle mesh (see mesh_measures.h).
#include "field/mesh_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "spline/vec.h"

namespace gllab::field {

using spline::Vec3;

namespace {

Vec3 vertex(const IndexedMesh& m, std::uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

/// Union-find over the triangles (path halving).
struct Components {
  std::vector<std::size_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

}  // namespace

// Every triangle edge as (smaller vertex, larger vertex, direction, triangle),
// sorted: the uses of one edge come together. An edge used once is a border,
// three or more times non-manifold, twice in the same direction misoriented
// (two neighbours that disagree on the orientation).
MeshTopology topology(const IndexedMesh& m) {
  MeshTopology t;
  t.triangles = m.triangle_count();
  struct Use {
    std::uint64_t key;
    bool forward;
    std::uint32_t triangle;
  };
  std::vector<Use> uses;
  uses.reserve(3 * t.triangles);
  std::vector<char> used(m.vertex_count(), 0);
  for (std::size_t f = 0; f < t.triangles; ++f)
    for (int s = 0; s < 3; ++s) {
      const std::uint32_t a = m.indices[3 * f + s], b = m.indices[3 * f + (s + 1) % 3];
      used[a] = 1;
      const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      uses.push_back({lo << 32 | hi, a < b, std::uint32_t(f)});
    }
  t.vertices = std::size_t(std::count(used.begin(), used.end(), 1));
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) { return x.key < y.key; });
  Components comp(t.triangles);
  for (std::size_t k = 0; k < uses.size();) {
    std::size_t e = k;
    int forward = 0;
    while (e < uses.size() && uses[e].key == uses[k].key) {
      forward += uses[e].forward;
      comp.join(uses[k].triangle, uses[e].triangle);
      ++e;
    }
    const std::size_t n = e - k;
    ++t.edges;
    if (n == 1) ++t.boundary_edges;
    if (n >= 3) ++t.nonmanifold_edges;
    if (n == 2 && forward != 1) ++t.misoriented_edges;
    k = e;
  }
  for (std::size_t f = 0; f < t.triangles; ++f) t.components += comp.find(f) == f;
  return t;
}

double surface_area(const IndexedMesh& m) {
  double area = 0;
  for (std::size_t f = 0; f < m.triangle_count(); ++f) {
    const Vec3 a = vertex(m, m.indices[3 * f]), b = vertex(m, m.indices[3 * f + 1]),
               c = vertex(m, m.indices[3 * f + 2]);
    area += 0.5 * norm(cross(b - a, c - a));
  }
  return area;
}

// Divergence theorem: each triangle and the origin span a tetrahedron of
// signed volume det(a, b, c) / 6 = a . (b x c) / 6.
double enclosed_volume(const IndexedMesh& m) {
  double volume = 0;
  for (std::size_t f = 0; f < m.triangle_count(); ++f) {
    const Vec3 a = vertex(m, m.indices[3 * f]), b = vertex(m, m.indices[3 * f + 1]),
               c = vertex(m, m.indices[3 * f + 2]);
    volume += dot(a, cross(b, c));
  }
  return volume / 6;
}

}  // namespace gllab::field
