// tests/field/peer_support.h — what the peer tests of field::marching_cubes
// share (vtk_peer_test.cpp, skimage_peer_test.cpp): the test grids, and the
// comparison of two vertex sets.
//
// The peers number their vertices in their own order, so vertices are
// compared as sets: each vertex of one set is matched with its nearest
// vertex of the other (a hash of the positions quantised to buckets of
// kBucket, searching the 27 buckets around), and the largest such distance is
// reported both ways. Two sets agree when they have the same size and every
// vertex has a partner within the tolerance on both sides.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "field/grid.h"
#include "field/marching_cubes.h"

namespace gllab::field::peer {

using P3 = std::array<double, 3>;

constexpr double kVertexTolerance = 1e-6;  // world units; the test grids span a few units

/// The grids the own core is compared with the peers on, iso value included.
struct PeerCase {
  std::string name;
  Grid3 grid;
  double c = 0;
};

inline PeerCase sphere_case() {
  // An off-centre sphere with a radius that is no multiple of the spacing: no
  // grid value is exactly the iso value (VTK calls f >= c inside, the own core f > c).
  const Vec3 centre{0.031, -0.017, 0.023};
  return {"sphere_48",
          sample([&](const Vec3& x) { return sphere_field(x, centre, 0.7137); }, Vec3{-1, -1, -1},
                 Vec3{1, 1, 1}, 48, 48, 48),
          0.0};
}

inline PeerCase torus_case() {
  return {"torus_64x64x32",
          sample([](const Vec3& x) { return torus_field(x, 0.6131, 0.2519); }, Vec3{-1, -1, -0.5},
                 Vec3{1, 1, 0.5}, 64, 64, 32),
          0.0};
}

/// Values uniform in [0, 1) from a fixed-seed generator, iso 0.5: about half
/// of all cells are crossed and many faces are saddles.
inline PeerCase noise_case() {
  Grid3 g;
  g.nx = 24;
  g.ny = 20;
  g.nz = 16;
  g.spacing = Vec3{0.1, 0.1, 0.1};
  g.values.resize(std::size_t(g.nx) * g.ny * g.nz);
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  for (float& v : g.values) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    v = float((s >> 40) * (1.0 / 16777216.0));  // 24 bits: exact in float
    if (v == 0.5f) v = 0.25f;
  }
  return {"noise_24x20x16", std::move(g), 0.5};
}

inline PeerCase blob_case(int n) {
  return {"two_blob_" + std::to_string(n), two_blob_benchmark_field(n), 0.5};
}

/// The cases by number, built per test (ctest runs each test in its own
/// process: it builds only the grid it needs).
constexpr int kPeerCases = 5;
inline PeerCase peer_case(int k) {
  switch (k) {
    case 0:
      return sphere_case();
    case 1:
      return torus_case();
    case 2:
      return noise_case();
    case 3:
      return blob_case(64);
    default:
      return blob_case(256);
  }
}
inline std::string peer_case_name(int k) {
  static const char* const names[kPeerCases] = {"sphere_48", "torus_64x64x32", "noise_24x20x16",
                                                "two_blob_64", "two_blob_256"};
  return names[k];
}

/// How many grid values equal c exactly (the peers may classify them
/// differently; the test grids have none).
inline std::size_t values_equal_to(const Grid3& g, double c) {
  return std::size_t(
      std::count_if(g.values.begin(), g.values.end(), [c](float v) { return double(v) == c; }));
}

inline std::vector<P3> positions(const IndexedMesh& m) {
  std::vector<P3> p(m.vertex_count());
  for (std::size_t k = 0; k < p.size(); ++k)
    p[k] = {m.positions[3 * k], m.positions[3 * k + 1], m.positions[3 * k + 2]};
  return p;
}

struct SetComparison {
  std::size_t a_count = 0, b_count = 0;
  double a_to_b = 0, b_to_a = 0;  // max over a (b) of the distance to the nearest of b (a)
  std::size_t a_unmatched = 0, b_unmatched = 0;  // farther than the tolerance
  bool agree(double tol = kVertexTolerance) const {
    return a_count == b_count && a_to_b <= tol && b_to_a <= tol && a_unmatched == 0 &&
           b_unmatched == 0;
  }
};

namespace detail {

constexpr double kBucket = 4e-6;  // > the tolerance: the 27 buckets around hold every candidate

struct KeyHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& k) const {
    return std::size_t(k[0] * 73856093 ^ k[1] * 19349663 ^ k[2] * 83492791);
  }
};
using Buckets =
    std::unordered_map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>, KeyHash>;

inline std::array<std::int64_t, 3> key(const P3& p) {
  return {std::int64_t(std::floor(p[0] / kBucket)), std::int64_t(std::floor(p[1] / kBucket)),
          std::int64_t(std::floor(p[2] / kBucket))};
}

// Max over a of the distance to the nearest of b (infinity when none within
// a bucket), and how many are farther than tol.
inline void nearest(const std::vector<P3>& a, const std::vector<P3>& b, double tol, double& max_d,
                    std::size_t& unmatched) {
  Buckets buckets;
  buckets.reserve(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) buckets[key(b[k])].push_back(std::uint32_t(k));
  max_d = 0;
  unmatched = 0;
  for (const P3& p : a) {
    const auto c = key(p);
    double best = std::numeric_limits<double>::infinity();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = buckets.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == buckets.end()) continue;
          for (std::uint32_t q : it->second) {
            const double ex = p[0] - b[q][0], ey = p[1] - b[q][1], ez = p[2] - b[q][2];
            best = std::min(best, std::sqrt(ex * ex + ey * ey + ez * ez));
          }
        }
    max_d = std::max(max_d, best);
    if (!(best <= tol)) ++unmatched;
  }
}

}  // namespace detail

inline SetComparison compare_sets(const std::vector<P3>& a, const std::vector<P3>& b,
                                  double tol = kVertexTolerance) {
  SetComparison r;
  r.a_count = a.size();
  r.b_count = b.size();
  detail::nearest(a, b, tol, r.a_to_b, r.a_unmatched);
  detail::nearest(b, a, tol, r.b_to_a, r.b_unmatched);
  return r;
}

inline std::string describe(const SetComparison& r, const char* a, const char* b) {
  char buf[320];
  std::snprintf(
      buf, sizeof buf,
      "%s %zu vertices, %s %zu; max distance %s->%s %.2e, %s->%s %.2e; unmatched %zu / %zu", a,
      r.a_count, b, r.b_count, a, b, r.a_to_b, b, a, r.b_to_a, r.a_unmatched, r.b_unmatched);
  return buf;
}

/// Cells the own core recorded: how many have a saddle face.
inline std::size_t ambiguous_cells(const McResult& r) {
  return std::size_t(std::count_if(r.cells.begin(), r.cells.end(),
                                   [](const McCell& c) { return c.saddle_faces != 0; }));
}

}  // namespace gllab::field::peer
