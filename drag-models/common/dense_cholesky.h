// Inverse of a small dense symmetric positive definite matrix of run-time
// size through its Cholesky factor (level 3's 2n x 2n coupling matrix
// I + zeta_o M, hydro/nonlocal_model.cpp, n ~ 10): a = L L^T, X = L^-1,
// a^-1 = X^T X, (1/2) n^3 flops in all against the n^3 of an LU and its
// inverse (common/dense_lu.h), and exactly symmetric. Unblocked, on
// columns (Eigen's LLT routes a 20 x 20 matrix through its blocked
// kernels). Golub & Van Loan, "Matrix Computations" (4th ed.), Alg. 4.2.2
// (outer-product Cholesky) and sec. 3.1 (triangular inverse).
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace hsrod {

// a^-1 into `inverse` (resized) when a (n x n, symmetric: its lower triangle
// is read) is positive definite; false, `inverse` undefined, when a pivot
// is not positive (the caller then takes an LU). `factor`: work storage
// (resized), left holding L in its lower triangle.
inline bool cholesky_inverse(const Eigen::MatrixXd& a, Eigen::MatrixXd& factor, Eigen::MatrixXd& inverse) {
  const int n = static_cast<int>(a.rows());
  factor = a;
  double* l = factor.data();
  for (int k = 0; k < n; ++k) {
    double* col_k = l + static_cast<long>(k) * n;
    if (!(col_k[k] > 0.0)) return false;
    const double pivot = std::sqrt(col_k[k]);
    col_k[k] = pivot;
    const double inverse_pivot = 1.0 / pivot;
    for (int r = k + 1; r < n; ++r) col_k[r] *= inverse_pivot;
    for (int c = k + 1; c < n; ++c) {
      double* col_c = l + static_cast<long>(c) * n;
      const double u = col_k[c];
      for (int r = c; r < n; ++r) col_c[r] -= col_k[r] * u;
    }
  }
  // X = L^-1 (lower), column j by forward substitution of e_j from row j.
  inverse.setZero(n, n);
  for (int j = 0; j < n; ++j) {
    double* x = inverse.data() + static_cast<long>(j) * n;
    x[j] = 1.0;
    for (int k = j; k < n; ++k) {
      const double* col_k = l + static_cast<long>(k) * n;
      x[k] /= col_k[k];
      const double xk = x[k];
      for (int r = k + 1; r < n; ++r) x[r] -= col_k[r] * xk;
    }
  }
  // a^-1 = X^T X: entry (i, j), i <= j, is the product of columns i and j
  // of X over rows j..n-1 (X is lower). Computed into the upper triangle
  // from columns that are still X's lower part, then mirrored.
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i <= j; ++i)
      inverse(i, j) = inverse.col(i).tail(n - j).dot(inverse.col(j).tail(n - j));
  }
  for (int j = 0; j < n; ++j)
    for (int i = j + 1; i < n; ++i) inverse(i, j) = inverse(j, i);
  return true;
}

}  // namespace hsrod
