// common/field/density.h — blobs: radial density functions and their sums
// (lecture notes ch. 1, §1.5 Blobby objects).
//
// A blob at P is the field F(x) = f(|x - P|) of a density f: [0, inf) -> [0, a].
// The notes ask of f: a polynomial on [0, b], 0 beyond the radius b, f(0) = a,
// f(b) = 0, f'(0) = f'(b) = 0, monotonically decreasing. The object is the
// iso-surface {x : sum_i F_i(x) = c}. Pure C++17, no GL.
#pragma once

#include <vector>

#include "spline/vec.h"

namespace gllab::field {

using spline::Vec3;

/// The notes' density: f(t) = a H0(t / b) for t <= b, 0 beyond, with
/// H0(s) = 1 - 3 s^2 + 2 s^3 the cubic Hermite basis function that is 1 with
/// slope 0 at s = 0 and 0 with slope 0 at s = 1. It meets every condition:
/// f(0) = a H0(0) = a; f(b) = a H0(1) = 0; f'(t) = (a / b) H0'(t / b) with
/// H0'(s) = -6 s (1 - s), which is 0 at s = 0 and s = 1 and negative between,
/// so f decreases monotonically; and f is C^1 at t = b, where it meets 0.
double hermite_density(double t, double a, double b);
double hermite_density_derivative(double t, double a, double b);  // df/dt

/// Wyvill, McPheeters and Wyvill's soft objects (1986): the sextic
/// f(t) = a (1 - 4/9 s^6 + 17/9 s^4 - 22/9 s^2), s = t / b, 0 beyond b.
/// f(b/2) = a/2 exactly.
double wyvill_density(double t, double a, double b);
double wyvill_density_derivative(double t, double a, double b);

/// Blinn's blobby molecules (1982): f(t) = a exp(-B t^2) with B = k / b^2;
/// never exactly 0, so it fails the notes' "0 beyond b" condition. The lab
/// and the core use k = 4 (f(b) = a e^-4 = 0.018 a).
double blinn_density(double t, double a, double b);
double blinn_density_derivative(double t, double a, double b);

enum class Density { kHermite, kWyvill, kBlinn };
const char* density_name(Density d);  // "hermite", "wyvill", "blinn"
/// f(t) of density d (one of the three above).
double density_value(Density d, double t, double a, double b);

struct Blob {
  Vec3 centre;
  double a = 1;  // f(0), the density at the centre
  double b = 1;  // the radius: f = 0 beyond it (not so for Blinn's)
};

/// The summed field sum_i f(|x - P_i|) of blobs sharing one density.
struct BlobField {
  std::vector<Blob> blobs;
  Density density = Density::kHermite;

  double value(const Vec3& x) const;
  Vec3 gradient(const Vec3& x) const;  // exact: sum f'(r_i) (x - P_i) / r_i, 0 at a centre
};

/// The radius r at which one blob's field equals c: f(r) = c, 0 < c < a.
/// Exact for the Hermite density (the root of 2 s^3 - 3 s^2 + 1 - c/a in
/// (0, 1)), by bisection to 1e-15 b for Wyvill's, closed form for Blinn's.
/// Throws std::invalid_argument naming c when c <= 0 or c >= a (and naming a
/// or b when either is not positive).
double iso_radius(Density d, double a, double b, double c);

/// Two equal blobs (a, b) at distance d apart merge, as d shrinks, when the
/// field at their midpoint reaches c: 2 f(d / 2) = c. Returns that distance,
/// d = 2 r with f(r) = c / 2 (iso_radius of c / 2). Throws as iso_radius,
/// naming c when c <= 0 or c >= 2a (c / 2 must be a value of one blob).
double merge_distance(Density d, double a, double b, double c);

}  // namespace gllab::field
