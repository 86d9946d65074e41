// The trial of one (sub)step under the accuracy guard: the quiet half steps
// at a wall, or the full step with Newton iterations on a changed
// wall-contact set, and the Newton error of the step (guarded_step.h).
#include "dynamics/guarded_step_internal.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace hsrod::guard_detail {
namespace {

// A quiet half step moves no sphere more than this share of the contact
// floor: the full step it replaces (~2x the first half step) would pass its
// comparison (limit: the floor) with a margin of > 100.
constexpr double kQuietMove = 2e-3;
// Quiet half steps pass the displacement and strain-change limits within
// this share of them, so the skipped full step (~2x a half step) would too.
constexpr double kQuietShareOfLimits = 0.5;
// ... and stay this far below max_bond_strain [-], room for the full step.
constexpr double kQuietBondStrainMargin = 0.01;
// No sphere within this many half-step moves of touching or leaving a wall:
// the full step (~2x the first half step) keeps the contact set, so it needs
// no Newton iterations on the contacts (whose result it would keep).
constexpr double kSettledContactBand = 8.0;
// Newton updates on the contacts are judged against at least this
// displacement [d]: a rod at rest on a wall would otherwise chase round-off.
constexpr double kContactUpdateFloor = 1e-6;
// A Hertz force below that of this overlap [d] counts as settled: forces
// of near-zero overlaps change by large fractions of nothing.
constexpr double kSettledOverlap = 1e-8;
// Hertz force ~ overlap^1.5: a force change of 1.5 e of itself is an
// overlap change of e.
constexpr double kHertzExponent = 1.5;
// Keeps the contact iterations' error ratio finite for a step that moves
// nothing [m].
constexpr double kNoDisplacement = 1e-300;
// Newton-error differences are judged against at least this displacement
// [d] (a relative test otherwise: lags are systematic and add up).
constexpr double kNewtonErrorFloor = 1e-6;

// Whether a sphere of the rod touches a planform or gap wall (as the step's
// own contact search finds it).
bool touching_wall(const OverdampedRod& rod, const ChannelGeometry& geometry, const WallContactParameters& walls) {
  for (int i = 0; i < rod.size(); ++i)
    if (wall_contact(geometry, walls, rod.positions[i], rod.radii[i]).touching) return true;
  return false;
}

// Whether every sphere at x is further than `band` [m] from touching a wall
// or from leaving one (its centre's distance to each wall minus its radius).
bool contact_set_settled(const std::vector<Eigen::Vector3d>& x, const std::vector<double>& radii,
                         const ChannelGeometry& geometry, const WallContactParameters& walls, double band) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = radii[i];
    if (walls.planform_walls && std::fabs(geometry.signed_distance(x[i].x(), x[i].y()) - r) <= band) return false;
    if (walls.gap_walls && (std::fabs(x[i].z() - walls.gap_bottom - r) <= band ||
                            std::fabs(walls.gap_bottom + geometry.gap_height() - x[i].z() - r) <= band))
      return false;
  }
  return true;
}

// Step doubling's two half steps of h from the substep's start (ws.substep_*)
// with the same drag, into ws.half (results: ws.first_half_result, then
// ws.half_result); ws.halves_moved = the largest move of a sphere in either [m].
void take_half_steps(OverdampedRodSolver& solver, const OverdampedRod& rod, const RodDrag& drag, double h,
                     const ChannelGeometry* geometry, const WallContactParameters* walls, GuardWorkspace& ws) {
  const int n = rod.size();
  ws.half = rod;
  ws.half.positions = ws.substep_positions;
  ws.half.orientations = ws.substep_orientations;
  solver.step(ws.half, drag, 0.5 * h, geometry, walls, ws.first_half_result);
  double moved = 0.0;
  for (int i = 0; i < n; ++i) moved = std::max(moved, (ws.half.positions[i] - ws.substep_positions[i]).norm());
  ws.middle_positions = ws.half.positions;
  solver.step(ws.half, drag, 0.5 * h, geometry, walls, ws.half_result);
  for (int i = 0; i < n; ++i) moved = std::max(moved, (ws.half.positions[i] - ws.middle_positions[i]).norm());
  ws.halves_moved = std::isfinite(moved) ? moved : HUGE_VAL;
}

// Which spheres of the rod touch a wall, and (if asked) their Hertz normal force [N].
void wall_contact_set(const OverdampedRod& rod, const ChannelGeometry& geometry, const WallContactParameters& walls,
                      std::vector<char>& set, std::vector<double>* force = nullptr) {
  const int n = rod.size();
  set.resize(n);
  if (force) force->assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const WallContact c = wall_contact(geometry, walls, rod.positions[i], rod.radii[i]);
    set[i] = c.touching;
    if (force)
      for (int k = 0; k < c.points; ++k) (*force)[i] += c.point[k].normal_force;
  }
}

// Newton iterations where the wall-contact set changed in the step
// (StepGuardLimits::contact_iterations): the converged state is kept.
void iterate_on_wall_contacts(const GuardedCall& c, const RodDrag& drag, SubstepTrial& t) {
  OverdampedRod& rod = c.rod;
  GuardWorkspace& ws = c.ws;
  const StepGuardLimits& limits = c.limits;
  const ChannelGeometry& geometry = *c.geometry;
  const WallContactParameters& walls = *c.walls;
  const int n = rod.size();
  wall_contact_set(rod, geometry, walls, ws.touching_end);
  ws.iterate_positions = rod.positions;
  rod.positions = ws.substep_positions;
  wall_contact_set(rod, geometry, walls, ws.touching_start);
  rod.positions = ws.iterate_positions;
  t.contact_iterated = ws.touching_start != ws.touching_end;
  // Converged: the update is below max_step_error of the step's
  // displacement (or kContactUpdateFloor d), the contact set no longer
  // changes and every Hertz force changed by less than 1.5 max_step_error of
  // itself (an overlap by max_step_error: a displacement test alone would
  // stop a stiff contact at an overlap whose force is many times the loads),
  // or by less than the force of an overlap of kSettledOverlap d.
  const double tolerance_floor = kContactUpdateFloor * t.d;
  const double force_floor = 4.0 / 3.0 * walls.effective_modulus() * std::sqrt(0.5 * t.d) *
                             std::pow(kSettledOverlap * t.d, kHertzExponent);
  if (t.contact_iterated) wall_contact_set(rod, geometry, walls, ws.touching_end, &ws.contact_force_end);
  for (int k = 0; t.contact_iterated && k < limits.contact_iterations; ++k) {
    ws.iterate_positions = rod.positions;
    ws.touching_start.swap(ws.touching_end);  // the previous iterate's set and forces
    ws.contact_force_start.swap(ws.contact_force_end);
    c.solver.iterate(rod, ws.substep_positions, ws.substep_orientations, drag, t.h, c.geometry, c.walls, ws.trial);
    ++c.report.contact_iterations;
    t.contact_update = t.contact_moved = 0.0;
    for (int i = 0; i < n; ++i) {
      t.contact_update = std::max(t.contact_update, (rod.positions[i] - ws.iterate_positions[i]).norm());
      t.contact_moved = std::max(t.contact_moved, (rod.positions[i] - ws.substep_positions[i]).norm());
    }
    if (!std::isfinite(t.contact_update)) break;
    wall_contact_set(rod, geometry, walls, ws.touching_end, &ws.contact_force_end);
    bool forces_settled = ws.touching_start == ws.touching_end;
    for (int i = 0; i < n && forces_settled; ++i)
      forces_settled = std::abs(ws.contact_force_end[i] - ws.contact_force_start[i]) <=
                       kHertzExponent * limits.max_step_error * std::max(ws.contact_force_end[i], force_floor);
    if (forces_settled && t.contact_update <= limits.max_step_error * std::max(t.contact_moved, tolerance_floor)) {
      t.contact_converged = true;
      break;
    }
  }
}

}  // namespace

void try_quiet_half_steps(const GuardedCall& c, const RodDrag& drag, SubstepTrial& t) {
  using NewtonCheck = StepGuardLimits::NewtonCheck;
  const StepGuardLimits& limits = c.limits;
  GuardWorkspace& ws = c.ws;
  if (!(ws.half_steps_first && !limits.adaptive && limits.newton_check != NewtonCheck::kNever && c.velocities_given &&
        c.geometry && c.walls && touching_wall(c.rod, *c.geometry, *c.walls)))
    return;
  take_half_steps(c.solver, c.rod, drag, t.h, c.geometry, c.walls, ws);
  t.halves_ready = true;
  if (ws.halves_moved <= kQuietMove * t.contact_floor) {
    t.a = assess_step(ws.substep_positions, ws.half, drag, t.h, c.geometry, c.walls, limits);
    // ... and no sphere within kSettledContactBand half-step moves of
    // touching or leaving a wall: the full step would keep the contact set.
    const StepAssessment& a = t.a;
    t.quiet = a.problem.empty() && a.displacement <= kQuietShareOfLimits * limits.max_displacement &&
              a.strain_change <= kQuietShareOfLimits * limits.max_strain_change &&
              a.bond_strain <= limits.max_bond_strain - kQuietBondStrainMargin &&
              contact_set_settled(ws.substep_positions, c.rod.radii, *c.geometry, *c.walls,
                                  kSettledContactBand * ws.halves_moved);
  }
}

void keep_quiet_half_steps(const GuardedCall& c, SubstepTrial& t) {
  // The two half steps, without the full step (header). The step's
  // result: contacts at its start (those of the first half step, as
  // the full step's), hydrodynamic forces at the mean velocity.
  OverdampedRod& rod = c.rod;
  GuardWorkspace& ws = c.ws;
  rod.positions = ws.half.positions;
  rod.orientations = ws.half.orientations;
  OverdampedStepResult& r = ws.trial;
  r = ws.first_half_result;
  r.largest_displacement = 0.0;
  for (int i = 0; i < rod.size(); ++i) {
    r.hydrodynamic_forces[i] =
        0.5 * (ws.first_half_result.hydrodynamic_forces[i] + ws.half_result.hydrodynamic_forces[i]);
    r.largest_displacement = std::max(r.largest_displacement, (rod.positions[i] - ws.substep_positions[i]).norm());
  }
  t.a.step_error = 0.0;  // not estimated (bounded far below the limit, header)
  ++ws.quiet_steps;
}

void take_full_step(const GuardedCall& c, const RodDrag& drag, SubstepTrial& t) {
  const StepGuardLimits& limits = c.limits;
  c.solver.step(c.rod, drag, t.h, c.geometry, c.walls, c.ws.trial);
  if (limits.contact_iterations > 0 && c.geometry && c.walls) iterate_on_wall_contacts(c, drag, t);
  StepAssessment& a = t.a;
  a = assess_step(c.ws.substep_positions, c.rod, drag, t.h, c.geometry, c.walls, limits);
  if (!t.contact_iterated) return;
  a.step_error = t.contact_update / std::max(t.contact_moved, kNoDisplacement);
  if (!std::isfinite(a.step_error)) a.step_error = HUGE_VAL;
  if (!t.contact_converged && a.problem.empty()) {
    std::ostringstream m;
    m.precision(3);
    m << "the Newton iterations on the wall contacts did not converge in " << limits.contact_iterations
      << " (last update " << t.contact_update / t.d << " d)";
    a.problem = m.str();
  }
}

void judge_newton_error(const GuardedCall& c, const RodDrag& drag, long level, SubstepTrial& t) {
  using NewtonCheck = StepGuardLimits::NewtonCheck;
  const StepGuardLimits& limits = c.limits;
  OverdampedRod& rod = c.rod;
  GuardWorkspace& ws = c.ws;
  StepAssessment& a = t.a;
  const int n = rod.size();
  const OverdampedStepResult& r = ws.trial;
  const bool suspect = limits.newton_check == NewtonCheck::kAlways ||
                       (limits.newton_check == NewtonCheck::kWhenSuspect &&
                        (a.bond_load_ratio > limits.suspect_bond_load || r.wall_contact || r.self_contact));
  t.quiet_at_wall = t.quiet;
  if (t.quiet || !a.problem.empty() || !suspect || t.contact_iterated) return;
  // Newton error: one more (simplified) Newton iteration with the
  // step's factors. Not across a contact: a sphere touching a wall (or
  // another sphere) at the start or the end of the step makes the
  // Hertz force a near-discontinuity that the step's stiffness (without
  // the new contact) does not describe, and the simplified iteration
  // overshoots (a rod pressed against the pore chatters between the
  // step and its correction); there, and where the solver keeps no
  // factors, step doubling (with the same drag: no trial evaluation).
  bool touching = r.wall_contact || r.self_contact;  // self-contact: the same Hertz impact
  if (!touching && c.geometry && c.walls) {
    for (int i = 0; i < n && !touching; ++i)
      touching = wall_contact(*c.geometry, *c.walls, rod.positions[i], rod.radii[i]).touching;
  }
  const bool corrected = !touching && c.solver.newton_correction(rod, drag, c.geometry, c.walls, ws.correction);
  if (!corrected && !t.halves_ready) take_half_steps(c.solver, rod, drag, t.h, c.geometry, c.walls, ws);
  if (!corrected) t.quiet_at_wall = r.wall_contact && ws.halves_moved <= kQuietMove * t.contact_floor;
  double difference = 0.0, moved = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d change = corrected ? Eigen::Vector3d(ws.correction.segment<3>(6 * i))
                                             : Eigen::Vector3d(ws.half.positions[i] - rod.positions[i]);
    difference = std::max(difference, change.norm());
    moved = std::max(moved, (rod.positions[i] - ws.substep_positions[i]).norm());
  }
  // While a sphere touches a wall the Hertz impact (overlap time scale
  // ~1e-8 s) is a near-discontinuity the step cannot follow, and the error
  // is bounded by the overlap limit instead.
  const double floor = touching ? t.contact_floor : kNewtonErrorFloor * t.d * limits.max_step_error;
  a.step_error = difference / std::max(moved, floor / limits.max_step_error);
  if (!std::isfinite(a.step_error)) a.step_error = HUGE_VAL;
  const bool accept =
      a.step_error <= limits.max_step_error || (at_finest_substep(level, limits) && !limits.refuse_unresolved_error);
  if (!accept) {
    std::ostringstream m;
    m.precision(3);
    m << "the linearised step's Newton error is " << a.step_error << " of its displacement (limit "
      << limits.max_step_error << ")";
    a.problem = m.str();
    return;
  }
  if (a.step_error > limits.max_step_error) {
    ++c.report.unresolved_substeps;
    c.report.unresolved_error = std::max(c.report.unresolved_error, a.step_error);
  }
  // Keep the more accurate state: corrected, or the two half steps.
  if (corrected) {
    c.solver.displace(rod, ws.correction);
  } else {
    rod.positions = ws.half.positions;
    rod.orientations = ws.half.orientations;
  }
}

}  // namespace hsrod::guard_detail
