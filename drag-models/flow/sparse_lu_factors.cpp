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
  // 2 300-32 000 cells (tests/benchmarks/RESULTS.md).
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
  // Transposed patterns for the reach of sparse right-hand sides (bilinear).
  lt_start_.assign(n_ + 1, 0);
  for (int k = 0; k < n_; ++k)
    for (int p = l_start_[k]; p < l_start_[k + 1] - 1; ++p) ++lt_start_[l_column_[p] + 1];
  for (int j = 0; j < n_; ++j) lt_start_[j + 1] += lt_start_[j];
  lt_row_.resize(lt_start_[n_]);
  {
    std::vector<int> next(lt_start_.begin(), lt_start_.end() - 1);
    for (int k = 0; k < n_; ++k)
      for (int p = l_start_[k]; p < l_start_[k + 1] - 1; ++p) lt_row_[next[l_column_[p]]++] = k;
  }
  ut_start_.assign(n_ + 1, 0);
  for (int j = 0; j < n_; ++j)
    for (int p = u_start_[j]; p < u_start_[j + 1] - 1; ++p) ++ut_start_[u_row_[p] + 1];
  for (int i = 0; i < n_; ++i) ut_start_[i + 1] += ut_start_[i];
  ut_column_.resize(ut_start_[n_]);
  {
    std::vector<int> next(ut_start_.begin(), ut_start_.end() - 1);
    for (int j = 0; j < n_; ++j)
      for (int p = u_start_[j]; p < u_start_[j + 1] - 1; ++p) ut_column_[next[u_row_[p]]++] = j;
  }
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

void SparseLuFactors::forward_block(bool upper, const std::vector<SparseColumn>& columns, int first, int count,
                                    std::vector<int>& reach, std::vector<double>& values, std::vector<char>& mark,
                                    std::vector<int>& stack, std::vector<double>& work) const {
  const std::vector<int>& pivot = upper ? pivot_of_column_ : pivot_of_row_;
  const std::vector<int>& child_start = upper ? ut_start_ : lt_start_;
  const std::vector<int>& child = upper ? ut_column_ : lt_row_;
  // The reach: every unknown a non-zero of the block's columns leads to
  // (L y = b: y_k depends on y_j where L(k, j) != 0; U^T w = t: w_j on w_i
  // where U(i, j) != 0), in ascending pivot order (a topological order).
  reach.clear();
  stack.clear();
  for (int c = first; c < first + count; ++c)
    for (const auto& entry : columns[c]) {
      const int k = pivot[entry.first];
      if (!mark[k]) {
        mark[k] = 1;
        stack.push_back(k);
      }
    }
  while (!stack.empty()) {
    const int j = stack.back();
    stack.pop_back();
    reach.push_back(j);
    for (int p = child_start[j]; p < child_start[j + 1]; ++p) {
      const int k = child[p];
      if (!mark[k]) {
        mark[k] = 1;
        stack.push_back(k);
      }
    }
  }
  std::sort(reach.begin(), reach.end());
  for (int k : reach) std::fill_n(&work[static_cast<std::size_t>(k) * kBlock], kBlock, 0.0);
  for (int c = 0; c < count; ++c)
    for (const auto& entry : columns[first + c])
      work[static_cast<std::size_t>(pivot[entry.first]) * kBlock + c] =
          upper ? entry.second : row_scale_[entry.first] * entry.second;
  if (!upper) {
    // L y = P R b over the reach (rows of L: gather; unit diagonal last)
    for (int k : reach) {
      double* yk = &work[static_cast<std::size_t>(k) * kBlock];
      for (int p = l_start_[k]; p < l_start_[k + 1] - 1; ++p) {
        const int j = l_column_[p];
        if (!mark[j]) continue;  // y_j = 0
        const double l = l_values_[p];
        const double* yj = &work[static_cast<std::size_t>(j) * kBlock];
        for (int c = 0; c < kBlock; ++c) yk[c] -= l * yj[c];
      }
    }
  } else {
    // U^T w = Q^T s over the reach (columns of U: gather; diagonal last)
    for (int j : reach) {
      double* wj = &work[static_cast<std::size_t>(j) * kBlock];
      const int last = u_start_[j + 1] - 1;
      for (int p = u_start_[j]; p < last; ++p) {
        const int i = u_row_[p];
        if (!mark[i]) continue;  // w_i = 0
        const double u = u_values_[p];
        const double* wi = &work[static_cast<std::size_t>(i) * kBlock];
        for (int c = 0; c < kBlock; ++c) wj[c] -= u * wi[c];
      }
      const double inverse = 1.0 / u_values_[last];
      for (int c = 0; c < kBlock; ++c) wj[c] *= inverse;
    }
  }
  values.resize(reach.size() * kBlock);
  for (std::size_t r = 0; r < reach.size(); ++r) {
    std::copy_n(&work[static_cast<std::size_t>(reach[r]) * kBlock], kBlock, &values[r * kBlock]);
    mark[reach[r]] = 0;
  }
}

Eigen::MatrixXd SparseLuFactors::bilinear(const std::vector<SparseColumn>& left,
                                          const std::vector<SparseColumn>& right) const {
  for (const auto* side : {&left, &right})
    for (const SparseColumn& column : *side)
      for (const auto& entry : column)
        if (entry.first < 0 || entry.first >= n_)
          throw std::invalid_argument("SparseLuFactors::bilinear: entry row out of range");
  const int nl = static_cast<int>(left.size()), nr = static_cast<int>(right.size());
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(nl, nr);
  if (nl == 0 || nr == 0) return result;
  const int blocks_l = (nl + kBlock - 1) / kBlock, blocks_r = (nr + kBlock - 1) / kBlock;
  std::vector<std::vector<int>> reach_l(blocks_l), reach_r(blocks_r);
  std::vector<std::vector<double>> values_l(blocks_l), values_r(blocks_r);
  std::vector<char> mark(n_, 0);
  std::vector<int> stack;
  // Work block (row-major, kBlock values per unknown): only the rows of a
  // block's reach are written and read, the rest is never initialised.
  std::vector<double> work(static_cast<std::size_t>(n_) * kBlock);
  for (int b = 0; b < blocks_r; ++b)
    forward_block(false, right, b * kBlock, std::min(kBlock, nr - b * kBlock), reach_r[b], values_r[b], mark, stack,
                  work);
  for (int b = 0; b < blocks_l; ++b)
    forward_block(true, left, b * kBlock, std::min(kBlock, nl - b * kBlock), reach_l[b], values_l[b], mark, stack,
                  work);
  // S^T A^-1 B = W^T Y over the unknowns both reaches hold.
  using Block = Eigen::Matrix<double, Eigen::Dynamic, kBlock, Eigen::RowMajor>;
  Block a, b;
  for (int bl = 0; bl < blocks_l; ++bl)
    for (int br = 0; br < blocks_r; ++br) {
      const std::vector<int>& rl = reach_l[bl];
      const std::vector<int>& rr = reach_r[br];
      std::vector<std::pair<int, int>> common;
      for (std::size_t i = 0, j = 0; i < rl.size() && j < rr.size();) {
        if (rl[i] < rr[j]) {
          ++i;
        } else if (rr[j] < rl[i]) {
          ++j;
        } else {
          common.emplace_back(static_cast<int>(i++), static_cast<int>(j++));
        }
      }
      if (common.empty()) continue;
      a.resize(static_cast<Eigen::Index>(common.size()), kBlock);
      b.resize(static_cast<Eigen::Index>(common.size()), kBlock);
      for (std::size_t r = 0; r < common.size(); ++r) {
        std::copy_n(&values_l[bl][static_cast<std::size_t>(common[r].first) * kBlock], kBlock, a.row(r).data());
        std::copy_n(&values_r[br][static_cast<std::size_t>(common[r].second) * kBlock], kBlock, b.row(r).data());
      }
      const int ml = std::min(kBlock, nl - bl * kBlock), mr = std::min(kBlock, nr - br * kBlock);
      const Eigen::Matrix<double, kBlock, kBlock> product = a.transpose() * b;
      result.block(bl * kBlock, br * kBlock, ml, mr) = product.topLeftCorner(ml, mr);
    }
  return result;
}

}  // namespace hsrod
