// The simplified-Newton correction of the last step: the backward-Euler
// residual at the new state, solved with the step's kept factors (an error
// estimate without a new factorisation).
#include "dynamics/overdamped_rod_step_internal.h"

namespace hsrod {

namespace {

Eigen::Matrix<double, 12, 1> bond_loads(const SphereState& si, const SphereState& sj, const RodBond& b) {
  const auto out = evaluate_beam_bond(si, sj, b.rest, b.stiffness, BeamBondDamping{});
  Eigen::Matrix<double, 12, 1> loads;
  loads << -out.force_on_j, out.torque_on_i, out.force_on_j, out.torque_on_j;
  return loads;
}

}  // namespace

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
    const Vector12d loads = pair_friction_loads(c, dy, dt);
    r.segment<6>(6 * c.i) -= loads.head<6>();
    r.segment<6>(6 * c.j) -= loads.tail<6>();
  }
  w.couple_translations(drag, dy, dt);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d resisted = w.translation_drag(drag, dy, dt, i);
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
  for (const SpherePairContact& c : w.pair_contacts) add_pair_contact_forces(c, r);
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
  delta = r;
  w.solve_kept(delta);  // factors are kept: checked above
  for (int i = 0; i < n; ++i) {
    delta.segment<3>(6 * i) = (w.turns[i] * delta.segment<3>(6 * i)).eval();
    delta.segment<3>(6 * i + 3) = (w.turns[i] * delta.segment<3>(6 * i + 3)).eval();
  }
  w.statistics.solve_seconds += seconds_between(t_start, Clock::now());
  return true;
}

}  // namespace hsrod
