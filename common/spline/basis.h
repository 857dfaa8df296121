// common/spline/basis.h — the B-spline basis functions, chapter 2 of The NURBS
// Book (Piegl & Tiller, 2nd ed.): A2.1 FindSpan, A2.2 BasisFuns, A2.3
// DersBasisFuns, A2.4 OneBasisFun, and the Cox–de Boor recursion as the lecture
// writes it (ch. 1 §1.6 Spline representations, B-splines).
//
// Notation (common/spline/README.md): p degree, n last control index, U knots
// with m + 1 = n + p + 2 entries (knots = control points + order), P points,
// w weights (empty: polynomial). The domain of a curve is [U[p], U[n+1]].
//
// These routines take the raw (p, U) and check only what is cheap: the
// degree, the length of U and the parameter's range.
#pragma once

#include <array>
#include <vector>

#include "spline/knots.h"

namespace gllab::spline {

/// A2.1 FindSpan (The NURBS Book, 2nd ed., p. 68). Returns i with
/// U[i] <= u < U[i+1], p <= i <= n. At the end of the domain, u == U[n+1],
/// returns the last non-empty span (n for a clamped curve).
/// Throws if u is outside [U[p], U[n+1]] or U.size() != n + p + 2.
int find_span(int n, int p, double u, const std::vector<double>& U);

/// The span seen from the left: i with U[i] < u <= U[i+1]. At u == U[p] returns
/// the first non-empty span. Used for left limits at a knot (Side::Left).
int find_span_left(int n, int p, double u, const std::vector<double>& U);

/// The last non-empty span at or below n: where find_span puts u == U[n+1].
int last_span(int n, int p, const std::vector<double>& U);

/// A2.2 BasisFuns (p. 70). N[j] = N_{i-p+j,p}(u), j = 0..p, for the span i
/// returned by find_span. The p + 1 values are >= 0 and sum to 1.
std::vector<double> basis_funs(int i, double u, int p, const std::vector<double>& U);
/// The same, writing p + 1 values to N (no allocation). Needs p <= kMaxDegree.
void basis_funs(int i, double u, int p, const std::vector<double>& U, double* N);

/// A2.2's triangle, as A2.3 keeps it: ndu[r][j] (r <= j) = N_{i-j+r,j}(u), the
/// basis functions of every degree j = 0..p, and ndu[j][r] (r < j) = U[i+r+1] -
/// U[i+1-j+r], the knot differences A2.2 divides by.
using BasisTriangle = std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1>;
/// A2.2 BasisFuns (p. 70) keeping the triangle: the one copy of A2.2's loop in
/// the textbook layer. Checks nothing (basis_funs and ders_basis_funs do).
void basis_triangle(int i, double u, int p, const std::vector<double>& U, BasisTriangle& ndu);

/// A2.3 DersBasisFuns (p. 72). ders[k][j] = k-th derivative of N_{i-p+j,p} at
/// u, k = 0..d, j = 0..p. Rows k > p are zero.
std::vector<std::vector<double>> ders_basis_funs(int i, double u, int p, int d, const std::vector<double>& U);
/// The same without allocating: ders[k * (p + 1) + j], (d + 1) * (p + 1) values.
void ders_basis_funs(int i, double u, int p, int d, const std::vector<double>& U, double* ders);

/// A2.4 OneBasisFun (p. 74): the single function N_{i,p}(u), 0 <= i <= m-p-1.
/// (Arguments ordered like basis_funs, not like the book's (p, m, U, i, u).)
/// At u == U[m] the last function is 1 (the book's special case).
double one_basis_fun(int i, double u, int p, const std::vector<double>& U);

/// The Cox–de Boor recursion exactly as the lecture write it (ch. 1 §1.6,
/// notes "Higher Order Surfaces"), with 0/0 := 0 and half-open N_{i,0} = 1 on [U[i], U[i+1]), plus
/// the right end: at u == U[m] the last non-empty interval counts as closed.
/// Exponential time; for teaching and plotting. Equals one_basis_fun.
double cox_de_boor(int i, double u, int p, const std::vector<double>& U);

/// All N_{0..n,p}(u) for n = U.size() - p - 2: a row to plot every basis
/// function of a knot vector, by the Cox–de Boor table (O(m p)). u may be
/// anywhere in [U[0], U[m]] (zeros outside); only on the domain do they sum to 1.
std::vector<double> all_basis_funs(double u, int p, const std::vector<double>& U);

}  // namespace gllab::spline
