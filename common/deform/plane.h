// common/deform/plane.h — a deformation of the plane: the lecture notes'
// deformation of a 2-D image (ch. 1, §1.7 Surface representations,
// "Deformation": "displacing control points of a regular grid structure. The
// surface defined by the displaced control net then maps the domain onto
// itself: (x', y') = f(x, y)").
//
// f is a tensor-product B-spline of the unit square [0, 1]^2 with control
// points c_ij in the plane:
//     f(x, y) = sum_i sum_j c_ij N_i(x) N_j(y),
// clamped uniform knots (spline/knots.h) of degree p in both directions, so
// a control point acts only on the (p + 1)^2 cells around it. With c_ij at the
// Greville abscissae f is the identity (linear precision); the border's
// control points stay there, so the border maps onto itself and f maps the
// square onto itself as long as it does not fold (det J > 0 everywhere).
//
// The morph (deform/morph.h) moves the geometry by
//     f(t, x) = (1 - t) x + t f2(x)            (§1.7, "Morphing"),
// and warps an image backwards, so it needs f(t, .)^-1: inverse_point
// solves f(t, x) = y by Newton's method.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "deform/mat.h"

namespace gllab::deform {

/// Control points count[0] along x by count[1] along y, P[i * count[1] + j];
/// 2..kMaxLatticePoints each, degree 1..kMaxLatticeDegree and below both counts.
struct PlaneDeformation {
  std::array<int, 2> count{7, 7};
  int degree = 3;
  std::vector<Vec2> P;

  Vec2& point(int i, int j) { return P[i * count[1] + j]; }
  const Vec2& point(int i, int j) const { return P[i * count[1] + j]; }
  /// True for the control points on the border of the grid (they keep it in place).
  bool on_border(int i, int j) const {
    return i == 0 || j == 0 || i == count[0] - 1 || j == count[1] - 1;
  }
};

/// The identity: c_ij at the Greville abscissae. Throws std::invalid_argument
/// naming a count or degree outside the limits.
PlaneDeformation identity_plane(int nx, int ny, int degree);

/// Throws std::invalid_argument naming the value: counts, degree, the size
/// of P, a point that is not finite.
void validate(const PlaneDeformation& f);

/// f and its partials at x, and the Jacobian J = [fx fy].
struct PlaneDerivs {
  Vec2 f, fx, fy;
  Mat2 jacobian() const { return {fx, fy}; }
};

/// Evaluates one deformation at many points: validates once. x must lie in
/// [0, 1]^2 (not checked here; plane_derivs checks).
class PlaneEvaluator {
 public:
  explicit PlaneEvaluator(const PlaneDeformation& f);
  PlaneDerivs operator()(Vec2 x) const;

 private:
  PlaneDeformation f_;
  std::array<std::vector<double>, 2> knots_;
};

/// One point, checked: throws std::invalid_argument naming x outside [0, 1]^2.
PlaneDerivs plane_derivs(const PlaneDeformation& f, Vec2 x);

/// x with f(t, x) = (1 - t) x + t f2(x) = y, by Newton's method from `guess`
/// (J = (1 - t) I + t J2), each step halved until |f(t, x) - y| decreases and
/// x kept in the square. Converged when |f(t, x) - y| <= kInverseTolerance;
/// none after kInverseIterations steps (where f folds, say).
inline constexpr double kInverseTolerance = 1e-13;
inline constexpr int kInverseIterations = 60;
std::optional<Vec2> inverse_point(const PlaneEvaluator& f2, double t, Vec2 y, Vec2 guess);

/// f2 from a feature correspondence: the inner control points of `base` move
/// so that f2(from[k]) = to[k] for every k, the border's points stay, and
/// the displacements d are as smooth as the constraints allow: they minimise
/// the membrane energy of the control grid, the sum over its edges (a, b) of
/// |d_a - d_b|^2 (the discrete Dirichlet energy; Lee et al. 1996 derive their
/// morphing warps by energy minimisation too). Outside the features' supports
/// d is a discrete harmonic function, with no maximum or minimum there (the
/// maximum principle), so it does not swing between the features the way the
/// plain least-norm displacement does (Hsu, Hughes and Kaufman 1992). On lab
/// 28's faces the least-norm f2 folds on most grids, this one on no cubic grid
/// from 12 x 12 to 24 x 24 (smallest det J 0.08 .. 0.2).
/// Solved with Lagrange multipliers: d = K^-1 W^T lambda, (W K^-1 W^T) lambda
/// = r, K the grid's Laplacian (a band, by Cholesky), W the features' basis
/// weights, r = to - base(from). Throws std::invalid_argument naming the
/// feature: counts differ, a point outside (0, 1)^2, or a feature the grid
/// cannot meet together with the others (missed by more than
/// kFeatureTolerance: two at nearly the same place going to different
/// places, more features than the grid can bend to).
inline constexpr double kFeatureTolerance = 1e-9;
PlaneDeformation fit_features(const PlaneDeformation& base, const std::vector<Vec2>& from,
                              const std::vector<Vec2>& to);

/// Where a deformation folds (det J <= 0), if it does: det J sampled on a
/// grid of samples * (count - 1) + 1 points per direction, the smallest.
struct PlaneFold {
  bool folds = false;
  double min_det = 0;
  Vec2 at;  // where, in the square
};
PlaneFold find_plane_fold(const PlaneDeformation& f, int samples = 8);

/// "the grid folds: det J = -0.21 at (x, y) = (0.41, 0.63)" or "no fold: det J >= 0.52".
std::string plane_fold_text(const PlaneFold& fold);

}  // namespace gllab::deform
