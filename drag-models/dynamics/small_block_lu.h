// LU factorisation with partial pivoting of one small fixed-size block
// (the 6x6 diagonal blocks of the block-tridiagonal rod step), unrolled at
// compile time. Eigen's PartialPivLU gives the same factors but routes the
// solves with a matrix right-hand side through its blocked (large-matrix)
// triangular kernels, which cost more than the arithmetic at this size
// (measured: ~20 % of a 1000-sphere step). Golub & Van Loan, "Matrix
// Computations" (4th ed.), Alg. 3.4.1 (Gaussian elimination with partial
// pivoting, outer-product form).
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <utility>

namespace hsrod {

template <int N>
class SmallBlockLu {
 public:
  using Matrix = Eigen::Matrix<double, N, N>;
  using RowMajorMatrix = Eigen::Matrix<double, N, N, Eigen::RowMajor>;

  SmallBlockLu() = default;  // unfactorised (call compute before solving)
  // Factorises P a = L U in place of a copy of a.
  explicit SmallBlockLu(const Matrix& a) : lu_(a) { factorise(); }
  void compute(const Matrix& a) {
    lu_ = a;
    factorise();
  }

  // Overwrites b (N rows, any number of columns) with a^-1 b.
  // Overwrites the N x N block b with a^-1 b, all columns at once: rows of
  // a row-major copy are updated as a whole (the same operations on every
  // entry in the same order as solve_in_place, so the same result to the
  // last bit, in fewer, vectorised instructions).
  void solve_block_in_place(Matrix& b) const {
    RowMajorMatrix x;
    solve_block_in_place(b, x);
  }
  // The same for any N x N block b (a Map of group storage), leaving the
  // solution also in `x`, row-major (for products that run along its rows).
  template <typename Block>
  void solve_block_in_place(Eigen::MatrixBase<Block>& b, Eigen::Matrix<double, N, N, Eigen::RowMajor>& x) const {
    x = b;
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k)
      if (pivots_[k] != k) x.row(k).swap(x.row(pivots_[k]));
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k)
#pragma GCC unroll 8
      for (int r = k + 1; r < N; ++r) x.row(r) -= lu_(r, k) * x.row(k);
#pragma GCC unroll 8
    for (int k = N - 1; k >= 0; --k) {
      x.row(k) *= inverse_diagonal_[k];
#pragma GCC unroll 8
      for (int r = 0; r < k; ++r) x.row(r) -= lu_(r, k) * x.row(k);
    }
    b = x;
  }

  // Each column is worked on in a local copy: written through `b`, the
  // compiler must assume that every store may change the factors and
  // reloads them (the same operations in the same order, ~2x fewer
  // instructions).
  template <typename Rhs>
  void solve_in_place(Eigen::MatrixBase<Rhs>& b) const {
    for (int j = 0; j < b.cols(); ++j) {
      double x[N];
#pragma GCC unroll 8
      for (int r = 0; r < N; ++r) x[r] = b(r, j);
#pragma GCC unroll 8
      for (int k = 0; k < N; ++k)
        if (pivots_[k] != k) std::swap(x[k], x[pivots_[k]]);
#pragma GCC unroll 8
      for (int k = 0; k < N; ++k) {
        const double xk = x[k];
#pragma GCC unroll 8
        for (int r = k + 1; r < N; ++r) x[r] -= lu_(r, k) * xk;
      }
#pragma GCC unroll 8
      for (int k = N - 1; k >= 0; --k) {
        x[k] *= inverse_diagonal_[k];
        const double xk = x[k];
#pragma GCC unroll 8
        for (int r = 0; r < k; ++r) x[r] -= lu_(r, k) * xk;
      }
#pragma GCC unroll 8
      for (int r = 0; r < N; ++r) b(r, j) = x[r];
    }
  }

 private:
  void factorise() {
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
      int pivot = k;
      for (int r = k + 1; r < N; ++r)
        if (std::fabs(lu_(r, k)) > std::fabs(lu_(pivot, k))) pivot = r;
      pivots_[k] = pivot;
      if (pivot != k)
        for (int c = 0; c < N; ++c) std::swap(lu_(k, c), lu_(pivot, c));
      const double inverse = 1.0 / lu_(k, k);
      inverse_diagonal_[k] = inverse;
#pragma GCC unroll 8
      for (int r = k + 1; r < N; ++r) lu_(r, k) *= inverse;
#pragma GCC unroll 8
      for (int c = k + 1; c < N; ++c) {
        const double u = lu_(k, c);
#pragma GCC unroll 8
        for (int r = k + 1; r < N; ++r) lu_(r, c) -= lu_(r, k) * u;
      }
    }
  }

  Matrix lu_ = Matrix::Zero();
  int pivots_[N] = {};
  double inverse_diagonal_[N] = {};  // 1 / U(k, k)
};

}  // namespace hsrod
