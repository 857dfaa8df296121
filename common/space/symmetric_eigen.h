// common/space/symmetric_eigen.h — eigenvalues and eigenvectors of a
// symmetric 3 x 3 matrix by the cyclic Jacobi method (Numerical Recipes, 3rd
// ed., §11.1). The PCA of the space partitions (pca.h) and the Nielson metric
// of the spline core (spline/parameterization.cpp) both use it.
//
// This file depends on the standard library only: it is the one piece of
// common/space that sits below the spline core (its own library,
// gllab_space_eigen), so that common/spline can link it.
#pragma once

namespace gllab::space {

/// A = sum_k values[k] v_k v_k^T, v_k the column k of `vectors`
/// (vectors[i][k] is component i of v_k).
struct SymmetricEigen {
  double values[3];      // descending: values[0] >= values[1] >= values[2]
  double vectors[3][3];  // orthonormal columns; each column's largest-magnitude
                         // component is positive (the first such on a tie)
  int sweeps;            // Jacobi sweeps used
};

/// The eigen-decomposition of the symmetric matrix A (A[i][j] == A[j][i] is
/// assumed; only the upper triangle is read). Throws std::invalid_argument
/// naming the entry when A has a NaN or an infinity.
SymmetricEigen symmetric_eigen(const double (&A)[3][3]);

}  // namespace gllab::space
