// The step's linear system (R/dt + K + C/dt) dy = rhs: its structure,
// analysed when the rod's bonds change, and its solution by the cheapest
// method the couplings allow (block-tridiagonal, grouped blocks, dense or
// sparse LU), keeping the factors for later right-hand sides.
#include "dynamics/overdamped_rod_step_internal.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <type_traits>

namespace hsrod {

// Whether the matrix is a chain's (in bond order or not) or banded in groups
// of spheres, the bonded partners of each sphere and the band's storage;
// redone only when the rod's size or bonds change.
void OverdampedRodSolver::Workspace::analyse_structure(const OverdampedRod& rod) {
  const int n = rod.size();
  bool same = n == analysed_spheres && rod.bonds.size() == analysed_bonds.size();
  for (std::size_t k = 0; same && k < rod.bonds.size(); ++k)
    same = rod.bonds[k].i == analysed_bonds[k].first && rod.bonds[k].j == analysed_bonds[k].second;
  if (same) return;
  analysed_spheres = n;
  analysed_bonds.clear();
  chain = true;
  ordered_chain = static_cast<int>(rod.bonds.size()) == n - 1;
  int bandwidth = 0;  // largest |i - j| of a bond
  std::vector<int> count(n + 1, 0);
  for (const RodBond& b : rod.bonds) {
    if (std::min(b.i, b.j) != static_cast<int>(analysed_bonds.size())) ordered_chain = false;
    analysed_bonds.emplace_back(b.i, b.j);
    if (std::abs(b.i - b.j) != 1) chain = false;
    bandwidth = std::max(bandwidth, std::abs(b.i - b.j));
    ++count[b.i + 1];
    ++count[b.j + 1];
  }
  for (int k = 0; k < n; ++k) count[k + 1] += count[k];
  partner_start = count;
  partners.assign(count[n], 0);
  ordered_chain = ordered_chain && chain;
  for (const RodBond& b : rod.bonds) {
    partners[count[b.i]++] = b.j;
    partners[count[b.j]++] = b.i;
  }
  // bond_loads, bond_jacobians: sized where they are used (step), not used
  // by the chain's fused assembly.
  diagonal.resize(n);
  upper.resize(n);
  lower.resize(n);
  block_lus.resize(n);
  // Groups of up to 8 spheres (48 x 48 blocks): beyond that the sparse LU
  // of the band is cheaper than dense blocks.
  group_spheres = !chain && bandwidth <= 8 ? bandwidth : 0;
  if (group_spheres > 0) {
    const int groups = (n + group_spheres - 1) / group_spheres;
    const int b = 6 * group_spheres;
    group_diagonal.assign(groups, Eigen::MatrixXd::Zero(b, b));
    group_upper.assign(groups, Eigen::MatrixXd::Zero(b, b));
    group_lower.assign(groups, Eigen::MatrixXd::Zero(b, b));
    group_work.setZero(b, b);
    group_lu = Eigen::PartialPivLU<Eigen::MatrixXd>(b);
    group_rhs.setZero(b * groups);
  }
  if (chain || group_spheres > 0) ++analyses;  // the band; the sparse path counts its own analyses
}

// Calls add(row, col, block) for every term of R / dt + K (dof offsets).
template <typename Add>
void OverdampedRodSolver::Workspace::add_couplings(const OverdampedRod& rod, const RodDrag& drag, double dt,
                                                   Add add) const {
  const int n = rod.size();
  for (int i = 0; i < n; ++i) {
    add(6 * i + 3, 6 * i + 3, (drag.rotational_resistance[i] / dt * Eigen::Matrix3d::Identity()).eval());
    if (drag.coupled()) {
      for (int k = 0; k < n; ++k)
        add(6 * i, 6 * k, (drag.coupled_resistance.block<3, 3>(3 * i, 3 * k) / dt).eval());
    } else {
      add(6 * i, 6 * i, (drag.resistance[i] / dt).eval());
    }
  }
  for (std::size_t k = 0; k < rod.bonds.size(); ++k) {
    const RodBond& b = rod.bonds[k];
    const BondJacobian& jacobian = bond_jacobians[k];
    add(6 * b.i, 6 * b.i, (-jacobian.block<6, 6>(0, 0)).eval());
    add(6 * b.i, 6 * b.j, (-jacobian.block<6, 6>(0, 6)).eval());
    add(6 * b.j, 6 * b.i, (-jacobian.block<6, 6>(6, 0)).eval());
    add(6 * b.j, 6 * b.j, (-jacobian.block<6, 6>(6, 6)).eval());
  }
  for (const SphereWallContact& c : wall_contacts) {
    add(6 * c.sphere, 6 * c.sphere, c.stiffness);
    if (c.rubbing) add(6 * c.sphere, 6 * c.sphere, (c.friction / dt).eval());
  }
  for (const SpherePairContact& c : pair_contacts) {
    add(6 * c.i, 6 * c.i, c.stiffness);
    add(6 * c.j, 6 * c.j, c.stiffness);
    add(6 * c.i, 6 * c.j, (-c.stiffness).eval());
    add(6 * c.j, 6 * c.i, (-c.stiffness).eval());
    if (!c.rubbing) continue;
    add(6 * c.i, 6 * c.i, (c.friction.block<6, 6>(0, 0) / dt).eval());
    add(6 * c.i, 6 * c.j, (c.friction.block<6, 6>(0, 6) / dt).eval());
    add(6 * c.j, 6 * c.i, (c.friction.block<6, 6>(6, 0) / dt).eval());
    add(6 * c.j, 6 * c.j, (c.friction.block<6, 6>(6, 6) / dt).eval());
  }
}

// Solves the step's system once assemble has filled `rhs` (and a chain's
// blocks), choosing the factorisation and recording it in `kept`; returns
// the solution dy (its first 6n entries: the grouped path pads it).
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve(const OverdampedRod& rod, const RodDrag& drag, double dt,
                                                             bool fused, bool eliminate_in_pass) {
  const int n = rod.size();
  const bool automatic = method == LinearSolver::automatic;
  if (eliminate_in_pass) {
    kept = Kept::banded;  // solved in the bond pass
    ++statistics.banded_steps;
    return rhs;
  }
  if (fused) return solve_chain(drag, dt, n);
  if (automatic && !drag.coupled() && fits_groups()) return solve_in_groups(rod, drag, dt);
  if (method == LinearSolver::dense_lu || (automatic && (drag.coupled() || n <= 16))) return solve_dense(rod, drag, dt);
  return solve_sparse(rod, drag, dt);
}

// A chain: drag and bonds are in the blocks already; the wall contacts
// last, as add_couplings adds them. Non-local drag goes through the Schur
// complement on the coupled translations (dynamics/coupled_chain_solve.h).
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve_chain(const RodDrag& drag, double dt, int n) {
  for (const SphereWallContact& c : wall_contacts) add_wall_contact_block(c, dt, diagonal[c.sphere]);
  if (!pair_contacts.empty()) return solve_chain_with_contacts(dt, n);  // local drag (fused)
  if (drag.coupled()) {
    coupled_chain.factorise(diagonal, upper, lower, drag.coupled_resistance, dt,
                            CoupledChainSolve::coupled_components(drag.coupled_resistance));
    dy = rhs;
    coupled_chain.solve_in_place(dy);
    kept = Kept::coupled_chain;
    ++statistics.dense_steps;
    return dy;
  }
  solve_banded(n);
  kept = Kept::banded;
  ++statistics.banded_steps;
  return rhs;
}

// Multi-sphere sections: block-tridiagonal in groups of `group_spheres`
// spheres, the last group padded by unit rows and columns.
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve_in_groups(const OverdampedRod& rod, const RodDrag& drag,
                                                                       double dt) {
  const int ndof = 6 * rod.size();
  const int g = group_spheres;
  for (int k = 0; k < static_cast<int>(group_diagonal.size()); ++k) {
    group_diagonal[k].setZero();
    group_upper[k].setZero();
    group_lower[k].setZero();
  }
  for (int dof = ndof; dof < static_cast<int>(group_rhs.size()); ++dof)
    group_diagonal.back()(dof % (6 * g), dof % (6 * g)) = 1.0;
  group_rhs.head(ndof) = rhs;
  group_rhs.tail(group_rhs.size() - ndof).setZero();
  add_couplings(rod, drag, dt, [this, g](int row, int col, const auto& block) {
    using Block = std::decay_t<decltype(block)>;
    const int r = row / (6 * g), c = col / (6 * g);
    Eigen::MatrixXd& target = c == r ? group_diagonal[r] : (c == r + 1 ? group_upper[r] : group_lower[r]);
    target.template block<Block::RowsAtCompileTime, Block::ColsAtCompileTime>(row - 6 * g * r, col - 6 * g * c) +=
        block;
  });
  solve_grouped();
  kept = Kept::none;  // the grouped blocks' LUs are not kept
  ++statistics.banded_steps;
  return group_rhs;
}

// The dense LU of the whole matrix: non-local drag off a chain, a rod of up
// to 16 spheres, or on request (LinearSolver::dense_lu).
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve_dense(const OverdampedRod& rod, const RodDrag& drag,
                                                                   double dt) {
  const int ndof = 6 * rod.size();
  dense.setZero(ndof, ndof);
  add_couplings(rod, drag, dt, [this](int row, int col, const auto& block) {
    using Block = std::decay_t<decltype(block)>;
    dense.template block<Block::RowsAtCompileTime, Block::ColsAtCompileTime>(row, col) += block;
  });
  dense_lu.compute_in_place(dense);
  dy = rhs;
  dense_lu.solve_in_place(dy);
  kept = Kept::dense;
  ++statistics.dense_steps;
  return dy;
}

// Couplings off the bands (a self-contact between spheres far apart in the
// numbering, wide bonds) or on request: the sparse LU. Every entry of a bond's block
// enters the pattern, also one that happens to be zero at this
// configuration, so that the pattern (and its LU analysis) stays put.
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve_sparse(const OverdampedRod& rod, const RodDrag& drag,
                                                                    double dt) {
  const int ndof = 6 * rod.size();
  triplets.clear();
  add_couplings(rod, drag, dt, [this](int row, int col, const auto& block) {
    for (int a = 0; a < block.rows(); ++a)
      for (int b = 0; b < block.cols(); ++b) triplets.emplace_back(row + a, col + b, block(a, b));
  });
  matrix.resize(ndof, ndof);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  if (!factorize_sparse()) {
    // Singular, or overflowed by a diverging contact iterate: Eigen's solve
    // would read sizes from the failed factors. A non-finite update makes
    // the step guard refuse this trial and take smaller substeps.
    dy.setConstant(ndof, std::numeric_limits<double>::quiet_NaN());
    kept = Kept::none;
    ++statistics.sparse_steps;
    return dy;
  }
  dy = lu.solve(rhs);
  kept = Kept::sparse;
  ++statistics.sparse_steps;
  return dy;
}

// Another right-hand side through the factors the last solve kept.
bool OverdampedRodSolver::Workspace::solve_kept(Eigen::VectorXd& b) const {
  switch (kept) {
    case Kept::banded: resolve_banded(b); return true;
    case Kept::coupled_chain: coupled_chain.solve_in_place(b); return true;
    case Kept::chain_contacts:
      resolve_banded(b);
      apply_off_band_correction(b);
      return true;
    case Kept::dense: dense_lu.solve_in_place(b); return true;
    case Kept::sparse: b = lu.solve(b).eval(); return true;
    case Kept::none: return false;
  }
  return false;
}

// Self-contacts between spheres at most `group_spheres` apart stay inside
// the blocks of neighbouring groups.
bool OverdampedRodSolver::Workspace::fits_groups() const {
  if (group_spheres == 0) return false;
  for (const SpherePairContact& c : pair_contacts)
    if (std::abs(c.i - c.j) > group_spheres) return false;
  return true;
}

// Factorises `matrix`, analysing its pattern only when it changed; false
// when the factorisation failed.
bool OverdampedRodSolver::Workspace::factorize_sparse() {
  const int outer_size = static_cast<int>(matrix.outerSize()) + 1;
  const int nonzeros = static_cast<int>(matrix.nonZeros());
  const bool same_pattern =
      !analysed_outer.empty() && static_cast<int>(analysed_outer.size()) == outer_size &&
      static_cast<int>(analysed_inner.size()) == nonzeros &&
      std::equal(analysed_outer.begin(), analysed_outer.end(), matrix.outerIndexPtr()) &&
      std::equal(analysed_inner.begin(), analysed_inner.end(), matrix.innerIndexPtr());
  if (!same_pattern) {
    lu.analyzePattern(matrix);
    analysed_outer.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + outer_size);
    analysed_inner.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + nonzeros);
    ++analyses;
  }
  lu.factorize(matrix);
  return lu.info() == Eigen::Success;
}

}  // namespace hsrod
