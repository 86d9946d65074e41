// Chains with pair contacts off the band: rods of a contact cluster (merged
// into one rod, each rod's spheres consecutive) and a chain folded onto
// itself. The step's matrix is A = T + E M E^T: T block-tridiagonal (drag,
// bonds, wall contacts, the pair contacts' diagonal blocks and those between
// neighbouring spheres), M (6p x 6p) the contact blocks coupling spheres
// further apart in the numbering, E the unit columns of those p spheres.
// With x = T^-1 (b - E M y) and y = E^T x (the p spheres' unknowns),
//     (I + G M) y = E^T T^-1 b,   G = E^T T^-1 E   (6p x 6p),
// the capacitance form of the Sherman-Morrison-Woodbury identity (Hager,
// "Updating the inverse of a matrix", SIAM Review 31 (1989) 221, eq. 1.2),
// written without M^-1 (a contact block has no inverse). T^-1 E is cheap: T
// is block diagonal over the chain segments (a rod's spheres), so the
// column of sphere s fills only its own segment. Cost per step: one band
// elimination, 6 columns per coupled sphere over its segment, and an LU of
// 6p x 6p (dense for a few coupled spheres, sparse beyond: I + G M couples
// sphere t to b only where a sphere of t's rod touches b), against a sparse
// LU of the whole cluster whose fill spans it.
//
// When the result cannot be trusted the same matrix goes to the sparse LU
// instead (solve_chain_contacts_sparse): a non-finite band pivot (T
// singular: a sphere nothing holds), a capacitance matrix whose condition
// estimate exceeds 1 / capacitance_rcond_floor, a componentwise backward
// error above backward_error_ceiling after one step of iterative refinement
// (Woodbury's solve is not backward stable in general: Yip, SIAM J. Sci.
// Stat. Comput. 7 (1986) 507), or where most of the chain's spheres are
// coupled (max_coupled_fraction), where the sparse LU of A is cheaper.
#include "dynamics/overdamped_rod_step_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsrod {

namespace {

// Below this reciprocal condition estimate of I + G M (1-norm, Eigen's
// PartialPivLU::rcond) its solve keeps fewer than ~4 of double's 16
// digits; the sparse LU of A then decides.
constexpr double capacitance_rcond_floor = 1e-12;
// Componentwise backward error (chain_contact_backward_error) accepted:
// ~45 unit round-offs. Passing it, x solves A + dA with |dA| <= 1e-14 |A|
// entry by entry, as a partial-pivoting LU does in practice (Higham, sec.
// 9.3); Woodbury's first solve is at 4e-14 - 2e-12 in the clusters of
// test_chain_contact_solve.cpp, one refinement brings it to ~2e-16.
constexpr double backward_error_ceiling = 1e-14;
// Coupled spheres beyond which I + G M is factorised sparsely: the dense
// LU's (6p)^3 / 3 multiply-adds grow past the sparse LU's, whose cost
// follows the contact graph (a few partners per sphere, G coupling only the
// spheres of one rod). On the clusters of test_chain_contact_solve.cpp the
// dense LU's step was 2x faster at p = 18-24, even at p = 40 and 2x slower
// at p = 64, 10-30x slower at p = 160-320. In the 100-rod pore scene
// (in.pore_many_rods, upstream 0) p stayed <= 10 over 600 steps; in a
// clogging plug it is several hundred.
constexpr int dense_capacitance_spheres = 32;
// Beyond that, the fraction of the chain's spheres coupled above which the
// sparse LU of the whole matrix is used instead: I + G M is then nearly as
// large as A and several times denser (a column per partner's rod, not per
// bond). Measured on test_chain_contact_solve.cpp's clusters (one step):
// with 10-50 % coupled the capacitance solve was 1.1-7.7x faster (n = 80 -
// 1600, p = 36-156), with 70-100 % coupled 1.4-1.7x slower (n = 160-320).
constexpr double max_coupled_fraction = 0.5;

// 2^-round(log2 largest): the power of two that scales `largest` to ~1 (1 for 0).
double power_of_two_scale(double largest) { return largest > 0.0 ? std::exp2(-std::round(std::log2(largest))) : 1.0; }

// Solves with the sparse factors of I + G M, and with their transpose, in
// the form Eigen's condition estimator takes (its SparseLU::adjoint() is
// not const).
struct SparseCapacitanceSolves {
  using MatrixType = Eigen::MatrixXd;
  using Scalar = double;
  using RealScalar = double;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>* lu;
  bool transposed;
  Eigen::Index rows() const { return lu->rows(); }
  Eigen::Index cols() const { return lu->cols(); }
  SparseCapacitanceSolves adjoint() const { return {lu, !transposed}; }
  template <typename Rhs>
  Eigen::VectorXd solve(const Rhs& b) const {
    const Eigen::VectorXd rhs = b;
    return transposed ? Eigen::VectorXd(lu->transpose().solve(rhs)) : Eigen::VectorXd(lu->solve(rhs));
  }
};

}  // namespace

// The pair contacts' blocks into the band (diagonal; neighbouring spheres)
// or the off-band list, in add_couplings' order (stiffness, then friction
// C / dt), so that the sums are those of the general paths.
void OverdampedRodSolver::Workspace::add_pair_contact_blocks(double dt, int n) {
  band_linked.assign(n, 0);
  for (int k = 0; k + 1 < n; ++k) band_linked[k] = bonded(k, k + 1) ? 1 : 0;
  off_band.clear();
  for (const SpherePairContact& c : pair_contacts) {
    diagonal[c.i].block<3, 3>(0, 0) += c.stiffness;
    diagonal[c.j].block<3, 3>(0, 0) += c.stiffness;
    Matrix6d ij = Matrix6d::Zero(), ji = Matrix6d::Zero();
    ij.block<3, 3>(0, 0) = -c.stiffness;
    ji.block<3, 3>(0, 0) = -c.stiffness;
    if (c.rubbing) {
      diagonal[c.i] += c.friction.block<6, 6>(0, 0) / dt;
      ij += c.friction.block<6, 6>(0, 6) / dt;
      ji += c.friction.block<6, 6>(6, 0) / dt;
      diagonal[c.j] += c.friction.block<6, 6>(6, 6) / dt;
    }
    if (c.j == c.i + 1 || c.i == c.j + 1) {  // not bonded: the band's block is zero so far
      const bool ascending = c.j == c.i + 1;
      const int first = ascending ? c.i : c.j;
      upper[first] += ascending ? ij : ji;
      lower[first + 1] += ascending ? ji : ij;
      band_linked[first] = 1;
      continue;
    }
    off_band.push_back({c.i, c.j, ij, ji});
  }
}

// The blocks assembled (fused) and the wall contacts added: adds the pair
// contacts, factorises and solves; `rhs` holds the right-hand side and
// becomes the solution.
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve_chain_with_contacts(double dt, int n) {
  add_pair_contact_blocks(dt, n);
  if (off_band.empty()) {  // a block-tridiagonal matrix: the chain's own elimination
    solve_banded(n);
    kept = Kept::banded;
    ++statistics.banded_steps;
    return rhs;
  }
  coupled_spheres.clear();
  for (const OffBandContact& c : off_band) {
    coupled_spheres.push_back(c.i);
    coupled_spheres.push_back(c.j);
  }
  std::sort(coupled_spheres.begin(), coupled_spheres.end());
  coupled_spheres.erase(std::unique(coupled_spheres.begin(), coupled_spheres.end()), coupled_spheres.end());
  // The matrix as assembled, for the residual and the sparse fallback (the
  // elimination overwrites diagonal and upper; lower it leaves).
  band_diagonal.assign(diagonal.begin(), diagonal.begin() + n);
  band_upper.assign(upper.begin(), upper.begin() + n);
  band_rhs = rhs;
  const int p = static_cast<int>(coupled_spheres.size());
  if (p > dense_capacitance_spheres && p > max_coupled_fraction * n) {  // coupled throughout: the LU by design
    ++statistics.capacitance_handovers;
    return solve_chain_contacts_sparse(n);
  }
  if (!factorise_capacitance(n)) {
    ++statistics.capacitance_fallbacks;
    return solve_chain_contacts_sparse(n);
  }
  apply_off_band_correction(rhs);
  // One step of iterative refinement where the backward error is above
  // round-off, with the same factors; the sparse LU if still above.
  if (chain_contact_backward_error(rhs) > backward_error_ceiling) {
    refinement = chain_contact_residual;
    resolve_banded(refinement);
    apply_off_band_correction(refinement);
    rhs += refinement;
    if (!(chain_contact_backward_error(rhs) <= backward_error_ceiling)) {
      ++statistics.capacitance_fallbacks;
      return solve_chain_contacts_sparse(n);
    }
  }
  kept = Kept::chain_contacts;
  ++statistics.banded_steps;
  ++statistics.capacitance_steps;
  if (capacitance_sparse_factors) ++statistics.sparse_capacitance_steps;
  return rhs;
}

// rhs <- T^-1 b, the columns T^-1 E_s of the coupled spheres and the LU of
// I + G M; false where the band or the capacitance matrix is singular or
// too ill-conditioned to trust.
bool OverdampedRodSolver::Workspace::factorise_capacitance(int n) {
  const int p = static_cast<int>(coupled_spheres.size());
  coupled_index.assign(n, -1);
  for (int a = 0; a < p; ++a) coupled_index[coupled_spheres[a]] = a;
  solve_banded(n);  // rhs <- T^-1 b; factors of T kept
  if (!rhs.allFinite()) return false;
  // Each coupled sphere's chain segment [first, last] and the coupled
  // spheres in it, [begin, end) in coupled_spheres (ascending).
  coupled_segment.resize(p);
  coupled_in_segment.resize(p);
  coupled_column_start.resize(p + 1);
  coupled_column_start[0] = 0;
  for (int a = 0; a < p; ++a) {
    const int s = coupled_spheres[a];
    int first = s, last = s;
    while (first > 0 && band_linked[first - 1]) --first;
    while (last + 1 < n && band_linked[last]) ++last;
    coupled_segment[a] = {first, last};
    coupled_in_segment[a] = {
        static_cast<int>(std::lower_bound(coupled_spheres.begin(), coupled_spheres.end(), first) - coupled_spheres.begin()),
        static_cast<int>(std::upper_bound(coupled_spheres.begin(), coupled_spheres.end(), last) - coupled_spheres.begin())};
    coupled_column_start[a + 1] = coupled_column_start[a] + (last - first + 1);
  }
  // Columns T^-1 E_s over each coupled sphere's segment: forward elimination
  // from s (the entries before s stay zero), back substitution over the
  // segment, with the factors solve_banded left (upper[k] = A'(k,k)^-1 A(k,k+1)).
  coupled_columns.resize(coupled_column_start[p]);
  for (int a = 0; a < p; ++a) {
    const int s = coupled_spheres[a], first = coupled_segment[a].first, last = coupled_segment[a].second;
    Matrix6d* y = coupled_columns.data() + coupled_column_start[a] - first;  // y[k]: sphere k's rows
    for (int k = first; k < s; ++k) y[k].setZero();
    y[s].setIdentity();
    block_lus[s].solve_block_in_place(y[s]);
    for (int k = s + 1; k <= last; ++k) {
      y[k].noalias() = -lower[k] * y[k - 1];
      block_lus[k].solve_block_in_place(y[k]);
    }
    for (int k = last - 1; k >= first; --k) y[k].noalias() -= upper[k] * y[k + 1];
  }
  // I + G M, G(t, a) = (T^-1 E_a) at sphere t when t is in a's segment; M
  // holds a contact (i, j)'s blocks at (a_i, a_j) and (a_j, a_i): block
  // (t, b) += G(t, a) m for each coupled sphere t of a's segment.
  const auto for_each_product = [&](auto&& add) {
    const auto column_times = [&](int a, int b, const Matrix6d& m) {
      const int first = coupled_segment[a].first;
      for (int t = coupled_in_segment[a].first; t < coupled_in_segment[a].second; ++t)
        add(t, b, coupled_columns[coupled_column_start[a] + coupled_spheres[t] - first] * m);
    };
    for (const OffBandContact& c : off_band) {
      column_times(coupled_index[c.i], coupled_index[c.j], c.ij);
      column_times(coupled_index[c.j], coupled_index[c.i], c.ji);
    }
  };
  capacitance_sparse_factors = p > dense_capacitance_spheres;
  if (capacitance_sparse_factors) {
    capacitance_triplets.clear();
    for (int r = 0; r < 6 * p; ++r) capacitance_triplets.emplace_back(r, r, 1.0);
    for_each_product([&](int t, int b, const Matrix6d& block) {
      for (int col = 0; col < 6; ++col)
        for (int row = 0; row < 6; ++row) capacitance_triplets.emplace_back(6 * t + row, 6 * b + col, block(row, col));
    });
    capacitance_sparse.resize(6 * p, 6 * p);
    capacitance_sparse.setFromTriplets(capacitance_triplets.begin(), capacitance_triplets.end());
    return factorise_sparse_capacitance();
  }
  capacitance.setIdentity(6 * p, 6 * p);
  for_each_product([&](int t, int b, const Matrix6d& block) { capacitance.block<6, 6>(6 * t, 6 * b) += block; });
  if (!capacitance.allFinite()) return false;
  equilibrate_capacitance();
  capacitance_lu.compute(capacitance);
  const double rcond = capacitance_lu.rcond();
  return rcond >= capacitance_rcond_floor;  // false for NaN too
}

// Rows, then columns, of I + G M scaled to largest entry ~1 by powers of
// two (exact): its unknowns mix displacements [m] and rotations [rad] and
// its blocks friction and stiffness, so unscaled its condition estimate
// measures the units (~1e12 for 3 um spheres in the pore scene), not the
// problem; equilibrated, it no longer depends on them (van der Sluis:
// equilibrated rows are within a factor sqrt(6p) of the best row scaling;
// Higham, "Accuracy and Stability of Numerical Algorithms", sec. 7.3) and
// the LU's pivots are chosen among comparable entries. Solves with the scaled
// matrix: C y = z as (Dr C Dc) (Dc^-1 y) = Dr z.
void OverdampedRodSolver::Workspace::equilibrate_capacitance() {
  const int m = static_cast<int>(capacitance.rows());
  capacitance_row_scale.resize(m);
  capacitance_column_scale.resize(m);
  for (int i = 0; i < m; ++i) capacitance_row_scale(i) = power_of_two_scale(capacitance.row(i).cwiseAbs().maxCoeff());
  capacitance = capacitance_row_scale.asDiagonal() * capacitance;
  for (int j = 0; j < m; ++j) capacitance_column_scale(j) = power_of_two_scale(capacitance.col(j).cwiseAbs().maxCoeff());
  capacitance = capacitance * capacitance_column_scale.asDiagonal();
}

// The sparse I + G M equilibrated as the dense one and factorised (the
// pattern's COLAMD ordering and symbolic analysis kept while the contacts
// stay); false where it is not finite, singular or its reciprocal condition
// estimate (1-norm, Hager-Higham: Eigen's estimator, with solves by the
// sparse factors) is below capacitance_rcond_floor.
bool OverdampedRodSolver::Workspace::factorise_sparse_capacitance() {
  for (int k = 0; k < capacitance_sparse.nonZeros(); ++k)
    if (!std::isfinite(capacitance_sparse.valuePtr()[k])) return false;
  equilibrate_sparse_capacitance();
  const int outer_size = static_cast<int>(capacitance_sparse.outerSize()) + 1;
  const int nonzeros = static_cast<int>(capacitance_sparse.nonZeros());
  const bool same_pattern =
      static_cast<int>(capacitance_outer.size()) == outer_size && static_cast<int>(capacitance_inner.size()) == nonzeros &&
      std::equal(capacitance_outer.begin(), capacitance_outer.end(), capacitance_sparse.outerIndexPtr()) &&
      std::equal(capacitance_inner.begin(), capacitance_inner.end(), capacitance_sparse.innerIndexPtr());
  if (!same_pattern) {
    capacitance_sparse_lu.analyzePattern(capacitance_sparse);
    capacitance_outer.assign(capacitance_sparse.outerIndexPtr(), capacitance_sparse.outerIndexPtr() + outer_size);
    capacitance_inner.assign(capacitance_sparse.innerIndexPtr(), capacitance_sparse.innerIndexPtr() + nonzeros);
  }
  capacitance_sparse_lu.factorize(capacitance_sparse);
  if (capacitance_sparse_lu.info() != Eigen::Success) {
    capacitance_outer.clear();  // a failed factorisation leaves no analysis to reuse
    return false;
  }
  double norm = 0.0;  // 1-norm: largest column sum
  for (int j = 0; j < capacitance_sparse.outerSize(); ++j) {
    double sum = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(capacitance_sparse, j); it; ++it) sum += std::fabs(it.value());
    norm = std::max(norm, sum);
  }
  const SparseCapacitanceSolves solves{&capacitance_sparse_lu, false};
  const double rcond = Eigen::internal::rcond_estimate_helper(norm, solves);
  return rcond >= capacitance_rcond_floor;  // false for NaN too
}

// The dense equilibration below on the sparse matrix: rows, then columns,
// to largest entry ~1 by powers of two.
void OverdampedRodSolver::Workspace::equilibrate_sparse_capacitance() {
  const int m = static_cast<int>(capacitance_sparse.rows());
  capacitance_row_scale.setZero(m);
  capacitance_column_scale.resize(m);
  using Iterator = Eigen::SparseMatrix<double>::InnerIterator;
  for (int j = 0; j < m; ++j)
    for (Iterator it(capacitance_sparse, j); it; ++it)
      capacitance_row_scale(it.row()) = std::max(capacitance_row_scale(it.row()), std::fabs(it.value()));
  for (int i = 0; i < m; ++i) capacitance_row_scale(i) = power_of_two_scale(capacitance_row_scale(i));
  for (int j = 0; j < m; ++j) {
    double largest = 0.0;
    for (Iterator it(capacitance_sparse, j); it; ++it) {
      it.valueRef() *= capacitance_row_scale(it.row());
      largest = std::max(largest, std::fabs(it.value()));
    }
    capacitance_column_scale(j) = power_of_two_scale(largest);
    for (Iterator it(capacitance_sparse, j); it; ++it) it.valueRef() *= capacitance_column_scale(j);
  }
}

// x <- x - T^-1 E M y with (I + G M) y = E^T x, for x = T^-1 b.
void OverdampedRodSolver::Workspace::apply_off_band_correction(Eigen::VectorXd& x) const {
  const int p = static_cast<int>(coupled_spheres.size());
  coupled_work.resize(6 * p);
  for (int a = 0; a < p; ++a) coupled_work.segment<6>(6 * a) = x.segment<6>(6 * coupled_spheres[a]);
  coupled_work.array() *= capacitance_row_scale.array();
  coupled_work = capacitance_sparse_factors ? capacitance_sparse_lu.solve(coupled_work).eval()
                                            : capacitance_lu.solve(coupled_work).eval();
  coupled_work.array() *= capacitance_column_scale.array();
  coupled_load.setZero(6 * p);  // M y
  for (const OffBandContact& c : off_band) {
    const int a = coupled_index[c.i], b = coupled_index[c.j];
    coupled_load.segment<6>(6 * a).noalias() += c.ij * coupled_work.segment<6>(6 * b);
    coupled_load.segment<6>(6 * b).noalias() += c.ji * coupled_work.segment<6>(6 * a);
  }
  for (int a = 0; a < p; ++a) {
    const int first = coupled_segment[a].first, last = coupled_segment[a].second;
    const Vector6d u = coupled_load.segment<6>(6 * a);
    for (int k = first; k <= last; ++k)
      x.segment<6>(6 * k).noalias() -= coupled_columns[coupled_column_start[a] + k - first] * u;
  }
}

// The componentwise backward error max_r |b - A x|_r / (|A| |x| + |b|)_r
// (Oettli and Prager 1964; Higham, sec. 7.2): unlike a normwise one it does
// not depend on the units of the unknowns (m, rad) or of the rows (N, N m),
// whose mix puts a normwise measure at ~1e-19 even for a solve that is off
// in its 9th digit. A from the blocks as assembled; leaves b - A x in
// chain_contact_residual.
double OverdampedRodSolver::Workspace::chain_contact_backward_error(const Eigen::VectorXd& x) {
  const int n = static_cast<int>(band_diagonal.size());
  chain_contact_residual = band_rhs;
  row_sums = band_rhs.cwiseAbs();  // (|A| |x| + |b|)
  const auto subtract = [&](int row, const Matrix6d& block, int col) {
    chain_contact_residual.segment<6>(6 * row).noalias() -= block * x.segment<6>(6 * col);
    row_sums.segment<6>(6 * row).noalias() += block.cwiseAbs() * x.segment<6>(6 * col).cwiseAbs();
  };
  for (int k = 0; k < n; ++k) {
    subtract(k, band_diagonal[k], k);
    if (k + 1 < n && band_linked[k]) subtract(k, band_upper[k], k + 1);
    if (k > 0 && band_linked[k - 1]) subtract(k, lower[k], k - 1);
  }
  for (const OffBandContact& c : off_band) {
    subtract(c.i, c.ij, c.j);
    subtract(c.j, c.ji, c.i);
  }
  double error = 0.0;
  for (int r = 0; r < 6 * n; ++r) {
    const double off = std::fabs(chain_contact_residual(r));
    if (!std::isfinite(off) || !std::isfinite(row_sums(r))) return std::numeric_limits<double>::infinity();
    if (off > 0.0) error = std::max(error, row_sums(r) > 0.0 ? off / row_sums(r) : std::numeric_limits<double>::infinity());
  }
  return error;
}

// The fallback (and the hand-over of a cluster coupled throughout): the same matrix (band blocks and off-band contacts as
// assembled) and right-hand side through the sparse LU (factorize_sparse).
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve_chain_contacts_sparse(int n) {
  triplets.clear();
  const auto add_block = [this](int row, int col, const Matrix6d& block) {
    for (int b = 0; b < 6; ++b)
      for (int a = 0; a < 6; ++a) triplets.emplace_back(6 * row + a, 6 * col + b, block(a, b));
  };
  for (int k = 0; k < n; ++k) {
    add_block(k, k, band_diagonal[k]);
    if (k + 1 < n && band_linked[k]) {
      add_block(k, k + 1, band_upper[k]);
      add_block(k + 1, k, lower[k + 1]);
    }
  }
  for (const OffBandContact& c : off_band) {
    add_block(c.i, c.j, c.ij);
    add_block(c.j, c.i, c.ji);
  }
  matrix.resize(6 * n, 6 * n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  ++statistics.sparse_steps;
  if (!factorize_sparse()) {  // singular: a non-finite update for the step guard (as solve_sparse)
    dy.setConstant(6 * n, std::numeric_limits<double>::quiet_NaN());
    kept = Kept::none;
    return dy;
  }
  dy = lu.solve(band_rhs);
  kept = Kept::sparse;
  return dy;
}

}  // namespace hsrod
