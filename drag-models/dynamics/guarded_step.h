// Accuracy guard around the linearly implicit rod step.
//
// OverdampedRodSolver::step (overdamped_rod_step.h) is one Newton step of
// backward Euler: stable for any dt, but it loses accuracy without notice
// when a step is large and it can carry a sphere through a wall in one
// step. (A turning stiff rod does not lag: the step's finite-rotation
// update, dynamics/finite_rotation_update.h, turns its bonds without
// stretching them.) The guard takes the step on a copy of the rod, checks
//   - the largest sphere displacement (in diameters),
//   - the largest change of any bond's axial strain, and the largest
//     absolute axial strain (a rod over-strained by steps that each stretch
//     it a little: the change limit alone lets the strain accumulate),
//   - the Newton (linearisation) error of the step: the nonlinear bond and
//     contact response the single linearised step missed, estimated by one
//     more (simplified) Newton iteration with the step's own factors
//     (OverdampedRodSolver::newton_correction: a residual evaluation and a
//     back substitution, no new factorisation, co-rotated with the spheres'
//     rotation in the step); the corrected state is the one kept. Where the solver keeps no factors (multi-sphere sections)
//     by step doubling (one step of h against two of h/2, same drag),
//   - that no sphere centre ends in, or passes through, a wall, and no new
//     wall overlap exceeds max_overlap radii,
//   - that the rod's speed does not grow by more than max_growth per
//     (sub)step (a rod leaving an unstable state; StepGuardLimits::max_growth).
// (The force residual of backward Euler at the new state is reported too,
// but is no usable criterion for stiff rods: any strain the linearisation
// leaves, times k_n L0, dwarfs the drag at a practical step although the
// next step relaxes it.)
// and accepts it only when all are within the limits; otherwise the step is
// retried as substeps of half the size (the drag re-evaluated at each
// substep's start through a callback), down to dt / max_substeps. A step
// still failing then is refused with StepRefused naming the figures.
// Quiet steps at a wall (a rod pressed against the pore, e.g. clogged:
// most of a clogging run's steps): a (sub)step that starts with a sphere
// touching a wall always goes to step doubling, which keeps the two half
// steps and uses the full step only for the comparison. Where the last
// accepted (sub)step was such a step and moved no sphere more than
// 2e-3 of the contact floor (0.5 max_overlap d) per half step, the half
// steps are taken first; if they are quiet again (the same bound) and pass
// the checks above with a margin (half the displacement and strain-change
// limits, max_bond_strain - 0.01) and no sphere is within 8 half-step moves
// of touching or leaving a wall (the full step keeps the contact set, so no
// Newton iterations on the contacts), they are accepted without the full step:
// the full step of the same linearised system moves no sphere more than
// ~2x the first half step, so its comparison (limit: the floor) and its own
// checks would pass with a margin of > 100, and the accepted state is the
// same two half steps, bit for bit. Otherwise the full step is taken and
// judged as above. (Used when the caller gives the rod's velocities and
// without `adaptive`.) 2 solves per such step instead of 3.
// The drag is evaluated only at accepted states (no trial evaluations), so
// a model that keeps state (level 4's windows) advances along the accepted
// path only. This wraps the solver; it does not change it.
#pragma once

#include "dynamics/overdamped_rod_step.h"

#include <functional>
#include <stdexcept>
#include <string>

namespace hsrod {

struct StepGuardLimits {
  double max_displacement = 0.25;   // largest sphere displacement per (sub)step [sphere diameters]
  double max_strain_change = 0.01;  // largest change of a bond's axial strain per (sub)step [-]
  // Largest |axial strain| of any bond after a (sub)step [-]: beyond it the
  // beam bonds (small-strain elasticity) and the reduced drag no longer
  // describe the rod (the change limit alone lets steps that each stretch
  // it a little add up to any strain).
  double max_bond_strain = 0.5;
  // Newton (linearisation) error of a (sub)step: the largest displacement of
  // the Newton correction (or of step doubling, see above), relative
  // to the largest displacement of the step; differences below 1e-8 d (below
  // max_overlap radii while a sphere touches a wall) always pass [-].
  double max_step_error = 0.01;
  // The estimate costs a bond evaluation and a back substitution (step
  // doubling: two more solves), so by default it runs only where
  // the linearisation is suspect: a bond's load change k_n L0 |d strain|
  // above `suspect_bond_load` of the largest drag force of the step
  // |R dx / dt| (a stiff rod whose bonds carry more than the drag), or a
  // wall contact during the step.
  enum class NewtonCheck { kAlways, kWhenSuspect, kNever };
  NewtonCheck newton_check = NewtonCheck::kWhenSuspect;
  double suspect_bond_load = 0.05;  // [-]
  double max_overlap = 0.1;         // largest new overlap with a wall [sphere radii]
  // Newton iterations on the wall-contact set (against the "pop" of a rod
  // off a pore wall). The linearised step knows only the contacts touching
  // at its start, so a sphere it carries onto a wall ends inside it,
  // unresisted, by up to the step's displacement (and a contact it releases
  // pulls as a linear spring).
  // The stored Hertz force of that overlap grows as E delta^(3/2): for
  // E = 1.5e12 Pa a 100 nm overlap of a 3 um sphere is 0.08 N, 5e4 times the
  // drag; released in the next step it flings the rod ~1 um per step at any
  // substep (a pivoting stiff rod ratchets itself deeper at each switch).
  // Where the set of spheres touching a wall differs between the (sub)step's
  // start and its end, the step is re-linearised about its end state
  // (OverdampedRodSolver::iterate: full Newton iterations of backward Euler,
  // contacts found at the iterate) until the update is below max_step_error
  // of the step's displacement (or 1e-6 d), the contact set is unchanged
  // and each Hertz force has settled to 1.5 max_step_error; not converged in this many
  // iterations: the substep is rejected (halved). 0: off.
  int contact_iterations = 30;
  int max_substeps = 1024;          // finest substep dt / max_substeps (a power of 2) [-]
  // At the finest substep a step failing only the Newton-error check is
  // refused (true) or accepted as its two half steps and counted in
  // GuardedStepReport::unresolved_substeps for the caller to report (false).
  bool refuse_unresolved_error = true;
  bool check_walls = true;          // refuse a sphere centre in or through a wall
  // Fill GuardedStepReport::largest_bond_strain and bond_energy (a pass over
  // every bond after the step); a caller that reports them only on demand
  // evaluates bond_strain_and_energy itself when asked.
  bool report_bond_state = true;
  // Accuracy-controlled substeps (the steps go where the motion is;
  // off by default: one step of dt where the checks above pass, fixed and
  // bit-reproducible). With `adaptive`, a (sub)step of h is also rejected
  // when its local truncation error, estimated from the change of the
  // sphere velocities (backward Euler: h^2/2 |x''|, x'' from the mean
  // velocities of this and the previous (sub)step, the latter from
  // OverdampedRod::velocities over the previous dt at a step's first
  // substep), exceeds `displacement_tolerance` of the step's displacement
  // (while a sphere touches a wall, of at least 0.5 max_overlap d /
  // max_step_error, as the Newton check). The substep then shrinks by the
  // factor the error asks for (a power of 2, h^2 scaling), so a large dt
  // is taken whole where the motion is smooth and cut where it changes.
  // Only solves: no extra drag evaluation, no state kept between steps
  // (restarts and ranks stay identical).
  bool adaptive = false;
  double displacement_tolerance = 1e-2;  // local error of a (sub)step / its displacement [-]
  // Growing motion (a rod leaving an unstable state: pinned across a pore,
  // then sliding off a cylinder). The linearised step sees a wall contact's
  // normal as fixed, so the growth that the normal's turn feeds (and that of
  // any mode the step's matrix misses) enters once per (sub)step, as
  // 1 + lambda h instead of exp(lambda h): a large step leaves the unstable
  // state late. The growth rate lambda of the rod's speed (root sum of
  // squares over its spheres) is estimated from this and the previous
  // (sub)step's mean velocities; a (sub)step with lambda h above
  // `max_growth` is rejected and retried with the substep it asks for.
  // Motion below 1e-6 d per (sub)step (round-off of a rod at rest) is not
  // judged. 0: off.
  double max_growth = 0.1;  // [-]
};

// Why a (sub)step was or would be rejected; empty when accepted.
struct StepAssessment {
  double displacement = 0.0;   // largest |dx| / d [-]
  double strain_change = 0.0;  // largest |d strain| [-]
  double residual = 0.0;       // backward-Euler force residual / load scale (reported only) [-]
  double step_error = 0.0;     // Newton-correction (step-doubling) error / step displacement [-] (0 if not checked)
  double bond_strain = 0.0;    // largest |axial strain| after the step [-]
  double truncation_error = 0.0;  // adaptive: local truncation error / step displacement [-] (0 if not checked)
  double growth = 0.0;         // growth rate of the rod's speed times the (sub)step, lambda h [-] (0 if not judged)
  double bond_load_ratio = 0.0;  // max k_n L0 |d strain| / max |R dx / dt| [-]
  int crossing_sphere = -1;    // a sphere whose centre ended in or crossed a wall, or -1
  int interpenetrating_sphere = -1;  // a sphere pressed > max_overlap radii deeper into another rod's, or -1
  std::string problem;         // "" if within the limits
};

struct GuardedStepReport {
  OverdampedStepResult result;  // over the whole dt: mean velocities, dt-weighted forces
  int substeps = 1;             // substeps taken
  int unresolved_substeps = 0;  // finest substeps accepted above max_step_error (refuse_unresolved_error false)
  int rejected_trials = 0;      // (sub)steps solved and rejected (each one solve)
  int contact_iterations = 30;   // Newton iterations on the wall-contact set (each one solve)
  double unresolved_error = 0.0;  // their largest step error [-]
  StepAssessment worst;         // largest figures over the accepted substeps
  double largest_bond_strain = 0.0;  // max |axial strain| after the step [-]
  double bond_energy = 0.0;          // elastic energy of all bonds after the step [J]
};

class StepRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Drag of `rod` at its current positions (called at each substep start).
using RodDragEvaluator = std::function<void(const OverdampedRod& rod, RodDrag& drag)>;

// Scratch of guarded_rod_step, kept between steps by a caller that steps
// the same rod repeatedly (no allocation per step once sized).
struct GuardWorkspace {
  std::vector<Eigen::Vector3d> start_positions, substep_positions;        // [m]
  std::vector<Eigen::Quaterniond> start_orientations, substep_orientations;
  OverdampedStepResult trial;
  RodDrag substep_drag;       // drag re-evaluated at a substep start
  Eigen::VectorXd correction;  // Newton correction (dx [m], dphi [rad])
  OverdampedRod half;          // step doubling (where no factors are kept)
  OverdampedStepResult half_result, first_half_result;
  // A cost hint, not state: the last accepted (sub)step of this rod was a
  // quiet one at a wall (see guarded_rod_step: "quiet steps at a wall"), so
  // the next one takes its half steps first. Either order gives the same
  // accepted state; a fresh workspace (a restart) only pays one more solve.
  bool half_steps_first = false;
  std::vector<Eigen::Vector3d> middle_positions;  // after the first half step [m]
  double halves_moved = 0.0;    // largest move of a sphere in either half step [m]
  long quiet_steps = 0;         // (sub)steps accepted as quiet half steps, without the full step (a count)
  std::vector<Eigen::Vector3d> previous_velocities;  // adaptive or max_growth: mean velocities of the last substep [m/s]
  std::vector<char> touching_start, touching_end;    // contact iterations: spheres on a wall
  std::vector<Eigen::Vector3d> iterate_positions;    // the last Newton iterate [m]
  std::vector<double> contact_force_start, contact_force_end;  // Hertz normal force per sphere [N]
};

// Advances `rod` by dt [s] under the guard. `drag` is the drag at the
// current positions; `drag_at` re-evaluates it for substeps (may be empty:
// the drag is then kept for all substeps). geometry / walls as in
// OverdampedRodSolver::step. Throws StepRefused (rod unchanged) when even
// dt / max_substeps fails; std::invalid_argument for a dt that is not
// finite and positive.
GuardedStepReport guarded_rod_step(OverdampedRodSolver& solver, OverdampedRod& rod, const RodDrag& drag,
                                   const RodDragEvaluator& drag_at, double dt, const ChannelGeometry* geometry,
                                   const WallContactParameters* walls, const StepGuardLimits& limits = {});
// The same with the caller's scratch (one per rod).
GuardedStepReport guarded_rod_step(OverdampedRodSolver& solver, OverdampedRod& rod, const RodDrag& drag,
                                   const RodDragEvaluator& drag_at, double dt, const ChannelGeometry* geometry,
                                   const WallContactParameters* walls, const StepGuardLimits& limits,
                                   GuardWorkspace& workspace);

// The same writing into `report` (its vectors keep their memory between steps).
void guarded_rod_step(OverdampedRodSolver& solver, OverdampedRod& rod, const RodDrag& drag,
                      const RodDragEvaluator& drag_at, double dt, const ChannelGeometry* geometry,
                      const WallContactParameters* walls, const StepGuardLimits& limits, GuardWorkspace& workspace,
                      GuardedStepReport& report);

// The checks of one step from `before` to `after` (result of solver.step
// with `drag` and dt), without taking it.
StepAssessment assess_rod_step(const OverdampedRod& before, const OverdampedRod& after,
                               const OverdampedStepResult& result, const RodDrag& drag, double dt,
                               const ChannelGeometry* geometry, const WallContactParameters* walls,
                               const StepGuardLimits& limits);

// Largest |axial strain| and total elastic energy [J] of the rod's bonds.
std::pair<double, double> bond_strain_and_energy(const OverdampedRod& rod);

}  // namespace hsrod
