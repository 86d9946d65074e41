// The step's right-hand side (driving, external, bond and contact loads, less
// an iterate's offset loads) and, for a chain, its blocks of R/dt + K + C/dt
// assembled while the bonds are evaluated.
#include "dynamics/overdamped_rod_step_internal.h"

namespace hsrod {

// With non-local drag, hydrodynamic (3n) <- R v for the velocities
// v = dx / dt of the translations in `moved` (6n: dx [m], dphi [rad]).
void OverdampedRodSolver::Workspace::couple_translations(const RodDrag& drag, const Eigen::VectorXd& moved,
                                                         double dt) {
  if (!drag.coupled()) return;
  const int n = static_cast<int>(moved.size()) / 6;
  velocities.resize(3 * n);
  for (int i = 0; i < n; ++i) velocities.segment<3>(3 * i) = moved.segment<3>(6 * i) / dt;
  hydrodynamic.noalias() = drag.coupled_resistance * velocities;
}

// Sphere i's translational drag R dx / dt for `moved` (after
// couple_translations with the same `moved` for non-local drag) [N].
Eigen::Vector3d OverdampedRodSolver::Workspace::translation_drag(const RodDrag& drag, const Eigen::VectorXd& moved,
                                                                 double dt, int i) const {
  return drag.coupled() ? Eigen::Vector3d(hydrodynamic.segment<3>(3 * i))
                        : Eigen::Vector3d(drag.resistance[i] * moved.segment<3>(6 * i) / dt);
}

// A Newton iteration (iterate()): the drag and friction of the offset
// y* - y0 the iterate has already moved from the step's start, which
// assemble takes off the right-hand side (the residual of backward Euler
// at y*).
void OverdampedRodSolver::Workspace::set_origin_load(const OverdampedRod& rod, const RodDrag& drag, double dt) {
  const int n = rod.size();
  const int ndof = 6 * n;
  origin_offset.resize(ndof);
  for (int i = 0; i < n; ++i) {
    origin_offset.segment<3>(6 * i) = rod.positions[i] - (*origin_positions)[i];
    origin_offset.segment<3>(6 * i + 3) =
        rotation_vector((rod.orientations[i] * (*origin_orientations)[i].inverse()).normalized());
  }
  origin_load.setZero(ndof);
  couple_translations(drag, origin_offset, dt);
  for (int i = 0; i < n; ++i) {
    origin_load.segment<3>(6 * i) = translation_drag(drag, origin_offset, dt, i);
    origin_load.segment<3>(6 * i + 3) = drag.rotational_resistance[i] * origin_offset.segment<3>(6 * i + 3) / dt;
  }
  for (const SphereWallContact& c : wall_contacts)
    if (c.rubbing) origin_load.segment<6>(6 * c.sphere) += c.friction * origin_offset.segment<6>(6 * c.sphere) / dt;
  for (const SpherePairContact& c : pair_contacts) {
    if (!c.rubbing) continue;
    const Vector12d loads = pair_friction_loads(c, origin_offset, dt);
    origin_load.segment<6>(6 * c.i) += loads.head<6>();
    origin_load.segment<6>(6 * c.j) += loads.tail<6>();
  }
}

// The right-hand side into `rhs`; with `fused` (a chain on the automatic
// path without pair contacts) also the chain's blocks, each bond's 12 x 12
// Jacobian used where it is made; with `eliminate_in_pass` each block row
// eliminated as soon as it is complete, leaving the solution in `rhs`.
void OverdampedRodSolver::Workspace::assemble(const OverdampedRod& rod, const RodDrag& drag, double dt, bool fused,
                                              bool eliminate_in_pass) {
  const int n = rod.size();
  const bool from_origin = origin_positions != nullptr;
  rhs.resize(6 * n);
  // A(i, i): rolling storage when each row is eliminated in the pass.
  const auto diagonal_of = [&](int i) -> Matrix6d& {
    return eliminate_in_pass ? rolling_diagonal[i & 1] : diagonal[i];
  };
  // Sphere i's blocks (drag) and right-hand side (driving and external loads).
  const auto start_sphere = [&](int i) {
    if (fused) {
      Matrix6d& d = diagonal_of(i);
      d.setZero();
      upper[i].setZero();
      lower[i].setZero();
      d.block<3, 3>(3, 3) += drag.rotational_resistance[i] / dt * Eigen::Matrix3d::Identity();
      if (!drag.coupled()) d.block<3, 3>(0, 0) += drag.resistance[i] / dt;
    }
    rhs.segment<3>(6 * i) = drag.driving_force[i] + rod.external_forces[i];
    rhs.segment<3>(6 * i + 3) = drag.driving_torque[i] + rod.external_torques[i];
    if (from_origin) rhs.segment<6>(6 * i) -= origin_load.segment<6>(6 * i);
  };
  // Bonds: loads at y_n and their Jacobian (K = -d loads / dy).
  BondLoads loads;
  const auto add_chain_bond = [&](const RodBond& b) {
    // A chain bond joins k and k+1 in either order.
    Matrix6d& ij = b.j == b.i + 1 ? upper[b.i] : lower[b.i];
    Matrix6d& ji = b.j == b.i + 1 ? lower[b.j] : upper[b.j];
    beam_bond_loads_and_add_stiffness(rod.positions[b.i], rod.orientations[b.i], rod.positions[b.j],
                                      rod.orientations[b.j], b.rest, b.stiffness, loads, diagonal_of(b.i), ij, ji,
                                      diagonal_of(b.j));
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
      for (; next_wall < wall_contacts.size() && wall_contacts[next_wall].sphere == k; ++next_wall) {
        add_wall_contact_loads(wall_contacts[next_wall], rhs);
        add_wall_contact_block(wall_contacts[next_wall], dt, diagonal_of(k));
      }
      eliminate_banded(k, n, diagonal_of(k));
    }
    back_substitute_banded(n);
    return;
  }
  for (int i = 0; i < n; ++i) start_sphere(i);
  if (fused) {
    for (const RodBond& b : rod.bonds) add_chain_bond(b);
  } else {
    bond_loads.resize(rod.bonds.size());
    bond_jacobians.resize(rod.bonds.size());
    for (std::size_t k = 0; k < rod.bonds.size(); ++k) {
      const RodBond& b = rod.bonds[k];
      beam_bond_loads_and_jacobian(rod.positions[b.i], rod.orientations[b.i], rod.positions[b.j],
                                   rod.orientations[b.j], b.rest, b.stiffness, bond_loads[k], bond_jacobians[k]);
      rhs.segment<6>(6 * b.i) += bond_loads[k].head<6>();
      rhs.segment<6>(6 * b.j) += bond_loads[k].tail<6>();
    }
  }
  for (const SphereWallContact& c : wall_contacts) add_wall_contact_loads(c, rhs);
  for (const SpherePairContact& c : pair_contacts) add_pair_contact_forces(c, rhs);
}

}  // namespace hsrod
