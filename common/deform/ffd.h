// common/deform/ffd.h — free-form deformation of a mesh (Sederberg and Parry
// 1986, "Free-form deformation of solid geometric models"): the object sits
// in a lattice's box, the lattice's control points move, and every point of
// the object moves with the volume (lecture notes ch. 1, §1.7 Surface
// representations, "Deformation" and "Morphing").
//
//   1. Local coordinates. The box is a parallelepiped x = X0 + s S + t T + u U;
//      a point's (s, t, u) come from Cramer's rule (Sederberg and Parry's
//      eq. 1): s = (T x U).(x - X0) / (T x U).S, and so on.
//   2. The deformed point is the volume at (s, t, u): X(s, t, u)
//      (deform/volume.h), whose control points are in world coordinates. A
//      point outside the box does not move (X = x, J = I): a lattice deforms
//      what is inside it.
//   3. The Jacobian in world coordinates is J = [Xs Xt Xu] M^-1, M = [S T U],
//      and det J = det [Xs Xt Xu] / det M: the factor by which a small volume
//      grows (1: unchanged; <= 0: the lattice folds there).
//   4. Normals. A tangent a of the surface maps to J a, so a normal n = a x b
//      maps to (J a) x (J b) = cof(J) n, the cofactor matrix det(J) J^-T
//      (deform/mat.h): the inverse transpose up to the factor det J. It keeps
//      the orientation where det J > 0 and turns the normal over, with the
//      triangles, where the lattice folds. No face is re-averaged: the normal
//      is the exact normal of the deformed surface when n was exact.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "deform/mat.h"
#include "deform/volume.h"
#include "mesh/indexed_mesh.h"

namespace gllab::deform {

/// The lattice's box: x = origin + s S + t T + u U, (s, t, u) in [0, 1]^3.
struct Frame {
  Vec3 origin;
  Vec3 S{1, 0, 0}, T{0, 1, 0}, U{0, 0, 1};
  Mat3 matrix() const { return {S, T, U}; }
};

/// The axis-aligned box [lo, hi]. Throws std::invalid_argument naming the
/// coordinates unless lo < hi in every direction.
Frame box_frame(Vec3 lo, Vec3 hi);

/// A lattice: its box and its volume, whose control points are in world
/// coordinates.
struct Lattice {
  Frame frame;
  Volume volume;
};

/// The lattice that maps its box to itself: the unit volume's control points
/// (bernstein_volume, bspline_volume: the identity of [0, 1]^3) carried into
/// the box, X0 + P.x S + P.y T + P.z U. Throws std::invalid_argument when the
/// frame is degenerate or left-handed (det M <= 0), naming det M.
Lattice identity_lattice(const Frame& frame, const Volume& unit);

/// (s, t, u) of x in the frame (Cramer's rule; exact for a point of the box
/// up to rounding).
Vec3 local_coordinates(const Frame& frame, Vec3 x);

/// Where x goes, and the Jacobian there (world coordinates).
struct FfdPoint {
  Vec3 x;
  Mat3 J;
  double det = 1;
  bool inside = false;  // false: outside the box, x unchanged, J = I
};

/// Points within kBoxSlack of the box (in s, t, u) count as inside and are
/// clamped onto it: a vertex on the box's face that rounding puts a hair
/// outside still follows the lattice.
inline constexpr double kBoxSlack = 1e-12;

/// One point through the lattice. Throws std::invalid_argument for an
/// invalid lattice (validate) or a point that is not finite.
FfdPoint ffd_point(const Lattice& lattice, Vec3 x);

/// The unit normal cof(J) n / |cof(J) n| (the comment at the top); the zero
/// vector when cof(J) n is zero (J singular in that direction).
Vec3 deform_normal(const Mat3& J, Vec3 n);

/// A mesh after the lattice.
struct DeformedMesh {
  IndexedMesh mesh;        // positions X(x); normals cof(J) n; colours and indices as given
  std::vector<float> det;  // det J per vertex
  std::size_t outside = 0; // vertices outside the box (not moved)
  std::size_t folded = 0;  // vertices with det J <= 0
  double min_det = 1, max_det = 1;  // over the vertices inside
};

/// Every vertex through the lattice; normals by the Jacobian when the mesh
/// has normals (else none). The vertices are floats, so a vertex counts as
/// on the box within their rounding (|M^-1| 2^-23 |x| in s, t, u) where that
/// exceeds kBoxSlack. Throws as ffd_point. Deterministic; one thread.
DeformedMesh deform_mesh(const Lattice& lattice, const IndexedMesh& mesh);

/// Normals recomputed from the deformed triangles instead: at each vertex the
/// sum of the cross products (b - a) x (c - a) of its triangles (each
/// triangle weighted by its area), normalised. What a renderer does when it
/// has no Jacobian; at a coarse mesh it is only an approximation of the
/// surface's normal. 3 floats per vertex.
std::vector<float> face_averaged_normals(const IndexedMesh& mesh);

/// The angle between two normal arrays (3 floats per vertex, unit length),
/// in degrees: the largest and the mean over the vertices.
struct AngleStats {
  double max_deg = 0, mean_deg = 0;
};
AngleStats normal_angles(const std::vector<float>& a, const std::vector<float>& b);

/// Where a lattice folds over itself (det J <= 0), if it does.
struct Fold {
  bool folds = false;
  double min_det = 0;  // the smallest det J found (world coordinates)
  Vec3 stu;            // where, in the box's (s, t, u)
  Vec3 x;              // the box's point there, before the deformation
};

/// det J sampled on a grid of (samples * (count - 1) + 1) points per
/// direction over the whole box, the box's faces included; the sample with
/// the smallest det J. A fold thinner than the sample spacing can slip
/// through; the vertices' own det J (DeformedMesh) cover what the object
/// touches. samples 1..64, else std::invalid_argument naming it.
Fold find_fold(const Lattice& lattice, int samples = 4);

/// "folds: det J -0.31 at (s, t, u) = (0.50, 0.25, 0.75)", or
/// "no fold: det J >= 0.42" when it does not.
std::string fold_text(const Fold& fold);

/// Throws std::invalid_argument with fold_text when find_fold finds a fold.
void require_no_fold(const Lattice& lattice, int samples = 4);

/// The volume of the image of the box [lo, hi] of (s, t, u) (inside [0, 1]^3):
/// the integral of det [Xs Xt Xu] over it, Gauss–Legendre with `points`
/// (1..16) nodes per direction on every polynomial piece (the knot spans), so
/// exact up to rounding once 2 points - 1 reaches det's degree, 3p - 1 per
/// direction. In world units: the original volume of that box is
/// det M (hi - lo).x (hi - lo).y (hi - lo).z. Throws std::invalid_argument
/// naming what is outside its range.
double deformed_volume(const Lattice& lattice, Vec3 lo, Vec3 hi, int points);

}  // namespace gllab::deform
