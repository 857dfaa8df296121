// common/space/pca.cpp — principal component analysis (lecture notes ch. 1,
// §1.8 Space partitioning, "Principal Component Analysis (PCA)").
#include "space/pca.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "space/symmetric_eigen.h"

namespace gllab::space {

Pca pca(const std::vector<Vec3>& points) {
  const std::size_t n = points.size();
  if (n < 2)
    throw std::invalid_argument("pca: " + std::to_string(n) +
                                " point(s) (B = A^T A / (n - 1) needs at least 2)");
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      char text[160];
      std::snprintf(text, sizeof text, "pca: P[%zu] = (%g, %g, %g) is not finite", i, p.x, p.y,
                    p.z);
      throw std::invalid_argument(text);
    }
  }
  // c = (1/n) sum P_i; the rows of A are P_i - c; B = A^T A / (n - 1).
  Vec3 c{};
  for (const Vec3& p : points) c += p;
  c = c / double(n);
  double B[3][3] = {};
  for (const Vec3& p : points) {
    const double a[3] = {p.x - c.x, p.y - c.y, p.z - c.z};
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) B[i][j] += a[i] * a[j];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) B[j][i] = B[i][j] = B[i][j] / double(n - 1);
  const SymmetricEigen e = symmetric_eigen(B);
  Pca r{};
  r.centre = c;
  r.count = n;
  for (int k = 0; k < 3; ++k) {
    r.variance[k] = std::max(0.0, e.values[k]);
    r.axis[k] = {e.vectors[0][k], e.vectors[1][k], e.vectors[2][k]};
  }
  r.axis[2] = cross(r.axis[0], r.axis[1]);  // right-handed (the same line, maybe turned over)
  return r;
}

Pca pca(const std::vector<Vec2>& points) {
  std::vector<Vec3> in;
  in.reserve(points.size());
  for (const Vec2& p : points) in.push_back({p.x, p.y, 0});
  Pca r = pca(in);
  // B's third row and column are zero: (0, 0, 1) is an eigenvector of eigenvalue 0. Put it
  // last whatever the order of equal zeros, and keep the other two in the plane.
  std::vector<Vec3> planar;
  std::vector<double> var;
  for (int k = 0; k < 3; ++k)
    if (std::abs(r.axis[k].z) < 0.5)
      planar.push_back({r.axis[k].x, r.axis[k].y, 0}), var.push_back(r.variance[k]);
  if (planar.size() == 2) {
    r.axis[0] = normalized(planar[0]);
    r.axis[1] = normalized(planar[1]);
    r.variance[0] = var[0];
    r.variance[1] = var[1];
  } else {  // all points coincide: any basis of the plane
    r.axis[0] = {1, 0, 0};
    r.axis[1] = {0, 1, 0};
    r.variance[0] = r.variance[1] = 0;
  }
  r.axis[2] = {0, 0, 1};
  r.variance[2] = 0;
  if (cross(r.axis[0], r.axis[1]).z < 0) r.axis[1] = -1 * r.axis[1];
  return r;
}

}  // namespace gllab::space
