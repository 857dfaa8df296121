// common/spline/basis_change.h — changing the basis of a cubic segment, notes "Higher Order
// Surfaces", "Changing Bases": Q(u) = U M1 P1 = U M2 P2 with U = [u^3 u^2 u 1], hence
// P1 = M1^-1 M2 P2. The four 4x4 basis matrices, all in the notes' layout (row r multiplies
// u^(3-r)), are the core's own:
//   Bézier           bezier_matrix(3) (bezier.h; notes "Higher Order Surfaces"), P = b_0..b_3
//   uniform B-spline kUniformCubicMatrix (bspline.h; same notes, "Matrix form"), P = P_i..P_{i+3}
//   Hermite          hermite_matrix() (interpolation.h; ch. 1 §1.6), rows reversed to this
//                    layout, P = (X(0), X'(0), X(1), X'(1))
//   power (monomial) the identity, P = (a, b, c, d) of X(u) = a u^3 + b u^2 + c u + d.
#pragma once

#include <array>
#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

enum class CubicBasis { kBezier, kUniformBspline, kHermite, kPower };

/// The basis matrix M of `basis` in the notes' layout: Q(u) = [u^3 u^2 u 1] M P.
std::array<std::array<double, 4>, 4> cubic_basis_matrix(CubicBasis basis);

/// The control data of the same cubic segment in basis `to`: P_to = M_to^-1 M_from P_from
/// (solved by Gaussian elimination with partial pivoting, interpolation.h gauss_solve).
/// P_from must have 4 entries, else std::invalid_argument.
std::vector<Vec3> change_cubic_basis(const std::vector<Vec3>& P_from, CubicBasis from,
                                     CubicBasis to);

/// Q(u) = [u^3 u^2 u 1] M P for the segment's data in `basis`.
Vec3 cubic_basis_point(const std::vector<Vec3>& P, CubicBasis basis, double u);

}  // namespace gllab::spline
