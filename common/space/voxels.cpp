// common/space/voxels.cpp — voxel grids and solid voxelization by ray parity
// (voxels.h).
#include "space/voxels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "space/internal.h"

namespace gllab::space {
namespace {

std::string text(Vec3 p) {
  char b[96];
  std::snprintf(b, sizeof b, "(%g, %g, %g)", p.x, p.y, p.z);
  return b;
}

void check_n(const char* what, int n) {
  if (n < 1 || n > 1024)
    throw std::invalid_argument(std::string(what) + ": n = " + std::to_string(n) +
                                " (must be 1..1024)");
}

/// The orientation of p against the directed edge u -> v in the xy-plane, with p moved by
/// (eps, eps^2) for an infinitesimal eps (simulation of simplicity, Edelsbrunner and Mücke
/// 1990): never 0 unless u == v. A point on an edge shared by two triangles is then inside
/// exactly one of them, and a column through a vertex crosses the fan around it once.
double orient(double ux, double uy, double vx, double vy, double px, double py) {
  const double o = (vx - ux) * (py - uy) - (vy - uy) * (px - ux);
  if (o != 0) return o;
  if (vy != uy) return -(vy - uy);  // d/d(px)
  return vx - ux;                   // d/d(py)
}

}  // namespace

VoxelGrid::VoxelGrid(Box3 cube, int n) : cube_(cube), n_(n) {
  check_n("VoxelGrid", n);
  const Vec3 s = cube.size();
  if (!(s.x > 0) || s.x != s.y || s.x != s.z)
    throw std::invalid_argument("VoxelGrid: the box " + text(cube.lo) + " .. " + text(cube.hi) +
                                " is not a cube with a positive edge");
  h_ = s.x / n;
  const std::size_t cells = std::size_t(n) * n * n;
  words_.assign((cells + 63) / 64, 0);
}

Vec3 VoxelGrid::centre(int i, int j, int k) const {
  return cube_.lo + h_ * Vec3{i + 0.5, j + 0.5, k + 0.5};
}

bool VoxelGrid::at(int i, int j, int k) const {
  const std::size_t b = (std::size_t(k) * n_ + j) * n_ + i;
  return words_[b >> 6] >> (b & 63) & 1;
}

void VoxelGrid::set(int i, int j, int k, bool solid) {
  const std::size_t b = (std::size_t(k) * n_ + j) * n_ + i;
  const std::uint64_t bit = std::uint64_t(1) << (b & 63);
  words_[b >> 6] = solid ? words_[b >> 6] | bit : words_[b >> 6] & ~bit;
}

std::size_t VoxelGrid::solid_count() const {
  std::size_t c = 0;
  for (std::uint64_t w : words_) c += std::size_t(__builtin_popcountll(w));
  return c;
}

bool VoxelGrid::contains(Vec3 p) const {
  if (!cube_.contains(p)) return false;
  const auto index = [&](double v, double lo) { return std::min(n_ - 1, int((v - lo) / h_)); };
  return at(index(p.x, cube_.lo.x), index(p.y, cube_.lo.y), index(p.z, cube_.lo.z));
}

std::string open_edge(const IndexedMesh& mesh) {
  // Every directed edge (a, b) of a triangle, as (min, max, forward?).
  struct Edge {
    std::uint32_t lo, hi;
    bool forward;
  };
  std::vector<Edge> edges;
  edges.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.indices[t + e], b = mesh.indices[t + (e + 1) % 3];
      if (a == b) continue;  // a triangle with a repeated index has no such edge
      edges.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.forward < y.forward;
  });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i, forward = 0;
    for (; j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi; ++j)
      forward += edges[j].forward;
    const std::size_t count = j - i;
    const std::string name =
        "edge (" + std::to_string(edges[i].lo) + ", " + std::to_string(edges[i].hi) + ")";
    if (count != 2)
      return name + " has " + std::to_string(count) + " triangle" + (count == 1 ? "" : "s") +
             " (every edge needs 2)";
    if (forward != 1)
      return name + " runs the same way in both its triangles (the orientation is inconsistent)";
    i = j;
  }
  return "";
}

VoxelGrid voxelize(const IndexedMesh& mesh, Box3 cube, int n, VoxelizeStats* stats) {
  check_n("voxelize", n);
  internal::require_valid_mesh(mesh, "voxelize");
  const std::string open = open_edge(mesh);
  if (!open.empty()) throw std::invalid_argument("voxelize: the mesh is not closed: " + open);
  VoxelGrid grid(cube, n);
  VoxelizeStats s;
  s.triangles = mesh.triangle_count();
  const double h = grid.voxel_size();
  const Vec3 lo = cube.lo;
  std::vector<std::vector<double>> columns(std::size_t(n) * n);  // crossing heights per (i, j)
  const auto P = [&](std::uint32_t v) {
    const float* p = &mesh.positions[3 * std::size_t(v)];
    return Vec3{p[0], p[1], p[2]};
  };
  for (std::size_t t = 0; t < s.triangles; ++t) {
    const Vec3 a = P(mesh.indices[3 * t]), b = P(mesh.indices[3 * t + 1]),
               c = P(mesh.indices[3 * t + 2]);
    if (norm(cross(b - a, c - a)) == 0) {  // no area: no crossing either; counted
      ++s.degenerate_skipped;
      continue;
    }
    // The columns whose centre (x_i, y_j) the triangle's shadow can cover.
    const auto first = [&](double v, double l) {
      return std::max(0, int(std::ceil((v - l) / h - 0.5)));
    };
    const auto last = [&](double v, double l) {
      return std::min(n - 1, int(std::floor((v - l) / h - 0.5)));
    };
    const int i0 = first(std::min({a.x, b.x, c.x}), lo.x),
              i1 = last(std::max({a.x, b.x, c.x}), lo.x);
    const int j0 = first(std::min({a.y, b.y, c.y}), lo.y),
              j1 = last(std::max({a.y, b.y, c.y}), lo.y);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double x = lo.x + (i + 0.5) * h, y = lo.y + (j + 0.5) * h;
        const double wa = orient(b.x, b.y, c.x, c.y, x, y), wb = orient(c.x, c.y, a.x, a.y, x, y),
                     wc = orient(a.x, a.y, b.x, b.y, x, y);
        if (!((wa > 0 && wb > 0 && wc > 0) || (wa < 0 && wb < 0 && wc < 0))) continue;
        // The height at (x, y) from the barycentric weights (the unperturbed ones: on an
        // edge one is 0, and the height is the edge's).
        const double ea = (c.x - b.x) * (y - b.y) - (c.y - b.y) * (x - b.x);
        const double eb = (a.x - c.x) * (y - c.y) - (a.y - c.y) * (x - c.x);
        const double ec = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
        columns[std::size_t(j) * n + i].push_back((ea * a.z + eb * b.z + ec * c.z) /
                                                  (ea + eb + ec));
        ++s.crossings;
      }
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      std::vector<double>& z = columns[std::size_t(j) * n + i];
      std::sort(z.begin(), z.end());
      std::size_t below = 0;  // crossings at or below the voxel centre
      for (int k = 0; k < n; ++k) {
        const double zc = lo.z + (k + 0.5) * h;
        while (below < z.size() && z[below] <= zc) ++below;
        if (below % 2 == 1) grid.set(i, j, k, true);
      }
    }
  if (stats) *stats = s;
  return grid;
}

SignedDistance sphere_distance(Vec3 centre, double r) {
  return [=](Vec3 p) { return norm(p - centre) - r; };
}

SignedDistance torus_distance(Vec3 centre, double R, double r) {
  return [=](Vec3 p) {
    const Vec3 q = p - centre;
    return std::hypot(std::hypot(q.x, q.y) - R, q.z) - r;
  };
}

VoxelGrid voxelize(const SignedDistance& solid, Box3 cube, int n) {
  VoxelGrid grid(cube, n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) grid.set(i, j, k, solid(grid.centre(i, j, k)) < 0);
  return grid;
}

}  // namespace gllab::space
