// The solver's public entry: a step (repeated while wall friction is put at
// its end velocities), its phases in order (contacts, assembly, solve, move),
// and the rod moved by a solution dy.
#include "dynamics/overdamped_rod_step_internal.h"

#include "rod/rod_linearisation.h"

#include <algorithm>

namespace hsrod {

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

OverdampedRodSolver::OverdampedRodSolver() : workspace_(std::make_unique<Workspace>()) {}
OverdampedRodSolver::~OverdampedRodSolver() = default;
OverdampedRodSolver::OverdampedRodSolver(OverdampedRodSolver&&) noexcept = default;
OverdampedRodSolver& OverdampedRodSolver::operator=(OverdampedRodSolver&&) noexcept = default;

// Orientations by their exact rotation; positions with finite bond
// rotations (dynamics/finite_rotation_update.h: the tangent update x + dx
// stretches a turning stiff rod, which then stops turning).
void OverdampedRodSolver::Workspace::displace(OverdampedRod& rod, const Eigen::VectorXd& step) {
  rotation_update.apply(rod, step);
  for (int i = 0; i < rod.size(); ++i)
    rod.orientations[i] =
        (quaternion_from_rotation_vector(step.segment<3>(6 * i + 3)) * rod.orientations[i]).normalized();
}

void OverdampedRodSolver::displace(OverdampedRod& rod, const Eigen::VectorXd& dy) { workspace_->displace(rod, dy); }

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
void OverdampedRodSolver::set_chain_contact_capacitance(bool on) { workspace_->chain_contact_capacitance = on; }

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
  result.friction_mismatch = w.friction_mismatch(rod, dt, *walls);
  for (int repeat = 0; result.friction_mismatch > walls->friction_tolerance && repeat < walls->friction_iterations;
       ++repeat) {
    if (w.kept == Workspace::Kept::none) {
      // Multi-sphere sections' grouped blocks keep no factors: the same
      // step (same secants) once more by the sparse LU, which keeps them.
      w.keep_abouts();
      w.restore_friction_start(rod);
      const LinearSolver method = w.method;
      w.method = LinearSolver::sparse_lu;
      step_once(rod, drag, dt, geometry, walls, result);
      w.method = method;
      if (w.kept == Workspace::Kept::none) break;
    }
    if (!w.set_friction_correction(rod, dt, *walls)) break;
    w.restore_friction_start(rod);
    ++result.friction_repeats;
    ++w.statistics.friction_repeats;
    step_once(rod, drag, dt, geometry, walls, result);
    result.friction_mismatch = w.friction_mismatch(rod, dt, *walls);
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
  if (w.origin_positions) w.set_origin_load(rod, drag, dt);  // a Newton iteration: the iterate's offset loads

  // A chain (the common case, and the rods of a contact cluster, each rod's
  // spheres consecutive) goes to the block-tridiagonal solve; pair contacts
  // (self-contacts, rods touching) enter the band or, off it, the
  // capacitance solve of dynamics/chain_contact_solve.cpp (with non-local
  // drag they go to the general paths instead). Its blocks are assembled while the bonds are
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
  const bool fused = automatic && w.chain && n > 0 &&
                     (w.pair_contacts.empty() || (!drag.coupled() && w.chain_contact_capacitance));
  const bool eliminate_in_pass = fused && !drag.coupled() && w.ordered_chain && w.pair_contacts.empty();
  w.assemble(rod, drag, dt, fused, eliminate_in_pass);
  const Clock::time_point t_bonds = Clock::now();

  // Matrix R / dt + K, factorised by the cheapest method its couplings allow.
  const Eigen::VectorXd& dy = w.solve(rod, drag, dt, fused, eliminate_in_pass);
  w.step_dy = dy.head(ndof);
  w.last_dy = dy.head(ndof);
  w.last_dt = dt;
  w.advance(rod, drag, dt, dy, result);
  const Clock::time_point t_end = Clock::now();
  OverdampedSolverStatistics& stats = w.statistics;
  ++stats.steps;
  stats.sphere_steps += n;
  stats.contact_seconds += seconds_between(t_start, t_contacts);
  stats.bond_seconds += seconds_between(t_contacts, t_bonds);  // with a chain's elimination when fused with it
  stats.solve_seconds += seconds_between(t_bonds, t_end);
}

// Moves the rod by the solution `step` and fills the result: velocities
// over the whole step (from y0 for an iteration), friction and hydrodynamic
// forces at them; keeps the velocities where the next step's wall friction
// is linearised and the displacement newton_correction's drag term takes.
void OverdampedRodSolver::Workspace::advance(OverdampedRod& rod, const RodDrag& drag, double dt,
                                             const Eigen::VectorXd& step, OverdampedStepResult& result) {
  const int n = rod.size();
  const bool from_origin = origin_positions != nullptr;
  result.velocities.resize(n);
  result.angular_velocities.resize(n);
  result.hydrodynamic_forces.resize(n);
  step_start = from_origin ? *origin_positions : rod.positions;
  displace(rod, step);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d dx = rod.positions[i] - step_start[i];
    const Eigen::Vector3d dphi =
        from_origin ? rotation_vector((rod.orientations[i] * (*origin_orientations)[i].inverse()).normalized())
                    : Eigen::Vector3d(step.segment<3>(6 * i + 3));
    last_dy.segment<3>(6 * i) = dx;  // newton_correction's drag term: the displacement taken
    last_dy.segment<3>(6 * i + 3) = dphi;
    result.velocities[i] = dx / dt;
    result.angular_velocities[i] = dphi / dt;
    result.largest_displacement = std::max(result.largest_displacement, dx.norm());
    previous_velocities[i] << result.velocities[i], result.angular_velocities[i];
  }
  for (const SphereWallContact& c : wall_contacts)
    if (c.rubbing)
      result.friction_force += (c.friction * previous_velocities[c.sphere] - c.friction_load).head<3>().norm();
  for (const SpherePairContact& c : pair_contacts) {
    if (!c.rubbing) continue;
    Vector12d u;
    u << previous_velocities[c.i], previous_velocities[c.j];
    result.friction_force += (c.friction * u).head<3>().norm();
  }
  drag.forces(result.velocities, result.hydrodynamic_forces, load_law_scratch);  // at the new velocities
}

}  // namespace hsrod
