// common/spline/nurbs.h — rational curves: homogeneous points, conic sections
// from the lecture's r parameter, the exact circle.
//
// A NURBS curve is a BsplineCurve with weights w (types.h). Its points in
// homogeneous space are Pw = (w x, w y, w z, w), the premultiplied form GLU
// takes with GL_MAP1_VERTEX_4. Evaluation lives in bspline.h (curve_point,
// curve_derivs handle rational curves: A4.1, A4.2).
#pragma once

#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

// ---- homogeneous form -----------------------------------------------------------

/// Pw[i] = (w_i x_i, w_i y_i, w_i z_i, w_i); w_i = 1 for a polynomial curve.
/// Checks the curve (validate).
std::vector<Vec4> to_homogeneous(const BsplineCurve& curve);

/// The curve whose homogeneous points are Pw: P[i] = Pw[i].xyz / Pw[i].w,
/// w[i] = Pw[i].w. Throws when a weight is <= 0 or not finite, or when the
/// result is not a valid curve. The result is rational even if all w are 1.
BsplineCurve from_homogeneous(int p, const std::vector<double>& U, const std::vector<Vec4>& Pw,
                              int dimension = 3);

// ---- conic sections by r (ch. 1 §1.6 "Conic sections") --------------------

/// The lecture's rational quadratic: X(u) = (P0 N0 + r/(1-r) P1 N1 + P2 N2) /
/// (N0 + r/(1-r) N1 + N2) on the knots {0,0,0,1,1,1} (a rational Bézier arc from
/// P0 to P2 with the apex P1). The lecture calls it "cubic"; its basis N_{i,3} has
/// order 3, i.e. degree 2.
enum class ConicType { Line, Ellipse, Parabola, Hyperbola };

/// r = 0 line, 0 < r < 1/2 ellipse, r = 1/2 parabola, 1/2 < r < 1 hyperbola
/// (ch. 1 §1.6). Throws for r < 0, r >= 1 or NaN.
ConicType classify_conic(double r);
const char* to_string(ConicType type);

/// The middle weight w1 = r / (1 - r) (ch. 1 §1.6); 0 <= r < 1.
double conic_weight(double r);
/// Its inverse, r = w1 / (1 + w1); w1 >= 0.
double conic_r(double w1);

/// The conic arc as a curve {p = 2, U = {0,0,0,1,1,1}, P = {P0, P1, P2},
/// w = {1, r/(1-r), 1}} for 0 < r < 1. For r = 0 the lecture's curve is the
/// straight segment P0P2, but a weight 0 is not allowed in a BsplineCurve:
/// it is returned as the polynomial quadratic {P0, (P0 + P2)/2, P2} (the same
/// points, a different parametrisation; conic_point keeps the lecture's one).
BsplineCurve conic_arc(Vec3 P0, Vec3 P1, Vec3 P2, double r, int dimension = 3);

/// The lecture's formula evaluated directly at u in [0, 1], 0 <= r < 1 (r = 0
/// included: the weight 0 leaves the segment P0P2).
Vec3 conic_point(Vec3 P0, Vec3 P1, Vec3 P2, double r, double u);

// ---- the exact circle (The NURBS Book §7.5, Ex. 7.2 / Fig. 7.16) ----------------

/// The full circle of the given centre and radius in the plane z = centre.z:
/// 9 control points (the square's corners and edge midpoints, starting at
/// centre + (radius, 0)), degree 2, weights 1, √2/2 alternating, knots
/// {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}. Counter-clockwise seen from +z;
/// C(0) = C(1) = centre + (radius, 0, 0); C(k/4) are the axis points.
/// dimension is 2 when centre.z == 0, else 3. Throws for radius <= 0.
BsplineCurve circle(Vec3 centre = {}, double radius = 1);

}  // namespace gllab::spline
