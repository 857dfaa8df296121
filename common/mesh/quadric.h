// common/mesh/quadric.h — quadric surfaces as implicit equations F(p) = 0
// (lecture notes ch. 1, §1.4 Quadric surfaces: "described with second-degree
// equations"), and the torus beside them for comparison. No GL.
//
// A Quadric holds the ten coefficients of the general second-degree equation
//   F(x, y, z) = xx x^2 + yy y^2 + zz z^2 + xy xy + yz yz + zx zx
//              + x x + y y + z z + c,
// with the sign chosen so that F < 0 inside the solid, F = 0 on the surface
// and F > 0 outside. The notes give two examples; this file adds the two
// GLU draws besides the sphere (gluCylinder is a cylinder, or a cone with
// top radius 0):
//   sphere     x^2 + y^2 + z^2 - r^2          The notes print "= r"; the
//              sphere of radius r is x^2 + y^2 + z^2 = r^2 (with "= r" its
//              radius would be sqrt(r)). Code and tests use r^2.
//   ellipsoid  (x/rx)^2 + (y/ry)^2 + (z/rz)^2 - 1     (the notes' form)
//   cylinder   x^2 + y^2 - r^2                (about z, infinite in z)
//   cone       x^2 + y^2 - (r (1 - z/h))^2    (apex at z = h, radius r at
//              z = 0, as gluCylinder(q, r, 0, h, ...); both nappes)
// The torus (labs 03-05) is of degree four, not a quadric:
//   (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2).
// None of these values is a distance; only their sign and their zero set mean
// something, and the gradient at a surface point is a normal there.
#pragma once

#include "spline/vec.h"

namespace gllab {

struct Quadric {
  double xx = 0, yy = 0, zz = 0, xy = 0, yz = 0, zx = 0, x = 0, y = 0, z = 0, c = 0;

  /// F(p): < 0 inside, 0 on the surface, > 0 outside.
  double operator()(spline::Vec3 p) const;
  /// grad F(p) = (dF/dx, dF/dy, dF/dz): an outward normal on the surface
  /// (not unit length).
  spline::Vec3 gradient(spline::Vec3 p) const;
};

// Each throws std::invalid_argument naming the value when a radius or height
// is not > 0 (or not finite).
Quadric sphere_quadric(double r);
Quadric ellipsoid_quadric(double rx, double ry, double rz);
Quadric cylinder_quadric(double r);
Quadric cone_quadric(double base_radius, double height);

/// The torus about the z axis with ring radius R (centre to tube centre) and
/// tube radius r, in the sign convention above. Throws unless 0 < r < R.
double torus_implicit(spline::Vec3 p, double R, double r);

}  // namespace gllab
