// common/deform/teapot.h — Newell's Utah teapot (1975) as 32 bicubic Bézier
// patches, and the indexed triangle mesh the free-form-deformation lab deforms
// (lecture notes ch. 1, §1.7 Surface representations, "Bézier tensor product").
//
// The data. Martin Newell's table (1975), as published in Frank Crow, "The
// origins of the teapot", IEEE Computer Graphics and Applications 7(1), 1987,
// and passed on since in the "teaset" files (teapot.cpp says which copy):
// 306 control points and 32 patches of 4 x 4 indices, the version with a
// bottom (4 patches added later; Newell's teapot had none) and with z up.
// The coordinates are the table's own: the teapot stands on z = 0 and reaches
// z = 3.15 at the lid's knob, the body's widest radius is 2 (at z = 0.9), the
// handle reaches x = -3 and the spout's tip x = 3.434; nothing is rescaled
// (the lab scales it). The 32 patches, in the table's order:
//     0..3 rim, 4..11 body (two rings of 4), 12..15 handle, 16..19 spout,
//     20..27 lid (the knob, then the lid), 28..31 bottom.
// What the table is, checked in tests/deform/teapot_test.cpp:
//   - 306 entries but 294 distinct points: the bottom repeats, as its own
//     entries (270..273, 282..284, 291..293, 300, 301), the 12 points of the
//     body's lowest ring, z = 0.15; and 4 entries are used by no patch (204,
//     205, 215, 222: points 0.002 from the knob's top, (0, 0, 3.15)).
//   - The knob's and the bottom's first row is one point repeated 4 times: a
//     collapsed edge, the pole where the 4 patches of the ring meet (the edge
//     u = 0 is a point, so Sv = 0 and Su x Sv = 0 along it).
//   - Neighbouring patches share the indices of their common boundary row or
//     column (C0 by construction), except the bottom, whose boundary with the
//     body uses those repeated points (the same coordinates, in the opposite
//     order). The handle's lower end uses the body's point 68, (-2, 0, 0.9).
//   - Handle and spout are separate tubes, open at both ends, that run into the
//     body; the lid (radius 1.3) does not reach the rim (inner radius 1.4). So
//     the surface is not closed and not a manifold.
//   - Rim, body, lid and bottom, closed by the flat ring between lid and rim
//     (z = 2.4, radius 1.3 to 1.4), enclose a volume of 25.25 (the table's
//     units cubed).
//
// Orientation. Every patch is listed as 4 rows of 4 indices. Read as the table
// stands, the row index as u and the column index as v, every one of the 32
// patches has Su x Sv pointing into the teapot (the body's rows run down, its
// columns clockwise seen from above; the bottom's rows run outward from the
// centre, its columns anticlockwise). All 32 agree: this version has no lid or
// bottom turned against the rest. teapot_patches() turns them all outward by
// reversing each row: P[i * 4 + j] = point[index[i * 4 + 3 - j]], so the
// normal (Su x Sv) / |Su x Sv| of surface.h points out of the teapot.
#pragma once

#include <array>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "spline/surface.h"
#include "spline/vec.h"

namespace gllab::deform {

using spline::Vec3;

inline constexpr int kTeapotPointCount = 306;
inline constexpr int kTeapotPatchCount = 32;

/// Newell's 306 control points, the table's order (z up, the table's units).
const std::vector<Vec3>& teapot_control_points();

/// The 32 patches as published: 16 indices (0-based) into
/// teapot_control_points() each, 4 rows of 4.
const std::vector<std::array<int, 16>>& teapot_patch_indices();

/// A part of the teapot: the patches first .. first + count - 1.
struct TeapotPart {
  const char* name;
  int first, count;
};
/// rim {0, 4}, body {4, 8}, handle {12, 4}, spout {16, 4}, lid {20, 8},
/// bottom {28, 4}: the table's order.
const std::array<TeapotPart, 6>& teapot_parts();

/// The 32 bicubic patches (n = m = 3, [0, 1]^2), in the table's order, each
/// row of the table reversed so that Su x Sv points outward (the note at the
/// top): P[i * 4 + j] = teapot_control_points()[teapot_patch_indices()[p][i * 4 + 3 - j]].
const std::vector<spline::BezierSurface>& teapot_patches();

/// Samples per patch side: teapot_mesh takes 1..kMaxTeapotPerPatch. At the
/// limit the mesh has 2.1e6 vertices and 4.2e6 triangles (about 100 MB of
/// floats and indices, 400 MB while it is built, 3 s), twenty times the
/// lab's finest setting.
inline constexpr int kMaxTeapotPerPatch = 256;

/// Two samples closer than this (in every coordinate, the table's units)
/// are one point. The same boundary curve evaluated from two patches agrees
/// only to rounding (up to 2e-15 here) where the two patches run along it in
/// opposite directions (bottom and body) or where a row of equal control
/// points is blended (the knob's pole), so an exact comparison would leave
/// cracks; 1e-9 is far above that rounding and far below the distance between
/// two distinct samples (at least 5e-5 at kMaxTeapotPerPatch).
inline constexpr double kTeapotWeldTolerance = 1e-9;

/// Coinciding samples share one vertex and an averaged normal only when their
/// normals are within this angle of each other (the patches meet smoothly
/// there); otherwise each keeps its own vertex and normal (a crease). Where
/// the teapot's patches meet their normals agree to rounding (1e-6 degrees,
/// what acos resolves); the one crease among coinciding samples, the handle's
/// lower end on the body at (-2, 0, 0.9), is 114 degrees. Any angle between
/// gives the same mesh.
inline constexpr double kTeapotCreaseDegrees = 1.0;

/// The teapot as an indexed triangle mesh. Each patch is sampled on the
/// (per_patch + 1)^2 grid u = a / per_patch, v = b / per_patch; each grid cell
/// gives the triangles (a, b), (a + 1, b), (a + 1, b + 1) and (a, b),
/// (a + 1, b + 1), (a, b + 1), counter-clockwise seen from outside. Samples
/// within kTeapotWeldTolerance of each other whose normals are within
/// kTeapotCreaseDegrees are one vertex (patch seams, the poles), its normal
/// the normalised sum of theirs; the position is the first sample's (patch
/// order, then a, then b). A triangle whose corners are not three different
/// vertices (one per cell next to a pole) is left out.
///
/// Normals: (Su x Sv) / |Su x Sv| from the patch, what spline::surface_normal
/// gives, computed for a whole patch at once by spline::surface_grid
/// (fast/surface_batch.h). At the two poles, the knob's top and the bottom's
/// centre, Su x Sv = 0 and surface_normal takes the normal's limit from inside
/// the patch (its first Taylor term; surface.h): (0, 0, 1) at the knob's top,
/// (0, 0, -1) at the bottom's centre, the same from each of the 4 patches and
/// from every sample on the collapsed edge. From per_patch = 6 on every
/// vertex normal lies on the outer side of each of its triangles; coarser
/// grids cut chords across the rim's and the spout's tight lips (per_patch = 1:
/// 60 of 168 corners on the wrong side).
///
/// Volume: the triangles' signed volume, sum p0 . (p1 x p2) / 6, is positive:
/// 25.68, 25.87, 25.914, 25.925 at per_patch = 8, 16, 32, 56, tending to the
/// patches' own 25.930 at second order (the open handle, spout and lid gap
/// counted as they are, about the origin).
///
/// Counts, with k = per_patch: the rim, body, bottom and lid are two grids of
/// 4k points around (the pole and 4k rows below it; the pole and 2k rows
/// below it), handle and spout two tubes of 2k points around and 2k + 1 along:
///     vertices  = 32 k^2 + 4 k + 2,     triangles = 64 k^2 - 8 k
/// (the handle's end point on the body counted twice, the crease above).
///     k = 8:   2 082 vertices,   4 032 triangles
///     k = 16:  8 258 vertices,  16 256 triangles   (about 10^4: the lab's default)
///     k = 32: 32 898 vertices,  65 280 triangles
///     k = 56: 100 578 vertices, 200 256 triangles  (about 10^5: the lab's finest)
/// Colours are empty. Throws std::invalid_argument naming per_patch when it is
/// outside 1..kMaxTeapotPerPatch.
IndexedMesh teapot_mesh(int per_patch);

}  // namespace gllab::deform
