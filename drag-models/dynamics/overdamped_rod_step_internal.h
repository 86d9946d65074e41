// What the step's .cpp files share and the public header keeps private: the
// solver's workspace (structure, contacts, assembly buffers, factors kept
// between steps), the contacts it holds and the cell list of the pair search.
#pragma once

#include "common/dense_lu.h"
#include "dynamics/coupled_chain_solve.h"
#include "dynamics/finite_rotation_update.h"
#include "dynamics/overdamped_rod_step.h"
#include "dynamics/small_block_lu.h"
#include "rod/beam_bond_jacobian.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

namespace hsrod {

using Clock = std::chrono::steady_clock;

inline double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// A sphere touching the walls: its Hertz force and stiffness, and its wall
// friction's secant resistance where it rubs.
struct SphereWallContact {
  int sphere;
  Eigen::Vector3d force;      // [N]
  Eigen::Matrix3d stiffness;  // [N/m]
  bool rubbing;               // wall friction acts (friction below is set)
  Matrix6d friction;          // friction resistance (secant or tangent, below) [N s/m, N s, N m s]
  // Friction loads on the sphere besides the secant's (step()'s correction
  // that puts friction at the end velocities) [N, N m]; zero in a plain step.
  Vector6d friction_load;
  // The walls touched and, where rubbing, the slip velocity each point's
  // secant is taken about [m/s] and its coefficient c = mu F_n / max(|about|, v_s) [N s/m].
  int points = 0;
  std::array<WallContactPoint, 3> point;
  std::array<Eigen::Vector3d, 3> about;
  std::array<double, 3> secant{};
};

// A wall contact's loads on its sphere (Hertz force, friction correction)
// added to `loads` (6n: F_i [N], T_i [N m]).
inline void add_wall_contact_loads(const SphereWallContact& c, Eigen::VectorXd& loads) {
  loads.segment<3>(6 * c.sphere) += c.force;
  if (c.rubbing) loads.segment<6>(6 * c.sphere) += c.friction_load;
}

// A wall contact's stiffness and friction resistance C / dt added to its
// sphere's diagonal block of the step's matrix.
inline void add_wall_contact_block(const SphereWallContact& c, double dt, Matrix6d& diagonal_block) {
  diagonal_block.block<3, 3>(0, 0) += c.stiffness;
  if (c.rubbing) diagonal_block += c.friction / dt;
}

// Two non-bonded spheres touching (of one rod, or of two rods of a cluster).
struct SpherePairContact {
  int i, j;
  Eigen::Vector3d force_on_i;  // [N]
  Eigen::Matrix3d stiffness;   // -dF_i/dx_i [N/m]
  bool rubbing;                // friction acts (friction below is set)
  Matrix12d friction;          // secant resistance about the previous velocities of (i, j) [N s/m, N s, N m s]
};

// A pair contact's Hertz forces added to `loads` (6n: F_i [N], T_i [N m]).
inline void add_pair_contact_forces(const SpherePairContact& c, Eigen::VectorXd& loads) {
  loads.segment<3>(6 * c.i) += c.force_on_i;
  loads.segment<3>(6 * c.j) -= c.force_on_i;
}

// A rubbing pair contact's friction loads C u / dt on spheres (i, j) for
// their displacements u in `moved` (6n: dx [m], dphi [rad]) over dt.
inline Vector12d pair_friction_loads(const SpherePairContact& c, const Eigen::VectorXd& moved, double dt) {
  Vector12d u;
  u << moved.segment<6>(6 * c.i), moved.segment<6>(6 * c.j);
  return c.friction * u / dt;
}

struct OverdampedRodSolver::Workspace {
  // Structure, analysed when the rod's size or bonds change.
  int analysed_spheres = -1;
  std::vector<std::pair<int, int>> analysed_bonds;
  bool chain = false;                        // every bond joins spheres k and k+1
  bool ordered_chain = false;                // a chain whose bond k joins spheres k and k+1
  // Sections: with bonds joining spheres at most g apart in the numbering
  // (g = 4 for the 2x2 sections of create_rod's `section 2`), groups of g
  // consecutive spheres couple only their neighbouring groups, so the
  // matrix is block-tridiagonal in 6g x 6g blocks. 0: not used (a chain, or
  // a bandwidth too large for dense blocks to pay).
  int group_spheres = 0;
  std::vector<int> partner_start, partners;  // bonded partners of each sphere (CSR)

  // Per step, sized once.
  std::vector<BondLoads> bond_loads;
  std::vector<BondJacobian> bond_jacobians;
  std::vector<SphereWallContact> wall_contacts;
  std::vector<SpherePairContact> pair_contacts;
  std::vector<std::pair<int, int>> candidates;
  PairSearchCells cells;
  Eigen::VectorXd rhs, dy;  // loads [N, N m], then displacements [m, rad]
  Eigen::VectorXd velocities, hydrodynamic;  // 3n work vectors for the coupled drag
  Eigen::VectorXd load_law_scratch;           // RodDrag::forces' stacked v and R v
  std::vector<Vector6d> previous_velocities;  // (v, omega) of the last step, where wall friction is linearised
  // Wall friction at the step's end velocities (step()): the slip velocity
  // of each rubbing wall-contact point (3 slots per contact, in the order
  // find_contacts finds them) its secant is taken about [m/s] (empty: the
  // previous velocities), and the correction loads. With the state the
  // step starts from (restored before the repeat).
  std::vector<Eigen::Vector3d> given_slip;
  std::vector<Vector6d> given_load;  // per wall contact: the correction loads [N, N m]
  std::vector<Eigen::Vector3d> point_load;  // per slot: the correction force at the point [N]
  Eigen::VectorXd step_dy;           // the last step_once's solution dy (6n) [m, rad]
  Eigen::MatrixXd friction_columns;  // (R/dt + K + C/dt)^-1 G_p^T e_a for each rubbing point's tangent direction
  std::vector<Eigen::Vector3d> friction_start_positions;
  std::vector<Eigen::Quaterniond> friction_start_orientations;

  // Block-tridiagonal storage: diagonal[k] = A(k, k), upper[k] = A(k, k+1),
  // lower[k] = A(k, k-1) (6x6 blocks).
  std::vector<Matrix6d> diagonal, upper, lower;
  // Eliminating in the assembly pass (step()), a diagonal block is dead once
  // its row is eliminated (block_lus keeps its LU): spheres k and k+1 only
  // are live, kept here by parity (at 10 000 spheres the 288 bytes per
  // sphere of `diagonal` no longer stream through the caches every step).
  Matrix6d rolling_diagonal[2];
  std::vector<SmallBlockLu<6>> block_lus;  // LU of each eliminated diagonal block (kept for re-solves)
  // The same over groups of `group_spheres` spheres (6g x 6g blocks), sized
  // at analysis. The last group is padded to g spheres by unit rows that
  // couple to nothing (their unknowns solve to 0), so every block has one
  // size and the 12x12 .. 24x24 cases run with fixed-size kernels.
  std::vector<Eigen::MatrixXd> group_diagonal, group_upper, group_lower;
  Eigen::MatrixXd group_work;
  Eigen::PartialPivLU<Eigen::MatrixXd> group_lu;
  Eigen::VectorXd group_rhs;  // padded right-hand side, then the solution

  // General couplings.
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::SparseMatrix<double> matrix;
  // Spheres are numbered along the rod, so without non-local drag the matrix
  // is banded (bonds couple neighbouring sections only; a self-contact adds
  // a block off the band): the natural ordering keeps the LU fill inside
  // the band, O(n).
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::NaturalOrdering<int>> lu;
  std::vector<int> analysed_outer, analysed_inner;  // pattern `lu` was analysed for
  Eigen::MatrixXd dense;  // assembled matrix, then its LU factors (dense_lu)
  DenseLu dense_lu;
  // A chain with non-local drag: its blocks above plus the dense resistance,
  // solved through the Schur complement on the coupled translations.
  CoupledChainSolve coupled_chain;
  // Chains with pair contacts off the band (chain_contact_solve.cpp): the
  // band's links (spheres k, k+1 coupled), the contacts off it with their
  // (i, j) and (j, i) blocks, the p spheres they couple (ascending; index of
  // each sphere or -1), each one's chain segment [first, last], the coupled
  // spheres in that segment ([begin, end) in coupled_spheres) and its
  // columns T^-1 E_s there (6x6 per sphere of the segment), and the factors
  // of I + G M. The matrix and right-hand side as assembled (band_*: the
  // elimination overwrites them) for the backward-error check and the
  // sparse fallback. Off (chain_contact_capacitance false): such a step
  // goes to the general dense or sparse LU.
  struct OffBandContact {
    int i, j;
    Matrix6d ij, ji;
  };
  bool chain_contact_capacitance = true;
  std::vector<char> band_linked;
  std::vector<OffBandContact> off_band;
  std::vector<int> coupled_spheres, coupled_index, coupled_column_start;
  std::vector<std::pair<int, int>> coupled_segment, coupled_in_segment;
  std::vector<Matrix6d> coupled_columns;
  std::vector<Matrix6d> band_diagonal, band_upper;
  Eigen::VectorXd band_rhs, chain_contact_residual, row_sums, refinement;
  Eigen::MatrixXd capacitance;  // I + G M, equilibrated: Dr (I + G M) Dc
  Eigen::VectorXd capacitance_row_scale, capacitance_column_scale;  // Dr, Dc (powers of two)
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_lu;
  // Beyond dense_capacitance_spheres coupled spheres the same matrix, sparse
  // (G block diagonal by chain segment, M the contact graph), by a sparse LU
  // with a fill-reducing column ordering, its pattern analysed only when it
  // changed (a plug's contacts persist over many steps).
  bool capacitance_sparse_factors = false;  // the last factors are capacitance_sparse_lu's
  std::vector<Eigen::Triplet<double>> capacitance_triplets;
  Eigen::SparseMatrix<double> capacitance_sparse;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> capacitance_sparse_lu;
  std::vector<int> capacitance_outer, capacitance_inner;  // pattern capacitance_sparse_lu was analysed for
  mutable Eigen::VectorXd coupled_work, coupled_load;  // y and M y of a solve

  // The factorisation of the last step, for newton_correction: which one
  // is kept, and the last step's solution dy and dt.
  enum class Kept { none, banded, coupled_chain, chain_contacts, dense, sparse };
  Kept kept = Kept::none;
  Eigen::VectorXd last_dy;
  double last_dt = 0.0;
  Eigen::VectorXd residual;  // work vector of newton_correction
  std::vector<Eigen::Matrix3d> turns;         // newton_correction: each sphere's rotation in the step
  FiniteRotationUpdate rotation_update;       // the position update (its bond graph's factors)
  std::vector<Eigen::Vector3d> step_start;    // positions before the step [m]
  OverdampedStepResult contact_scratch;
  // iterate(): the step's start y0 (null in a plain step) and the loads
  // (R + C) (y* - y0) / dt of the iterate's offset from it [N, N m].
  const std::vector<Eigen::Vector3d>* origin_positions = nullptr;
  const std::vector<Eigen::Quaterniond>* origin_orientations = nullptr;
  Eigen::VectorXd origin_offset, origin_load;  // 6n: (dx [m], dphi [rad]); loads

  int analyses = 0;
  OverdampedSolverStatistics statistics;
  LinearSolver method = LinearSolver::automatic;

  // Contacts (step_contacts.cpp).
  void find_contacts(const OverdampedRod& rod, const ChannelGeometry* geometry, const WallContactParameters* walls,
                     OverdampedStepResult& result);
  // (v, omega) of sphere i about which friction is linearised: the rod's
  // given velocities, else the solver's last step.
  Vector6d previous_velocity(const OverdampedRod& rod, int i) const {
    const int n = rod.size();
    Vector6d u0 = previous_velocities[i];
    if (static_cast<int>(rod.velocities.size()) == n) {
      u0.head<3>() = rod.velocities[i];
      u0.tail<3>() = static_cast<int>(rod.angular_velocities.size()) == n ? rod.angular_velocities[i]
                                                                           : Eigen::Vector3d::Zero();
    }
    return u0;
  }
  bool bonded(int i, int j) const {
    return std::find(partners.begin() + partner_start[i], partners.begin() + partner_start[i + 1], j) !=
           partners.begin() + partner_start[i + 1];
  }

  // The right-hand side and a chain's blocks (step_assembly.cpp).
  void set_origin_load(const OverdampedRod& rod, const RodDrag& drag, double dt);
  void assemble(const OverdampedRod& rod, const RodDrag& drag, double dt, bool fused, bool eliminate_in_pass);
  void couple_translations(const RodDrag& drag, const Eigen::VectorXd& moved, double dt);
  Eigen::Vector3d translation_drag(const RodDrag& drag, const Eigen::VectorXd& moved, double dt, int i) const;

  // The linear system's structure and solution (step_linear_solves.cpp).
  void analyse_structure(const OverdampedRod& rod);
  template <typename Add>
  void add_couplings(const OverdampedRod& rod, const RodDrag& drag, double dt, Add add) const;
  const Eigen::VectorXd& solve(const OverdampedRod& rod, const RodDrag& drag, double dt, bool fused,
                               bool eliminate_in_pass);
  const Eigen::VectorXd& solve_chain(const RodDrag& drag, double dt, int n);
  const Eigen::VectorXd& solve_chain_with_contacts(double dt, int n);
  void add_pair_contact_blocks(double dt, int n);
  bool factorise_capacitance(int n);
  void equilibrate_capacitance();
  bool factorise_sparse_capacitance();
  void equilibrate_sparse_capacitance();
  void apply_off_band_correction(Eigen::VectorXd& x) const;
  double chain_contact_backward_error(const Eigen::VectorXd& x);
  const Eigen::VectorXd& solve_chain_contacts_sparse(int n);
  const Eigen::VectorXd& solve_in_groups(const OverdampedRod& rod, const RodDrag& drag, double dt);
  const Eigen::VectorXd& solve_dense(const OverdampedRod& rod, const RodDrag& drag, double dt);
  const Eigen::VectorXd& solve_sparse(const OverdampedRod& rod, const RodDrag& drag, double dt);
  bool solve_kept(Eigen::VectorXd& b) const;  // b <- A^-1 b with the kept factors; false if none are kept
  bool fits_groups() const;
  bool factorize_sparse();

  // Block elimination (block_tridiagonal_solve.cpp).
  void solve_banded(int n);
  void eliminate_banded(int k, int n, Matrix6d& diagonal_k);
  void back_substitute_banded(int n);
  void resolve_banded(Eigen::VectorXd& b) const;
  void solve_grouped();
  template <int B>
  void solve_grouped_fixed();

  // The rod moved by the solution, and the result (overdamped_rod_step.cpp).
  void displace(OverdampedRod& rod, const Eigen::VectorXd& step);
  void advance(OverdampedRod& rod, const RodDrag& drag, double dt, const Eigen::VectorXd& step,
               OverdampedStepResult& result);
  void restore_friction_start(OverdampedRod& rod) const {
    rod.positions = friction_start_positions;
    rod.orientations = friction_start_orientations;
  }

  // Wall friction at the step's end velocities (step_friction_correction.cpp).
  Vector6d step_displacement(int i) const;
  double friction_mismatch(const OverdampedRod& rod, double dt, const WallContactParameters& walls) const;
  void keep_abouts();
  bool set_friction_correction(const OverdampedRod& rod, double dt, const WallContactParameters& walls);
};

}  // namespace hsrod
