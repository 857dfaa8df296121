// common/mesh/coordinates.h — Cartesian, spherical and cylindrical coordinates
// (lecture notes "B-Spline Polynomials", "3-D Graphics", "Problem # 1:
// Modeling" and "Conversions"). No GL; lab 35 builds a sphere and a cylinder
// from them.
//
// The notes' convention, kept here (right-handed, z up):
//   spherical (rho, theta, phi):  x = rho sin(phi) cos(theta)
//                                 y = rho sin(phi) sin(theta)
//                                 z = rho cos(phi)
//     rho   distance from the origin, >= 0;
//     theta azimuth in the xy-plane, from +x towards +y (counter-clockwise
//           seen from +z), the same angle as the cylindrical theta;
//     phi   polar angle from +z: 0 at the north pole, pi/2 on the equator,
//           pi at the south pole.
//   cylindrical (r, theta, z):    x = r cos(theta),  y = r sin(theta),  z = z
//     (the notes list it but leave its conversion out; this is the usual one).
// GLU measures its sphere's and cylinder's angle the other way: gluSphere puts
// slice i at x = sin(a), y = cos(a) with a = 2 pi i / slices, from +y
// clockwise seen from +z, so theta = pi/2 - a.
//
// Back to spherical or cylindrical, the angles come out canonical:
// theta in (-pi, pi] by atan2, phi in [0, pi]. Where an angle is undefined
// the functions return 0 for it: on the z axis (x = y = 0) theta = 0; at the
// origin also phi = 0. So the poles are (rho, 0, 0) and (rho, 0, pi), a point
// on the axis is (0, 0, z), and the origin is (0, 0, 0) in both systems.
#pragma once

#include "spline/vec.h"

namespace gllab {

struct Spherical {
  double rho = 0, theta = 0, phi = 0;  // radians
};

struct Cylindrical {
  double r = 0, theta = 0, z = 0;  // theta in radians
};

/// The notes' formula. Any finite angles; throws std::invalid_argument naming
/// the value when rho < 0 or a coordinate is not finite.
spline::Vec3 spherical_to_cartesian(Spherical s);

/// rho = |p|, theta = atan2(y, x), phi = atan2(sqrt(x^2 + y^2), z) (accurate
/// near the poles, where acos(z / rho) is not). Throws when p is not finite.
Spherical cartesian_to_spherical(spline::Vec3 p);

/// x = r cos(theta), y = r sin(theta), z. Throws when r < 0 or a coordinate
/// is not finite.
spline::Vec3 cylindrical_to_cartesian(Cylindrical c);

/// r = sqrt(x^2 + y^2), theta = atan2(y, x), z. Throws when p is not finite.
Cylindrical cartesian_to_cylindrical(spline::Vec3 p);

}  // namespace gllab
