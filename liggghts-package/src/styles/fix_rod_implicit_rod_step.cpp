/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit: the step of a rod alone (no other rod within
   contact or hydrodynamic reach): its drag, the implicit step (with the
   accuracy guard's substeps, dynamics/guarded_step.h), the box faces and
   the scatter back to the atoms. See fix_rod_implicit.h.
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "domain.h"
#include "error.h"
#include "fix_hele_shaw_drag.h"
#include "fix_rod_bonds.h"
#include "lmptype.h"
#include "update.h"

#include "hydro/rod_hydrodynamics.h"
#include "rod/rod_bond_set.h"

#include <algorithm>
#include <cstdio>
#include <string>

using namespace LAMMPS_NS;

double FixRodImplicit::seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

hsrod::WallContactParameters FixRodImplicit::wall_contact_parameters() const {
  const hsrod::RodBondSet &bond_set = bonds_->bond_set();
  hsrod::WallContactParameters walls;
  walls.youngs_modulus = bond_set.youngs_modulus;
  walls.poisson_ratio = bond_set.poisson_ratio;
  walls.gap_bottom = drag_->hydrodynamics().gap_bottom();
  walls.friction_coefficient = wall_friction_;
  walls.slip_velocity = slip_velocity_;
  walls.friction_iterations = friction_iterations_;
  walls.friction_tolerance = friction_tolerance_;
  walls.rod_contact = rod_contact_;
  walls.rod_friction_coefficient = rod_contact_ ? rod_friction_ : 0.0;
  return walls;
}

// The rod's drag at the step's start, evaluated into its scratch.
void FixRodImplicit::evaluate_rod_drag(int molecule, RodScratch &scratch) {
  const Clock::time_point drag_start = Clock::now();
  if (apart()) {
    apart_loads({molecule}, {scratch.geometry}, scratch.drag, true);
    cost_.drag_seconds += seconds_since(drag_start);
    cost_.sphere_steps += scratch.geometry.size();
    return;
  }
  try {
    drag_->hydrodynamics().loads(scratch.geometry, scratch.drag);
  } catch (const std::exception &e) {
    char msg[768];
    std::snprintf(msg, sizeof(msg), "fix rod/implicit: rod %d at step " BIGINT_FORMAT ": drag model: %s", molecule,
                  update->ntimestep, e.what());
    error->all(FLERR, msg);
  }
  cost_.drag_seconds += seconds_since(drag_start);
  cost_.sphere_steps += scratch.geometry.size();
}

bool FixRodImplicit::step_rod_alone(int molecule, const std::vector<GatheredSphere> &spheres,
                                    const hsrod::WallContactParameters &walls, StepTotals &totals) {
  hsrod::RodHydrodynamics &hydro = drag_->hydrodynamics();
  const int n = static_cast<int>(spheres.size());
  // The rod's structures live from step to step (no allocation per step).
  RodWork &work = work_by_rod_[molecule];
  RodScratch &scratch = work.scratch;
  hsrod::OverdampedRod &rod = scratch.rod;
  update_overdamped_rod(spheres, bonds_->bond_set(), rod, scratch.stiffnesses);
  // Wall friction is linearised about the velocities of the last step
  // (this fix set them: v = dx/dt).
  rod.velocities.resize(n);
  rod.angular_velocities.resize(n);
  for (int k = 0; k < n; k++) {
    rod.velocities[k] = spheres[k].velocity;
    rod.angular_velocities[k] = spheres[k].angular_velocity;
  }
  update_rod_geometry(hydro, molecule, spheres, scratch.geometry);
  evaluate_rod_drag(molecule, scratch);
  scratch.before = rod.positions;
  // Self-contact (a folding rod) is always on; scene walls with `walls yes`.
  const hsrod::ChannelGeometry *scene_walls = walls_ ? &hydro.geometry() : nullptr;
  hsrod::OverdampedRodSolver &solver = work.solver;
  solver.set_chain_contact_capacitance(contact_capacitance_);
  const hsrod::OverdampedStepResult &result = guard_ ? scratch.report.result : scratch.result;
  if (guard_) {
    // Accuracy guard: substeps (drag re-evaluated at each) or a refusal.
    RodScratch *at = &scratch;  // two pointers: std::function keeps them without allocating
    auto drag_at = [this, at, molecule](const hsrod::OverdampedRod &moved, hsrod::RodDrag &out) {
      const Clock::time_point substep_drag_start = Clock::now();
      at->substep_geometry = at->geometry;
      at->substep_geometry.positions = moved.positions;
      if (apart()) apart_loads({molecule}, {at->substep_geometry}, out, false);
      else drag_->hydrodynamics().loads(at->substep_geometry, out);
      cost_.drag_seconds += seconds_since(substep_drag_start);
    };
    try {
      hsrod::guarded_rod_step(solver, rod, scratch.drag, drag_at, update->dt, scene_walls, &walls, limits_,
                              work.guard, scratch.report);
      account_guard_report("rod " + std::to_string(molecule), scratch.report, totals.substeps);
    } catch (const std::exception &e) {
      char msg[768];
      std::snprintf(msg, sizeof(msg), "fix rod/implicit: rod %d at step " BIGINT_FORMAT ": %s", molecule,
                    update->ntimestep, e.what());
      error->all(FLERR, msg);
    }
  } else {
    solver.step(rod, scratch.drag, update->dt, scene_walls, &walls, scratch.result);
  }
  stepped_rods_.push_back(molecule);  // its bond state (strain, energy) on demand
  // A step that would carry a sphere centre out of the box (the outlet,
  // or any non-periodic face) is taken only up to the face: the rod is
  // held there, whole, instead of LIGGGHTS dropping its spheres one by one.
  const int face = leaving_face(rod.positions, domain->boxlo, domain->boxhi, domain->periodicity);
  if (face >= 0) {
    held_rods_.insert(molecule);
    report_held_at_face("rod " + std::to_string(molecule), face);
    hold_rod_at_face(spheres, scratch.before, rod.positions);
    return false;
  }
  totals.largest = std::max(totals.largest, result.largest_displacement / scratch.geometry.sphere_diameter);
  totals.wall_force += result.wall_force;
  if (result.wall_contact) totals.contacts++;
  RodContactRecord &record = contacts_by_rod_[molecule];
  record.touching = result.wall_contact;
  record.ever_touched = record.ever_touched || result.wall_contact;
  record.wall_force = result.wall_force;
  record.largest_wall_force = std::max(record.largest_wall_force, result.wall_force);
  return true;  // scattered by step_all once no other rod met it within the step
}
