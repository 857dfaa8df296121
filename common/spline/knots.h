// common/spline/knots.h — knot vectors: the checks every curve and surface
// makes (validate_knots), the domain, multiplicity, the clamped and uniform
// knot vectors and the Greville abscissae.
//
// Notation (common/spline/README.md): p degree, n last control index, U knots
// with m + 1 = n + p + 2 entries (knots = control points + order), P points,
// w weights (empty: polynomial). The domain of a curve is [U[p], U[n+1]].
#pragma once

#include <cstddef>
#include <vector>

namespace gllab::spline {

/// The largest degree the allocation-free paths support (GLU stops at order 24).
inline constexpr int kMaxDegree = 31;
/// The most control points of a curve, and of a surface (n + 1)(m + 1): 10^6.
/// The labs' largest net has 400 (20 x 20, the benchmark's surface); a spline
/// file at its size limit (common/io, 8 MiB) holds at most about 10^6 points.
inline constexpr std::size_t kMaxControlPoints = 1000000;

/// The knot-vector part of validate(), for curves and for each direction of a
/// surface: `what` starts the messages ("knot vector", "V knot vector", ...) and
/// `symbol` names the array in them ("U[5]=0.4", "V[2]=2").
void validate_knots(int p, int num_points, const std::vector<double>& U, const char* what = "knot vector",
                    const char* symbol = "U");

/// A closed parameter interval [a, b].
struct ParamInterval {
  double a = 0, b = 1;
};

/// The domain of raw (p, U): [U[p], U[U.size() - p - 1]], i.e. [U[p], U[n+1]]
/// (ch. 1 §1.6: X(u) for u_{m-1} <= u <= u_{n+1} with order m = p + 1).
/// Checks nothing; domain(curve) in bspline.h checks the curve first.
ParamInterval domain(int p, const std::vector<double>& U);

/// Throws "u=1.5 is outside the domain [0, 1]" (also for NaN).
void require_in_domain(double u, ParamInterval dom);

/// How many times the value u appears in U (exact comparison).
int knot_multiplicity(const std::vector<double>& U, double u);

// ---- knot vectors -----------------------------------------------------------

/// Clamped ("nonperiodic", notes "Higher Order Surfaces") uniform knots for P[0..n] of degree p:
/// p + 1 zeros, the interior knots j / (n - p + 1), j = 1..n-p, p + 1 ones.
/// Domain [0, 1]; the curve interpolates P[0] and P[n]. Needs 1 <= p <= n.
std::vector<double> clamped_uniform_knots(int n, int p);

/// Unclamped uniform knots 0, 1, 2, ..., n + p + 1 (notes "Higher Order Surfaces", "knots = 0, 1, 2,
/// ..., n"). Domain [p, n + 1]; segment i (0-based) is u in [p + i, p + i + 1].
/// Needs 1 <= p <= n.
std::vector<double> uniform_knots(int n, int p);

/// The Greville abscissae (knot averages) xi_i = (U[i+1] + ... + U[i+p]) / p,
/// i = 0..n, for n = U.size() - p - 2. A B-spline with the control values xi_i
/// is the parameter itself on the domain: sum_i xi_i N_{i,p}(u) = u (linear
/// precision, from Marsden's identity; de Boor, "A Practical Guide to
/// Splines", rev. ed. 2001, ch. IX). common/gl/glu_nurbs.cpp feeds them to
/// GLU as a texture-coordinate map so that every GLU vertex tells its u.
/// Throws for p < 1 or U.size() < p + 2 (no control point).
std::vector<double> greville_abscissae(int p, const std::vector<double>& U);

}  // namespace gllab::spline
