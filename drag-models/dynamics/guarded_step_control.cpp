// Substep control of the accuracy guard: the judges that reject a (sub)step
// and choose the smaller substep of the retry (local truncation error,
// growing motion, unconverged wall friction), and the refusal at the finest.
#include "common/math_constants.h"
#include "dynamics/guarded_step_internal.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace hsrod::guard_detail {
namespace {

// The substep a rejection asks for is aimed this far inside the limit (h^2
// scaling for the truncation error, h for growth): a retry sized to exactly
// the estimate fails again on the estimate's scatter.
constexpr double kShrinkSafety = 0.8;
// At most this factor finer per rejection: an estimate blown up by one
// impact costs another retry, not a needlessly fine rest of the step.
constexpr long kMaxShrink = 64;
// Away from walls, the truncation error is judged against at least this
// displacement [d]: a rod almost at rest is not cut for relative changes of
// a negligible motion.
constexpr double kTruncationFloor = 1e-3;
// Motion below this per (sub)step [d] is round-off of a rod at rest: its
// growth is not judged.
constexpr double kGrowthMotionFloor = 1e-6;
// Beyond it the message names the fold [deg]: past 90 deg the beam bond's
// restoring law (small rotations) no longer describes the joint, and near
// 180 deg its rotation-vector torque flips direction.
constexpr double kFoldedBondDegrees = 90.0;
// Beyond it a refusal for displacement names the strain, not the step:
// 10 % axial strain is far outside the small-strain beam bond [-].
constexpr double kStrongStrain = 0.1;

// The factor of the next substep level for an error `wanted` times the
// limit: powers of 2 up to kMaxShrink, never finer than dt / max_substeps.
long substep_shrink(double wanted, long level, const StepGuardLimits& limits) {
  long shrink = 2;
  while (shrink < kMaxShrink && shrink < wanted && level * shrink * 2 <= limits.max_substeps) shrink *= 2;
  return shrink;
}

// A bond turned far from its rest state: the largest angle between the bond
// vector and its rest direction in either sphere's frame, or of the spheres'
// relative rotation against its rest value [deg]. For the refusal message
// only: a fold that no substep resolves.
struct BondTurn {
  double degrees = 0.0;
  int i = -1, j = -1;
};

BondTurn largest_bond_turn(const std::vector<Eigen::Vector3d>& positions,
                           const std::vector<Eigen::Quaterniond>& orientations, const std::vector<RodBond>& bonds) {
  BondTurn worst;
  const auto angle_between = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
  };
  for (const RodBond& b : bonds) {
    const Eigen::Vector3d bond = positions[b.j] - positions[b.i];
    const Eigen::Vector3d rest_i = orientations[b.i] * b.rest.rest_vector_in_frame_i;
    const Eigen::Quaterniond rest_j_frame = orientations[b.j] * b.rest.rest_relative_rotation.inverse();
    const Eigen::Vector3d rest_j = rest_j_frame * b.rest.rest_vector_in_frame_i;
    const Eigen::Quaterniond relative =
        b.rest.rest_relative_rotation.inverse() * orientations[b.i].inverse() * orientations[b.j];
    const double turn = std::max({angle_between(rest_i, bond), angle_between(rest_j, bond),
                                  Eigen::AngleAxisd(relative.normalized()).angle()});
    const double degrees = std::min(turn, 2.0 * kPi - turn) * 180.0 / kPi;
    if (degrees > worst.degrees) worst = {degrees, b.i, b.j};
  }
  return worst;
}

}  // namespace

void judge_truncation_error(const GuardedCall& c, const SubstepSchedule& s, SubstepTrial& t) {
  const StepGuardLimits& limits = c.limits;
  const OverdampedRod& rod = c.rod;
  const GuardWorkspace& ws = c.ws;
  StepAssessment& a = t.a;
  if (!a.problem.empty() || !limits.adaptive) return;
  // Local truncation error h^2/2 |x''| of backward Euler, x'' from the
  // mean velocities of this substep and of the previous one.
  const int n = rod.size();
  const double h = t.h;
  const double h_before = c.report.substeps == 0 ? c.dt : s.previous_h;
  const bool have_before = c.report.substeps > 0 || static_cast<int>(rod.velocities.size()) == n;
  double error = 0.0, moved = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d v = (rod.positions[i] - ws.substep_positions[i]) / h;
    const Eigen::Vector3d v_before = c.report.substeps > 0 ? ws.previous_velocities[i]
                                     : have_before         ? rod.velocities[i]
                                                           : Eigen::Vector3d::Zero();
    error = std::max(error, h * h * (v - v_before).norm() / (h + h_before));
    moved = std::max(moved, h * v.norm());
  }
  const bool touching = ws.trial.wall_contact || ws.trial.self_contact;
  const double floor = touching ? t.contact_floor / limits.max_step_error : kTruncationFloor * t.d;
  a.truncation_error = error / std::max(moved, floor);
  if (!std::isfinite(a.truncation_error)) a.truncation_error = HUGE_VAL;
  if (a.truncation_error > limits.displacement_tolerance && !at_finest_substep(s.level, limits)) {
    t.shrink = substep_shrink(std::sqrt(a.truncation_error / limits.displacement_tolerance) / kShrinkSafety, s.level,
                              limits);
    std::ostringstream m;
    m.precision(3);
    m << "the step's truncation error is " << a.truncation_error << " of its displacement (tolerance "
      << limits.displacement_tolerance << ")";
    a.problem = m.str();
  }
}

void judge_growth(const GuardedCall& c, const SubstepSchedule& s, SubstepTrial& t) {
  const StepGuardLimits& limits = c.limits;
  const OverdampedRod& rod = c.rod;
  const GuardWorkspace& ws = c.ws;
  StepAssessment& a = t.a;
  if (!(a.problem.empty() && limits.max_growth > 0.0 && (c.report.substeps > 0 || c.velocities_given))) return;
  const int n = rod.size();
  const double h = t.h;
  const double h_before = c.report.substeps == 0 ? c.dt : s.previous_h;
  double now = 0.0, before = 0.0;  // squared speeds [m^2/s^2]
  for (int i = 0; i < n; ++i) {
    now += ((rod.positions[i] - ws.substep_positions[i]) / h).squaredNorm();
    before += (c.report.substeps > 0 ? ws.previous_velocities[i] : rod.velocities[i]).squaredNorm();
  }
  now = std::sqrt(now);
  before = std::sqrt(before);
  if (!(before > 0.0 && now > before && now * h > kGrowthMotionFloor * t.d)) return;
  const double rate = (now - before) / before / (0.5 * (h + h_before));  // lambda [1/s]
  a.growth = rate * h;
  if (a.growth > limits.max_growth && !at_finest_substep(s.level, limits)) {
    t.shrink = substep_shrink(a.growth / limits.max_growth / kShrinkSafety, s.level, limits);
    a.problem = "the rod's speed grows at " + g3(rate) + " 1/s: " + g3(a.growth) + " per step (limit max_growth " +
                g3(limits.max_growth) + ")";
  }
}

void judge_wall_friction(const GuardedCall& c, SubstepTrial& t) {
  // Wall friction at the step's end velocities (WallContactParameters::
  // friction_iterations) that did not converge: the step's friction is
  // off the law by more than the step-error limit.
  const WallContactParameters* walls = c.walls;
  const GuardWorkspace& ws = c.ws;
  if (!(t.a.problem.empty() && walls && walls->friction_iterations > 0)) return;
  // (The half steps' figures are reset at each (sub)step's start.)
  const double mismatch =
      std::max({ws.trial.friction_mismatch, ws.first_half_result.friction_mismatch, ws.half_result.friction_mismatch});
  if (mismatch > std::max(c.limits.max_step_error, walls->friction_tolerance)) {
    std::ostringstream m;
    m.precision(3);
    m << "wall friction at the step's end velocities did not converge in " << walls->friction_iterations
      << " repeats (friction force off the law by " << mismatch << " of itself)";
    t.a.problem = m.str();
  }
}

void refuse_step(const GuardedCall& c, const SubstepSchedule& s, const SubstepTrial& t) {
  const StepGuardLimits& limits = c.limits;
  const StepAssessment& a = t.a;
  std::ostringstream m;
  m.precision(3);
  m << "implicit rod step of dt = " << c.dt << " s refused: even substeps of " << t.h << " s (dt / " << s.level
    << ") fail the accuracy guard at t + " << s.done << " s: " << a.problem;
  const BondTurn turn = largest_bond_turn(c.ws.substep_positions, c.ws.substep_orientations, c.rod.bonds);
  if (a.bond_strain > limits.max_bond_strain && a.displacement <= limits.max_displacement &&
      a.strain_change <= limits.max_strain_change)
    m << "; the rod itself is over-strained (the loads stretch it beyond small-strain bonds at any step: "
         "a stiffer rod (youngs_modulus) or a slower flow (the drag's inflow or viscosity))";
  else if (turn.degrees > kFoldedBondDegrees)
    m << "; the rod is folded at the substep's start: the bond between spheres " << turn.i << " and " << turn.j
      << " is turned " << turn.degrees << " deg against its spheres' frames (beam bonds are "
      << "small-rotation elements; a smaller timestep does not undo the fold: a stiffer rod, a slower "
      << "flow, or the state before the fold)";
  else if (a.bond_strain > kStrongStrain)
    // Not the step: a rod strained this far by the loads moves its
    // spheres faster than the flow (a whip), at any step.
    m << "; the rod is strained to " << a.bond_strain << " by the loads (bonds are small-strain elements): "
      << "a stiffer rod (youngs_modulus) or a slower flow (the drag's inflow or viscosity), else a smaller "
         "timestep";
  else
    m << "; use a smaller timestep";
  throw StepRefused(m.str());
}

}  // namespace hsrod::guard_detail
