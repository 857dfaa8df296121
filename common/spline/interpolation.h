// common/spline/interpolation.h — polynomial interpolation: given nodes t_i
// and values f_i (numbers or points), find the polynomial p with p(t_i) = f_i.
//
// Four ways to the same polynomial, as in ch. 1 §1.6 "Interpolation problem":
//   - Vandermonde: solve A c = f for the monomial coefficients c_j (Theorem 1),
//   - Lagrange:    p(t) = sum f_i L_i(t) with L_i(t_j) = delta_ij (Theorem 2),
//   - Newton:      p(t) = sum a_i N_i(t), a_i divided differences; nodes can be
//                  added one at a time without starting again,
//   - Hermite:     values AND derivatives at the nodes (Theorem 3); the cubic
//                  Hermite basis H0, H0-bar, H1, H1-bar on [0, 1].
//
// Values are double or Vec3: a curve through points is three scalar problems
// with the same matrix (ch. 1 §1.6, "Note: ... For each coordinate, we get a
// linear system with an identical matrix A").
//
// Throughout, `nodes` are the t_i (pairwise distinct, finite) and `t` is where
// the polynomial is evaluated. Monomial coefficients are ascending:
// c[j] multiplies t^j. Bad input throws std::invalid_argument naming the values.
#pragma once

#include <array>
#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

// ---- dense linear systems ---------------------------------------------------

/// Gaussian elimination with partial pivoting: returns x with A x = rhs.
/// A is n x n (A[row][column]); every row swap picks the largest |pivot| in
/// the column, which keeps the elimination stable. Throws if A is not square,
/// the sizes differ, an entry is not finite, or A is singular (a column has
/// no non-zero pivot). O(n^3).
std::vector<double> gauss_solve(std::vector<std::vector<double>> A, std::vector<double> rhs);
/// The same with point right-hand sides: three systems sharing one matrix.
std::vector<Vec3> gauss_solve(std::vector<std::vector<double>> A, std::vector<Vec3> rhs);

// ---- monomial (power) form and Vandermonde (ch. 1 §1.6, Theorem 1) ------

/// The Vandermonde matrix A[i][j] = t_i^j, i, j = 0..n (ch. 1 §1.6).
/// det A = prod_{i>j} (t_i - t_j): regular exactly when the nodes differ.
std::vector<std::vector<double>> vandermonde_matrix(const std::vector<double>& nodes);

/// Monomial coefficients c_0..c_n of the interpolating polynomial, from the
/// Vandermonde system A c = f solved by gauss_solve (ch. 1 §1.6, Theorem 1).
/// Note how quickly A becomes ill-conditioned as n grows: this is the method
/// the lecture proves existence with, not the one to use for many nodes.
std::vector<double> vandermonde_coefficients(const std::vector<double>& nodes, const std::vector<double>& f);
std::vector<Vec3> vandermonde_coefficients(const std::vector<double>& nodes, const std::vector<Vec3>& f);

/// p(t) = sum c_j t^j by Horner's rule: (...(c_n t + c_{n-1}) t + ...) t + c_0.
/// An empty c is the zero polynomial.
double monomial_value(const std::vector<double>& c, double t);
Vec3 monomial_value(const std::vector<Vec3>& c, double t);

// ---- Lagrange (ch. 1 §1.6, Theorem 2) ------------------------------------

/// L_i(t) = prod_{k != i} (t - t_k) / (t_i - t_k): 1 at t_i, 0 at every other node.
double lagrange_basis(const std::vector<double>& nodes, int i, double t);
/// All of them: L[i] = L_i(t), i = 0..n. They sum to 1 for every t.
std::vector<double> lagrange_basis_all(const std::vector<double>& nodes, double t);

/// p(t) = sum f_i L_i(t), the interpolating polynomial in Lagrange form.
double lagrange_value(const std::vector<double>& nodes, const std::vector<double>& f, double t);
Vec3 lagrange_value(const std::vector<double>& nodes, const std::vector<Vec3>& f, double t);

// ---- Newton (ch. 1 §1.6, "Newton interpolation") ------------------------

/// The Newton basis N_i(t) = prod_{k=0}^{i-1} (t - t_k); N_0 = 1. N_i vanishes
/// at t_0..t_{i-1}. Uses nodes[0..i-1] only.
double newton_basis(const std::vector<double>& nodes, int i, double t);

/// The divided-difference table of ch. 1 §1.6, column by column:
/// table[k][j] = f[t_j, ..., t_{j+k}], k = 0..n, j = 0..n-k, where
///   f[t_j] = f_j,
///   f[t_j..t_{j+k}] = (f[t_{j+1}..t_{j+k}] - f[t_j..t_{j+k-1}]) / (t_{j+k} - t_j).
/// The Newton coefficients are the top entries a_k = table[k][0].
std::vector<std::vector<double>> divided_difference_table(const std::vector<double>& nodes,
                                                          const std::vector<double>& f);
std::vector<std::vector<Vec3>> divided_difference_table(const std::vector<double>& nodes,
                                                        const std::vector<Vec3>& f);

/// The Newton form built one node at a time (ch. 1 §1.6: "additional nodes
/// can be added without having to re-compute all basis functions").
///
///   NewtonInterpolant<double> p;
///   p.add_node(0, 1); p.add_node(2, 3); p.add_node(4, 5);   // lecture example
///   p.coefficients();   // {1, 1, 0}: p(x) = 1 + 1 (x - 0) + 0 (x - 0)(x - 2)
///   p(3.0);             // 4
///
/// add_node appends one diagonal to the table: n + 1 new divided differences,
/// O(n) work; the entries already there do not change. T is double or Vec3.
template <class T>
class NewtonInterpolant {
 public:
  NewtonInterpolant() = default;
  /// Adds (t, value) as node t_{n+1}. Throws if t or value is not finite or t
  /// equals an earlier node (the divided difference would divide by zero).
  void add_node(double t, T value);

  /// The nodes t_0..t_n in the order they were added.
  const std::vector<double>& nodes() const { return nodes_; }
  /// a_i = f[t_0, ..., t_i], i = 0..n: p(t) = sum a_i N_i(t).
  std::vector<T> coefficients() const;
  /// The whole triangular table, laid out like divided_difference_table():
  /// table()[k][j] = f[t_j, ..., t_{j+k}]. A lab draws it column by column.
  const std::vector<std::vector<T>>& table() const { return table_; }
  /// Number of nodes (degree + 1; the degree may be lower, ch. 1 §1.6 "Beware").
  int size() const { return static_cast<int>(nodes_.size()); }

  /// p(t), nested like Horner's rule:
  /// p(t) = a_0 + (t - t_0)(a_1 + (t - t_1)(a_2 + ... + (t - t_{n-1}) a_n)).
  /// Throws if there are no nodes yet or t is not finite.
  T operator()(double t) const;

 private:
  std::vector<double> nodes_;
  std::vector<std::vector<T>> table_;  // table_[k][j] = f[t_j..t_{j+k}]
};

// Both instantiations are compiled once, in interpolation.cpp.
extern template class NewtonInterpolant<double>;
extern template class NewtonInterpolant<Vec3>;

// ---- cubic Hermite (ch. 1 §1.6, "Hermite interpolation") ----------------

/// The four cubic Hermite polynomials at one parameter (ch. 1 §1.6):
///   H0(t)     = 2t^3 - 3t^2 + 1      value 1 at t = 0
///   H0bar(t)  = t^3 - 2t^2 + t       slope 1 at t = 0
///   H1(t)     = -2t^3 + 3t^2         value 1 at t = 1
///   H1bar(t)  = t^3 - t^2            slope 1 at t = 1
/// H_i(j) = delta_ij, H_i'(j) = 0, H_i-bar(j) = 0, H_i-bar'(j) = delta_ij.
struct HermiteBasis {
  double H0 = 0, H0bar = 0, H1 = 0, H1bar = 0;
};

/// H0, H0-bar, H1, H1-bar at t (any finite t; [0, 1] is the segment).
HermiteBasis cubic_hermite_basis(double t);
/// Their first derivatives at t: H0' = 6t^2 - 6t, H0-bar' = 3t^2 - 4t + 1,
/// H1' = -6t^2 + 6t, H1-bar' = 3t^2 - 2t.
HermiteBasis cubic_hermite_basis_derivative(double t);

/// The Hermite matrix of ch. 1 §1.6: (c_0, c_1, c_2, c_3) = M (f(0), f'(0),
/// f(1), f'(1)), c ascending monomial coefficients. It is the inverse of the
/// system matrix [[1,0,0,0], [0,1,0,0], [1,1,1,1], [0,1,2,3]]; column k holds
/// the coefficients of H0, H0-bar, H1, H1-bar respectively.
const std::array<std::array<double, 4>, 4>& hermite_matrix();

/// The cubic Hermite segment X(t) = H0 p0 + H1 p1 + H0bar m0 + H1bar m1 on
/// [0, 1] (ch. 1 §1.6, "Interpolation"): X(0) = p0, X(1) = p1, X'(0) = m0,
/// X'(1) = m1. Throws if t is outside [0, 1] or anything is not finite; a t
/// that misses only by round-off (4 machine epsilons of the interval's size,
/// as for Bézier curves, bezier.h) is taken as the end.
Vec3 hermite_point(Vec3 p0, Vec3 m0, Vec3 p1, Vec3 m1, double t);
double hermite_value(double f0, double d0, double f1, double d1, double t);
/// X'(t) of the same segment (the tangent a lab draws).
Vec3 hermite_derivative(Vec3 p0, Vec3 m0, Vec3 p1, Vec3 m1, double t);

/// The same segment on a general interval [a, b] with tangents m0, m1 taken
/// with respect to t: with h = b - a and s = (t - a) / h,
///   X(t) = H0(s) p0 + H1(s) p1 + h (H0bar(s) m0 + H1bar(s) m1)
/// (chain rule: dX/dt = (1/h) dX/ds, so the s-tangents are h m). Needs a < b.
Vec3 hermite_point(Vec3 p0, Vec3 m0, Vec3 p1, Vec3 m1, double t, double a, double b);

// ---- general Hermite interpolation (ch. 1 §1.6, Theorem 3) --------------

/// One node of a Hermite problem: derivatives[j] = f^(j)(t), j = 0..n_i-1
/// (derivatives[0] is the value). ch. 1 §1.6 "Interpolating derivatives".
template <class T>
struct HermiteNode {
  double t = 0;
  std::vector<T> derivatives;
};

/// Monomial coefficients c_0..c_m, m = sum n_i - 1, of the unique polynomial
/// with p^(j)(t_i) = f_i^(j) (ch. 1 §1.6, Theorem 3). Built exactly as the
/// lecture does: one row per condition, d^j/dt^j t^k = k!/(k-j)! t^(k-j), solved
/// by gauss_solve (a "confluent" Vandermonde system). With nodes 0 and 1 and
/// two conditions each this is the cubic Hermite system above.
/// Throws on no nodes, a node with no conditions, equal nodes, non-finite data.
/// With braces, name the node type (a Vec3 also takes {1.0}):
///   hermite_coefficients(std::vector<HermiteNode<double>>{{0, {f0, d0}}, {1, {f1, d1}}});
std::vector<double> hermite_coefficients(const std::vector<HermiteNode<double>>& nodes);
std::vector<Vec3> hermite_coefficients(const std::vector<HermiteNode<Vec3>>& nodes);

}  // namespace gllab::spline
