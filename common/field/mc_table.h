// common/field/mc_table.h — internal (not part of the API): the marching
// cubes triangulation table, generated at first use (mc_table.cpp), and the
// cube's corner, edge and face numbering that marching_cubes.cpp shares.
//
// Corner b is at (b & 1, (b >> 1) & 1, b >> 2) in the unit cell. Edge e joins
// corners c0 < c1 that differ in one bit, the edge's axis: e = 0..3 along x
// (e = y + 2 z of c0), 4..7 along y (e - 4 = x + 2 z), 8..11 along z
// (e - 8 = x + 2 y). Face f = 2 axis + side: -x +x -y +y -z +z.
#pragma once

#include <cstdint>

namespace gllab::field::detail {

/// The most triangles one cell's entry holds (checked when the table is built).
constexpr int kMaxCellTriangles = 12;

/// One cell's triangles: 3 local edges each, counter-clockwise seen from
/// outside (f < c).
struct McEntry {
  std::uint8_t triangles = 0;
  std::uint8_t edges[3 * kMaxCellTriangles] = {};
};

struct McTables {
  /// entries[mask][decision]: decision bit f set = on face f the inside
  /// corners are joined (the face's saddle value > c); only the bits of
  /// saddle_faces[mask] matter, the others are ignored (every decision is filled).
  McEntry entries[256][64];
  std::uint8_t saddle_faces[256];    // bit f: face f's diagonal corners agree, its others differ
  std::uint8_t lorensen_cline[256];  // the decision FaceRule::kLorensenCline takes for a mask
  std::uint8_t base_class[256];      // Lorensen and Cline's class 0..14
  int loops_searched = 0;            // loops no fan could cut without a face diagonal (README)
  int loops_relaxed = 0;             // of those, loops no triangulation could (README)
  int fans_with_face_diagonal = 0;   // of those, loops even the side rule could not: 0
};

/// Built once, on first use (a function-local static: thread-safe).
const McTables& mc_tables();

/// Face f's corners as (00, 10, 01, 11) over its two other axes, the lower
/// axis first: a face's diagonals are (0, 3) and (1, 2) of this list.
extern const std::uint8_t kFaceCorners[6][4];

/// The representative mask of Lorensen and Cline's class k (marching_cubes.h).
extern const std::uint8_t kBaseCaseMasks[15];

}  // namespace gllab::field::detail
