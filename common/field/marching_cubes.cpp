// common/field/marching_cubes.cpp — iso-surfaces of a trilinear grid
// (Lorensen and Cline 1987; lecture notes ch. 1, §1.7 Surface
// representations, Iso-surfaces), with the saddle faces decided by the
// asymptotic decider (Nielson and Hamann 1991) and the empty space skipped
// as Flying Edges does (Schroeder, Maynard and Geveci 2015).
//
// Two passes over the grid, in grid order (z slabs, y rows, x fastest):
//  1. classify_rows: for each x-row of points, the first and last x-edge the
//     surface crosses and whether its first and last points are inside. A
//     row outside that range is all one side of c.
//  2. For each cell row (four point rows), cell_row_range trims the x-range
//     of cells the surface can cross (none: the row is skipped), and
//     march_cell_row visits those cells: corner mask, face decisions, the
//     generated table (mc_table.cpp), one vertex per crossed grid edge.
#include "field/marching_cubes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <string>

#include "field/internal.h"
#include "field/mc_table.h"

namespace gllab::field {

using detail::fail;
using detail::num;

namespace {

// ---- checks -------------------------------------------------------------------

void check_input(const Grid3& g, double c) {
  const int n[3] = {g.nx, g.ny, g.nz};
  const char* names[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < 3; ++a)
    if (n[a] < 2)
      fail("marching_cubes: grid " + std::string(names[a]) + "=" + std::to_string(n[a]) +
           " (must be at least 2)");
  const std::size_t count = std::size_t(g.nx) * g.ny * g.nz;
  if (g.values.size() != count)
    fail("marching_cubes: values.size()=" + std::to_string(g.values.size()) +
         " (nx ny nz = " + std::to_string(count) + ")");
  const double h[3] = {g.spacing.x, g.spacing.y, g.spacing.z};
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a)
    if (!(h[a] > 0) || !std::isfinite(h[a]))
      fail("marching_cubes: spacing." + std::string(axes[a]) + "=" + num(h[a]) +
           " (must be positive and finite)");
  if (!std::isfinite(g.origin.x) || !std::isfinite(g.origin.y) || !std::isfinite(g.origin.z))
    fail("marching_cubes: origin=(" + num(g.origin.x) + ", " + num(g.origin.y) + ", " +
         num(g.origin.z) + ") (must be finite)");
  if (!std::isfinite(c)) fail("marching_cubes: c=" + num(c) + " (the iso value must be finite)");
}

[[noreturn]] void non_finite_value(const Grid3& g, std::size_t row, const float* v) {
  int i = 0;
  while (std::isfinite(v[i])) ++i;
  const int j = int(row % g.ny), k = int(row / g.ny);
  fail("marching_cubes: value(" + std::to_string(i) + ", " + std::to_string(j) + ", " +
       std::to_string(k) + ")=" + num(v[i]) + " (values must be finite)");
}

/// The float threshold cf with (v > cf) == (double(v) > c) for every float
/// v: c rounded down to a float (a float above that is above c too).
float float_threshold(double c) {
  if (c >= double(FLT_MAX)) return FLT_MAX;
  if (c < -double(FLT_MAX)) return -INFINITY;
  float cf = float(c);
  if (double(cf) > c) cf = std::nextafter(cf, -INFINITY);
  return cf;
}

// ---- pass 1: the x-rows of points ---------------------------------------------

/// What pass 1 knows about one x-row of points: the surface crosses x-edges
/// lo .. hi - 1 only (none: lo = nx - 1, hi = 0), and the row's first and
/// last points are inside or not.
struct RowSpan {
  int lo, hi;
  bool first_in, last_in;
};

/// The first i >= from with (v[i] > cf) != side, or n. Blocks of 16 are
/// tested with a count the compiler vectorises; the block that changes is
/// searched one by one.
int find_change(const float* v, int from, int n, float cf, bool side) {
  int i = from;
  for (; i + 16 <= n; i += 16) {
    int count = 0;
    for (int m = 0; m < 16; ++m) count += v[i + m] > cf;
    if (count != (side ? 16 : 0)) break;
  }
  for (; i < n; ++i)
    if ((v[i] > cf) != side) return i;
  return n;
}

/// The last i < to with (v[i] > cf) != side, or -1 (as find_change, backwards).
int find_change_back(const float* v, int to, float cf, bool side) {
  int i = to;
  for (; i >= 16; i -= 16) {
    int count = 0;
    for (int m = 1; m <= 16; ++m) count += v[i - m] > cf;
    if (count != (side ? 16 : 0)) break;
  }
  for (; i-- > 0;)
    if ((v[i] > cf) != side) return i;
  return -1;
}

/// One row: a single vectorised sweep counts the inside points and checks
/// that every value is finite (exponent bits not all set); only a row with
/// both kinds of points is searched for its first and last crossing, from
/// each end (the part between is never looked at again here).
RowSpan classify_row(const Grid3& g, std::size_t row, const float* v, float cf) {
  const int nx = g.nx;
  int inside = 0;
  std::uint32_t non_finite = 0;
  for (int i = 0; i < nx; ++i) {
    std::uint32_t bits;
    std::memcpy(&bits, v + i, sizeof bits);
    non_finite |= (bits & 0x7f800000u) == 0x7f800000u;
    inside += v[i] > cf;
  }
  if (non_finite) non_finite_value(g, row, v);
  const bool first_in = v[0] > cf, last_in = v[nx - 1] > cf;
  if (inside == 0 || inside == nx) return {nx - 1, 0, first_in, last_in};
  // x-edge i joins points i and i + 1: the first crossed edge ends at the
  // first point unlike point 0, the last starts at the last point unlike point nx - 1.
  const int lo = find_change(v, 1, nx, cf, first_in) - 1;
  const int hi = find_change_back(v, nx - 1, cf, last_in) + 1;
  return {lo, hi, first_in, last_in};
}

std::vector<RowSpan> classify_rows(const Grid3& g, float cf) {
  const std::size_t rows = std::size_t(g.ny) * g.nz;
  std::vector<RowSpan> spans(rows);
  for (std::size_t r = 0; r < rows; ++r)
    spans[r] = classify_row(g, r, g.values.data() + r * g.nx, cf);
  return spans;
}

// ---- pass 2: the cell rows ------------------------------------------------------

/// The cells [i0, i1) of cell row (j, k) that the surface can cross, from its
/// four point rows; i0 >= i1 when none. Left of every row's first crossing
/// the four rows are each one side of c: if they agree there no cell is
/// crossed, if not every cell is (by y- or z-edges); the same on the right.
void cell_row_range(const std::vector<RowSpan>& spans, int nx, int ny, int j, int k, int& i0,
                    int& i1) {
  const RowSpan* r[4] = {&spans[std::size_t(k) * ny + j], &spans[std::size_t(k) * ny + j + 1],
                         &spans[std::size_t(k + 1) * ny + j],
                         &spans[std::size_t(k + 1) * ny + j + 1]};
  int lo = nx - 1, hi = 0;
  bool first_same = true, last_same = true;
  for (const RowSpan* s : r) {
    lo = std::min(lo, s->lo);
    hi = std::max(hi, s->hi);
    first_same = first_same && s->first_in == r[0]->first_in;
    last_same = last_same && s->last_in == r[0]->last_in;
  }
  i0 = first_same ? lo : 0;
  i1 = last_same ? hi : nx - 1;
}

/// The vertex of each crossed grid edge, made once: ids of the x- and y-edges
/// of two z-planes of points (by parity) and of the z-edges of the current
/// slab. The arrays are never cleared: an id counts only if it was made
/// while a slab touching its plane (or, for z-edges, this slab) was marched,
/// i.e. it is >= that slab's first id. Vertex ids only grow, so an id left
/// over from an older plane is smaller and reads as "none".
class EdgeVertices {
 public:
  EdgeVertices(const Grid3& g, double c, bool normals, IndexedMesh& mesh)
      : g_(g), c_(c), normals_(normals), mesh_(mesh), plane_size_(std::size_t(g.nx) * g.ny) {
    for (int p = 0; p < 2; ++p) {
      x_[p].assign(plane_size_, kNone);
      y_[p].assign(plane_size_, kNone);
    }
    z_.assign(plane_size_, kNone);
  }

  /// Called before slab k (planes k and k + 1) is marched.
  void begin_slab(int k) {
    const std::uint32_t now = count();
    lo_[k & 1] = k == 0 ? now : slab_lo_;  // plane k: made in slab k - 1 or k
    lo_[(k + 1) & 1] = now;                // plane k + 1: only in slab k (and later)
    slab_lo_ = now;                        // z-edges: this slab only
    k_ = k;
  }

  /// The vertex on local edge e (mc_table.h numbering) of cell (i, j, k_).
  std::uint32_t get(int e, int i, int j) {
    const int axis = e >> 2, b0 = e & 1, b1 = (e >> 1) & 1;
    switch (axis) {
      case 0:  // x-edge from point (i, j + b0, k + b1)
        return lookup(x_[(k_ + b1) & 1][std::size_t(j + b0) * g_.nx + i], lo_[(k_ + b1) & 1], i,
                      j + b0, k_ + b1, 0);
      case 1:  // y-edge from point (i + b0, j, k + b1)
        return lookup(y_[(k_ + b1) & 1][std::size_t(j) * g_.nx + i + b0], lo_[(k_ + b1) & 1],
                      i + b0, j, k_ + b1, 1);
      default:  // z-edge from point (i + b0, j + b1, k)
        return lookup(z_[std::size_t(j + b1) * g_.nx + i + b0], slab_lo_, i + b0, j + b1, k_, 2);
    }
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  std::uint32_t count() const { return std::uint32_t(mesh_.positions.size() / 3); }

  std::uint32_t lookup(std::uint32_t& slot, std::uint32_t lo, int i, int j, int k, int axis) {
    // lo <= slot < count, in one unsigned comparison (kNone wraps to large).
    if (slot - lo < count() - lo) return slot;
    slot = count();
    make_vertex(i, j, k, axis);
    return slot;
  }

  /// p0 + t (p1 - p0), t = (c - f0) / (f1 - f0) in double from the floats, p0
  /// the edge's lower-index end (vtkMarchingCubes' formula); the normal is
  /// the grid gradient interpolated along the edge, normalised and turned
  /// outward (towards f < c: minus the gradient).
  void make_vertex(int i, int j, int k, int axis) {
    const int i1 = i + (axis == 0), j1 = j + (axis == 1), k1 = k + (axis == 2);
    const double f0 = g_.at(i, j, k), f1 = g_.at(i1, j1, k1);
    const double t = (c_ - f0) / (f1 - f0);
    const Vec3 p0 = g_.point(i, j, k), p1 = g_.point(i1, j1, k1);
    const Vec3 p = p0 + t * (p1 - p0);
    mesh_.positions.insert(mesh_.positions.end(), {float(p.x), float(p.y), float(p.z)});
    if (!normals_) return;
    const Vec3 n0 = g_.grid_gradient(i, j, k), n1 = g_.grid_gradient(i1, j1, k1);
    const Vec3 n = -normalized(n0 + t * (n1 - n0));
    mesh_.normals.insert(mesh_.normals.end(), {float(n.x), float(n.y), float(n.z)});
  }

  const Grid3& g_;
  const double c_;
  const bool normals_;
  IndexedMesh& mesh_;
  const std::size_t plane_size_;
  std::vector<std::uint32_t> x_[2], y_[2], z_;
  std::uint32_t lo_[2] = {0, 0}, slab_lo_ = 0;
  int k_ = 0;
};

/// The asymptotic decider on the saddle faces of a cell (Nielson and Hamann
/// 1991): the bilinear interpolant of a face has its saddle value
/// (f00 f11 - f10 f01) / (f00 + f11 - f10 - f01); with g = f - c the inside
/// corners are joined iff the saddle value of g is > 0, i.e. iff the product
/// of g on the inside diagonal exceeds the product on the other (the
/// denominator has the sign of the inside diagonal). Both cells that share a
/// face compute this from the same four values alike.
int decide_faces(const double gc[8], int mask, int saddles) {
  int decision = 0;
  for (int f = 0; f < 6; ++f) {
    if (!((saddles >> f) & 1)) continue;
    const std::uint8_t* q = detail::kFaceCorners[f];
    const double d03 = gc[q[0]] * gc[q[3]], d12 = gc[q[1]] * gc[q[2]];
    const bool inside_03 = (mask >> q[0]) & 1;
    if (inside_03 ? d03 > d12 : d12 > d03) decision |= 1 << f;
  }
  return decision;
}

struct Marcher {
  const Grid3& g;
  double c;
  float cf;
  McOptions options;
  const detail::McTables& tables;
  EdgeVertices& vertices;
  McResult& result;

  /// Cells [i0, i1) of cell row (j, k): each cell's mask from its eight
  /// corners (bit b = corner b inside), the four corners at x = i + 1 kept
  /// for the next cell; crossed cells emit the table's triangles.
  void march_cell_row(int j, int k, int i0, int i1) {
    const std::size_t nx = std::size_t(g.nx), ny = std::size_t(g.ny);
    const float* row[4] = {&g.values[(k * ny + j) * nx], &g.values[(k * ny + j + 1) * nx],
                           &g.values[((k + 1) * ny + j) * nx],
                           &g.values[((k + 1) * ny + j + 1) * nx]};
    auto side = [&](int i) {  // corners 0, 2, 4, 6 of a cell whose x = 0 face is at i
      return unsigned(row[0][i] > cf) | unsigned(row[1][i] > cf) << 2 |
             unsigned(row[2][i] > cf) << 4 | unsigned(row[3][i] > cf) << 6;
    };
    unsigned left = side(i0);
    for (int i = i0; i < i1; ++i) {
      const unsigned right = side(i + 1);
      const unsigned mask = left | right << 1;
      left = right;
      if (mask != 0 && mask != 255) emit_cell(row, i, j, k, mask);
    }
  }

  void emit_cell(const float* const row[4], int i, int j, int k, unsigned mask) {
    const int saddles = tables.saddle_faces[mask];
    int decision = 0;
    if (saddles) {
      if (options.faces == FaceRule::kLorensenCline) {
        decision = tables.lorensen_cline[mask];
      } else {
        double gc[8];
        for (int b = 0; b < 8; ++b) gc[b] = double(row[b >> 1][i + (b & 1)]) - c;
        decision = decide_faces(gc, int(mask), saddles);
      }
    }
    const detail::McEntry& entry = tables.entries[mask][decision];
    std::vector<std::uint32_t>& indices = result.mesh.indices;
    const std::uint32_t first = std::uint32_t(indices.size() / 3);
    for (int t = 0; t < 3 * entry.triangles; ++t)
      indices.push_back(vertices.get(entry.edges[t], i, j));
    if (options.record_cells)
      result.cells.push_back({i, j, k, std::uint8_t(mask), tables.base_class[mask],
                              std::uint8_t(saddles), first, entry.triangles});
  }
};

}  // namespace

McResult marching_cubes(const Grid3& g, double c, const McOptions& options) {
  check_input(g, c);
  const detail::McTables& tables = detail::mc_tables();
  const float cf = float_threshold(c);
  const std::vector<RowSpan> spans = classify_rows(g, cf);  // pass 1 (and the finite check)
  McResult result;
  EdgeVertices vertices(g, c, options.normals, result.mesh);
  Marcher marcher{g, c, cf, options, tables, vertices, result};
  for (int k = 0; k + 1 < g.nz; ++k) {  // pass 2
    vertices.begin_slab(k);
    for (int j = 0; j + 1 < g.ny; ++j) {
      int i0, i1;
      cell_row_range(spans, g.nx, g.ny, j, k, i0, i1);
      if (i0 < i1) marcher.march_cell_row(j, k, i0, i1);
    }
  }
  return result;
}

std::uint8_t base_case_mask(int k) {
  if (k < 0 || k > 14) fail("base_case_mask: k=" + std::to_string(k) + " (must be in 0..14)");
  return detail::kBaseCaseMasks[k];
}

int base_case_of(std::uint8_t mask) { return detail::mc_tables().base_class[mask]; }

}  // namespace gllab::field
