// common/field/marching_squares.cpp — iso-curves of a bilinear grid (lecture
// notes ch. 1, §1.7 Surface representations, Iso-curves), the saddle cells 5
// and 10 joined naively or by the asymptotic decider (Nielson and Hamann 1991).
#include "field/marching_squares.h"

#include <cmath>
#include <cstdint>
#include <string>

#include "field/internal.h"

namespace gllab::field {

using detail::fail;
using detail::num;

namespace {

void check_input(const Grid2& g, double c) {
  if (g.nx < 2) fail("marching_squares: grid nx=" + std::to_string(g.nx) + " (must be at least 2)");
  if (g.ny < 2) fail("marching_squares: grid ny=" + std::to_string(g.ny) + " (must be at least 2)");
  if (g.values.size() != std::size_t(g.nx) * g.ny)
    fail("marching_squares: values.size()=" + std::to_string(g.values.size()) +
         " (nx ny = " + std::to_string(std::size_t(g.nx) * g.ny) + ")");
  if (!(g.hx > 0) || !std::isfinite(g.hx))
    fail("marching_squares: hx=" + num(g.hx) + " (must be positive)");
  if (!(g.hy > 0) || !std::isfinite(g.hy))
    fail("marching_squares: hy=" + num(g.hy) + " (must be positive)");
  if (!std::isfinite(c)) fail("marching_squares: c=" + num(c) + " (the iso value must be finite)");
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (!std::isfinite(g.at(i, j)))
        fail("marching_squares: value(" + std::to_string(i) + ", " + std::to_string(j) +
             ")=" + num(g.at(i, j)) + " (values must be finite)");
}

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

/// The crossing on each grid edge, made once: x-edges (i, j)-(i+1, j) and
/// y-edges (i, j)-(i, j+1), indexed by their lower point.
struct EdgePoints {
  const Grid2& g;
  double c;
  IsoCurves& out;
  std::vector<std::uint32_t> x, y;

  /// p0 + t (p1 - p0), t = (c - f0) / (f1 - f0), p0 the lower-index end.
  int get(int i, int j, int axis) {
    std::uint32_t& slot = (axis == 0 ? x : y)[std::size_t(j) * g.nx + i];
    if (slot != kNone) return int(slot);
    const int i1 = i + (axis == 0), j1 = j + (axis == 1);
    const double f0 = g.at(i, j), f1 = g.at(i1, j1), t = (c - f0) / (f1 - f0);
    const double x0 = g.x0 + i * g.hx, y0 = g.y0 + j * g.hy;
    const double x1 = g.x0 + i1 * g.hx, y1 = g.y0 + j1 * g.hy;
    slot = std::uint32_t(out.points.size());
    out.points.push_back({x0 + t * (x1 - x0), y0 + t * (y1 - y0)});
    return int(slot);
  }
};

/// The saddle cells' decision: true when the inside corners are joined
/// through the cell, i.e. the bilinear interpolant's saddle value exceeds c.
/// With g = f - c that value is (g0 g2 - g1 g3) / (g0 + g2 - g1 - g3), whose
/// denominator has the sign of the inside diagonal: so the inside corners
/// are joined iff the product of g on their diagonal exceeds the other's.
bool join_inside(const double f[4], int mask, double c) {
  const double d02 = (f[0] - c) * (f[2] - c), d13 = (f[1] - c) * (f[3] - c);
  return mask == 5 ? d02 > d13 : d13 > d02;
}

}  // namespace

// Each cell's corners 0 (i, j), 1 (i+1, j), 2 (i+1, j+1), 3 (i, j+1) run
// counter-clockwise; edge m joins corner m and m + 1. Going round, a segment
// starts where the cycle leaves the inside (in -> out) and ends where it
// enters (out -> in): the inside is then on the segment's left. An inside
// corner is cut off by pairing its exit with the entry just behind it; the
// decider's "joined" pairs an exit with the next entry ahead instead.
IsoCurves marching_squares(const Grid2& g, double c, Saddle rule) {
  check_input(g, c);
  IsoCurves out;
  EdgePoints edges{g, c, out, std::vector<std::uint32_t>(g.values.size(), kNone),
                   std::vector<std::uint32_t>(g.values.size(), kNone)};
  for (int j = 0; j + 1 < g.ny; ++j)
    for (int i = 0; i + 1 < g.nx; ++i) {
      const double f[4] = {g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1), g.at(i, j + 1)};
      int mask = 0;
      for (int m = 0; m < 4; ++m) mask |= int(f[m] > c) << m;
      if (mask == 0 || mask == 15) continue;
      const bool saddle = mask == 5 || mask == 10;
      const bool joined = saddle && rule == Saddle::kDecider && join_inside(f, mask, c);
      auto in = [&](int m) { return (mask >> (m & 3)) & 1; };
      // edge m of the cell as a grid edge: 0 bottom, 1 right, 2 top, 3 left
      auto point = [&](int m) {
        switch (m & 3) {
          case 0:
            return edges.get(i, j, 0);
          case 1:
            return edges.get(i + 1, j, 1);
          case 2:
            return edges.get(i, j + 1, 0);
          default:
            return edges.get(i, j, 1);
        }
      };
      for (int m = 0; m < 4; ++m) {
        if (!in(m) || in(m + 1)) continue;  // not an exit
        for (int step = 1; step < 4; ++step) {
          const int e = joined ? m + step : m + 4 - step;  // the entry ahead / behind
          if (!in(e) && in(e + 1)) {
            out.segments.push_back({point(m), point(e)});
            break;
          }
        }
      }
      out.cells.push_back({i, j, mask, saddle});
    }
  return out;
}

// Each point starts at most one segment and ends at most one (each grid edge
// is crossed once and lies in two cells). Open chains start at a point no
// segment ends at; what is left are closed loops.
std::vector<std::vector<int>> IsoCurves::polylines() const {
  const std::size_t n = points.size();
  std::vector<int> next(n, -1);
  std::vector<char> has_prev(n, 0), used(n, 0);
  for (const auto& s : segments) {
    next[s[0]] = s[1];
    has_prev[s[1]] = 1;
  }
  std::vector<std::vector<int>> lines;
  auto walk = [&](int start) {
    std::vector<int> line{start};
    used[start] = 1;
    for (int p = next[start]; p >= 0; p = next[p]) {
      line.push_back(p);
      if (used[p]) break;  // back at the start: closed
      used[p] = 1;
    }
    lines.push_back(std::move(line));
  };
  for (const auto& s : segments)
    if (!has_prev[s[0]] && !used[s[0]]) walk(s[0]);
  for (const auto& s : segments)
    if (!used[s[0]]) walk(s[0]);
  return lines;
}

}  // namespace gllab::field
