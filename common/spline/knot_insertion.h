// common/spline/knot_insertion.h — knot insertion (the lecture's formula, ch. 1
// §1.6, and A5.1 CurveKnotIns), knot refinement (A5.4), Bézier decomposition
// and its inverse, and splitting a curve. The NURBS Book (Piegl & Tiller, 2nd
// ed.) chapter 5. Rational curves are treated in homogeneous space.
//
// Notation (common/spline/README.md): p degree, n last control index, U knots
// with m + 1 = n + p + 2 entries (knots = control points + order), P points,
// w weights (empty: polynomial). The domain of a curve is [U[p], U[n+1]].
#pragma once

#include <utility>
#include <vector>

#include "spline/types.h"

namespace gllab::spline {

/// One insertion of the knot t by the lecture's formula (ch. 1 §1.6, Boehm):
/// t in [U[k], U[k+1]), q_i = (1 - a_i) P[i-1] + a_i P[i] with
/// a_i = (t - U[i]) / (U[i+p] - U[i]) for k - p + 1 <= i <= k.
/// a[j] is a_{first + j}, first = k - p + 1 (so a.size() == p). k is
/// find_span(t) (at the end of the domain, t == U[k+1]). Needs the same as
/// knot_insert with r = 1.
struct KnotInsertStep {
  BsplineCurve curve;
  int k = 0;
  int first = 0;
  std::vector<double> a;
};
KnotInsertStep knot_insert_step(const BsplineCurve& curve, double t);

/// A5.1 CurveKnotIns (p. 151): insert u r times. Needs U[p] <= u <= U[n+1] and
/// s + r <= p where s is the multiplicity u already has. The curve is unchanged.
BsplineCurve knot_insert(const BsplineCurve& curve, double u, int r = 1);

/// A5.4 RefineKnotVectCurve (p. 164): insert all knots X (non-decreasing,
/// inside the domain; final multiplicities <= p).
BsplineCurve knot_refine(const BsplineCurve& curve, const std::vector<double>& X);

/// The Bézier pieces of a polynomial curve, one per non-empty knot span of the
/// domain, each with its parameter interval [a, b]. Made by raising every knot
/// of the domain to multiplicity p with one knot refinement (A5.4), as ch. 1
/// §1.6 "Displaying B-spline curves" describes; the result is that of A5.6
/// DecomposeCurve, and it works for unclamped curves too. Throws for a rational
/// curve (BezierCurve has no weights; use bezier_segments).
std::vector<BezierCurve> bezier_decompose(const BsplineCurve& curve);

/// The same decomposition for any curve (rational too): each piece is a
/// single-span curve with knots {a x (p+1), b x (p+1)}.
std::vector<BsplineCurve> bezier_segments(const BsplineCurve& curve);

/// The inverse of bezier_decompose: Bézier segments of one degree p >= 1,
/// each starting where the previous one ends (same point, same parameter),
/// as one B-spline curve. The knots are a x (p+1), every joint x p, b x (p+1),
/// and the control points are the segments' points with each joint once
/// (ch. 1 §1.6, "B-splines": a B-spline whose knots all have multiplicity
/// m - 1, m the order, has the Bézier points as its control points). The
/// curve is only C0 at the joints, unless the points make it smoother.
/// Throws for no segments, a degree < 1 or different degrees, a gap between
/// intervals, or a segment that does not start at the previous one's end.
BsplineCurve from_bezier_segments(const std::vector<BezierCurve>& segments);

/// Splits at u strictly inside the domain (by inserting u up to multiplicity p):
/// first covers [U[p], u], second [u, U[n+1]]. Each keeps the original
/// parameters and the end knots it inherits (clamped at u).
std::pair<BsplineCurve, BsplineCurve> split(const BsplineCurve& curve, double u);

}  // namespace gllab::spline
