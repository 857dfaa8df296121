// common/space/pca.h — principal component analysis of a point cloud, for
// the splitting planes of BSP trees (lecture notes ch. 1, §1.8 Space
// partitioning, "Principal Component Analysis (PCA)"):
//     c = (1/n) sum P_i,   A = the n x 3 matrix of rows P_i - c,
//     B = A^T A / (n - 1),  B e_i = lambda_i e_i.
// The notes stop at "B has real eigenvalues and eigenvectors"; the
// eigenvectors are computed here by the Jacobi method (symmetric_eigen.h).
// The extent of the cloud along e_i is proportional to sqrt(lambda_i).
#pragma once

#include <cstddef>
#include <vector>

#include "spline/vec.h"

namespace gllab::space {

using spline::Vec2;
using spline::Vec3;

struct Pca {
  Vec3 centre;         // c
  double variance[3];  // lambda_1 >= lambda_2 >= lambda_3 >= 0 (negative rounding clamped to 0)
  Vec3 axis[3];        // e_1, e_2, e_3: orthonormal, right-handed (e_3 = e_1 x e_2)
  std::size_t count;   // n
};

/// The PCA of the points. Throws std::invalid_argument with one line when
/// there are fewer than 2 points (B divides by n - 1), or a coordinate is
/// not finite (naming the point: "pca: P[3] = (nan, 0, 1) is not finite").
/// Repeated eigenvalues (a sphere-like cloud, a square's corners) give some
/// orthonormal basis of the eigenspace, as any solver does.
Pca pca(const std::vector<Vec3>& points);

/// The same for points of the plane, taken as (x, y, 0): axis[0] and axis[1]
/// lie in the plane, axis[2] is (0, 0, 1) exactly and variance[2] is 0.
Pca pca(const std::vector<Vec2>& points);

}  // namespace gllab::space
