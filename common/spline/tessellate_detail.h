// common/spline/tessellate_detail.h — internal: not part of the core's API.
// Include it only from the tessellator's own files (tessellate*.cpp,
// triangulate.cpp, patch_*.cpp); labs and tests use tessellate.h.
//
// The few helpers that two parts of the tessellator share: lattice positions
// and recursive bisection (curve flattening and the patch edges), the
// orientation test and the loop triangulator (ear clipping and the cut cells),
// and pi (link, flip_slivers).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "spline/vec.h"

namespace gllab::spline::detail {

inline constexpr double kPi = 3.14159265358979323846;

/// Lattice positions: integer k in [0, n] stands for a + (b - a) k / n. The end
/// k == n is b itself, so a patch's last sample is exactly its neighbour's first.
using Index = std::int64_t;
inline double lattice_param(double a, double b, Index k, Index n) {
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

/// Twice the signed area of the triangle a b c: > 0 when it turns counter-clockwise.
inline double orient(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

/// Ear clipping of loops of indices into pt, each outer loop with its holes
/// (triangulate.cpp); appends the triangles to out.
void triangulate_loops(const std::vector<Vec2>& pt, const std::vector<std::vector<int>>& loops,
                       std::vector<std::array<int, 3>>& out);

}  // namespace gllab::spline::detail
