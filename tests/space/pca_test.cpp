// tests/space/pca_test.cpp — the symmetric eigen-solver and the PCA
// (lecture notes ch. 1, §1.8 Space partitioning, "Principal Component
// Analysis"), against Eigen's SelfAdjointEigenSolver (Eigen 3.4) on random
// and degenerate clouds: collinear, coplanar, repeated eigenvalues, one
// repeated point.
#include "space/pca.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "space/symmetric_eigen.h"

namespace {

using gllab::space::Pca;
using gllab::space::Vec3;

// Eigen's answer for B = A^T A / (n - 1), the notes' formula, computed with Eigen.
Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen_pca(const std::vector<Vec3>& P) {
  Eigen::MatrixXd A(P.size(), 3);
  for (std::size_t i = 0; i < P.size(); ++i) A.row(Eigen::Index(i)) << P[i].x, P[i].y, P[i].z;
  const Eigen::RowVector3d c = A.colwise().mean();
  A.rowwise() -= c;
  const Eigen::Matrix3d B = A.transpose() * A / double(P.size() - 1);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(B);
}

Eigen::Vector3d E(Vec3 v) { return {v.x, v.y, v.z}; }

// Our PCA against Eigen's: variances to 1e-12 of the largest; each eigenspace compared by
// its projector sum e e^T over the axes of (numerically) equal eigenvalue, so that a
// repeated eigenvalue, whose eigenvectors are any basis of the space, compares fairly.
void expect_agrees(const std::vector<Vec3>& P, const std::string& what) {
  const Pca ours = gllab::space::pca(P);
  const auto theirs = eigen_pca(P);
  const Eigen::Vector3d lt = theirs.eigenvalues().reverse();  // Eigen: ascending
  const Eigen::Matrix3d vt = theirs.eigenvectors().rowwise().reverse();
  const double scale = std::max(lt(0), 1e-300);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(ours.variance[k], std::max(0.0, lt(k)), 1e-12 * scale) << what << " lambda " << k;
  // Groups of equal eigenvalues (within 1e-9 of the largest).
  for (int k = 0; k < 3;) {
    int end = k + 1;
    while (end < 3 && std::abs(lt(end) - lt(k)) <= 1e-9 * scale) ++end;
    Eigen::Matrix3d Po = Eigen::Matrix3d::Zero(), Pt = Eigen::Matrix3d::Zero();
    for (int i = k; i < end; ++i) {
      Po += E(ours.axis[i]) * E(ours.axis[i]).transpose();
      Pt += vt.col(i) * vt.col(i).transpose();
    }
    // A well separated eigenvalue's vector is as accurate as the gap allows: 1e-12 relative
    // for the clouds here (gaps of 1e-2 and more of the largest eigenvalue).
    EXPECT_LT((Po - Pt).norm(), 1e-10) << what << " eigenspace from " << k;
    k = end;
  }
  // Orthonormal and right-handed.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(dot(ours.axis[i], ours.axis[j]), i == j ? 1 : 0, 1e-14) << what;
  EXPECT_NEAR(dot(cross(ours.axis[0], ours.axis[1]), ours.axis[2]), 1, 1e-14) << what;
}

TEST(Pca, RandomCloudsAgreeWithEigen) {
  std::mt19937 rng(17);
  std::normal_distribution<double> g(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec3> P;
    const double sx = 1 + trial % 5, sy = 0.5, sz = 0.1 + 0.01 * (trial % 7);
    for (int i = 0; i < 50; ++i) {
      const double gx = g(rng), gy = g(rng), gz = g(rng), shear = g(rng);  // drawn in order
      P.push_back({sx * gx + 3, sy * gy - 1, sz * gz + 0.5 * shear});
    }
    expect_agrees(P, "random " + std::to_string(trial));
  }
}

TEST(Pca, DegenerateCloudsAgreeWithEigen) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> line, plane, repeated(10, Vec3{0.3, -2, 7});
  for (int i = 0; i < 40; ++i) {
    const double t = u(rng), s = u(rng);
    line.push_back(Vec3{1, 2, 3} + t * Vec3{0.6, -0.8, 0});
    plane.push_back(Vec3{0, 0, 1} + t * Vec3{1, 1, 0} + s * Vec3{-1, 1, 1});
  }
  expect_agrees(line, "collinear");
  expect_agrees(plane, "coplanar");
  // Repeated eigenvalues: a cube's 8 corners (all three equal), a regular hexagon in z = 0
  // (two equal, one zero).
  std::vector<Vec3> cube, hexagon;
  for (int c = 0; c < 8; ++c) cube.push_back({double(c & 1), double(c >> 1 & 1), double(c >> 2)});
  for (int k = 0; k < 6; ++k)
    hexagon.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0});
  expect_agrees(cube, "cube corners");
  expect_agrees(hexagon, "hexagon");
  // One point repeated: c = (1/n) sum P_i rounds to within an ulp of the point, so every
  // variance is at most the square of that rounding (about 1e-33 here), not more.
  const Pca r = gllab::space::pca(repeated);
  for (int k = 0; k < 3; ++k) EXPECT_LT(r.variance[k], 1e-30);
  EXPECT_NEAR(r.centre.x, 0.3, 1e-16);
  EXPECT_EQ(r.centre.y, -2);
  EXPECT_EQ(r.centre.z, 7);
}

TEST(Pca, CubeCornersHaveTheFormulasVariance) {
  // Coordinates 0 or 1, four of each among 8 corners: the variance with n - 1 is
  // 8 * 0.25 / 7 = 2/7 along every axis (the notes' B, by hand).
  std::vector<Vec3> cube;
  for (int c = 0; c < 8; ++c) cube.push_back({double(c & 1), double(c >> 1 & 1), double(c >> 2)});
  const Pca r = gllab::space::pca(cube);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.variance[k], 2.0 / 7, 1e-15);
  EXPECT_EQ(r.centre, (Vec3{0.5, 0.5, 0.5}));
}

TEST(Pca, PlanarCloudKeepsItsAxesInThePlane) {
  // A rectangle's corners (+-2, +-1): e1 = (1, 0), e2 = (0, 1) up to sign, variances
  // 4 * 4 / 3 and 1 * 4 / 3; e3 = (0, 0, 1).
  const Pca r =
      gllab::space::pca(std::vector<gllab::space::Vec2>{{2, 1}, {-2, 1}, {-2, -1}, {2, -1}});
  EXPECT_NEAR(r.variance[0], 16.0 / 3, 1e-14);
  EXPECT_NEAR(r.variance[1], 4.0 / 3, 1e-14);
  EXPECT_EQ(r.variance[2], 0);
  EXPECT_NEAR(std::abs(r.axis[0].x), 1, 1e-15);
  EXPECT_NEAR(std::abs(r.axis[1].y), 1, 1e-15);
  EXPECT_EQ(r.axis[2], (Vec3{0, 0, 1}));
}

TEST(Pca, BadInputIsOneLineNamingTheValue) {
  try {
    gllab::space::pca(std::vector<Vec3>{{1, 2, 3}});
    FAIL() << "one point accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("1 point"), std::string::npos) << e.what();
  }
  try {
    gllab::space::pca(std::vector<Vec3>{{1, 2, 3}, {0, 0, 0}, {0, 0, 0}, {NAN, 0, 1}});
    FAIL() << "NaN accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "pca: P[3] = (nan, 0, 1) is not finite");
  }
}

TEST(SymmetricEigen, DecomposesRandomMatrices) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int trial = 0; trial < 500; ++trial) {
    double A[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) A[i][j] = A[j][i] = u(rng);
    const gllab::space::SymmetricEigen e = gllab::space::symmetric_eigen(A);
    EXPECT_GE(e.values[0], e.values[1]);
    EXPECT_GE(e.values[1], e.values[2]);
    EXPECT_LE(e.sweeps, 10);
    double scale = 0;
    for (int k = 0; k < 3; ++k) scale = std::max(scale, std::abs(e.values[k]));
    for (int k = 0; k < 3; ++k) {
      int big = 0;
      for (int i = 0; i < 3; ++i) {
        // A v = lambda v, to rounding of the largest eigenvalue.
        double Av = 0;
        for (int j = 0; j < 3; ++j) Av += A[i][j] * e.vectors[j][k];
        EXPECT_NEAR(Av, e.values[k] * e.vectors[i][k], 1e-14 * scale);
        if (std::abs(e.vectors[i][k]) > std::abs(e.vectors[big][k])) big = i;
        double vv = 0;
        for (int j = 0; j < 3; ++j) vv += e.vectors[j][k] * e.vectors[j][i];
        EXPECT_NEAR(vv, i == k ? 1 : 0, 1e-15 * 4);
      }
      EXPECT_GT(e.vectors[big][k], 0);  // the sign convention
    }
  }
}

TEST(SymmetricEigen, RejectsANonFiniteEntry) {
  double A[3][3] = {{1, 0, 0}, {0, 1, INFINITY}, {0, 0, 1}};
  EXPECT_THROW(gllab::space::symmetric_eigen(A), std::invalid_argument);
}

}  // namespace
