// common/spline/tridiagonal.h — O(n) solvers for the linear systems of cubic
// spline interpolation.
//
// The natural and clamped cubic splines lead to a tridiagonal system, the
// periodic spline to a cyclic tridiagonal one (ch. 1 §1.6, "the LU
// decomposition for tridiagonal matrices is appropriate due to its complexity
// of O(n)"). Row i of an N x N system reads
//
//     lower[i] * x[i-1]  +  diag[i] * x[i]  +  upper[i] * x[i+1]  =  rhs[i]
//
// Plain tridiagonal: lower[0] and upper[N-1] are outside the matrix and ignored.
// Cyclic: the indices wrap around, so lower[0] multiplies x[N-1] (top-right
// corner) and upper[N-1] multiplies x[0] (bottom-left corner).
//
// The right-hand side is a number per row, or a Vec3 per row: a parametric
// curve solves its x, y and z components with one matrix at once
// (ch. 1 §1.6, "compute the spline curves for each component individually").
//
// Neither solver pivots. That is safe for the spline matrices, which are
// strictly diagonally dominant (ch. 1 §1.6, comment 2). Any other matrix
// may hit a zero pivot; the solvers then throw std::invalid_argument naming
// the row, e.g. "solve_tridiagonal: zero pivot 0 in row 0 (the matrix needs
// pivoting or is singular)".
#pragma once

#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

/// Thomas algorithm: Gaussian elimination without pivoting on a tridiagonal
/// matrix, O(N). Returns x with lower[i] x[i-1] + diag[i] x[i] + upper[i] x[i+1]
/// = rhs[i]. All four vectors have N entries; N == 0 returns an empty x.
std::vector<double> solve_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                      const std::vector<double>& upper, const std::vector<double>& rhs);
std::vector<Vec3> solve_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                    const std::vector<double>& upper, const std::vector<Vec3>& rhs);

/// Cyclic tridiagonal system (indices wrap: row 0 couples to x[N-1] through
/// lower[0], row N-1 to x[0] through upper[N-1]), O(N), by the Sherman–Morrison
/// formula over two Thomas solves. N == 1 reads (lower + diag + upper) x = rhs;
/// N == 2 adds both off-diagonal entries of a row, which hit the same unknown.
std::vector<double> solve_cyclic_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                             const std::vector<double>& upper, const std::vector<double>& rhs);
std::vector<Vec3> solve_cyclic_tridiagonal(const std::vector<double>& lower, const std::vector<double>& diag,
                                           const std::vector<double>& upper, const std::vector<Vec3>& rhs);

}  // namespace gllab::spline
