// Sparse LU of a square matrix by SuiteSparse UMFPACK (unsymmetric strategy,
// its default fill-reducing ordering), kept as explicit factors
//     P R A Q = L U
// (P, Q permutations, R UMFPACK's row scaling, L unit lower, U upper
// triangular) so that many right-hand sides are solved together: one pass
// over the factors for a block of columns instead of one pass per column.
// The level-4 window systems (flow/brinkman_window.h: ~28 000 unknowns,
// ~3e6 entries in L and U) are solved for 2n columns at a time; a pass over
// the factors costs as much memory traffic as the arithmetic of ~10 columns,
// so blocks of columns are several times faster than UMFPACK's own
// one-column solve (flow/README.md).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <utility>
#include <vector>

namespace hsrod {

class SparseLuFactors {
 public:
  // Factorises `matrix` (square, compressed column storage). Throws
  // std::runtime_error if UMFPACK fails or the matrix is singular.
  explicit SparseLuFactors(const Eigen::SparseMatrix<double>& matrix);

  int rows() const { return n_; }
  // Solves A X = B for all columns of B.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;
  // The same for a B given by its non-zeros (column c: (row, value) pairs,
  // rows distinct), returning X only at `rows` (rows.size() x columns): the
  // same arithmetic as solve() (bit for bit), without the dense B and X
  // (a level-4 update needs the response at its footprints only).
  using SparseColumn = std::vector<std::pair<int, double>>;
  Eigen::MatrixXd solve_selected(const std::vector<SparseColumn>& columns, const std::vector<int>& rows) const;
  // S^T A^-1 B for sparse S (columns `left`: (row, weight) pairs) and B
  // (columns `right`: (row, value) pairs), rows distinct within a column:
  // left.size() x right.size(). With A^-1 = Q U^-1 L^-1 P R this is
  // (U^-T Q^T S)^T (L^-1 P R B): two forward substitutions, each over the
  // reach of its sparse columns in the factors' graphs only (the unknowns
  // whose value can be non-zero: a block of nearby footprints reaches
  // ~4 % of a level-4 window's unknowns and ~25 % of its factors' entries),
  // and a dense product over the unknowns two reaches share. The same
  // value as the rows S^T solve(B) to round-off (different summation
  // order; a level-4 update without the full back-substitution of
  // solve_selected, ~3x less work on a 600 um rod's window).
  Eigen::MatrixXd bilinear(const std::vector<SparseColumn>& left, const std::vector<SparseColumn>& right) const;

 private:
  int n_ = 0;
  std::vector<int> l_start_, l_column_;  // L by rows (unit diagonal stored last in each row)
  std::vector<double> l_values_;
  std::vector<int> u_start_, u_row_;     // U by columns (diagonal last in each column)
  std::vector<double> u_values_;
  std::vector<int> row_order_;           // P[k]: the original row of pivot row k
  std::vector<int> column_order_;        // Q[k]: the original column of pivot column k
  std::vector<double> row_scale_;        // R as multipliers
  std::vector<int> pivot_of_row_;        // inverse of row_order_: pivot row k of original row i
  std::vector<int> pivot_of_column_;     // inverse of column_order_
  // Patterns of L by columns and of U by rows (strictly off-diagonal), for
  // the reach of a sparse right-hand side (bilinear): 4 bytes per factor
  // entry beside the factors' 12 (a level-4 run of a 600 um rod: peak
  // memory 448 -> 565 MB with the blocks' stored reaches).
  std::vector<int> lt_start_, lt_row_;   // column j of L: the rows k > j with L(k, j) != 0
  std::vector<int> ut_start_, ut_column_;  // row i of U: the columns j > i with U(i, j) != 0
  // Forward substitution of one block (bilinear): `reach` gets the pivot
  // indices whose value can be non-zero (ascending), `values` their values
  // (kBlock per index, row-major).
  void forward_block(bool upper, const std::vector<SparseColumn>& columns, int first, int count,
                     std::vector<int>& reach, std::vector<double>& values, std::vector<char>& mark,
                     std::vector<int>& stack, std::vector<double>& work) const;
  // Columns solved together: the 2n columns of a level-4 update in one pass for rods of up to 16 spheres.
  static constexpr int kBlock = 32;
};

}  // namespace hsrod
