// Block elimination of the step's block-tridiagonal systems: a chain's 6x6
// blocks, and groups of spheres (multi-sphere sections) in 6g x 6g blocks.
#include "dynamics/overdamped_rod_step_internal.h"

namespace hsrod {

// Block elimination of the block-tridiagonal system in place: rhs becomes
// the solution, upper[k] becomes A'(k,k)^-1 A(k,k+1).
void OverdampedRodSolver::Workspace::solve_banded(int n) {
  for (int k = 0; k < n; ++k) eliminate_banded(k, n, diagonal[k]);
  back_substitute_banded(n);
}

// Forward elimination of block row k (rows 0..k-1 eliminated before).
// `diagonal_k`: A(k, k), diagonal[k] or a rolling copy (step()).
void OverdampedRodSolver::Workspace::eliminate_banded(int k, int n, Matrix6d& diagonal_k) {
  auto y = rhs.segment<6>(6 * k);
  if (k > 0) {
    diagonal_k.noalias() -= lower[k] * upper[k - 1];
    y.noalias() -= lower[k] * rhs.segment<6>(6 * (k - 1));
  }
  SmallBlockLu<6>& block_lu = block_lus[k];
  block_lu.compute(diagonal_k);
  block_lu.solve_in_place(y);
  if (k + 1 < n) block_lu.solve_block_in_place(upper[k]);
}

void OverdampedRodSolver::Workspace::back_substitute_banded(int n) {
  for (int k = n - 2; k >= 0; --k) rhs.segment<6>(6 * k).noalias() -= upper[k] * rhs.segment<6>(6 * (k + 1));
}

// Another right-hand side through the factors solve_banded left: forward
// elimination with the unchanged lower blocks and the kept block LUs, then
// back substitution with upper[k] = A'(k,k)^-1 A(k,k+1).
void OverdampedRodSolver::Workspace::resolve_banded(Eigen::VectorXd& b) const {
  const int n = static_cast<int>(block_lus.size());
  for (int k = 0; k < n; ++k) {
    auto y = b.segment<6>(6 * k);
    if (k > 0) y.noalias() -= lower[k] * b.segment<6>(6 * (k - 1));
    block_lus[k].solve_in_place(y);
  }
  for (int k = n - 2; k >= 0; --k) b.segment<6>(6 * k).noalias() -= upper[k] * b.segment<6>(6 * (k + 1));
}

// diagonal -= lower * upper for the B x B blocks of two neighbouring
// groups, with upper row-major. Only the 6x6 blocks of `lower` that are not
// zero enter: a group couples to the previous one through the bonds (and
// contacts) between their spheres, in the 2x2 sections one axial bond per
// sphere, so a quarter of `lower` is non-zero. Each entry is summed as
// Eigen's product sums it, over k in ascending order from zero and
// subtracted at the end; the terms left out are exact zeros (0 x finite),
// so the result is the same to the last bit, in a quarter of the work.
namespace {
template <int B>
void subtract_block_sparse_product(const Eigen::Map<const Eigen::Matrix<double, B, B>>& lower,
                                   const Eigen::Matrix<double, B, B, Eigen::RowMajor>& upper,
                                   Eigen::Map<Eigen::Matrix<double, B, B>>& diagonal) {
  constexpr int S = B / 6;  // spheres per group
  using Rows = Eigen::Matrix<double, 6, B, Eigen::RowMajor>;
  for (int r = 0; r < S; ++r) {
    int columns[S];
    int count = 0;
    for (int c = 0; c < S; ++c) {
      bool nonzero = false;
      for (int j = 0; j < 6 && !nonzero; ++j)
        for (int i = 0; i < 6 && !nonzero; ++i) nonzero = lower(6 * r + i, 6 * c + j) != 0.0;
      if (nonzero) columns[count++] = c;
    }
    if (count == 0) continue;
    Rows sum = Rows::Zero();
    for (int i = 0; i < 6; ++i)
      for (int m = 0; m < count; ++m)
        for (int j = 0; j < 6; ++j) {
          const int k = 6 * columns[m] + j;
          sum.row(i) += lower(6 * r + i, k) * upper.row(k);
        }
    diagonal.template middleRows<6>(6 * r) -= sum;
  }
}
}  // namespace

// solve_banded over groups of spheres: group_rhs (padded) becomes the
// solution. Fixed-size blocks B = 6g for g = 2..4 (unrolled LU,
// small_block_lu.h), otherwise dynamic blocks and Eigen's partial-pivoting LU.
template <int B>
void OverdampedRodSolver::Workspace::solve_grouped_fixed() {
  using Block = Eigen::Matrix<double, B, B>;
  using Vector = Eigen::Matrix<double, B, 1>;
  const int groups = static_cast<int>(group_diagonal.size());
  // A'(k-1,k-1)^-1 A(k-1,k) of the previous group, row-major.
  Eigen::Matrix<double, B, B, Eigen::RowMajor> upper_previous;
  for (int k = 0; k < groups; ++k) {
    Eigen::Map<Block> diagonal_k(group_diagonal[k].data());
    Eigen::Map<Vector> y(group_rhs.data() + B * k);
    if (k > 0) {
      const Eigen::Map<const Block> lower_k(group_lower[k].data());
      subtract_block_sparse_product<B>(lower_k, upper_previous, diagonal_k);
      y.noalias() -= lower_k * Eigen::Map<const Vector>(group_rhs.data() + B * (k - 1));
    }
    const SmallBlockLu<B> block_lu(diagonal_k);
    block_lu.solve_in_place(y);
    if (k + 1 < groups) {
      // All columns at once (the same operations as solve_in_place per
      // column, so the same result to the last bit, vectorised).
      Eigen::Map<Block> upper_k(group_upper[k].data());
      block_lu.solve_block_in_place(upper_k, upper_previous);
    }
  }
  for (int k = groups - 2; k >= 0; --k)
    Eigen::Map<Vector>(group_rhs.data() + B * k).noalias() -=
        Eigen::Map<const Block>(group_upper[k].data()) * Eigen::Map<const Vector>(group_rhs.data() + B * (k + 1));
}

void OverdampedRodSolver::Workspace::solve_grouped() {
  const int b = 6 * group_spheres;
  switch (b) {
    case 12: solve_grouped_fixed<12>(); return;
    case 18: solve_grouped_fixed<18>(); return;
    case 24: solve_grouped_fixed<24>(); return;
    default: break;
  }
  const int groups = static_cast<int>(group_diagonal.size());
  for (int k = 0; k < groups; ++k) {
    auto y = group_rhs.segment(b * k, b);
    if (k > 0) {
      group_diagonal[k].noalias() -= group_lower[k] * group_upper[k - 1];
      y.noalias() -= group_lower[k] * group_rhs.segment(b * (k - 1), b);
    }
    group_lu.compute(group_diagonal[k]);
    y = group_lu.solve(y).eval();
    if (k + 1 < groups) {
      group_work = group_lu.solve(group_upper[k]);
      group_upper[k].swap(group_work);
    }
  }
  for (int k = groups - 2; k >= 0; --k)
    group_rhs.segment(b * k, b).noalias() -= group_upper[k] * group_rhs.segment(b * (k + 1), b);
}

}  // namespace hsrod
