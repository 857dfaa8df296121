// common/deform/fast_deform.h — free-form deformation of many vertices at
// once: what deform_mesh (ffd.h) computes, fast enough for a window that
// deforms a 10^5-vertex mesh every frame.
//
// deform_mesh is the textbook layer: per vertex A2.1 FindSpan and A2.3
// DersBasisFuns in each direction (The NURBS Book, 2nd ed., pp. 68, 72), the
// triple sum, then J = [Xs Xt Xu] M^-1 and cof(J) n. It stays the reference.
// The fast layer computes the same quantities in another order
// (fast_deform.cpp explains each step and bench/README.md has what each one
// bought):
//   - each direction's knot spans as polynomials in Taylor form about the
//     span's centre, the coefficients from A2.3 with all p derivatives;
//   - per lattice cell (one span in each direction; the Bernstein lattice is
//     one cell) the trivariate polynomial X(s, t, u) in that form, so a
//     vertex costs a nested Horner scheme instead of basis functions and a
//     (p + 1)^3 sum;
//   - vertices bucketed by cell, and the loop over a bucket vectorised over
//     the vertices (degree fixed at compile time for 1..5).
//
// Agreement with deform_mesh (tests/deform/fast_deform_test.cpp): in double,
// positions to 1e-12 of the lattice's size, det J to 1e-12 of |Xs| |Xt| |Xu| /
// det M, unit normals to 1e-12 times the condition |cof J| / |cof J n| (measured:
// 8e-16, 3e-14, 1.4e-14); in float the outputs are mostly identical and
// otherwise one float rounding apart. The inside / outside test (deform_mesh's
// slack for float vertices; kBoxSlack for double points, as ffd_point), the
// clamping onto the box, the outside vertices' values, the counts and the
// exceptions are deform_mesh's exactly. Deterministic, one thread; the same
// bits with every instruction set (no contraction into FMA, no
// reassociation). bench/README.md ("ffd_bench") has the speed.
#pragma once

#include <cstddef>
#include <vector>

#include "deform/ffd.h"

namespace gllab::deform {

/// deform_mesh(lattice, mesh), computed by the fast layer: the same fields
/// (positions, normals when the mesh has them, colours and indices as given,
/// det J per vertex, outside, folded, min_det, max_det), the same exceptions
/// (an invalid lattice, a vertex that is not finite: "deform_mesh_fast:
/// vertex 5 (...) is not finite").
DeformedMesh deform_mesh_fast(const Lattice& lattice, const IndexedMesh& mesh);

/// The same into `out`, whose arrays are reused: they are not reallocated
/// once `out` has held a mesh at least this large (what a window that
/// deforms every frame wants; the scratch, about 0.5 MB, is allocated per
/// call). `mesh` must not be `out.mesh`; after an exception `out` is partly
/// written.
void deform_mesh_fast(const Lattice& lattice, const IndexedMesh& mesh, DeformedMesh& out);

/// Points in double through the lattice, the fast layer's arithmetic without
/// the float conversions: x[i] goes to ffd_point(lattice, x[i]).x, normals[i]
/// (when given: as many as x, else none) to deform_normal(J, normals[i]).
struct DeformedPoints {
  std::vector<Vec3> x, normals;
  std::vector<double> det;  // det J per point (1 outside the box)
  std::size_t outside = 0, folded = 0;
  double min_det = 1, max_det = 1;  // over the points inside
};
DeformedPoints deform_points_fast(const Lattice& lattice, const std::vector<Vec3>& x,
                                  const std::vector<Vec3>& normals = {});

/// Lattices whose largest degree is above this are deformed by the textbook
/// evaluator (the same results as deform_mesh): the power form about a span's
/// centre loses digits with the degree (measured on random Bernstein
/// lattices: 1e-14 of the lattice's size at degree 8, 4e-14 at 11, 2e-12 at
/// 15; the textbook's A2.3 stays at 1e-15).
inline constexpr int kMaxFastDegree = 8;

}  // namespace gllab::deform
