// common/spline/basis_change.cpp — see basis_change.h.
#include "spline/basis_change.h"

#include <stdexcept>
#include <string>

#include "spline/bezier.h"
#include "spline/bspline.h"
#include "spline/interpolation.h"

namespace gllab::spline {

std::array<std::array<double, 4>, 4> cubic_basis_matrix(CubicBasis basis) {
  std::array<std::array<double, 4>, 4> M{};
  switch (basis) {
    case CubicBasis::kBezier: {
      const std::vector<std::vector<double>> B = bezier_matrix(3);
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) M[r][c] = B[r][c];
      break;
    }
    case CubicBasis::kUniformBspline:
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) M[r][c] = kUniformCubicMatrix[r][c];
      break;
    case CubicBasis::kHermite:  // ascending rows c_0..c_3 -> the notes' u^3..u^0 rows
      for (int r = 0; r < 4; ++r) M[r] = hermite_matrix()[3 - r];
      break;
    case CubicBasis::kPower:
      for (int r = 0; r < 4; ++r) M[r][r] = 1;
      break;
  }
  return M;
}

std::vector<Vec3> change_cubic_basis(const std::vector<Vec3>& P_from, CubicBasis from,
                                     CubicBasis to) {
  if (P_from.size() != 4)
    throw std::invalid_argument("change_cubic_basis: needs 4 control entries, got " +
                                std::to_string(P_from.size()));
  const auto M1 = cubic_basis_matrix(from), M2 = cubic_basis_matrix(to);
  std::vector<Vec3> power(4, Vec3{0, 0, 0});  // M_from P_from: the power coefficients
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) power[r] = power[r] + P_from[c] * M1[r][c];
  std::vector<std::vector<double>> A(4, std::vector<double>(4));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) A[r][c] = M2[r][c];
  return gauss_solve(A, power);
}

Vec3 cubic_basis_point(const std::vector<Vec3>& P, CubicBasis basis, double u) {
  if (P.size() != 4)
    throw std::invalid_argument("cubic_basis_point: needs 4 control entries, got " +
                                std::to_string(P.size()));
  const auto M = cubic_basis_matrix(basis);
  const double U[4] = {u * u * u, u * u, u, 1};
  Vec3 q{0, 0, 0};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) q = q + P[c] * (U[r] * M[r][c]);
  return q;
}

}  // namespace gllab::spline
