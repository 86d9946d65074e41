// guarded_rod_step: the entry, the sequence of each substep's phases
// (trial, judges, acceptance or retry) and the step's totals. The phases
// are in guarded_step_trial.cpp and guarded_step_control.cpp.
#include "dynamics/guarded_step.h"

#include "dynamics/guarded_step_internal.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsrod {

using namespace guard_detail;

namespace {

// dt counts as done within this fraction of it: the substeps' sum misses dt
// by rounding, and a sliver of a last substep would cost a solve.
constexpr double kEndOfStep = 1e-12;
// Adaptive: the first substep moves a sphere at the incoming speed by at
// most this share of max_displacement, room for the speed to change.
constexpr double kStartDisplacementShare = 0.8;

// A fresh report in the caller's memory.
void reset_report(GuardedStepReport& report, int n) {
  report.substeps = report.unresolved_substeps = report.rejected_trials = report.contact_iterations = 0;
  report.unresolved_error = report.largest_bond_strain = report.bond_energy = 0.0;
  report.worst = StepAssessment();
  OverdampedStepResult& total = report.result;
  total.largest_displacement = total.wall_force = total.friction_force = 0.0;
  total.wall_contact = total.self_contact = total.rod_contact = false;
  total.rod_contact_force = 0.0;
  total.velocities.assign(n, Eigen::Vector3d::Zero());
  total.angular_velocities.assign(n, Eigen::Vector3d::Zero());
  total.hydrodynamic_forces.assign(n, Eigen::Vector3d::Zero());
  total.sphere_wall_force.assign(n, 0.0);
}

// The first substep level: 1, or with `adaptive` the substep the incoming
// velocities ask for (the displacement limit), not dt: no state is kept
// between steps.
long first_substep_level(const OverdampedRod& rod, double dt, const StepGuardLimits& limits) {
  const int n = rod.size();
  long level = 1;
  if (limits.adaptive && static_cast<int>(rod.velocities.size()) == n) {
    double speed = 0.0;
    for (int i = 0; i < n; ++i) speed = std::max(speed, rod.velocities[i].norm() / (2.0 * rod.radii[i]));
    while (!at_finest_substep(level, limits) &&
           speed * dt / static_cast<double>(level) > kStartDisplacementShare * limits.max_displacement)
      level *= 2;
  }
  return level;
}

void restore(OverdampedRod& rod, const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Quaterniond>& q) {
  rod.positions = x;
  rod.orientations = q;
}

// The next substep of h from the rod's state, kept in ws.substep_* to go back to.
SubstepTrial start_substep(const GuardedCall& c, const SubstepSchedule& s) {
  SubstepTrial t;
  t.h = std::min(c.dt / static_cast<double>(s.level), c.dt - s.done);
  c.ws.substep_positions = c.rod.positions;
  c.ws.substep_orientations = c.rod.orientations;
  t.d = 2.0 * c.rod.radii[0];
  t.contact_floor = 0.5 * c.limits.max_overlap * t.d;
  c.ws.first_half_result.friction_mismatch = c.ws.half_result.friction_mismatch = 0.0;
  return t;
}

// A rejected (sub)step: refused at the finest substep, else retried from
// its start at the substep its judges asked for.
void reject_substep(const GuardedCall& c, SubstepSchedule& s, const SubstepTrial& t) {
  ++c.report.rejected_trials;
  if (at_finest_substep(s.level, c.limits)) refuse_step(c, s, t);
  restore(c.rod, c.ws.substep_positions, c.ws.substep_orientations);
  s.level *= t.shrink;
}

// An accepted (sub)step: its share of the step's totals and worst figures,
// then the drag at the next substep's start.
void accept_substep(const GuardedCall& c, SubstepSchedule& s, const SubstepTrial& t) {
  OverdampedRod& rod = c.rod;
  GuardWorkspace& ws = c.ws;
  GuardedStepReport& report = c.report;
  const int n = rod.size();
  const double h = t.h, dt = c.dt;
  const StepAssessment& a = t.a;
  const OverdampedStepResult& r = ws.trial;
  if (c.limits.adaptive || c.limits.max_growth > 0.0) {
    ws.previous_velocities.resize(n);
    for (int i = 0; i < n; ++i) ws.previous_velocities[i] = (rod.positions[i] - ws.substep_positions[i]) / h;
    s.previous_h = h;
  }
  OverdampedStepResult& total = report.result;
  for (int i = 0; i < n; ++i) {
    total.angular_velocities[i] +=
        rotation_vector((rod.orientations[i] * ws.substep_orientations[i].inverse()).normalized()) / dt;
    total.hydrodynamic_forces[i] += r.hydrodynamic_forces[i] * (h / dt);
    total.sphere_wall_force[i] += r.sphere_wall_force[i] * (h / dt);
  }
  total.wall_contact = total.wall_contact || r.wall_contact;
  total.self_contact = total.self_contact || r.self_contact;
  total.rod_contact = total.rod_contact || r.rod_contact;
  total.rod_contact_force += r.rod_contact_force * (h / dt);
  total.wall_force += r.wall_force * (h / dt);
  total.largest_displacement = std::max(total.largest_displacement, r.largest_displacement);
  report.worst.displacement = std::max(report.worst.displacement, a.displacement);
  report.worst.strain_change = std::max(report.worst.strain_change, a.strain_change);
  report.worst.bond_strain = std::max(report.worst.bond_strain, a.bond_strain);
  report.worst.step_error = std::max(report.worst.step_error, a.step_error);
  report.worst.truncation_error = std::max(report.worst.truncation_error, a.truncation_error);
  report.worst.bond_load_ratio = std::max(report.worst.bond_load_ratio, a.bond_load_ratio);
  s.done += h;
  ++report.substeps;
  if (s.done < dt * (1.0 - kEndOfStep) && c.drag_at) {
    c.drag_at(rod, ws.substep_drag);
    s.drag = &ws.substep_drag;
  }
}

// The step's mean velocities, its displacement and the bonds' state after it.
void finish_step(const GuardedCall& c) {
  const OverdampedRod& rod = c.rod;
  const GuardWorkspace& ws = c.ws;
  OverdampedStepResult& total = c.report.result;
  const int n = rod.size();
  for (int i = 0; i < n; ++i) total.velocities[i] = (rod.positions[i] - ws.start_positions[i]) / c.dt;
  if (c.report.substeps > 1) {
    // Displacement over the whole step, as the unguarded step reports it.
    total.largest_displacement = 0.0;
    for (int i = 0; i < n; ++i)
      total.largest_displacement =
          std::max(total.largest_displacement, (rod.positions[i] - ws.start_positions[i]).norm());
  }
  if (c.limits.report_bond_state) {
    const auto [strain, energy] = bond_strain_and_energy(rod);
    c.report.largest_bond_strain = strain;
    c.report.bond_energy = energy;
  }
}

}  // namespace

GuardedStepReport guarded_rod_step(OverdampedRodSolver& solver, OverdampedRod& rod, const RodDrag& drag,
                                   const RodDragEvaluator& drag_at, double dt, const ChannelGeometry* geometry,
                                   const WallContactParameters* walls, const StepGuardLimits& limits) {
  GuardWorkspace workspace;
  return guarded_rod_step(solver, rod, drag, drag_at, dt, geometry, walls, limits, workspace);
}

GuardedStepReport guarded_rod_step(OverdampedRodSolver& solver, OverdampedRod& rod, const RodDrag& drag,
                                   const RodDragEvaluator& drag_at, double dt, const ChannelGeometry* geometry,
                                   const WallContactParameters* walls, const StepGuardLimits& limits,
                                   GuardWorkspace& ws) {
  GuardedStepReport report;
  guarded_rod_step(solver, rod, drag, drag_at, dt, geometry, walls, limits, ws, report);
  return report;
}

void guarded_rod_step(OverdampedRodSolver& solver, OverdampedRod& rod, const RodDrag& drag,
                      const RodDragEvaluator& drag_at, double dt, const ChannelGeometry* geometry,
                      const WallContactParameters* walls, const StepGuardLimits& limits, GuardWorkspace& ws,
                      GuardedStepReport& report) {
  if (!(std::isfinite(dt) && dt > 0.0)) {
    std::ostringstream m;
    m << "implicit rod step: timestep " << dt << " s must be finite and > 0";
    throw std::invalid_argument(m.str());
  }
  if (limits.max_substeps < 1) throw std::invalid_argument("StepGuardLimits: max_substeps must be >= 1");
  const int n = rod.size();
  reset_report(report, n);
  // The rod itself is stepped; (x0, q0) of the whole step and of the
  // current substep are kept to go back to.
  ws.start_positions = rod.positions;
  ws.start_orientations = rod.orientations;
  const GuardedCall c{solver, rod, drag_at, dt, geometry, walls, limits, ws, report,
                      static_cast<int>(rod.velocities.size()) == n};
  SubstepSchedule s{&drag, 0.0, first_substep_level(rod, dt, limits), dt};
  try {
    while (s.done < dt * (1.0 - kEndOfStep)) {
      SubstepTrial t = start_substep(c, s);
      // Quiet steps at a wall (header): the half steps first.
      try_quiet_half_steps(c, *s.drag, t);
      if (t.quiet)
        keep_quiet_half_steps(c, t);
      else
        take_full_step(c, *s.drag, t);
      judge_newton_error(c, *s.drag, s.level, t);
      judge_truncation_error(c, s, t);
      judge_growth(c, s, t);
      judge_wall_friction(c, t);
      // The next (sub)step of this rod takes its half steps first when this
      // one was accepted quiet at a wall.
      ws.half_steps_first = t.a.problem.empty() && t.quiet_at_wall;
      if (t.a.problem.empty())
        accept_substep(c, s, t);
      else
        reject_substep(c, s, t);
    }
  } catch (...) {
    restore(rod, ws.start_positions, ws.start_orientations);  // the rod unchanged
    throw;
  }
  finish_step(c);
}

}  // namespace hsrod
