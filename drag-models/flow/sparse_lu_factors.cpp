#include "flow/sparse_lu_factors.h"

#include <umfpack.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

namespace hsrod {

namespace {
// Frees UMFPACK's symbolic and numeric objects on every path.
struct UmfpackObjects {
  void* symbolic = nullptr;
  void* numeric = nullptr;
  ~UmfpackObjects() {
    if (numeric) umfpack_di_free_numeric(&numeric);
    if (symbolic) umfpack_di_free_symbolic(&symbolic);
  }
};

}  // namespace

SparseLuFactors::SparseLuFactors(const Eigen::SparseMatrix<double>& matrix) : n_(static_cast<int>(matrix.rows())) {
  if (matrix.rows() != matrix.cols() || n_ == 0) throw std::invalid_argument("SparseLuFactors: need a square matrix");
  Eigen::SparseMatrix<double> a = matrix;
  a.makeCompressed();
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_di_defaults(control);
  // The window's saddle-point matrix is unsymmetric in value and pattern
  // (Brinkman momentum rows against continuity rows): the unsymmetric
  // strategy with COLAMD alone. UMFPACK's default ordering (CHOLMOD: COLAMD,
  // then METIS when the fill looks large) spent ~15 % more on factorising
  // and gave ~7-18 % more fill (slower solves) on the pore windows of
  // 2 300-32 000 cells (tests/benchmarks/RESULTS.md, session 13).
  control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_UNSYMMETRIC;
  control[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
  UmfpackObjects objects;
  int status = umfpack_di_symbolic(n_, n_, a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(), &objects.symbolic,
                                   control, info);
  if (status == UMFPACK_OK)
    status = umfpack_di_numeric(a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(), objects.symbolic,
                                &objects.numeric, control, info);
  if (status != UMFPACK_OK)  // includes UMFPACK_WARNING_singular_matrix
    throw std::runtime_error("SparseLuFactors: UMFPACK factorisation failed (status " + std::to_string(status) + ")");
  int lnz = 0, unz = 0, n_row = 0, n_col = 0, nz_udiag = 0;
  umfpack_di_get_lunz(&lnz, &unz, &n_row, &n_col, &nz_udiag, objects.numeric);
  l_start_.resize(n_ + 1);
  l_column_.resize(lnz);
  l_values_.resize(lnz);
  u_start_.resize(n_ + 1);
  u_row_.resize(unz);
  u_values_.resize(unz);
  row_order_.resize(n_);
  column_order_.resize(n_);
  row_scale_.resize(n_);
  int do_recip = 0;
  status = umfpack_di_get_numeric(l_start_.data(), l_column_.data(), l_values_.data(), u_start_.data(), u_row_.data(),
                                  u_values_.data(), row_order_.data(), column_order_.data(), nullptr, &do_recip,
                                  row_scale_.data(), objects.numeric);
  if (status != UMFPACK_OK)
    throw std::runtime_error("SparseLuFactors: UMFPACK could not return the factors (status " + std::to_string(status) + ")");
  if (!do_recip)
    for (double& r : row_scale_) r = 1.0 / r;
  pivot_of_row_.resize(n_);
  pivot_of_column_.resize(n_);
  for (int k = 0; k < n_; ++k) {
    pivot_of_row_[row_order_[k]] = k;
    pivot_of_column_[column_order_[k]] = k;
  }
  for (int j = 0; j < n_; ++j)  // the solve divides by U's diagonal, the last entry of each column
    if (u_start_[j + 1] == u_start_[j] || u_row_[u_start_[j + 1] - 1] != j || u_values_[u_start_[j + 1] - 1] == 0.0)
      throw std::runtime_error("SparseLuFactors: singular matrix");
}

Eigen::MatrixXd SparseLuFactors::solve(const Eigen::MatrixXd& rhs) const {
  if (rhs.rows() != n_) throw std::invalid_argument("SparseLuFactors::solve: wrong number of rows");
  Eigen::MatrixXd x(n_, rhs.cols());
  // Row-major work block: the kBlock values of one unknown are contiguous.
  std::vector<double> y(static_cast<std::size_t>(n_) * kBlock);
  for (Eigen::Index first = 0; first < rhs.cols(); first += kBlock) {
    const int m = static_cast<int>(std::min<Eigen::Index>(kBlock, rhs.cols() - first));
    // y = P R b
    for (int k = 0; k < n_; ++k) {
      const int i = row_order_[k];
      double* yk = &y[static_cast<std::size_t>(k) * kBlock];
      for (int c = 0; c < m; ++c) yk[c] = row_scale_[i] * rhs(i, first + c);
    }
    // L y' = y (rows of L: gather from earlier unknowns; unit diagonal last)
    for (int k = 0; k < n_; ++k) {
      double* yk = &y[static_cast<std::size_t>(k) * kBlock];
      for (int p = l_start_[k]; p < l_start_[k + 1] - 1; ++p) {
        const double l = l_values_[p];
        const double* yj = &y[static_cast<std::size_t>(l_column_[p]) * kBlock];
        for (int c = 0; c < m; ++c) yk[c] -= l * yj[c];
      }
    }
    // U z = y' (columns of U: scatter into earlier unknowns; diagonal last)
    for (int j = n_ - 1; j >= 0; --j) {
      double* yj = &y[static_cast<std::size_t>(j) * kBlock];
      const int last = u_start_[j + 1] - 1;
      const double inverse = 1.0 / u_values_[last];
      for (int c = 0; c < m; ++c) yj[c] *= inverse;
      for (int p = u_start_[j]; p < last; ++p) {
        const double u = u_values_[p];
        double* yi = &y[static_cast<std::size_t>(u_row_[p]) * kBlock];
        for (int c = 0; c < m; ++c) yi[c] -= u * yj[c];
      }
    }
    // x = Q z
    for (int k = 0; k < n_; ++k) {
      const double* yk = &y[static_cast<std::size_t>(k) * kBlock];
      for (int c = 0; c < m; ++c) x(column_order_[k], first + c) = yk[c];
    }
  }
  return x;
}

Eigen::MatrixXd SparseLuFactors::solve_selected(const std::vector<SparseColumn>& columns,
                                                const std::vector<int>& rows) const {
  for (int r : rows)
    if (r < 0 || r >= n_) throw std::invalid_argument("SparseLuFactors::solve_selected: row out of range");
  for (const SparseColumn& column : columns)
    for (const auto& entry : column)
      if (entry.first < 0 || entry.first >= n_)
        throw std::invalid_argument("SparseLuFactors::solve_selected: entry row out of range");
  const int total = static_cast<int>(columns.size());
  Eigen::MatrixXd x(rows.size(), total);
  // The substitutions are solve()'s, written out again rather than shared:
  // as a separate function the compiler vectorised the column loops worse
  // (measured ~35 % slower on a 8 100-unknown system).
  std::vector<double> y(static_cast<std::size_t>(n_) * kBlock);
  for (int first = 0; first < total; first += kBlock) {
    const int m = std::min(kBlock, total - first);
    // y = P R b: zero but at the non-zeros of b
    std::fill(y.begin(), y.end(), 0.0);
    for (int c = 0; c < m; ++c)
      for (const auto& entry : columns[first + c])
        y[static_cast<std::size_t>(pivot_of_row_[entry.first]) * kBlock + c] = row_scale_[entry.first] * entry.second;
    // L y' = y (rows of L: gather from earlier unknowns; unit diagonal last)
    for (int k = 0; k < n_; ++k) {
      double* yk = &y[static_cast<std::size_t>(k) * kBlock];
      for (int p = l_start_[k]; p < l_start_[k + 1] - 1; ++p) {
        const double l = l_values_[p];
        const double* yj = &y[static_cast<std::size_t>(l_column_[p]) * kBlock];
        for (int c = 0; c < m; ++c) yk[c] -= l * yj[c];
      }
    }
    // U z = y' (columns of U: scatter into earlier unknowns; diagonal last)
    for (int j = n_ - 1; j >= 0; --j) {
      double* yj = &y[static_cast<std::size_t>(j) * kBlock];
      const int last = u_start_[j + 1] - 1;
      const double inverse = 1.0 / u_values_[last];
      for (int c = 0; c < m; ++c) yj[c] *= inverse;
      for (int p = u_start_[j]; p < last; ++p) {
        const double u = u_values_[p];
        double* yi = &y[static_cast<std::size_t>(u_row_[p]) * kBlock];
        for (int c = 0; c < m; ++c) yi[c] -= u * yj[c];
      }
    }
    // x = Q z at the rows asked for
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const double* z = &y[static_cast<std::size_t>(pivot_of_column_[rows[r]]) * kBlock];
      for (int c = 0; c < m; ++c) x(static_cast<Eigen::Index>(r), first + c) = z[c];
    }
  }
  return x;
}

}  // namespace hsrod
