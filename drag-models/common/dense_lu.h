// LU factorisation with partial pivoting of a dense matrix of run-time size
// (the implicit step's matrix when non-local drag couples every sphere, 6n x
// 6n with n ~ 10, or its Schur complement; level 3's 2n x 2n coupling
// matrix, hydro/nonlocal_model.cpp): the outer-product algorithm of
// dynamics/small_block_lu.h on storage kept between steps (no allocation
// once sized). Eigen's
// PartialPivLU<MatrixXd> routes a 60 x 60 matrix through its blocked
// (large-matrix) kernels, whose packing cost more than the arithmetic at
// this size (callgrind: ~340 k instructions per 60 x 60 factorisation).
// Golub & Van Loan, "Matrix Computations" (4th ed.), Alg. 3.4.1.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <utility>
#include <vector>

namespace hsrod {

class DenseLu {
 public:
  // Factorises P a = L U; a is overwritten by the factors (the caller's
  // assembly buffer, reused: no copy).
  void compute_in_place(Eigen::MatrixXd& a) {
    lu_ = &a;
    const int n = static_cast<int>(a.rows());
    pivots_.resize(n);
    inverse_diagonal_.resize(n);
    double* m = a.data();
    for (int k = 0; k < n; ++k) {
      double* col_k = m + static_cast<long>(k) * n;
      int pivot = k;
      for (int r = k + 1; r < n; ++r)
        if (std::fabs(col_k[r]) > std::fabs(col_k[pivot])) pivot = r;
      pivots_[k] = pivot;
      if (pivot != k)
        for (int c = 0; c < n; ++c) std::swap(m[static_cast<long>(c) * n + k], m[static_cast<long>(c) * n + pivot]);
      const double inverse = 1.0 / col_k[k];
      inverse_diagonal_[k] = inverse;
      for (int r = k + 1; r < n; ++r) col_k[r] *= inverse;
      for (int c = k + 1; c < n; ++c) {
        double* col_c = m + static_cast<long>(c) * n;
        const double u = col_c[k];
        if (u == 0.0) continue;  // exact: the update would subtract zeros
        for (int r = k + 1; r < n; ++r) col_c[r] -= col_k[r] * u;
      }
    }
  }

  // a^-1 (n x n) into `inverse` (resized): a^-1 e_j column by column. The
  // forward substitution of the permuted unit vector starts at its one
  // (the entries above stay zero): (2/3) n^3 flops in all.
  void inverse(Eigen::MatrixXd& inverse) const {
    const Eigen::MatrixXd& lu = *lu_;
    const int n = static_cast<int>(lu.rows());
    const double* m = lu.data();
    inverse.setZero(n, n);
    for (int j = 0; j < n; ++j) {
      double* b = inverse.data() + static_cast<long>(j) * n;
      int one = j;  // where the permutation takes the one of e_j
      for (int k = 0; k < n; ++k) {
        if (pivots_[k] == one) one = k;
        else if (k == one) one = pivots_[k];
      }
      b[one] = 1.0;
      for (int k = one; k < n; ++k) {
        const double* col_k = m + static_cast<long>(k) * n;
        const double bk = b[k];
        if (bk == 0.0) continue;  // exact: the update would subtract zeros
        for (int r = k + 1; r < n; ++r) b[r] -= col_k[r] * bk;
      }
      for (int k = n - 1; k >= 0; --k) {
        const double* col_k = m + static_cast<long>(k) * n;
        b[k] *= inverse_diagonal_[k];
        const double bk = b[k];
        for (int r = 0; r < k; ++r) b[r] -= col_k[r] * bk;
      }
    }
  }

  // Overwrites b (n entries) with a^-1 b.
  void solve_in_place(Eigen::VectorXd& b) const {
    const Eigen::MatrixXd& lu = *lu_;
    const int n = static_cast<int>(lu.rows());
    const double* m = lu.data();
    for (int k = 0; k < n; ++k)
      if (pivots_[k] != k) std::swap(b[k], b[pivots_[k]]);
    for (int k = 0; k < n; ++k) {
      const double* col_k = m + static_cast<long>(k) * n;
      const double bk = b[k];
      for (int r = k + 1; r < n; ++r) b[r] -= col_k[r] * bk;
    }
    for (int k = n - 1; k >= 0; --k) {
      const double* col_k = m + static_cast<long>(k) * n;
      b[k] *= inverse_diagonal_[k];
      const double bk = b[k];
      for (int r = 0; r < k; ++r) b[r] -= col_k[r] * bk;
    }
  }

 private:
  const Eigen::MatrixXd* lu_ = nullptr;  // factors, in the caller's matrix
  std::vector<int> pivots_;
  std::vector<double> inverse_diagonal_;  // 1 / U(k, k)
};

}  // namespace hsrod
