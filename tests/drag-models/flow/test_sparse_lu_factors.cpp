// SparseLuFactors (flow/sparse_lu_factors.h): the blocked solve with
// UMFPACK's explicit factors against Eigen's dense partial-pivoting LU, on
// a saddle-point system of the kind level 4 solves (zero pressure diagonal:
// the factorisation must pivot off the diagonal).
#include "flow/sparse_lu_factors.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

namespace {

using hsrod::SparseLuFactors;

// [A G; D 0] on an m x m lattice: A a shifted 5-point Laplacian with
// non-symmetric perturbations, G/D first differences to a "pressure" per
// cell (the last cell's row fixes p = 0 so that the system is regular).
Eigen::SparseMatrix<double> saddle_point(int m, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> noise(-0.2, 0.2);
  const int nv = m * m, n = 2 * nv;
  std::vector<Eigen::Triplet<double>> t;
  auto at = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int r = at(i, j);
      t.emplace_back(r, r, 4.0 + 12.0 + noise(random));
      if (i > 0) t.emplace_back(r, at(i - 1, j), -1.0 + noise(random));
      if (i + 1 < m) t.emplace_back(r, at(i + 1, j), -1.0 + noise(random));
      if (j > 0) t.emplace_back(r, at(i, j - 1), -1.0 + noise(random));
      if (j + 1 < m) t.emplace_back(r, at(i, j + 1), -1.0 + noise(random));
      // velocity r couples to pressures r and its right neighbour (gradient)
      t.emplace_back(r, nv + r, 1.0);
      if (j + 1 < m) t.emplace_back(r, nv + at(i, j + 1), -1.0);
      // continuity of cell r (divergence), except the gauge row
      if (r == nv - 1) {
        t.emplace_back(nv + r, nv + r, 1.0);
      } else {
        t.emplace_back(nv + r, r, -1.0);
        if (j > 0) t.emplace_back(nv + r, at(i, j - 1), 1.0);
      }
    }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(SparseLuFactors, BlockedSolveMatchesDenseLuOnASaddlePointSystem) {
  const Eigen::SparseMatrix<double> a = saddle_point(12, 7);
  const SparseLuFactors lu(a);
  ASSERT_EQ(lu.rows(), a.rows());
  // 45 columns: one full block of 32 and a partial one.
  Eigen::MatrixXd b = Eigen::MatrixXd::Random(a.rows(), 45);
  const Eigen::MatrixXd x = lu.solve(b);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(a).partialPivLu().solve(b);
  EXPECT_LT((x - dense).norm() / dense.norm(), 1e-12);
  EXPECT_LT((a * x - b).norm() / b.norm(), 1e-12);
  // Each column alone gives the same as in the block.
  for (int c : {0, 31, 32, 44}) {
    const Eigen::MatrixXd one = lu.solve(b.col(c));
    EXPECT_LT((one - x.col(c)).norm(), 1e-14 * x.col(c).norm()) << "column " << c;
  }
}

// The sparse right-hand side / selected rows path (a level-4 update: unit
// forces on footprints, the response read at the footprints) is the same
// arithmetic as the dense solve: bit for bit equal rows, for compiled block
// widths (multiples of 4 up to 32 columns) and beyond one block.
TEST(SparseLuFactors, SelectedRowsOfSparseColumnsEqualTheDenseSolveBitForBit) {
  const Eigen::SparseMatrix<double> a = saddle_point(12, 11);
  const SparseLuFactors lu(a);
  const int n = static_cast<int>(a.rows());
  std::mt19937 random(5);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const std::vector<int> rows = {0, 3, n / 2, n - 1, 17, 3};
  for (int columns : {1, 7, 16, 20, 24, 32, 45}) {
    std::vector<SparseLuFactors::SparseColumn> sparse(columns);
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, columns);
    for (int c = 0; c < columns; ++c)
      for (int k = 0; k < 6; ++k) {
        const int r = row(random);
        if (dense(r, c) != 0.0) continue;  // rows distinct within a column
        dense(r, c) = value(random);
        sparse[c].emplace_back(r, dense(r, c));
      }
    const Eigen::MatrixXd full = lu.solve(dense);
    const Eigen::MatrixXd picked = lu.solve_selected(sparse, rows);
    ASSERT_EQ(picked.rows(), static_cast<Eigen::Index>(rows.size()));
    ASSERT_EQ(picked.cols(), columns);
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (int c = 0; c < columns; ++c)
        EXPECT_EQ(picked(static_cast<Eigen::Index>(r), c), full(rows[r], c)) << columns << " columns, row " << rows[r];
    EXPECT_LT((a * full - dense).norm() / dense.norm(), 1e-12);
  }
  EXPECT_THROW(lu.solve_selected({{{n, 1.0}}}, rows), std::invalid_argument);
  EXPECT_THROW(lu.solve_selected({{{0, 1.0}}}, {-1}), std::invalid_argument);
}

TEST(SparseLuFactors, RefusesSingularAndNonSquareMatrices) {
  Eigen::SparseMatrix<double> singular = saddle_point(5, 3);
  singular.coeffRef(singular.rows() - 1, singular.cols() - 1) = 0.0;  // drop the gauge: p defined up to a constant
  singular.prune(0.0);
  EXPECT_THROW(SparseLuFactors{singular}, std::runtime_error);
  EXPECT_THROW(SparseLuFactors{Eigen::SparseMatrix<double>(4, 5)}, std::invalid_argument);
}

}  // namespace
