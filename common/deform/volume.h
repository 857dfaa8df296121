// common/deform/volume.h — trivariate tensor-product volumes: the lattices
// of free-form deformation (lecture notes ch. 1, §1.7 Surface
// representations, "Morphing": "three-dimensional objects can be cross-faded,
// e.g. using B-spline volumes, which are called free-form deformations").
//
// A volume is the tensor product of three curve bases, one per direction:
//     X(s, t, u) = sum_i sum_j sum_k P_ijk N_i(s) N_j(t) N_k(u),   (s, t, u) in [0, 1]^3,
// as a surface is the product of two (§1.7, "Bézier tensor product"). Two kinds:
//   - Bernstein (Sederberg and Parry 1986, "Free-form deformation of solid
//     geometric models", SIGGRAPH '86): N_i = B_i^l, the degree l = points - 1
//     in each direction. Every control point acts on the whole volume: global
//     control.
//   - B-spline: N_i = N_{i,p} over clamped uniform knots (spline/knots.h
//     clamped_uniform_knots), degree p < points. A control point acts only on
//     the (p + 1)^3 spans around it: local control.
// A Bernstein basis of degree l is the B-spline basis of degree l over the
// knots {0 x (l + 1), 1 x (l + 1)} (no interior knot), so one evaluator does
// both: A2.1 FindSpan and A2.3 DersBasisFuns (The NURBS Book, 2nd ed., pp. 68,
// 72; spline/basis.h) per direction, then the triple sum.
//
// Notation: counts (nx, ny, nz) of control points along s, t, u; degrees
// (px, py, pz); P stored with u fastest: P[(i * ny + j) * nz + k]. The Jacobian
// of X with respect to (s, t, u) is J = [Xs Xt Xu] (columns, deform/mat.h).
#pragma once

#include <array>
#include <vector>

#include "deform/mat.h"
#include "spline/vec.h"

namespace gllab::deform {

/// Limits: 2..kMaxLatticePoints points per direction, degree 1..kMaxLatticeDegree
/// (a Bernstein lattice therefore has at most kMaxLatticeDegree + 1 points per
/// direction). Evaluating costs (p + 1)^3 points; the caps keep that bounded.
inline constexpr int kMaxLatticePoints = 64;
inline constexpr int kMaxLatticeDegree = 15;

struct Volume {
  std::array<int, 3> count{4, 4, 4};   // control points along s, t, u
  std::array<int, 3> degree{3, 3, 3};  // count - 1 in a direction: Bernstein there
  std::vector<Vec3> P;                 // count[0] * count[1] * count[2] points

  int index(int i, int j, int k) const { return (i * count[1] + j) * count[2] + k; }
  const Vec3& point(int i, int j, int k) const { return P[index(i, j, k)]; }
  Vec3& point(int i, int j, int k) { return P[index(i, j, k)]; }
  /// True when every direction has degree count - 1: Sederberg and Parry's
  /// Bernstein lattice.
  bool bernstein() const;
};

/// The identity of the unit cube: P_ijk at the Greville abscissae of the
/// knots in each direction, (g_i, g_j, g_k) with g_i = (U[i+1] + ... +
/// U[i+p]) / p: for Bernstein g_i = i / l, Sederberg and Parry's regular
/// lattice. By linear precision X(s, t, u) = (s, t, u). Throws
/// std::invalid_argument naming the count or degree outside the limits above.
Volume bernstein_volume(int nx, int ny, int nz);
Volume bspline_volume(int nx, int ny, int nz, int degree);

/// The knots of direction `axis` (0, 1, 2): clamped uniform, count + degree + 1 of them.
std::vector<double> volume_knots(const Volume& v, int axis);

/// Throws std::invalid_argument naming the value: a count or degree outside
/// the limits, P of the wrong size, a control point that is not finite.
void validate(const Volume& v);

/// X and its first partial derivatives at (s, t, u).
struct VolumeDerivs {
  Vec3 X, Xs, Xt, Xu;
  /// J = [Xs Xt Xu].
  Mat3 jacobian() const { return {Xs, Xt, Xu}; }
};

/// X(s, t, u) with its partials. (s, t, u) must lie in [0, 1]^3; throws
/// std::invalid_argument naming the parameter otherwise (and for an invalid
/// volume).
VolumeDerivs volume_derivs(const Volume& v, double s, double t, double u);
Vec3 volume_point(const Volume& v, double s, double t, double u);

/// det [Xs Xt Xu]: how the volume maps a small cube's volume. Positive where
/// the map keeps orientation, 0 or negative where the volume folds over itself.
inline double volume_jacobian_det(const VolumeDerivs& d) { return det(d.jacobian()); }

/// The same evaluator for many points, without re-checking the volume at
/// each: build once, then call at (s, t, u) in [0, 1]^3 (not checked here).
/// What deform_mesh and the benchmark use.
class VolumeEvaluator {
 public:
  explicit VolumeEvaluator(const Volume& v);  // validates v
  VolumeDerivs operator()(double s, double t, double u) const;

 private:
  Volume v_;
  std::array<std::vector<double>, 3> knots_;
};

}  // namespace gllab::deform
