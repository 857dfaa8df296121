// common/spline/arc_length.h — the arc length s(u) of a B-spline or NURBS curve,
// its inverse u(s), and parameters at equal steps of s.
//
// Lecture notes ch. 1, §1.6 "Spline Representations", "Parameter transformation":
// L(t0, t1) = integral of |X'(t)| dt, and a curve can be re-parameterized so that
// |X'| = 1; notes "Higher Order Surfaces", "Arc Length Parameterization": equal
// steps in u are not equal steps along the curve, u2 - u1 != s(u2) - s(u1).
#pragma once

#include <cstddef>
#include <vector>

#include "spline/bspline.h"
#include "spline/quadrature.h"
#include "spline/types.h"

namespace gllab::spline {

/// Gauss–Legendre points per panel: exact for |X'| of degree <= 31 (a polynomial
/// speed never is one, being a square root, but on a panel where it is smooth
/// the rule's error falls like h^32).
inline constexpr int kArcLengthGaussPoints = 16;
/// At most this many panels; a curve that would need more (a tolerance below
/// rounding, a speed with a kink) stops there, and error_estimate() says so.
inline constexpr std::size_t kArcLengthMaxPanels = std::size_t{1} << 16;

/// The arc-length table of one curve. The domain is cut at every distinct knot
/// (|X'| is smooth only inside a knot span), and each piece is bisected until
/// the Gauss rule on it and on its two halves agree within `tolerance` times the
/// halves' length (adaptive quadrature: Davis and Rabinowitz, "Methods of Numerical
/// Integration", ch. 6). The accepted halves are the panels.
class ArcLength {
 public:
  /// tolerance: relative, finite, in [1e-15, 0.1]; else SplineError naming it.
  /// Checks the curve (validate) once.
  explicit ArcLength(const BsplineCurve& curve, double tolerance = 1e-14);

  /// L = s(u_end): the length of the whole curve.
  double length() const { return cumulative_.back(); }
  /// The sum over panels of |G(panel) - G(left half) - G(right half)|: the
  /// error of the coarser rule, so (the finer rule being used) an upper
  /// estimate of the error of length().
  double error_estimate() const { return error_; }
  std::size_t panels() const { return breaks_.size() - 1; }
  /// The panels' ends, from the domain's start to its end.
  const std::vector<double>& breaks() const { return breaks_; }

  /// |X'(u)|, the speed: how fast s grows with u.
  double speed(double u) const;
  /// s(u) = integral from the domain's start to u of |X'|; u in the domain.
  double s(double u) const;
  /// The inverse: the u with s(u) = s, for s in [0, L]. Safeguarded Newton
  /// on F(u) = s(u) - s inside the panel that holds s: F' = |X'(u)| >= 0, so a
  /// Newton step that leaves the bracket, or a zero speed, falls back to
  /// bisection (Numerical Recipes, 3rd ed., §9.4 "rtsafe"). Stops when |F| <=
  /// 4 eps L or the bracket is a few ulps wide.
  double u(double s) const;
  /// count >= 2 parameters u_k with s(u_k) = k L / (count - 1): the curve
  /// sampled at equal steps of arc length (the first and last are the domain's ends).
  std::vector<double> equal_steps(int count) const;

 private:
  double panel_integral(double a, double b) const;
  void add_span(double a, double b, double tolerance, int depth);

  CurveEvaluator curve_;  // checked once
  GaussRule rule_;
  std::vector<double> breaks_;
  std::vector<double> cumulative_;  // s at each break
  double error_ = 0;
};

}  // namespace gllab::spline
