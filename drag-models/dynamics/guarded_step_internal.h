// Private to the accuracy guard (guarded_step*.cpp): what the phases of one
// guarded_rod_step call share, and the phases its substep loop runs in turn.
#pragma once

#include "dynamics/guarded_step.h"

#include <string>
#include <vector>

namespace hsrod::guard_detail {

// The arguments of one guarded_rod_step call.
struct GuardedCall {
  OverdampedRodSolver& solver;
  OverdampedRod& rod;
  const RodDragEvaluator& drag_at;
  double dt;  // the whole step [s]
  const ChannelGeometry* geometry;
  const WallContactParameters* walls;
  const StepGuardLimits& limits;
  GuardWorkspace& ws;
  GuardedStepReport& report;
  bool velocities_given;  // rod.velocities holds the rod's velocities before the step
};

// How far the step has come through dt, and the substep it takes next.
struct SubstepSchedule {
  const RodDrag* drag;  // the drag at the current substep's start
  double done = 0.0;    // time advanced [s]
  long level = 1;       // current substep = dt / level
  double previous_h;    // adaptive or max_growth: the last accepted substep [s]
};

// One (sub)step's trial, as its phases leave it.
struct SubstepTrial {
  double h = 0.0;              // [s]
  double d = 0.0;              // sphere diameter [m]
  double contact_floor = 0.0;  // the doubling test's limit while touching: max_overlap radii [m]
  bool halves_ready = false;   // ws.half holds the two half steps of h
  bool quiet = false;          // taken as its two half steps, without the full step
  bool quiet_at_wall = false;  // this (sub)step, if accepted, was quiet at a wall
  // Newton iterations on the wall contacts: run, converged, the last
  // update and the step's displacement then [m].
  bool contact_iterated = false, contact_converged = false;
  double contact_update = 0.0, contact_moved = 0.0;
  long shrink = 2;  // factor of the next substep level after a rejection
  StepAssessment a;
};

// The substep is dt / max_substeps or finer: no retry is left.
inline bool at_finest_substep(long level, const StepGuardLimits& limits) { return level * 2 > limits.max_substeps; }

// v as an ostream with precision 3 prints it (%.3g).
std::string g3(double v);

// The checks of a step from x0 to the rod's state `after` without the
// residual (which is reported only): displacement, strain change and
// absolute strain, bond load against drag load, walls.
StepAssessment assess_step(const std::vector<Eigen::Vector3d>& x0, const OverdampedRod& after, const RodDrag& drag,
                           double dt, const ChannelGeometry* geometry, const WallContactParameters* walls,
                           const StepGuardLimits& limits);

// The trial (guarded_step_trial.cpp), in this order: the quiet half steps
// at a wall where the last (sub)step was quiet there; if they are not
// quiet, the full step (with Newton iterations on a changed contact set);
// then its Newton error (may keep a more accurate state in the rod).
void try_quiet_half_steps(const GuardedCall& c, const RodDrag& drag, SubstepTrial& t);
void keep_quiet_half_steps(const GuardedCall& c, SubstepTrial& t);
void take_full_step(const GuardedCall& c, const RodDrag& drag, SubstepTrial& t);
void judge_newton_error(const GuardedCall& c, const RodDrag& drag, long level, SubstepTrial& t);

// Substep control (guarded_step_control.cpp): each judge leaves t.a.problem
// empty or names why the (sub)step is rejected, and t.shrink the factor of
// the retry's smaller substep.
void judge_truncation_error(const GuardedCall& c, const SubstepSchedule& s, SubstepTrial& t);
void judge_growth(const GuardedCall& c, const SubstepSchedule& s, SubstepTrial& t);
void judge_wall_friction(const GuardedCall& c, SubstepTrial& t);
// A rejection at the finest substep: throws StepRefused naming the figures
// and, where it is the rod's state and not the step, what to change.
[[noreturn]] void refuse_step(const GuardedCall& c, const SubstepSchedule& s, const SubstepTrial& t);

}  // namespace hsrod::guard_detail
