#include "dynamics/overdamped_rod_step.h"
#include "dynamics/contact_friction_problem.h"

#include "dynamics/coupled_chain_solve.h"
#include "common/dense_lu.h"
#include "dynamics/finite_rotation_update.h"
#include "dynamics/small_block_lu.h"

#include "rod/beam_bond_jacobian.h"
#include "rod/rod_linearisation.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <type_traits>

namespace hsrod {

namespace {

Eigen::Matrix<double, 12, 1> bond_loads(const SphereState& si, const SphereState& sj, const RodBond& b) {
  const auto out = evaluate_beam_bond(si, sj, b.rest, b.stiffness, BeamBondDamping{});
  Eigen::Matrix<double, 12, 1> loads;
  loads << -out.force_on_j, out.torque_on_i, out.force_on_j, out.torque_on_j;
  return loads;
}

}  // namespace

OverdampedRod make_overdamped_rod(const RodLayout& layout, const BeamBondMaterial& material, double sphere_diameter) {
  OverdampedRod rod;
  const int n = static_cast<int>(layout.spheres.size());
  for (const auto& s : layout.spheres) rod.positions.push_back(s.position);
  rod.orientations.assign(n, Eigen::Quaterniond::Identity());
  rod.radii.assign(n, 0.5 * sphere_diameter);
  rod.external_forces.assign(n, Eigen::Vector3d::Zero());
  rod.external_torques.assign(n, Eigen::Vector3d::Zero());
  for (const auto& b : layout.bonds) {
    RodBond bond;
    bond.i = b.first;
    bond.j = b.second;
    bond.rest = layout_rest_state(layout, b);
    bond.stiffness = BeamBondStiffness::from_material(material, bond.rest.rest_length());
    rod.bonds.push_back(bond);
  }
  return rod;
}

namespace {

struct Cell {
  std::int64_t cx, cy;
  int sphere;
};

bool cell_order(const Cell& a, const Cell& b) { return std::tie(a.cx, a.cy, a.sphere) < std::tie(b.cx, b.cy, b.sphere); }

// Sorts cells that were sorted at the previous step and have moved a
// little since (few entries out of place): insertion sort, O(n) then; falls
// back to std::sort when the order has changed much.
void resort_cells(std::vector<Cell>& cells) {
  long moves = 0;
  const long budget = 8L * static_cast<long>(cells.size()) + 64;
  for (std::size_t k = 1; k < cells.size(); ++k) {
    const Cell c = cells[k];
    std::size_t m = k;
    for (; m > 0 && cell_order(c, cells[m - 1]); --m) cells[m] = cells[m - 1];
    cells[m] = c;
    moves += static_cast<long>(k - m);
    if (moves > budget) {
      std::sort(cells.begin(), cells.end(), cell_order);
      return;
    }
  }
}

// nearby_sphere_pairs with its cell buffer passed in (kept by a solver:
// `cells` from the previous call of the same rod are re-sorted, not sorted
// anew). With sort_pairs false the pairs come in cell order.
void find_nearby_pairs(const std::vector<Eigen::Vector3d>& positions, double reach, std::vector<Cell>& cells,
                       std::vector<std::pair<int, int>>& pairs, bool sort_pairs) {
  pairs.clear();
  const int n = static_cast<int>(positions.size());
  if (n < 2 || !(reach > 0.0)) {
    cells.clear();
    return;
  }
  if (n <= 32) {
    // A short rod: every pair, the same test as below (sorting cells costs
    // more than the n (n - 1) / 2 comparisons here).
    cells.clear();
    for (int i = 0; i < n; ++i) {
      if (!positions[i].allFinite()) continue;  // it has already spoilt the step; no neighbours
      for (int j = i + 1; j < n; ++j) {
        if (!positions[j].allFinite()) continue;
        const Eigen::Vector3d offset = positions[i] - positions[j];
        if (std::fabs(offset.x()) > reach || std::fabs(offset.y()) > reach) continue;
        pairs.emplace_back(i, j);
      }
    }
    return;  // in lexicographic order already
  }
  // Cells of side `reach` in the plane: a pair within reach in x and y lies
  // in the same or a neighbouring cell. The gap holds only a few spheres
  // across z, so cells stay nearly empty and the search is O(n log n).
  double x_min = std::numeric_limits<double>::infinity(), y_min = x_min;
  bool all_finite = true;
  for (const auto& p : positions) {
    if (!p.allFinite()) {
      all_finite = false;
      continue;
    }
    x_min = std::min(x_min, p.x());
    y_min = std::min(y_min, p.y());
  }
  const auto cell_of = [&](int i) {
    return Cell{static_cast<std::int64_t>(std::floor((positions[i].x() - x_min) / reach)),
                static_cast<std::int64_t>(std::floor((positions[i].y() - y_min) / reach)), i};
  };
  if (all_finite && static_cast<int>(cells.size()) == n) {
    for (Cell& c : cells) c = cell_of(c.sphere);
    resort_cells(cells);
  } else {
    cells.clear();
    // A non-finite sphere has already spoilt the step; it has no neighbours.
    for (int i = 0; i < n; ++i)
      if (positions[i].allFinite()) cells.push_back(cell_of(i));
    std::sort(cells.begin(), cells.end(), cell_order);
  }
  // Cells (cx + dx, cy - 1 .. cy + 1) are contiguous in the sorted list,
  // and where that run starts only moves forward as c goes through the
  // list in order: one cursor per dx, advanced instead of searched for
  // (O(n) in all; the pairs found and their order are those of a search).
  std::size_t start[3] = {0, 0, 0};
  for (const Cell& c : cells) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      const Cell first{c.cx + dx, c.cy - 1, -1};
      std::size_t& k = start[dx + 1];
      while (k < cells.size() && cell_order(cells[k], first)) ++k;
      for (std::size_t m = k; m < cells.size() && cells[m].cx == first.cx && cells[m].cy <= c.cy + 1; ++m) {
        const Cell& other = cells[m];
        if (other.sphere <= c.sphere) continue;
        const Eigen::Vector3d offset = positions[c.sphere] - positions[other.sphere];
        if (std::fabs(offset.x()) > reach || std::fabs(offset.y()) > reach) continue;
        pairs.emplace_back(c.sphere, other.sphere);
      }
    }
  }
  if (sort_pairs) std::sort(pairs.begin(), pairs.end());
}

}  // namespace

std::vector<std::pair<int, int>> nearby_sphere_pairs(const std::vector<Eigen::Vector3d>& positions, double reach) {
  std::vector<Cell> cells;
  std::vector<std::pair<int, int>> pairs;
  find_nearby_pairs(positions, reach, cells, pairs, true);
  return pairs;
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

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

struct SpherePairContact {
  int i, j;
  Eigen::Vector3d force_on_i;  // [N]
  Eigen::Matrix3d stiffness;   // -dF_i/dx_i [N/m]
  bool rubbing;                // friction acts (friction below is set)
  Matrix12d friction;          // secant resistance about the previous velocities of (i, j) [N s/m, N s, N m s]
};

}  // namespace

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
  std::vector<Cell> cells;
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
  bool solve_kept(Eigen::VectorXd& b) const;  // b <- A^-1 b with the kept factors; false if none are kept
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

  // The factorisation of the last step, for newton_correction: which one
  // is kept, and the last step's solution dy and dt.
  enum class Kept { none, banded, coupled_chain, dense, sparse };
  Kept kept = Kept::none;
  Eigen::VectorXd last_dy;
  double last_dt = 0.0;
  Eigen::VectorXd residual;  // work vector of newton_correction
  std::vector<Eigen::Matrix3d> turns;         // newton_correction: each sphere's rotation in the step
  FiniteRotationUpdate rotation_update;       // the position update (its bond graph's factors)
  std::vector<Eigen::Vector3d> step_start;    // positions before the step [m]
  std::vector<Eigen::Vector3d> correction_forces;
  OverdampedStepResult contact_scratch;
  // iterate(): the step's start y0 (null in a plain step) and the loads
  // (R + C) (y* - y0) / dt of the iterate's offset from it [N, N m].
  const std::vector<Eigen::Vector3d>* origin_positions = nullptr;
  const std::vector<Eigen::Quaterniond>* origin_orientations = nullptr;
  Eigen::VectorXd origin_offset, origin_load;  // 6n: (dx [m], dphi [rad]); loads

  int analyses = 0;
  OverdampedSolverStatistics statistics;
  LinearSolver method = LinearSolver::automatic;

  void analyse_structure(const OverdampedRod& rod);
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
  template <typename Add>
  void add_couplings(const OverdampedRod& rod, const RodDrag& drag, double dt, Add add) const;
  void solve_banded(int n);
  void eliminate_banded(int k, int n, Matrix6d& diagonal_k);
  void back_substitute_banded(int n);
  void resolve_banded(Eigen::VectorXd& b) const;
  bool fits_groups() const;
  void solve_grouped();
  template <int B>
  void solve_grouped_fixed();
  void factorize_sparse();
};

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

void OverdampedRodSolver::Workspace::find_contacts(const OverdampedRod& rod, const ChannelGeometry* geometry,
                                                   const WallContactParameters* walls, OverdampedStepResult& result) {
  wall_contacts.clear();
  pair_contacts.clear();
  const int n = rod.size();
  if (geometry && walls) {
    for (int i = 0; i < n; ++i) {
      const WallContact c = wall_contact(*geometry, *walls, rod.positions[i], rod.radii[i]);
      if (!c.touching) continue;
      result.wall_contact = true;
      result.wall_force += c.force.norm();
      if (static_cast<int>(result.sphere_wall_force.size()) == n) result.sphere_wall_force[i] += c.force.norm();
      SphereWallContact contact{i, c.force, c.stiffness, false, Matrix6d::Zero(), Vector6d::Zero(), c.points, c.point,
                                {},  {}};
      // Wall friction: its secant c G^T G (dynamics/wall_contact.h) about
      // the previous velocities (or, when step() repeats the step, about the
      // slip it is given, with the given correction loads), on the sphere's
      // own 6x6 block.
      if (walls->friction_coefficient > 0.0) {
        const Vector6d u0 = previous_velocity(rod, i);
        contact.rubbing = true;
        const std::size_t m = wall_contacts.size();
        for (int k = 0; k < c.points; ++k) {
          const std::size_t slot = 3 * m + k;
          contact.about[k] = slot < given_slip.size() ? given_slip[slot] : wall_slip(c.point[k], rod.radii[i], u0);
          contact.secant[k] =
              walls->friction_coefficient * c.point[k].normal_force / std::max(contact.about[k].norm(), walls->slip_velocity);
          contact.friction += wall_friction_resistance_at_slip(c.point[k], rod.radii[i], walls->friction_coefficient,
                                                               walls->slip_velocity, contact.about[k].norm());
        }
        if (m < given_load.size()) contact.friction_load = given_load[m];
      }
      wall_contacts.push_back(contact);
    }
  }
  // Non-bonded spheres touching each other: a folding rod, or two rods of
  // a cluster stepped together.
  if (walls && sphere_pair_search_on(rod, *walls)) {
    double largest_radius = 0.0;
    for (double r : rod.radii) largest_radius = std::max(largest_radius, r);
    find_nearby_pairs(rod.positions, 2.0 * largest_radius, cells, candidates, false);
    for (const auto& pair : candidates) {
      const int i = pair.first, j = pair.second;
      if (bonded(i, j) || !sphere_pair_contact_on(rod, *walls, i, j)) continue;
      const WallContact c = sphere_contact(*walls, rod.positions[i], rod.radii[i], rod.positions[j], rod.radii[j]);
      if (!c.touching) continue;
      result.self_contact = true;
      if (!rod.same_rod(i, j)) {
        result.rod_contact = true;
        result.rod_contact_force += c.point[0].normal_force;
      }
      SpherePairContact contact{i, j, c.force, c.stiffness, false, Matrix12d::Zero()};
      if (walls->rod_friction_coefficient > 0.0) {
        Vector12d u0;
        u0 << previous_velocity(rod, i), previous_velocity(rod, j);
        contact.rubbing = true;
        contact.friction = sphere_friction_resistance(c.point[0], rod.radii[i], rod.radii[j],
                                                      walls->rod_friction_coefficient, walls->slip_velocity, u0);
      }
      pair_contacts.push_back(contact);
    }
    // Summed in the order of the sphere indices, independent of the cells.
    std::sort(pair_contacts.begin(), pair_contacts.end(),
              [](const SpherePairContact& a, const SpherePairContact& b) {
                return std::tie(a.i, a.j) < std::tie(b.i, b.j);
              });
  }
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
bool OverdampedRodSolver::Workspace::solve_kept(Eigen::VectorXd& b) const {
  switch (kept) {
    case Kept::banded: resolve_banded(b); return true;
    case Kept::coupled_chain: coupled_chain.solve_in_place(b); return true;
    case Kept::dense: dense_lu.solve_in_place(b); return true;
    case Kept::sparse: b = lu.solve(b).eval(); return true;
    case Kept::none: return false;
  }
  return false;
}

void OverdampedRodSolver::Workspace::resolve_banded(Eigen::VectorXd& b) const {
  const int n = static_cast<int>(block_lus.size());
  for (int k = 0; k < n; ++k) {
    auto y = b.segment<6>(6 * k);
    if (k > 0) y.noalias() -= lower[k] * b.segment<6>(6 * (k - 1));
    block_lus[k].solve_in_place(y);
  }
  for (int k = n - 2; k >= 0; --k) b.segment<6>(6 * k).noalias() -= upper[k] * b.segment<6>(6 * (k + 1));
}

// Self-contacts between spheres at most `group_spheres` apart stay inside
// the blocks of neighbouring groups.
bool OverdampedRodSolver::Workspace::fits_groups() const {
  if (group_spheres == 0) return false;
  for (const SpherePairContact& c : pair_contacts)
    if (std::abs(c.i - c.j) > group_spheres) return false;
  return true;
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

// Factorises `matrix`, analysing its pattern only when it changed.
void OverdampedRodSolver::Workspace::factorize_sparse() {
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
}

OverdampedRodSolver::OverdampedRodSolver() : workspace_(std::make_unique<Workspace>()) {}
OverdampedRodSolver::~OverdampedRodSolver() = default;
OverdampedRodSolver::OverdampedRodSolver(OverdampedRodSolver&&) noexcept = default;
OverdampedRodSolver& OverdampedRodSolver::operator=(OverdampedRodSolver&&) noexcept = default;

void OverdampedRodSolver::displace(OverdampedRod& rod, const Eigen::VectorXd& dy) {
  workspace_->rotation_update.apply(rod, dy);
  for (int i = 0; i < rod.size(); ++i)
    rod.orientations[i] =
        (quaternion_from_rotation_vector(dy.segment<3>(6 * i + 3)) * rod.orientations[i]).normalized();
}

void OverdampedRodSolver::iterate(OverdampedRod& rod, const std::vector<Eigen::Vector3d>& start_positions,
                                  const std::vector<Eigen::Quaterniond>& start_orientations, const RodDrag& drag,
                                  double dt, const ChannelGeometry* geometry, const WallContactParameters* walls,
                                  OverdampedStepResult& result) {
  Workspace& w = *workspace_;
  w.origin_positions = &start_positions;
  w.origin_orientations = &start_orientations;
  try {
    step(rod, drag, dt, geometry, walls, result);
  } catch (...) {
    w.origin_positions = nullptr;
    w.origin_orientations = nullptr;
    throw;
  }
  w.origin_positions = nullptr;
  w.origin_orientations = nullptr;
}

int OverdampedRodSolver::pattern_analyses() const { return workspace_->analyses; }
const OverdampedSolverStatistics& OverdampedRodSolver::statistics() const { return workspace_->statistics; }
void OverdampedRodSolver::set_linear_solver(LinearSolver method) { workspace_->method = method; }

OverdampedStepResult overdamped_rod_step(OverdampedRod& rod, const RodDrag& drag, double dt,
                                         const ChannelGeometry* geometry, const WallContactParameters* walls) {
  OverdampedRodSolver solver;
  return solver.step(rod, drag, dt, geometry, walls);
}

OverdampedStepResult OverdampedRodSolver::step(OverdampedRod& rod, const RodDrag& drag, double dt,
                                               const ChannelGeometry* geometry, const WallContactParameters* walls) {
  OverdampedStepResult result;
  step(rod, drag, dt, geometry, walls, result);
  return result;
}

void OverdampedRodSolver::step(OverdampedRod& rod, const RodDrag& drag, double dt, const ChannelGeometry* geometry,
                               const WallContactParameters* walls, OverdampedStepResult& result) {
  Workspace& w = *workspace_;
  w.given_slip.clear();
  w.given_load.clear();
  result.friction_mismatch = 0.0;
  result.friction_repeats = 0;
  const bool iterate_friction = geometry && walls && walls->friction_coefficient > 0.0 && walls->friction_iterations > 0;
  if (iterate_friction) {
    w.friction_start_positions = rod.positions;
    w.friction_start_orientations = rod.orientations;
  }
  step_once(rod, drag, dt, geometry, walls, result);
  if (!iterate_friction) return;
  // Backward Euler's friction is the law at the step's end velocities; the
  // step above took each point's secant -c w about the previous slip. The
  // step's own matrix A = R/dt + K + C/dt (kept factorised) gives how the
  // slips w of the rubbing points answer extra contact forces g (2 tangent
  // directions per point): w = w0 + M g, M = G A^-1 G^T / dt (the Delassus
  // operator of the contacts, 2k x 2k, from 2k back substitutions). The
  // friction is right where g = f(w) + c w (f the law), a small convex
  // problem (contact_friction_problem.h); the step is
  // then repeated with the same secants and the loads G^T g. Only where the
  // secant was off by more than friction_tolerance mu F_n (a contact that
  // sticks or slides steadily is consistent at once).
  const double mu = walls->friction_coefficient, v_s = walls->slip_velocity;
  const auto measure_mismatch = [&]() {
    double mismatch = 0.0;
    for (const SphereWallContact& c : w.wall_contacts) {
      if (!c.rubbing) continue;
      // The velocities of the step's linear system (the finite-rotation
      // position update changes the slip, a small difference of v and
      // r omega for a rolling sphere, by more than v_s).
      Vector6d u = w.step_dy.segment<6>(6 * c.sphere);
      if (w.origin_positions) u += w.origin_offset.segment<6>(6 * c.sphere);
      u /= dt;
      // The correction's force at each point is spread over the sphere's
      // points below; judge the sphere's total tangential friction.
      Eigen::Vector3d law = Eigen::Vector3d::Zero(), applied = c.friction_load.head<3>();
      double sliding = 0.0;
      for (int k = 0; k < c.points; ++k) {
        const Eigen::Vector3d slip = wall_slip(c.point[k], rod.radii[c.sphere], u);
        law += wall_friction_force(c.point[k], mu, v_s, slip);
        applied -= c.secant[k] * slip;
        sliding += mu * c.point[k].normal_force;
      }
      if (sliding > 0.0) mismatch = std::max(mismatch, (law - applied).norm() / sliding);
    }
    return mismatch;
  };
  result.friction_mismatch = measure_mismatch();
  const auto keep_abouts = [&w]() {
    w.given_slip.assign(3 * w.wall_contacts.size(), Eigen::Vector3d::Zero());
    for (std::size_t m = 0; m < w.wall_contacts.size(); ++m)
      for (int k = 0; k < w.wall_contacts[m].points; ++k) w.given_slip[3 * m + k] = w.wall_contacts[m].about[k];
  };
  for (int repeat = 0; result.friction_mismatch > walls->friction_tolerance && repeat < walls->friction_iterations;
       ++repeat) {
    if (w.kept == Workspace::Kept::none) {
      // Multi-sphere sections' grouped blocks keep no factors: the same
      // step (same secants) once more by the sparse LU, which keeps them.
      keep_abouts();
      rod.positions = w.friction_start_positions;
      rod.orientations = w.friction_start_orientations;
      const LinearSolver method = w.method;
      w.method = LinearSolver::sparse_lu;
      step_once(rod, drag, dt, geometry, walls, result);
      w.method = method;
      if (w.kept == Workspace::Kept::none) break;
    }
    // The rubbing points and their tangent bases.
    struct Point {
      int contact, k, sphere;
      Eigen::Matrix<double, 3, 6> g;
      Eigen::Matrix<double, 3, 2> basis;
      double sliding, secant;
    };
    std::vector<Point> points;
    for (std::size_t m = 0; m < w.wall_contacts.size(); ++m) {
      const SphereWallContact& c = w.wall_contacts[m];
      if (!c.rubbing) continue;
      for (int k = 0; k < c.points; ++k) {
        const double sliding = mu * c.point[k].normal_force;
        if (!(sliding > 0.0)) continue;
        const Eigen::Vector3d& n = c.point[k].normal;
        Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
        Eigen::Matrix<double, 3, 2> basis;
        basis << t1, t2;
        points.push_back({static_cast<int>(m), k, c.sphere, wall_slip_operator(c.point[k], rod.radii[c.sphere]), basis,
                          sliding, c.secant[k]});
      }
    }
    const int unknowns = 2 * static_cast<int>(points.size());
    if (unknowns == 0) break;
    w.friction_columns.resize(6 * rod.size(), unknowns);
    Eigen::VectorXd column(6 * rod.size());
    bool solved = true;
    for (int p = 0; p < static_cast<int>(points.size()) && solved; ++p)
      for (int a = 0; a < 2; ++a) {
        column.setZero();
        column.segment<6>(6 * points[p].sphere) = points[p].g.transpose() * points[p].basis.col(a);
        solved = w.solve_kept(column);
        w.friction_columns.col(2 * p + a) = column;
      }
    if (!solved) break;
    // Slips (in each point's basis) of the step as taken, the Delassus
    // operator M, and the correction loads g already applied [m/s, N].
    Eigen::VectorXd w0(unknowns), g0(unknowns);
    Eigen::MatrixXd delassus(unknowns, unknowns);
    for (int p = 0; p < static_cast<int>(points.size()); ++p) {
      const Point& pt = points[p];
      const Eigen::Matrix<double, 2, 6> bg = pt.basis.transpose() * pt.g;
      // (In a Newton iteration, iterate(), the step's velocities are over
      // the whole step from its start: the iterate's offset plus dy.)
      Vector6d moved = w.step_dy.segment<6>(6 * pt.sphere);
      if (w.origin_positions) moved += w.origin_offset.segment<6>(6 * pt.sphere);
      w0.segment<2>(2 * p) = bg * moved / dt;
      for (int q = 0; q < unknowns; ++q)
        delassus.block<2, 1>(2 * p, q) = bg * w.friction_columns.col(q).segment<6>(6 * pt.sphere) / dt;
      // The correction force already applied at this point (a repeat).
      g0.segment<2>(2 * p) = w.given_load.empty() ? Eigen::Vector2d::Zero()
                                                  : Eigen::Vector2d(pt.basis.transpose() * w.point_load[3 * pt.contact + pt.k]);
    }
    // The friction forces at the step's end slips (contact_friction_problem.h).
    std::vector<FrictionPointLaw> laws;
    laws.reserve(points.size());
    double smallest_sliding = HUGE_VAL;
    for (const Point& pt : points) {
      laws.push_back({pt.sliding, pt.secant});
      smallest_sliding = std::min(smallest_sliding, pt.sliding);
    }
    const Eigen::VectorXd force = contact_friction_correction(
        delassus, w0, g0, laws, v_s, 1e-3 * walls->friction_tolerance * smallest_sliding);
    // The correction loads per contact point (lab frame) and per sphere.
    w.point_load.assign(3 * w.wall_contacts.size(), Eigen::Vector3d::Zero());
    w.given_load.assign(w.wall_contacts.size(), Vector6d::Zero());
    keep_abouts();
    for (int p = 0; p < static_cast<int>(points.size()); ++p) {
      const Eigen::Vector3d load = points[p].basis * force.segment<2>(2 * p);
      w.point_load[3 * points[p].contact + points[p].k] = load;
      w.given_load[points[p].contact] += points[p].g.transpose() * load;
    }
    rod.positions = w.friction_start_positions;
    rod.orientations = w.friction_start_orientations;
    ++result.friction_repeats;
    ++w.statistics.friction_repeats;
    step_once(rod, drag, dt, geometry, walls, result);
    result.friction_mismatch = measure_mismatch();
  }
  w.given_load.clear();
  w.given_slip.clear();
}

void OverdampedRodSolver::step_once(OverdampedRod& rod, const RodDrag& drag, double dt,
                                    const ChannelGeometry* geometry, const WallContactParameters* walls,
                                    OverdampedStepResult& result) {
  Workspace& w = *workspace_;
  const Clock::time_point t_start = Clock::now();
  const int n = rod.size();
  const int ndof = 6 * n;
  result.largest_displacement = 0.0;
  result.wall_contact = result.self_contact = result.rod_contact = false;
  result.wall_force = 0.0;
  result.rod_contact_force = 0.0;
  result.sphere_wall_force.assign(n, 0.0);
  result.friction_force = 0.0;
  w.analyse_structure(rod);
  if (static_cast<int>(w.previous_velocities.size()) != n) w.previous_velocities.assign(n, Vector6d::Zero());

  // Contacts first: whether a self-contact takes the step off the band
  // decides how the bonds are assembled (they do not depend on the bonds).
  w.find_contacts(rod, geometry, walls, result);
  const Clock::time_point t_contacts = Clock::now();

  // A Newton iteration (iterate()): the drag and friction of the offset
  // y* - y0 the iterate has already moved from the step's start, taken off
  // the right-hand side (the residual of backward Euler at y*).
  const bool from_origin = w.origin_positions != nullptr;
  if (from_origin) {
    w.origin_offset.resize(ndof);
    for (int i = 0; i < n; ++i) {
      w.origin_offset.segment<3>(6 * i) = rod.positions[i] - (*w.origin_positions)[i];
      w.origin_offset.segment<3>(6 * i + 3) =
          rotation_vector((rod.orientations[i] * (*w.origin_orientations)[i].inverse()).normalized());
    }
    w.origin_load.setZero(ndof);
    if (drag.coupled()) {
      w.velocities.resize(3 * n);
      for (int i = 0; i < n; ++i) w.velocities.segment<3>(3 * i) = w.origin_offset.segment<3>(6 * i) / dt;
      w.hydrodynamic.noalias() = drag.coupled_resistance * w.velocities;
    }
    for (int i = 0; i < n; ++i) {
      w.origin_load.segment<3>(6 * i) = drag.coupled()
                                            ? Eigen::Vector3d(w.hydrodynamic.segment<3>(3 * i))
                                            : Eigen::Vector3d(drag.resistance[i] * w.origin_offset.segment<3>(6 * i) / dt);
      w.origin_load.segment<3>(6 * i + 3) = drag.rotational_resistance[i] * w.origin_offset.segment<3>(6 * i + 3) / dt;
    }
    for (const SphereWallContact& c : w.wall_contacts)
      if (c.rubbing) w.origin_load.segment<6>(6 * c.sphere) += c.friction * w.origin_offset.segment<6>(6 * c.sphere) / dt;
    for (const SpherePairContact& c : w.pair_contacts) {
      if (!c.rubbing) continue;
      Vector12d u;
      u << w.origin_offset.segment<6>(6 * c.i), w.origin_offset.segment<6>(6 * c.j);
      const Vector12d loads = c.friction * u / dt;
      w.origin_load.segment<6>(6 * c.i) += loads.head<6>();
      w.origin_load.segment<6>(6 * c.j) += loads.tail<6>();
    }
  }

  // A chain (the common case) goes to the block-tridiagonal solve unless a
  // self-contact appears: its blocks are assembled while the bonds are
  // evaluated, each bond's 12 x 12 Jacobian used where it is made and not
  // stored (at 10 000 spheres the stored Jacobians alone are 11 MB, beyond
  // the caches). The sums are those of add_couplings in its order: drag,
  // then bonds in order, then wall contacts. With non-local drag the
  // blocks hold all but the translations' resistance, which the Schur
  // complement solve (dynamics/coupled_chain_solve.h) adds. With local drag
  // and the bonds in chain order (bond k joins k and k+1) sphere k's block
  // row is complete once bond k is in, and is eliminated there, in the same
  // pass (solve_banded's operations in its order: the same result to the
  // last bit), while its blocks are still in cache.
  const bool automatic = w.method == LinearSolver::automatic;
  const bool fused = automatic && w.chain && n > 0 && w.pair_contacts.empty();
  const bool eliminate_in_pass = fused && !drag.coupled() && w.ordered_chain;
  Eigen::VectorXd& rhs = w.rhs;
  rhs.resize(ndof);
  // A(i, i): rolling storage when each row is eliminated in the pass.
  const auto diagonal = [&](int i) -> Matrix6d& {
    return eliminate_in_pass ? w.rolling_diagonal[i & 1] : w.diagonal[i];
  };
  // Sphere i's blocks (drag) and right-hand side (driving and external loads).
  const auto start_sphere = [&](int i) {
    if (fused) {
      Matrix6d& d = diagonal(i);
      d.setZero();
      w.upper[i].setZero();
      w.lower[i].setZero();
      d.block<3, 3>(3, 3) += drag.rotational_resistance[i] / dt * Eigen::Matrix3d::Identity();
      if (!drag.coupled()) d.block<3, 3>(0, 0) += drag.resistance[i] / dt;
    }
    rhs.segment<3>(6 * i) = drag.driving_force[i] + rod.external_forces[i];
    rhs.segment<3>(6 * i + 3) = drag.driving_torque[i] + rod.external_torques[i];
    if (from_origin) rhs.segment<6>(6 * i) -= w.origin_load.segment<6>(6 * i);
  };
  // Bonds: loads at y_n and their Jacobian (K = -d loads / dy).
  BondLoads loads;
  const auto add_chain_bond = [&](const RodBond& b) {
    // A chain bond joins k and k+1 in either order.
    Matrix6d& ij = b.j == b.i + 1 ? w.upper[b.i] : w.lower[b.i];
    Matrix6d& ji = b.j == b.i + 1 ? w.lower[b.j] : w.upper[b.j];
    beam_bond_loads_and_add_stiffness(rod.positions[b.i], rod.orientations[b.i], rod.positions[b.j],
                                      rod.orientations[b.j], b.rest, b.stiffness, loads, diagonal(b.i), ij, ji,
                                      diagonal(b.j));
    rhs.segment<6>(6 * b.i) += loads.head<6>();
    rhs.segment<6>(6 * b.j) += loads.tail<6>();
  };
  if (eliminate_in_pass) {
    std::size_t next_wall = 0;  // wall_contacts are in sphere order
    start_sphere(0);
    for (int k = 0; k < n; ++k) {
      if (k + 1 < n) {
        start_sphere(k + 1);
        add_chain_bond(rod.bonds[k]);
      }
      for (; next_wall < w.wall_contacts.size() && w.wall_contacts[next_wall].sphere == k; ++next_wall) {
        const SphereWallContact& c = w.wall_contacts[next_wall];
        rhs.segment<3>(6 * k) += c.force;
        if (c.rubbing) rhs.segment<6>(6 * k) += c.friction_load;
        diagonal(k).block<3, 3>(0, 0) += c.stiffness;
        if (c.rubbing) diagonal(k) += c.friction / dt;
      }
      w.eliminate_banded(k, n, diagonal(k));
    }
    w.back_substitute_banded(n);
  } else {
    for (int i = 0; i < n; ++i) start_sphere(i);
    if (fused) {
      for (const RodBond& b : rod.bonds) add_chain_bond(b);
    } else {
      w.bond_loads.resize(rod.bonds.size());
      w.bond_jacobians.resize(rod.bonds.size());
      for (std::size_t k = 0; k < rod.bonds.size(); ++k) {
        const RodBond& b = rod.bonds[k];
        beam_bond_loads_and_jacobian(rod.positions[b.i], rod.orientations[b.i], rod.positions[b.j],
                                     rod.orientations[b.j], b.rest, b.stiffness, w.bond_loads[k],
                                     w.bond_jacobians[k]);
        rhs.segment<6>(6 * b.i) += w.bond_loads[k].head<6>();
        rhs.segment<6>(6 * b.j) += w.bond_loads[k].tail<6>();
      }
    }
    for (const SphereWallContact& c : w.wall_contacts) {
      rhs.segment<3>(6 * c.sphere) += c.force;
      if (c.rubbing) rhs.segment<6>(6 * c.sphere) += c.friction_load;
    }
    for (const SpherePairContact& c : w.pair_contacts) {
      rhs.segment<3>(6 * c.i) += c.force_on_i;
      rhs.segment<3>(6 * c.j) -= c.force_on_i;
    }
  }
  const Clock::time_point t_bonds = Clock::now();

  // Matrix R / dt + K, factorised by the cheapest method its couplings allow.
  const Eigen::VectorXd* displacement = &rhs;
  if (eliminate_in_pass) {
    w.kept = Workspace::Kept::banded;  // solved in the bond pass
    ++w.statistics.banded_steps;
  } else if (fused) {
    // Drag and bonds are in the blocks already; the wall contacts last, as
    // add_couplings adds them.
    for (const SphereWallContact& c : w.wall_contacts) {
      w.diagonal[c.sphere].block<3, 3>(0, 0) += c.stiffness;
      if (c.rubbing) w.diagonal[c.sphere] += c.friction / dt;
    }
    if (drag.coupled()) {
      w.coupled_chain.factorise(w.diagonal, w.upper, w.lower, drag.coupled_resistance, dt,
                                CoupledChainSolve::coupled_components(drag.coupled_resistance));
      w.dy = rhs;
      w.coupled_chain.solve_in_place(w.dy);
      displacement = &w.dy;
      w.kept = Workspace::Kept::coupled_chain;
      ++w.statistics.dense_steps;
    } else {
      w.solve_banded(n);
      w.kept = Workspace::Kept::banded;
      ++w.statistics.banded_steps;
    }
  } else if (automatic && !drag.coupled() && w.fits_groups()) {
    const int g = w.group_spheres;
    for (int k = 0; k < static_cast<int>(w.group_diagonal.size()); ++k) {
      w.group_diagonal[k].setZero();
      w.group_upper[k].setZero();
      w.group_lower[k].setZero();
    }
    // Padding of the last group: unit rows and columns.
    for (int dof = ndof; dof < static_cast<int>(w.group_rhs.size()); ++dof)
      w.group_diagonal.back()(dof % (6 * g), dof % (6 * g)) = 1.0;
    w.group_rhs.head(ndof) = rhs;
    w.group_rhs.tail(w.group_rhs.size() - ndof).setZero();
    w.add_couplings(rod, drag, dt, [&w, g](int row, int col, const auto& block) {
      using Block = std::decay_t<decltype(block)>;
      const int r = row / (6 * g), c = col / (6 * g);
      Eigen::MatrixXd& target = c == r ? w.group_diagonal[r] : (c == r + 1 ? w.group_upper[r] : w.group_lower[r]);
      target.template block<Block::RowsAtCompileTime, Block::ColsAtCompileTime>(row - 6 * g * r, col - 6 * g * c) +=
          block;
    });
    w.solve_grouped();
    displacement = &w.group_rhs;
    w.kept = Workspace::Kept::none;  // the grouped blocks' LUs are not kept
    ++w.statistics.banded_steps;
  } else if (w.method == LinearSolver::dense_lu || (automatic && (drag.coupled() || n <= 16))) {
    w.dense.setZero(ndof, ndof);
    w.add_couplings(rod, drag, dt, [&w](int row, int col, const auto& block) {
      using Block = std::decay_t<decltype(block)>;
      w.dense.template block<Block::RowsAtCompileTime, Block::ColsAtCompileTime>(row, col) += block;
    });
    w.dense_lu.compute_in_place(w.dense);
    w.dy = rhs;
    w.dense_lu.solve_in_place(w.dy);
    displacement = &w.dy;
    w.kept = Workspace::Kept::dense;
    ++w.statistics.dense_steps;
  } else {
    // Every entry of a bond's block enters the pattern, also one that
    // happens to be zero at this configuration, so that the pattern (and its
    // LU analysis) stays put.
    w.triplets.clear();
    w.add_couplings(rod, drag, dt, [&w](int row, int col, const auto& block) {
      for (int a = 0; a < block.rows(); ++a)
        for (int b = 0; b < block.cols(); ++b) w.triplets.emplace_back(row + a, col + b, block(a, b));
    });
    w.matrix.resize(ndof, ndof);
    w.matrix.setFromTriplets(w.triplets.begin(), w.triplets.end());
    w.factorize_sparse();
    w.dy = w.lu.solve(rhs);
    displacement = &w.dy;
    w.kept = Workspace::Kept::sparse;
    ++w.statistics.sparse_steps;
  }
  const Eigen::VectorXd& dy = *displacement;
  w.step_dy = dy.head(ndof);
  w.last_dy = dy.head(ndof);
  w.last_dt = dt;

  result.velocities.resize(n);
  result.angular_velocities.resize(n);
  result.hydrodynamic_forces.resize(n);
  // Positions with finite bond rotations (dynamics/finite_rotation_update.h:
  // the tangent update x + dx stretches a turning stiff rod, which then
  // stops turning); orientations by their exact rotation.
  w.step_start = from_origin ? *w.origin_positions : rod.positions;
  w.rotation_update.apply(rod, dy);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d dx = rod.positions[i] - w.step_start[i];
    rod.orientations[i] = (quaternion_from_rotation_vector(dy.segment<3>(6 * i + 3)) * rod.orientations[i]).normalized();
    // Over the whole step (from y0 for an iteration).
    const Eigen::Vector3d dphi =
        from_origin ? rotation_vector((rod.orientations[i] * (*w.origin_orientations)[i].inverse()).normalized())
                    : Eigen::Vector3d(dy.segment<3>(6 * i + 3));
    w.last_dy.segment<3>(6 * i) = dx;  // newton_correction's drag term: the displacement taken
    w.last_dy.segment<3>(6 * i + 3) = dphi;
    result.velocities[i] = dx / dt;
    result.angular_velocities[i] = dphi / dt;
    result.largest_displacement = std::max(result.largest_displacement, dx.norm());
    w.previous_velocities[i] << result.velocities[i], result.angular_velocities[i];
  }
  for (const SphereWallContact& c : w.wall_contacts)
    if (c.rubbing)
      result.friction_force += (c.friction * w.previous_velocities[c.sphere] - c.friction_load).head<3>().norm();
  for (const SpherePairContact& c : w.pair_contacts) {
    if (!c.rubbing) continue;
    Vector12d u;
    u << w.previous_velocities[c.i], w.previous_velocities[c.j];
    result.friction_force += (c.friction * u).head<3>().norm();
  }
  drag.forces(result.velocities, result.hydrodynamic_forces, w.load_law_scratch);  // at the new velocities
  const Clock::time_point t_end = Clock::now();
  OverdampedSolverStatistics& stats = w.statistics;
  ++stats.steps;
  stats.sphere_steps += n;
  stats.contact_seconds += seconds_between(t_start, t_contacts);
  stats.bond_seconds += seconds_between(t_contacts, t_bonds);  // with a chain's elimination when fused with it
  stats.solve_seconds += seconds_between(t_bonds, t_end);
}

bool OverdampedRodSolver::newton_correction(const OverdampedRod& rod, const RodDrag& drag,
                                            const ChannelGeometry* geometry, const WallContactParameters* walls,
                                            Eigen::VectorXd& delta) {
  Workspace& w = *workspace_;
  const int n = rod.size();
  if (w.kept == Workspace::Kept::none || w.last_dy.size() != 6 * n || n == 0) return false;
  const Clock::time_point t_start = Clock::now();
  const double dt = w.last_dt;
  const Eigen::VectorXd& dy = w.last_dy;
  Eigen::VectorXd& r = w.residual;
  r.setZero(6 * n);
  // Friction first: find_contacts below replaces the step's contacts.
  for (const SphereWallContact& c : w.wall_contacts)
    if (c.rubbing) {
      r.segment<6>(6 * c.sphere).noalias() -= c.friction * dy.segment<6>(6 * c.sphere) / dt;
      r.segment<6>(6 * c.sphere) += c.friction_load;
    }
  for (const SpherePairContact& c : w.pair_contacts) {
    if (!c.rubbing) continue;
    Vector12d u;
    u << dy.segment<6>(6 * c.i), dy.segment<6>(6 * c.j);
    const Vector12d loads = c.friction * u / dt;
    r.segment<6>(6 * c.i) -= loads.head<6>();
    r.segment<6>(6 * c.j) -= loads.tail<6>();
  }
  if (drag.coupled()) {
    w.velocities.resize(3 * n);
    for (int i = 0; i < n; ++i) w.velocities.segment<3>(3 * i) = dy.segment<3>(6 * i) / dt;
    w.hydrodynamic.noalias() = drag.coupled_resistance * w.velocities;
  }
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d resisted = drag.coupled() ? Eigen::Vector3d(w.hydrodynamic.segment<3>(3 * i))
                                                    : Eigen::Vector3d(drag.resistance[i] * dy.segment<3>(6 * i) / dt);
    r.segment<3>(6 * i) += drag.driving_force[i] + rod.external_forces[i] - resisted;
    r.segment<3>(6 * i + 3) += drag.driving_torque[i] + rod.external_torques[i] -
                               drag.rotational_resistance[i] / dt * dy.segment<3>(6 * i + 3);
  }
  for (const RodBond& b : rod.bonds) {
    const SphereState si = rod.pose(b.i), sj = rod.pose(b.j);
    const Eigen::Matrix<double, 12, 1> loads = bond_loads(si, sj, b);
    r.segment<6>(6 * b.i) += loads.head<6>();
    r.segment<6>(6 * b.j) += loads.tail<6>();
  }
  w.contact_scratch.wall_contact = w.contact_scratch.self_contact = w.contact_scratch.rod_contact = false;
  w.contact_scratch.wall_force = w.contact_scratch.rod_contact_force = 0.0;
  w.find_contacts(rod, geometry, walls, w.contact_scratch);
  for (const SphereWallContact& c : w.wall_contacts) r.segment<3>(6 * c.sphere) += c.force;
  for (const SpherePairContact& c : w.pair_contacts) {
    r.segment<3>(6 * c.i) += c.force_on_i;
    r.segment<3>(6 * c.j) -= c.force_on_i;
  }
  // Co-rotated: the factors are those of the stiffness at the step's start,
  // whose stiff directions (a bond's axis) have turned with the spheres by
  // dphi_i since. A rigid rotation Q turns the stiffness to Q K Q^T, so the
  // correction is Q (R/dt + K)^-1 Q^T r with Q_i = Exp(dphi_i) per sphere.
  // Solved unrotated, the residual along a stiff rod's new axis (its
  // remaining strain times k_n) would be taken partly as a transverse load
  // on the drag alone and amplified by k_n dt / zeta (1e8 for E = 1.5e12 Pa).
  w.turns.resize(n);
  for (int i = 0; i < n; ++i) {
    w.turns[i] = quaternion_from_rotation_vector(dy.segment<3>(6 * i + 3)).toRotationMatrix();
    r.segment<3>(6 * i) = (w.turns[i].transpose() * r.segment<3>(6 * i)).eval();
    r.segment<3>(6 * i + 3) = (w.turns[i].transpose() * r.segment<3>(6 * i + 3)).eval();
  }
  switch (w.kept) {
    case Workspace::Kept::banded:
      delta = r;
      w.resolve_banded(delta);
      break;
    case Workspace::Kept::coupled_chain:
      delta = r;
      w.coupled_chain.solve_in_place(delta);
      break;
    case Workspace::Kept::dense:
      delta = r;
      w.dense_lu.solve_in_place(delta);
      break;
    case Workspace::Kept::sparse: delta = w.lu.solve(r); break;
    case Workspace::Kept::none: return false;
  }
  for (int i = 0; i < n; ++i) {
    delta.segment<3>(6 * i) = (w.turns[i] * delta.segment<3>(6 * i)).eval();
    delta.segment<3>(6 * i + 3) = (w.turns[i] * delta.segment<3>(6 * i + 3)).eval();
  }
  w.statistics.solve_seconds += seconds_between(t_start, Clock::now());
  return true;
}

}  // namespace hsrod
