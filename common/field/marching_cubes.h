// common/field/marching_cubes.h — iso-surfaces f(x, y, z) = c of a trilinear
// grid (Lorensen and Cline 1987, "Marching cubes"), with the ambiguous faces
// decided consistently (lecture notes ch. 1, §1.7 Surface representations,
// "Iso-surfaces").
//
// A cell's 8 corners (inside: f > c) give one of 256 cases. The surface
// crosses each cell edge whose corners differ, at the point of linear
// interpolation. On a face whose diagonal corners agree (a saddle face) the
// crossings can be joined two ways. Lorensen and Cline's table decides by the
// cell's case alone, so two cells that share such a face can decide it
// differently and the surface has a hole there. Here every face is decided
// by its own four values with the asymptotic decider (Nielson and Hamann
// 1991), which both cells see alike: the surface is closed.
//
// The triangulation table is not typed in: it is generated, for every case
// and every decision on its saddle faces, by joining the crossings on each
// face (marching squares on the cell's six faces) into closed loops around
// the cell and cutting each loop into a fan of triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "field/grid.h"
#include "mesh/indexed_mesh.h"

namespace gllab::field {

enum class FaceRule {
  kDecider,        // the asymptotic decider on every saddle face: closed surfaces
  kLorensenCline,  // the case alone decides (separate the corners of the fewer kind), as the
                   // 1987 table does: holes where two cells disagree
};

struct McOptions {
  FaceRule faces = FaceRule::kDecider;
  bool normals = true;        // from grid_gradient, interpolated along the edge, normalised
  bool record_cells = false;  // fill McResult::cells
};

struct McCell {
  int i, j, k;          // the cell's lowest corner
  std::uint8_t mask;    // bit b = corner b inside; corner b at (b & 1, (b >> 1) & 1, b >> 2)
  std::uint8_t base;    // Lorensen and Cline's class 0..14 (rotations and complement)
  std::uint8_t saddle_faces;  // bit f set: face f is a saddle face (f: -x +x -y +y -z +z)
  std::uint32_t first_triangle, triangle_count;  // in McResult::mesh.indices / 3
};

struct McResult {
  IndexedMesh mesh;  // positions, normals (if asked), indices; each grid-edge vertex once;
                     // triangles counter-clockwise seen from outside ({f <= c}); no colours
  std::vector<McCell> cells;  // cells the surface crosses, in grid order, if record_cells
};

/// The iso-surface {f = c} of the trilinear interpolant of g. Throws
/// std::invalid_argument naming the value when g is smaller than 2 x 2 x 2,
/// its values and c are not finite, or the spacing is not positive.
McResult marching_cubes(const Grid3& g, double c, const McOptions& options = {});

/// Lorensen and Cline's 15 base cases: the corner mask of a representative of
/// class k (0..14), and the class of any mask. 254 of the 256 masks are a
/// rotation and / or complement of one representative.
std::uint8_t base_case_mask(int k);
int base_case_of(std::uint8_t mask);

}  // namespace gllab::field
