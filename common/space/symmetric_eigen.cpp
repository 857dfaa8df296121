// common/space/symmetric_eigen.cpp — the cyclic Jacobi method for a symmetric
// 3 x 3 matrix (Numerical Recipes, 3rd ed., §11.1). Moved here from the spline
// core's Nielson metric, which now calls it.
#include "space/symmetric_eigen.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace gllab::space {
namespace {

/// Jacobi sweeps for a 3 x 3 symmetric matrix; it converges in far fewer.
constexpr int kMaxSweeps = 50;

using Matrix3 = double[3][3];

}  // namespace

SymmetricEigen symmetric_eigen(const double (&M)[3][3]) {
  Matrix3 A, V;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double a = i <= j ? M[i][j] : M[j][i];  // the upper triangle
      if (!std::isfinite(a))
        throw std::invalid_argument("symmetric_eigen: A[" + std::to_string(i) + "][" +
                                    std::to_string(j) + "] = " + std::to_string(a) +
                                    " is not finite");
      A[i][j] = a;
      V[i][j] = i == j ? 1.0 : 0.0;
    }
  SymmetricEigen r{};
  for (r.sweeps = 0; r.sweeps < kMaxSweeps; ++r.sweeps) {
    const double off = A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2];
    const double on = A[0][0] * A[0][0] + A[1][1] * A[1][1] + A[2][2] * A[2][2];
    if (off == 0 || off <= 1e-32 * on) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (A[p][q] == 0) continue;
        // The rotation that zeroes A[p][q]: t = tan of its angle, the smaller root of
        // t^2 + 2 theta t - 1 = 0 (Numerical Recipes eq. 11.1.8).
        const double theta = (A[q][q] - A[p][p]) / (2 * A[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        Matrix3 J = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        J[p][p] = c;
        J[q][q] = c;
        J[p][q] = s;
        J[q][p] = -s;
        Matrix3 AJ = {}, JtAJ = {}, VJ = {};
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) {
              AJ[i][j] += A[i][k] * J[k][j];
              VJ[i][j] += V[i][k] * J[k][j];
            }
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) JtAJ[i][j] += J[k][i] * AJ[k][j];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            A[i][j] = JtAJ[i][j];
            V[i][j] = VJ[i][j];
          }
        A[p][q] = A[q][p] = 0;  // exactly zero by the choice of t
      }
  }
  // Sort descending (a stable selection over three), then fix each vector's sign.
  int order[3] = {0, 1, 2};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (A[order[j]][order[j]] > A[order[i]][order[i]]) std::swap(order[i], order[j]);
  for (int k = 0; k < 3; ++k) {
    const int c = order[k];
    r.values[k] = A[c][c];
    int big = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(V[i][c]) > std::abs(V[big][c])) big = i;
    const double sign = V[big][c] < 0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i) r.vectors[i][k] = sign * V[i][c];
  }
  return r;
}

}  // namespace gllab::space
