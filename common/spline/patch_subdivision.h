// common/spline/patch_subdivision.h — splitting a Bézier patch (lecture notes
// "Higher Order Surfaces", "Rendering Bezier Patches": "Patch Splitting",
// "Splitting Termination"), its diagonal curve and its matrix form.
//
//   split_u / split_v    one direction only: X(u, v) = sum_j B_j(v) sum_i b_ij
//                        B_i(u), so every column of the net (along u) is split
//                        as a Bézier curve, the v direction left alone
//                        ("we can split in each direction separately").
//   patch_flatness       the notes' test: the plane through three corner
//                        vertices, the largest distance of the others from it.
//   split_adaptive       split in both directions until flat, or until
//                        max_depth: the depth bound is the termination
//                        guarantee (at most 4^max_depth leaves).
//   diagonal_curve       X(t, t) as a Bézier curve of degree n + m.
//   matrix_form_point    U M_n P M_m^T V^T ("Higher Order Surfaces", the
//                        matrix form of the patch).
//
// Notation as surface.h: degree n along u (row i), m along v (column j),
// b_ij = P[i * (m + 1) + j]. Bad input throws SplineError (std::invalid_argument).
//   leaf_quads           each leaf drawn as the flat quad of its four corners:
//                        where a finer leaf meets a coarser one, the finer
//                        leaf's corner on the shared edge is a point of the
//                        surface but the coarser quad's edge is a straight
//                        segment, so a crack opens ("Patch Cracking"). With
//                        close_cracks every such T-junction vertex is snapped
//                        onto the coarser side's edge line (linear in the
//                        parameter between that edge's own end points).
#pragma once

#include <vector>

#include "spline/surface.h"

namespace gllab::spline {

/// The two halves of a patch split along one direction.
struct BezierSurfaceSplit {
  BezierSurface first;   // u (or v) in [a, u0] (or [c, v0])
  BezierSurface second;  // the rest
};

/// Split at u0 (a < u0 < b): each column j of the net is split by de Casteljau
/// (subdivide, bezier.h); both halves keep their part of [a, b] and all of [c, d].
BezierSurfaceSplit split_u(const BezierSurface& surface, double u0);
/// The same along v (a < v0 < d), each row split.
BezierSurfaceSplit split_v(const BezierSurface& surface, double v0);

/// The notes' flatness measure: the plane through b_00, b_n0 and b_0m; the
/// largest distance of any control vertex from it. When those three corners
/// are collinear (no plane) the largest distance from b_00 is returned, which
/// is never smaller, so the test stays on the safe side.
double patch_flatness(const BezierSurface& surface);

/// One leaf of split_adaptive: the sub-patch and how often it was split.
struct PatchLeaf {
  BezierSurface patch;
  int depth = 0;
};

/// Split at the middle of both directions while patch_flatness > tolerance
/// and depth < max_depth. Terminates: depth grows by one per split, so there
/// are at most 4^max_depth leaves. Throws when tolerance <= 0 or max_depth is
/// outside [0, 12]. Leaves in depth-first order (first u half, then v half).
std::vector<PatchLeaf> split_adaptive(const BezierSurface& surface, double tolerance,
                                      int max_depth);

/// One flat quad per leaf: the (u, v) corners (a,c) (b,c) (b,d) (a,d) and their
/// points. close_cracks == false: the points are X at the corners. true: a
/// corner that lies inside (not at an end of) another leaf's edge is moved to
/// the longest such edge's segment, linearly in its parameter between that
/// edge's end points (which are placed the same way first), so every vertex on
/// a shared edge lies on the coarser quad's edge. Leaves must tile a rectangle
/// as split_adaptive's do.
struct LeafQuad {
  Vec2 uv[4];
  Vec3 p[4];
  int depth = 0;
};
std::vector<LeafQuad> leaf_quads(const BezierSurface& surface, const std::vector<PatchLeaf>& leaves,
                                 bool close_cracks);

/// The curve t -> X(a + t (b - a), c + t (d - c)), t in [0, 1], along the
/// domain's diagonal: a Bézier curve of degree n + m, since
/// B_i^n(t) B_j^m(t) = C(n,i) C(m,j) / C(n+m,i+j) B_{i+j}^{n+m}(t), so
///   d_k = sum_{i+j=k} C(n,i) C(m,j) / C(n+m,k) b_ij.
BezierCurve diagonal_curve(const BezierSurface& surface);

/// X(u, v) = (s^n .. s 1) M_n P M_m^T (t^m .. t 1)^T with M from bezier_matrix.
Vec3 matrix_form_point(const BezierSurface& surface, double u, double v);

}  // namespace gllab::spline
