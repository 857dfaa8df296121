// common/field/mc_table.cpp — the marching cubes table, generated rather
// than typed in (lecture notes ch. 1, §1.7 Surface representations,
// Iso-surfaces; Lorensen and Cline 1987 list the 15 base cases this
// reproduces). For every corner mask and every decision on the saddle faces:
//  1. on each face, join its edge crossings into segments, as marching
//     squares does on that face (saddle faces as the decision says);
//  2. the segments of the six faces chain into closed loops around the cell
//     (each crossed edge lies on two faces: it ends a segment on one and
//     starts one on the other);
//  3. each loop is cut into a fan of triangles.
#include "field/mc_table.h"

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace gllab::field::detail {

const std::uint8_t kFaceCorners[6][4] = {
    {0, 2, 4, 6}, {1, 3, 5, 7},  // -x, +x: (y, z)
    {0, 1, 4, 5}, {2, 3, 6, 7},  // -y, +y: (x, z)
    {0, 1, 2, 3}, {4, 5, 6, 7},  // -z, +z: (x, y)
};

// Representatives of Lorensen and Cline's 15 classes (their figure 3; the
// numbering of 9, 11 and 14 is the common reading of it, common/field/README.md).
const std::uint8_t kBaseCaseMasks[15] = {
    0x00,  // 0: no corner
    0x01,  // 1: one corner (0)
    0x03,  // 2: an edge (0, 1)
    0x09,  // 3: a face diagonal (0, 3)
    0x81,  // 4: a body diagonal (0, 7)
    0x07,  // 5: three corners of a face (0, 1, 2)
    0x43,  // 6: an edge and a far corner (0, 1; 6)
    0x16,  // 7: three corners pairwise on face diagonals (1, 2, 4)
    0x0F,  // 8: a face (0, 1, 2, 3)
    0x17,  // 9: a corner and its three neighbours (0; 1, 2, 4): one hexagon
    0xC3,  // 10: two opposite edges (0, 1; 6, 7)
    0x8B,  // 11: a chain of three edges 0-1-3-7, turning one way
    0x87,  // 12: case 5 and a corner none of them touches (0, 1, 2; 7)
    0x69,  // 13: alternate corners, a tetrahedron (0, 3, 5, 6)
    0x8D,  // 14: the chain 0-2-3-7, the mirror image of 11 (no rotation maps one to the other)
};

namespace {

int corner_bit(int corner, int axis) { return (corner >> axis) & 1; }

/// The local edge that joins corners a and b (which differ in one bit).
int edge_of(int a, int b) {
  const int c0 = std::min(a, b), d = a ^ b;
  const int axis = d == 1 ? 0 : d == 2 ? 1 : 2;
  const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;  // the other two axes, lower first
  return 4 * axis + corner_bit(c0, u) + 2 * corner_bit(c0, v);
}

/// The two faces (a bit mask) that an edge lies on.
int faces_of_edge(int e) {
  const int axis = e / 4, u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
  return 1 << (2 * u + (e & 1)) | 1 << (2 * v + ((e >> 1) & 1));
}

/// Face f's corners in the order that runs counter-clockwise seen from
/// outside the cell: (00, 10, 11, 01), reversed when that turns clockwise
/// about the outward normal (found from the corners' positions, not typed).
std::array<int, 4> face_cycle(int f) {
  const std::uint8_t* q = kFaceCorners[f];
  std::array<int, 4> cyc = {q[0], q[1], q[3], q[2]};
  auto pos = [](int c, int axis) { return corner_bit(c, axis); };
  int d1[3], d2[3];
  for (int a = 0; a < 3; ++a) {
    d1[a] = pos(cyc[1], a) - pos(cyc[0], a);
    d2[a] = pos(cyc[2], a) - pos(cyc[1], a);
  }
  const int normal_axis = f / 2, outward = f % 2 ? 1 : -1;
  const int cross = d1[(normal_axis + 1) % 3] * d2[(normal_axis + 2) % 3] -
                    d1[(normal_axis + 2) % 3] * d2[(normal_axis + 1) % 3];
  if (cross * outward < 0) std::reverse(cyc.begin(), cyc.end());
  return cyc;
}

bool inside(int mask, int corner) { return (mask >> corner) & 1; }

/// A saddle face: its diagonal corners agree, neighbouring corners differ.
bool is_saddle(int mask, int f) {
  const std::uint8_t* q = kFaceCorners[f];
  const bool a = inside(mask, q[0]), b = inside(mask, q[1]);
  return a != b && inside(mask, q[3]) == a && inside(mask, q[2]) == b;
}

/// Step 1 on one face: next[e] = the edge where the segment that starts on
/// edge e ends. Going round the face counter-clockwise seen from outside, a
/// segment starts where the cycle enters the inside (out -> in) and ends
/// where it leaves (in -> out), which puts the inside on its right seen from
/// outside: the loop then runs counter-clockwise around the outward normal.
/// The inside run entered at m is separated by the next exit ahead; joined
/// (on a saddle face decided so) the entry pairs with the previous exit.
void join_face(int mask, int f, bool join_inside, int next[12]) {
  const std::array<int, 4> q = face_cycle(f);
  auto in = [&](int m) { return inside(mask, q[(m + 4) % 4]); };
  for (int m = 0; m < 4; ++m) {
    if (in(m) || !in(m + 1)) continue;  // not an entry
    for (int step = 1; step < 4; ++step) {
      const int e = join_inside ? (m - step + 4) % 4 : (m + step) % 4;
      if (in(e) && !in(e + 1)) {
        next[edge_of(q[m], q[(m + 1) % 4])] = edge_of(q[e], q[(e + 1) % 4]);
        break;
      }
    }
  }
}

/// Two loop vertices may be joined by a diagonal unless they lie on one face.
/// Two such vertices that are not neighbours in the loop are possible only on
/// a saddle face (its four crossings make two segments), and the cell next
/// door, which sees the same four crossings, might draw the same diagonal:
/// the edge would be used four times.
bool diagonal_ok(int a, int b) { return (faces_of_edge(a) & faces_of_edge(b)) == 0; }

/// Where no triangulation avoids such a diagonal, the two cells of a face
/// must at least not pick the same one: on its + face (bit 1 of the face
/// number) a cell may join only the two crossings on the face's edges along
/// the lower of its two axes; on its - face any other pair. A pair of one
/// face is the + face of one cell and the - face of the other: never both.
bool diagonal_ok_relaxed(int a, int b) {
  const int shared = faces_of_edge(a) & faces_of_edge(b);
  if (shared == 0) return true;
  const int f = __builtin_ctz(unsigned(shared)), axis = f / 2;
  const int lower = axis == 0 ? 1 : 0;  // the face's lower other axis
  const bool parallel_to_lower = a / 4 == lower && b / 4 == lower;
  return (f & 1) ? parallel_to_lower : !parallel_to_lower;
}

/// Step 3, the usual way: a fan from the first apex whose diagonals are all
/// allowed; -1 when no apex has that.
int fan_apex(const std::vector<int>& loop) {
  const int n = int(loop.size());
  for (int s = 0; s < n; ++s) {
    bool ok = true;
    for (int j = 2; j <= n - 2 && ok; ++j) ok = diagonal_ok(loop[s], loop[(s + j) % n]);
    if (ok) return s;
  }
  return -1;
}

/// Step 3 where no fan will do (a few loops of six or more vertices that pass
/// a saddle face twice): any triangulation with allowed diagonals, by search.
/// The triangle on the side (p[0], p[n-1]) has some apex p[k]; its two other
/// sides must be loop edges or allowed diagonals, and both halves must
/// triangulate. Triangles keep the loop's order (counter-clockwise).
template <class Ok>
bool triangulate_polygon(const std::vector<int>& p, Ok ok, std::vector<std::array<int, 3>>& out) {
  const int n = int(p.size());
  if (n == 3) {
    out.push_back({p[0], p[1], p[2]});
    return true;
  }
  for (int k = 1; k + 1 < n; ++k) {
    if (k > 1 && !ok(p[0], p[k])) continue;
    if (k < n - 2 && !ok(p[k], p[n - 1])) continue;
    const std::size_t mark = out.size();
    out.push_back({p[0], p[k], p[n - 1]});
    const std::vector<int> left(p.begin(), p.begin() + k + 1), right(p.begin() + k, p.end());
    if ((left.size() < 3 || triangulate_polygon(left, ok, out)) &&
        (right.size() < 3 || triangulate_polygon(right, ok, out)))
      return true;
    out.resize(mark);
  }
  return false;
}

/// A loop's triangles: the fan if one will do; else the search without a
/// face diagonal; else the search with the face diagonals the cell's side
/// allows (diagonal_ok_relaxed); else (never, for this table: counted in
/// fans_with_face_diagonal) the fan from vertex 0.
std::vector<std::array<int, 3>> triangulate_loop(const std::vector<int>& loop, int& searched,
                                                 int& relaxed, int& bad) {
  std::vector<std::array<int, 3>> tris;
  const int n = int(loop.size());
  int s = fan_apex(loop);
  if (s < 0) {
    ++searched;
    if (triangulate_polygon(loop, diagonal_ok, tris)) return tris;
    ++relaxed;
    if (triangulate_polygon(loop, diagonal_ok_relaxed, tris)) return tris;
    ++bad;
    s = 0;
  }
  for (int j = 1; j + 1 < n; ++j)
    tris.push_back({loop[s], loop[(s + j) % n], loop[(s + j + 1) % n]});
  return tris;
}

/// Steps 1-3 for one mask and one decision.
McEntry triangulate(int mask, int decision, McTables& tables) {
  int next[12];
  std::fill(next, next + 12, -1);
  for (int f = 0; f < 6; ++f) join_face(mask, f, is_saddle(mask, f) && ((decision >> f) & 1), next);
  McEntry entry;
  bool seen[12] = {};
  for (int e0 = 0; e0 < 12; ++e0) {
    if (next[e0] < 0 || seen[e0]) continue;
    std::vector<int> loop;
    for (int e = e0; !seen[e]; e = next[e]) {
      if (next[e] < 0) throw std::logic_error("mc_table: open loop, mask " + std::to_string(mask));
      seen[e] = true;
      loop.push_back(e);
    }
    for (const auto& tri : triangulate_loop(loop, tables.loops_searched, tables.loops_relaxed,
                                            tables.fans_with_face_diagonal)) {
      if (entry.triangles == kMaxCellTriangles)
        throw std::logic_error("mc_table: too many triangles");
      std::uint8_t* out = entry.edges + 3 * entry.triangles++;
      for (int v = 0; v < 3; ++v) out[v] = std::uint8_t(tri[v]);
    }
  }
  return entry;
}

/// The 24 rotations of the cube as permutations of its corners: the closure
/// of a quarter turn about x and one about z.
std::vector<std::array<int, 8>> cube_rotations() {
  auto turn = [](int axis) {
    std::array<int, 8> p{};
    for (int c = 0; c < 8; ++c) {
      int x = c & 1, y = (c >> 1) & 1, z = c >> 2, nx = x, ny = y, nz = z;
      if (axis == 0)
        ny = 1 - z, nz = y;  // (x, y, z) -> (x, 1 - z, y)
      else
        nx = 1 - y, ny = x;  // about z: (x, y, z) -> (1 - y, x, z)
      p[c] = nx | ny << 1 | nz << 2;
    }
    return p;
  };
  std::vector<std::array<int, 8>> group = {{0, 1, 2, 3, 4, 5, 6, 7}};
  const std::array<std::array<int, 8>, 2> gens = {turn(0), turn(2)};
  for (std::size_t k = 0; k < group.size(); ++k)
    for (const auto& g : gens) {
      std::array<int, 8> h{};
      for (int c = 0; c < 8; ++c) h[c] = g[group[k][c]];
      if (std::find(group.begin(), group.end(), h) == group.end()) group.push_back(h);
    }
  return group;
}

int apply(const std::array<int, 8>& p, int mask) {
  int out = 0;
  for (int c = 0; c < 8; ++c)
    if (inside(mask, c)) out |= 1 << p[c];
  return out;
}

/// Each mask's class: the representative whose orbit under the rotations
/// and complement holds it.
void classify(McTables& t) {
  const auto rotations = cube_rotations();
  if (rotations.size() != 24) throw std::logic_error("mc_table: not 24 rotations");
  std::fill(t.base_class, t.base_class + 256, std::uint8_t(255));
  for (int k = 0; k < 15; ++k)
    for (const auto& r : rotations)
      for (int m : {int(kBaseCaseMasks[k]), 255 - kBaseCaseMasks[k]}) {
        std::uint8_t& slot = t.base_class[apply(r, m)];
        if (slot != 255 && slot != k) throw std::logic_error("mc_table: classes overlap");
        slot = std::uint8_t(k);
      }
  for (int m = 0; m < 256; ++m)
    if (t.base_class[m] == 255) throw std::logic_error("mc_table: mask without class");
}

std::unique_ptr<McTables> build() {
  auto t = std::make_unique<McTables>();
  for (int mask = 0; mask < 256; ++mask) {
    int saddles = 0;
    for (int f = 0; f < 6; ++f) saddles |= is_saddle(mask, f) << f;
    t->saddle_faces[mask] = std::uint8_t(saddles);
    // Lorensen and Cline: separate the corners of the kind there are fewer
    // of; with four of each, the inside corners (README).
    const int count = __builtin_popcount(unsigned(mask));
    t->lorensen_cline[mask] = std::uint8_t(count > 4 ? saddles : 0);
    for (int decision = 0; decision < 64; ++decision) {
      if ((decision & ~saddles) != 0) {
        t->entries[mask][decision] = t->entries[mask][decision & saddles];  // ignored bits
        continue;
      }
      t->entries[mask][decision] = triangulate(mask, decision, *t);
    }
  }
  classify(*t);
  return t;
}

}  // namespace

const McTables& mc_tables() {
  static const std::unique_ptr<McTables> tables = build();
  return *tables;
}

}  // namespace gllab::field::detail
