// common/field/phantom.h — the 3-D Shepp–Logan head phantom: the "CT-like
// volume" of the iso-surface lab (lecture notes ch. 1, §1.7 Surface
// representations, Iso-surfaces).
//
// Ten ellipsoids with additive densities (Kak and Slaney, "Principles of
// Computerized Tomographic Imaging", 1988, the 3-D extension of Shepp and
// Logan's head section), with the contrast-enhanced "modified" densities
// (Toft 1996) so that the ventricles and small tumours inside the brain show:
// skull 1, brain 0.2, ventricles 0, tumours 0.3, air outside 0. The table is
// in phantom.cpp. Pure C++17, no GL.
#pragma once

#include <vector>

#include "field/grid.h"

namespace gllab::field {

/// One ellipsoid: the points x with |E^-1 R (x - centre)| <= 1, E =
/// diag(semi_axes) and R the z-x-z Euler rotation of (phi, theta, psi)
/// degrees; it adds `density` to every point inside.
struct PhantomEllipsoid {
  double density;
  Vec3 semi_axes;
  Vec3 centre;
  double phi, theta, psi;  // degrees
};

/// The ten ellipsoids of the modified 3-D Shepp–Logan phantom, head first.
const std::vector<PhantomEllipsoid>& shepp_logan_ellipsoids();

/// The phantom's density at x: the sum of the densities of the ellipsoids
/// that contain x (boundary included). 0 outside the head.
double shepp_logan_density(const Vec3& x);

/// The phantom sampled at n x n x n points over [-1, 1]^3 (origin (-1, -1, -1),
/// spacing 2 / (n - 1)). Each value is the mean of 2 x 2 x 2 point densities
/// at (+-h/4, +-h/4, +-h/4) around the grid point, so edges are smooth
/// (partial-volume values) and the result is the same on every run. Throws
/// std::invalid_argument naming n unless 2 <= n <= 1024.
Grid3 shepp_logan_phantom(int n);

}  // namespace gllab::field
