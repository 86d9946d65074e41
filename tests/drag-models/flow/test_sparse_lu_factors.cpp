// SparseLuFactors (flow/sparse_lu_factors.h): the blocked solve with
// UMFPACK's explicit factors against Eigen's dense partial-pivoting LU, on
// a saddle-point system of the kind level 4 solves (zero pressure diagonal:
// the factorisation must pivot off the diagonal).
#include "flow/sparse_lu_factors.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// S^T A^-1 B by two forward substitutions over the reaches of the sparse
// columns (a level-4 update: unit forces on footprints, the response
// averaged over the footprints) equals the weighted rows of the full solve
// to round-off: on a lattice large enough that nearby columns reach a
// fraction of the unknowns (the pruned paths) and across blocks (45
// columns: a full block and a partial one, and 1 column).
TEST(SparseLuFactors, BilinearOfSparseColumnsEqualsTheWeightedFullSolve) {
  const Eigen::SparseMatrix<double> a = saddle_point(40, 13);
  const SparseLuFactors lu(a);
  const int n = static_cast<int>(a.rows()), nv = n / 2;
  std::mt19937 random(9);
  std::uniform_real_distribution<double> value(0.1, 1.0);
  // Footprint-like columns: a 3 x 3 patch of velocity unknowns around a
  // cell of the lattice (40 x 40), patches along a line as a rod's spheres.
  // (This system's velocities are divergence-free along each lattice line
  // with no inflow: zero but on the gauge's line; the left columns read the
  // pressures, which are not.)
  auto patch = [&](int centre_i, int centre_j, int offset) {
    SparseLuFactors::SparseColumn column;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        column.emplace_back(offset + (centre_i + di) * 40 + centre_j + dj, value(random));
    return column;
  };
  for (int columns : {1, 45}) {
    std::vector<SparseLuFactors::SparseColumn> left, right;
    for (int c = 0; c < columns; ++c) {
      right.push_back(patch(5 + (c * 29) / std::max(1, columns - 1), 20 + c % 2, 0));
      left.push_back(patch(5 + (c * 29) / std::max(1, columns - 1), 19 + c % 3, nv));
    }
    left.push_back({{nv + 7, 1.0}, {3, -0.5}});  // a pressure unknown too, and a 46th left column
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(left.size()));
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, columns);
    for (std::size_t c = 0; c < left.size(); ++c)
      for (const auto& e : left[c]) s(e.first, static_cast<Eigen::Index>(c)) = e.second;
    for (int c = 0; c < columns; ++c)
      for (const auto& e : right[c]) b(e.first, c) = e.second;
    const Eigen::MatrixXd full = s.transpose() * lu.solve(b);
    const Eigen::MatrixXd m = lu.bilinear(left, right);
    ASSERT_EQ(m.rows(), full.rows());
    ASSERT_EQ(m.cols(), full.cols());
    const double scale = full.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    EXPECT_LT((m - full).cwiseAbs().maxCoeff(), 1e-12 * scale) << columns << " columns";
    // Entries far below the scale too (the pruning drops only exact zeros).
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j)
        EXPECT_LE(std::abs(m(i, j) - full(i, j)), 1e-10 * std::abs(full(i, j)) + 1e-15 * scale)
            << "entry " << i << ", " << j;
  }
  EXPECT_EQ(lu.bilinear({}, {{{0, 1.0}}}).size(), 0);
  EXPECT_THROW(lu.bilinear({{{n, 1.0}}}, {{{0, 1.0}}}), std::invalid_argument);
  EXPECT_THROW(lu.bilinear({{{0, 1.0}}}, {{{-1, 1.0}}}), std::invalid_argument);
}

TEST(SparseLuFactors, RefusesSingularAndNonSquareMatrices) {
  Eigen::SparseMatrix<double> singular = saddle_point(5, 3);
  singular.coeffRef(singular.rows() - 1, singular.cols() - 1) = 0.0;  // drop the gauge: p defined up to a constant
  singular.prune(0.0);
  EXPECT_THROW(SparseLuFactors{singular}, std::runtime_error);
  EXPECT_THROW(SparseLuFactors{Eigen::SparseMatrix<double>(4, 5)}, std::invalid_argument);
}

}  // namespace
