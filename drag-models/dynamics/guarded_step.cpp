#include "dynamics/guarded_step.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace hsrod {
namespace {

// Generalised loads (F_i, T_i / r_i per sphere: torques in force units) of
// bonds, wall and self contacts at the rod's current state; the same terms
// as OverdampedRodSolver::step, evaluated without linearisation.
Eigen::VectorXd elastic_loads(const OverdampedRod& rod, const ChannelGeometry* geometry,
                              const WallContactParameters* walls) {
  const int n = rod.size();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * n);
  std::vector<SphereState> s(n);
  for (int i = 0; i < n; ++i) {
    s[i].position = rod.positions[i];
    s[i].orientation = rod.orientations[i];
  }
  for (const RodBond& b : rod.bonds) {
    const BeamBondLoads l = evaluate_beam_bond(s[b.i], s[b.j], b.rest, b.stiffness, BeamBondDamping{});
    f.segment<3>(6 * b.i) -= l.force_on_j;
    f.segment<3>(6 * b.i + 3) += l.torque_on_i / rod.radii[b.i];
    f.segment<3>(6 * b.j) += l.force_on_j;
    f.segment<3>(6 * b.j + 3) += l.torque_on_j / rod.radii[b.j];
  }
  if (geometry && walls)
    for (int i = 0; i < n; ++i) {
      const WallContact c = wall_contact(*geometry, *walls, rod.positions[i], rod.radii[i]);
      if (c.touching) f.segment<3>(6 * i) += c.force;
    }
  if (walls && sphere_pair_search_on(rod, *walls)) {
    double largest_radius = 0.0;
    for (double r : rod.radii) largest_radius = std::max(largest_radius, r);
    std::vector<std::vector<int>> bonded(n);
    for (const RodBond& b : rod.bonds) {
      bonded[b.i].push_back(b.j);
      bonded[b.j].push_back(b.i);
    }
    for (const auto& [i, j] : nearby_sphere_pairs(rod.positions, 2.0 * largest_radius)) {
      if (std::find(bonded[i].begin(), bonded[i].end(), j) != bonded[i].end()) continue;
      if (!sphere_pair_contact_on(rod, *walls, i, j)) continue;
      const WallContact c = sphere_contact(*walls, rod.positions[i], rod.radii[i], rod.positions[j], rod.radii[j]);
      if (!c.touching) continue;
      f.segment<3>(6 * i) += c.force;
      f.segment<3>(6 * j) -= c.force;
    }
  }
  return f;
}

// v as an ostream with precision 3 prints it (%.3g).
std::string g3(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// True when the centre at p lies in a planform wall or outside the gap.
bool in_gap_wall(const Eigen::Vector3d& p, const ChannelGeometry& geometry, const WallContactParameters* walls) {
  return walls && walls->gap_walls && (p.z() < walls->gap_bottom || p.z() > walls->gap_bottom + geometry.gap_height());
}

bool in_wall(const Eigen::Vector3d& p, const ChannelGeometry& geometry, const WallContactParameters* walls) {
  if (geometry.signed_distance(p.x(), p.y()) < 0.0) return true;
  return in_gap_wall(p, geometry, walls);
}

// Planform signed distances [m] of sphere centres that assess_step has
// evaluated, by sphere, with the centre's (x, y) bits: the next call's start
// centres are the last call's end centres (an accepted substep) or start
// centres (a rejected one, restored), so each distance is looked up instead
// of recomputed (ChannelGeometry::signed_distance is a pure function of
// (x, y): the same value to the last bit). Callgrind, level 1 pore passage:
// 26 940 -> ~13 500 distances.
struct KnownDistances {
  const ChannelGeometry* geometry = nullptr;
  std::uint64_t identity = 0;  // geometry->identity() of the distances kept
  std::vector<std::uint64_t> x_bits, y_bits;  // per sphere, two slots (start 2i, end 2i + 1)
  std::vector<double> distance;               // [m]
  static std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }
  void reset(const ChannelGeometry* g, int n) {
    geometry = g;
    if (g->identity() != identity || static_cast<int>(distance.size()) != 2 * n) {
      identity = g->identity();
      // Empty slots: all-ones bits (a NaN) and a NaN distance, what
      // signed_distance gives for a centre with those bits.
      x_bits.assign(2 * n, ~std::uint64_t{0});
      y_bits.assign(2 * n, ~std::uint64_t{0});
      distance.assign(2 * n, std::numeric_limits<double>::quiet_NaN());
    }
  }
  // The distance of sphere i's centre p, from a slot if known.
  double of(int i, const Eigen::Vector3d& p) const {
    const std::uint64_t bx = bits(p.x()), by = bits(p.y());
    for (int slot = 2 * i; slot <= 2 * i + 1; ++slot)
      if (x_bits[slot] == bx && y_bits[slot] == by) return distance[slot];
    return geometry->signed_distance(p.x(), p.y());
  }
  void keep(int slot, const Eigen::Vector3d& p, double d) {
    x_bits[slot] = bits(p.x());
    y_bits[slot] = bits(p.y());
    distance[slot] = d;
  }
};

// Work storage of assess_step (its start distances and the known
// distances), kept between steps.
std::vector<double>& thread_local_start_distance() {
  thread_local std::vector<double> distances;
  return distances;
}
KnownDistances& thread_local_known_distances() {
  thread_local KnownDistances known;
  return known;
}

}  // namespace

std::pair<double, double> bond_strain_and_energy(const OverdampedRod& rod) {
  double strain = 0.0, energy = 0.0;
  for (const RodBond& b : rod.bonds) {
    const SphereState si = rod.pose(b.i), sj = rod.pose(b.j);
    const BeamBondLoads l = evaluate_beam_bond(si, sj, b.rest, b.stiffness, BeamBondDamping{});
    strain = std::max(strain, std::abs(l.axial_strain));
    energy += l.elastic_energy;
  }
  return {strain, energy};
}

namespace {

// The checks of a step from (x0, q0) to the rod's state `after` without the
// residual (which is reported only): displacement, strain change and
// absolute strain, bond load against drag load, walls.
// A bond turned far from its rest state: the largest angle between the bond
// vector and its rest direction in either sphere's frame, or of the spheres'
// relative rotation against its rest value [deg]. For the refusal message
// only: a fold that no substep resolves.
struct BondTurn {
  double degrees = 0.0;
  int i = -1, j = -1;
};
// Beyond it the message names the fold [deg]: past 90 deg the beam bond's
// restoring law (small rotations) no longer describes the joint, and near
// 180 deg its rotation-vector torque flips direction.
constexpr double kFoldedBondDegrees = 90.0;
// Beyond it a refusal for displacement names the strain, not the step:
// 10 % axial strain is far outside the small-strain beam bond [-].
constexpr double kStrongStrain = 0.1;

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
    const double degrees = std::min(turn, 2.0 * 3.14159265358979323846 - turn) * 180.0 / 3.14159265358979323846;
    if (degrees > worst.degrees) worst = {degrees, b.i, b.j};
  }
  return worst;
}

StepAssessment assess_step(const std::vector<Eigen::Vector3d>& x0, const OverdampedRod& after, const RodDrag& drag,
                           double dt, const ChannelGeometry* geometry, const WallContactParameters* walls,
                           const StepGuardLimits& limits) {
  StepAssessment a;
  const int n = after.size();
  for (int i = 0; i < n; ++i) {
    const double moved = (after.positions[i] - x0[i]).norm() / (2.0 * after.radii[i]);
    a.displacement = std::isfinite(moved) ? std::max(a.displacement, moved) : HUGE_VAL;
  }
  // Bond strain change, the bond load it carries, and the strain itself.
  double bond_load = 0.0;
  for (const RodBond& b : after.bonds) {
    const double l0 = b.rest.rest_length();
    const double e0 = (x0[b.j] - x0[b.i]).norm() / l0 - 1.0;
    const double e1 = (after.positions[b.j] - after.positions[b.i]).norm() / l0 - 1.0;
    const double change = std::abs(e1 - e0);
    a.strain_change = std::isfinite(change) ? std::max(a.strain_change, change) : HUGE_VAL;
    a.bond_strain = std::isfinite(e1) ? std::max(a.bond_strain, std::abs(e1)) : HUGE_VAL;
    bond_load = std::max(bond_load, b.stiffness.axial * l0 * change);
  }
  // Largest drag force of the step |R dx / dt|.
  double drag_load = 0.0;
  if (drag.coupled()) {
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d f = Eigen::Vector3d::Zero();
      for (int k = 0; k < n; ++k) f += drag.coupled_resistance.block<3, 3>(3 * i, 3 * k) * (after.positions[k] - x0[k]);
      drag_load = std::max(drag_load, f.norm() / dt);
    }
  } else {
    for (int i = 0; i < n; ++i)
      drag_load = std::max(drag_load, (drag.resistance[i] * (after.positions[i] - x0[i])).norm() / dt);
  }
  a.bond_load_ratio = drag_load > 0.0 ? bond_load / drag_load : (bond_load > 0.0 ? HUGE_VAL : 0.0);
  // Walls: the new centre, and the path (sampled every quarter radius).
  // The planform's signed distance is 1-Lipschitz (a minimum of distances),
  // so a path shorter in the plane than the start's distance to the walls
  // (by a margin far above rounding) has every sample off them: only the
  // gap walls are then checked along it (the same answers, fewer distances;
  // the start's distance is kept for the overlap check below).
  std::vector<double>& start_distance = thread_local_start_distance();
  KnownDistances& known = thread_local_known_distances();
  if (limits.check_walls && geometry) {
    start_distance.assign(n, 0.0);
    known.reset(geometry, n);
    for (int i = 0; i < n && a.crossing_sphere < 0; ++i) {
      const Eigen::Vector3d step = after.positions[i] - x0[i];
      const int samples = std::clamp(static_cast<int>(std::ceil(step.norm() / (0.25 * after.radii[i]))), 1, 64);
      const double d0 = known.of(i, x0[i]);
      start_distance[i] = d0;
      known.keep(2 * i, x0[i], d0);
      const double reach = step.head<2>().norm();
      const bool planform_clear = d0 - reach > 1e-9 * (std::fabs(d0) + reach);
      for (int k = 1; k <= samples; ++k) {
        const Eigen::Vector3d p = x0[i] + step * (double(k) / samples);
        if ((planform_clear ? in_gap_wall(p, *geometry, walls) : in_wall(p, *geometry, walls)) &&
            !in_wall(x0[i], *geometry, walls)) {
          a.crossing_sphere = i;
          break;
        }
      }
    }
  }
  // New wall overlap beyond max_overlap radii.
  if (limits.check_walls && geometry && a.crossing_sphere < 0) {
    for (int i = 0; i < n; ++i) {
      const double radius = after.radii[i];
      auto overlap = [&](const Eigen::Vector3d& p, double planform_distance) {
        double o = radius - planform_distance;
        if (walls && walls->gap_walls) {
          o = std::max(o, radius - (p.z() - walls->gap_bottom));
          o = std::max(o, radius - (walls->gap_bottom + geometry->gap_height() - p.z()));
        }
        return o;
      };
      const Eigen::Vector3d& p1 = after.positions[i];
      const double d1 = geometry->signed_distance(p1.x(), p1.y());
      known.keep(2 * i + 1, p1, d1);
      const double grown = overlap(p1, d1) -
                           std::max(0.0, overlap(x0[i], start_distance[i]));
      if (grown > limits.max_overlap * radius) {
        a.crossing_sphere = i;
        break;
      }
    }
  }
  // Spheres of two rods (a cluster stepped together) pressed into each other
  // beyond max_overlap radii in one step: the Hertz contact, linearised at
  // the step's start, cannot stop an approach it did not see.
  if (walls && walls->rod_contact && !after.rod_of_sphere.empty() && a.crossing_sphere < 0) {
    double largest_radius = 0.0;
    for (double r : after.radii) largest_radius = std::max(largest_radius, r);
    for (const auto& [i, j] : nearby_sphere_pairs(after.positions, 2.0 * largest_radius)) {
      if (after.same_rod(i, j)) continue;
      const double contact = after.radii[i] + after.radii[j];
      const double grown = (contact - (after.positions[i] - after.positions[j]).norm()) -
                           std::max(0.0, contact - (x0[i] - x0[j]).norm());
      if (grown > limits.max_overlap * std::min(after.radii[i], after.radii[j])) {
        a.interpenetrating_sphere = i;
        break;
      }
    }
  }
  if (a.displacement > limits.max_displacement || a.strain_change > limits.max_strain_change ||
      a.bond_strain > limits.max_bond_strain || a.crossing_sphere >= 0 || a.interpenetrating_sphere >= 0) {
    // Built from snprintf pieces, not an ostringstream (a stream's set-up
    // costs ~8 000 instructions, and a rejected trial builds one message).
    if (a.displacement > limits.max_displacement)
      a.problem = "a sphere moves " + g3(a.displacement) + " d in one step (limit " + g3(limits.max_displacement) +
                  " d)";
    else if (a.strain_change > limits.max_strain_change)
      a.problem = "a bond's strain changes by " + g3(a.strain_change) + " in one step (limit " +
                  g3(limits.max_strain_change) + ")";
    else if (a.bond_strain > limits.max_bond_strain)
      a.problem = "a bond's axial strain reaches " + g3(a.bond_strain) + " (limit max_bond_strain " +
                  g3(limits.max_bond_strain) + ")";
    else if (a.crossing_sphere >= 0)
      a.problem = "sphere " + std::to_string(a.crossing_sphere) +
                  " of the rod would cross or enter a wall (new overlap > " + g3(limits.max_overlap) + " radii)";
    else
      a.problem = "sphere " + std::to_string(a.interpenetrating_sphere) +
                  " would press into a sphere of another rod (new overlap > " + g3(limits.max_overlap) + " radii)";
  }
  return a;
}

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

}  // namespace

StepAssessment assess_rod_step(const OverdampedRod& before, const OverdampedRod& after,
                               const OverdampedStepResult& result, const RodDrag& drag, double dt,
                               const ChannelGeometry* geometry, const WallContactParameters* walls,
                               const StepGuardLimits& limits) {
  (void)result;
  StepAssessment a = assess_step(before.positions, after, drag, dt, geometry, walls, limits);
  const int n = before.size();
  // Backward-Euler residual (reported only): R dy / dt = F_drive + F_ext + F_elastic(y_{n+1}).
  Eigen::VectorXd dx(3 * n), dphi(3 * n);
  for (int i = 0; i < n; ++i) {
    dx.segment<3>(3 * i) = after.positions[i] - before.positions[i];
    dphi.segment<3>(3 * i) = rotation_vector((after.orientations[i] * before.orientations[i].inverse()).normalized());
  }
  Eigen::VectorXd resist = Eigen::VectorXd::Zero(6 * n), driving = Eigen::VectorXd::Zero(6 * n);
  Eigen::VectorXd translational_resist =
      drag.coupled() ? Eigen::VectorXd(drag.coupled_resistance * dx / dt) : Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i) {
    const double r = before.radii[i];
    if (!drag.coupled()) translational_resist.segment<3>(3 * i) = drag.resistance[i] * dx.segment<3>(3 * i) / dt;
    resist.segment<3>(6 * i) = translational_resist.segment<3>(3 * i);
    resist.segment<3>(6 * i + 3) = drag.rotational_resistance[i] * dphi.segment<3>(3 * i) / dt / r;
    driving.segment<3>(6 * i) = drag.driving_force[i] + before.external_forces[i];
    driving.segment<3>(6 * i + 3) = (drag.driving_torque[i] + before.external_torques[i]) / r;
  }
  const Eigen::VectorXd loads_before = elastic_loads(before, geometry, walls);
  const Eigen::VectorXd loads_after = elastic_loads(after, geometry, walls);
  const double scale = resist.norm() + driving.norm() + loads_before.norm();
  const double residual = (resist - driving - loads_after).norm();
  a.residual = scale > 0.0 ? residual / scale : 0.0;
  if (!std::isfinite(a.residual)) a.residual = HUGE_VAL;
  return a;
}

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
  // A fresh report in the caller's memory.
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

  // The rod itself is stepped; (x0, q0) of the whole step and of the
  // current substep are kept to go back to.
  ws.start_positions = rod.positions;
  ws.start_orientations = rod.orientations;
  const auto restore = [&rod](const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Quaterniond>& q) {
    rod.positions = x;
    rod.orientations = q;
  };
  const RodDrag* current_drag = &drag;
  const bool velocities_given = static_cast<int>(rod.velocities.size()) == n;
  double done = 0.0;  // time advanced [s]
  long level = 1;     // current substep = dt / level
  double previous_h = dt;  // adaptive: the last accepted substep [s]
  if (limits.adaptive && static_cast<int>(rod.velocities.size()) == n) {
    // Start at the substep the incoming velocities ask for (the
    // displacement limit), not at dt: no state is kept between steps.
    double speed = 0.0;
    for (int i = 0; i < n; ++i) speed = std::max(speed, rod.velocities[i].norm() / (2.0 * rod.radii[i]));
    while (level * 2 <= limits.max_substeps && speed * dt / static_cast<double>(level) > 0.8 * limits.max_displacement)
      level *= 2;
  }
  try {
    while (done < dt * (1.0 - 1e-12)) {
      const double h = std::min(dt / static_cast<double>(level), dt - done);
      ws.substep_positions = rod.positions;
      ws.substep_orientations = rod.orientations;
      using NewtonCheck = StepGuardLimits::NewtonCheck;
      // Quiet steps at a wall (header): the half steps first.
      const double d = 2.0 * rod.radii[0];
      const double contact_floor = 0.5 * limits.max_overlap * d;  // the doubling test's limit while touching [m]
      const double quiet_move = 2e-3 * contact_floor;             // largest half-step move of a quiet step [m]
      bool halves_ready = false, quiet = false;
      ws.first_half_result.friction_mismatch = ws.half_result.friction_mismatch = 0.0;
      StepAssessment a;
      // Newton iterations on the wall contacts (below), where the full step is taken.
      bool contact_iterated = false, contact_converged = false;
      double contact_update = 0.0, contact_moved = 0.0;
      if (ws.half_steps_first && !limits.adaptive && limits.newton_check != NewtonCheck::kNever && velocities_given &&
          geometry && walls && touching_wall(rod, *geometry, *walls)) {
        take_half_steps(solver, rod, *current_drag, h, geometry, walls, ws);
        halves_ready = true;
        if (ws.halves_moved <= quiet_move) {
          a = assess_step(ws.substep_positions, ws.half, *current_drag, h, geometry, walls, limits);
          // ... and no sphere within 8 half-step moves of touching or leaving
          // a wall (the full step moves ~2x the first half step): the full
          // step would keep the contact set (no Newton iterations on the
          // contacts, whose result would be kept instead of the halves).
          quiet = a.problem.empty() && a.displacement <= 0.5 * limits.max_displacement &&
                  a.strain_change <= 0.5 * limits.max_strain_change && a.bond_strain <= limits.max_bond_strain - 0.01 &&
                  contact_set_settled(ws.substep_positions, rod.radii, *geometry, *walls, 8.0 * ws.halves_moved);
        }
      }
      if (quiet) {
        // The two half steps, without the full step (header). The step's
        // result: contacts at its start (those of the first half step, as
        // the full step's), hydrodynamic forces at the mean velocity.
        rod.positions = ws.half.positions;
        rod.orientations = ws.half.orientations;
        OverdampedStepResult& r = ws.trial;
        r = ws.first_half_result;
        r.largest_displacement = 0.0;
        for (int i = 0; i < n; ++i) {
          r.hydrodynamic_forces[i] = 0.5 * (ws.first_half_result.hydrodynamic_forces[i] + ws.half_result.hydrodynamic_forces[i]);
          r.largest_displacement = std::max(r.largest_displacement, (rod.positions[i] - ws.substep_positions[i]).norm());
        }
        a.step_error = 0.0;  // not estimated (bounded far below the limit, header)
        ++ws.quiet_steps;
      } else {
        solver.step(rod, *current_drag, h, geometry, walls, ws.trial);
        // Newton iterations where the wall-contact set changed in the step
        // (StepGuardLimits::contact_iterations): the converged state is kept.
        if (limits.contact_iterations > 0 && geometry && walls) {
          // Which spheres touch a wall, and their Hertz normal force [N].
          const auto touching_set = [&](std::vector<char>& set, std::vector<double>* force = nullptr) {
            set.resize(n);
            if (force) force->assign(n, 0.0);
            for (int i = 0; i < n; ++i) {
              const WallContact c = wall_contact(*geometry, *walls, rod.positions[i], rod.radii[i]);
              set[i] = c.touching;
              if (force)
                for (int k = 0; k < c.points; ++k) (*force)[i] += c.point[k].normal_force;
            }
          };
          touching_set(ws.touching_end);
          ws.iterate_positions = rod.positions;
          rod.positions = ws.substep_positions;
          touching_set(ws.touching_start);
          rod.positions = ws.iterate_positions;
          contact_iterated = ws.touching_start != ws.touching_end;
          // Converged: the update is below max_step_error of the step's
          // displacement (or 1e-6 d), the contact set no longer changes and
          // every Hertz force changed by less than 1.5 max_step_error of itself
          // (an overlap by max_step_error: a displacement test alone would stop
          // a stiff contact at an overlap whose force is many times the loads),
          // or by less than the force of an overlap of 1e-8 d.
          const double tolerance_floor = 1e-6 * d;
          const double force_floor = 4.0 / 3.0 * walls->effective_modulus() * std::sqrt(0.5 * d) * std::pow(1e-8 * d, 1.5);
          if (contact_iterated) touching_set(ws.touching_end, &ws.contact_force_end);
          for (int k = 0; contact_iterated && k < limits.contact_iterations; ++k) {
            ws.iterate_positions = rod.positions;
            ws.touching_start.swap(ws.touching_end);  // the previous iterate's set and forces
            ws.contact_force_start.swap(ws.contact_force_end);
            solver.iterate(rod, ws.substep_positions, ws.substep_orientations, *current_drag, h, geometry, walls,
                           ws.trial);
            ++report.contact_iterations;
            contact_update = contact_moved = 0.0;
            for (int i = 0; i < n; ++i) {
              contact_update = std::max(contact_update, (rod.positions[i] - ws.iterate_positions[i]).norm());
              contact_moved = std::max(contact_moved, (rod.positions[i] - ws.substep_positions[i]).norm());
            }
            if (!std::isfinite(contact_update)) break;
            touching_set(ws.touching_end, &ws.contact_force_end);
            bool forces_settled = ws.touching_start == ws.touching_end;
            for (int i = 0; i < n && forces_settled; ++i)
              forces_settled = std::abs(ws.contact_force_end[i] - ws.contact_force_start[i]) <=
                               1.5 * limits.max_step_error * std::max(ws.contact_force_end[i], force_floor);
            if (forces_settled && contact_update <= limits.max_step_error * std::max(contact_moved, tolerance_floor)) {
              contact_converged = true;
              break;
            }
          }
        }
        a = assess_step(ws.substep_positions, rod, *current_drag, h, geometry, walls, limits);
        if (contact_iterated) {
          a.step_error = contact_update / std::max(contact_moved, 1e-300);
          if (!std::isfinite(a.step_error)) a.step_error = HUGE_VAL;
          if (!contact_converged && a.problem.empty()) {
            std::ostringstream m;
            m.precision(3);
            m << "the Newton iterations on the wall contacts did not converge in " << limits.contact_iterations
              << " (last update " << contact_update / (2.0 * rod.radii[0]) << " d)";
            a.problem = m.str();
          }
        }
      }
      const OverdampedStepResult& r = ws.trial;
      const bool suspect = limits.newton_check == NewtonCheck::kAlways ||
                           (limits.newton_check == NewtonCheck::kWhenSuspect &&
                            (a.bond_load_ratio > limits.suspect_bond_load || r.wall_contact || r.self_contact));
      bool quiet_at_wall = quiet;  // this (sub)step, if accepted, was quiet at a wall
      if (!quiet && a.problem.empty() && suspect && !contact_iterated) {
        // Newton error: one more (simplified) Newton iteration with the
        // step's factors. Not across a contact: a sphere touching a wall (or
        // another sphere) at the start or the end of the step makes the
        // Hertz force a near-discontinuity that the step's stiffness (without
        // the new contact) does not describe, and the simplified iteration
        // overshoots (a rod pressed against the pore chattered between the
        // step and its correction); there, and where the solver keeps no
        // factors, step doubling (with the same drag: no trial evaluation).
        bool touching = r.wall_contact || r.self_contact;  // self-contact: the same Hertz impact
        if (!touching && geometry && walls) {
          for (int i = 0; i < n && !touching; ++i)
            touching = wall_contact(*geometry, *walls, rod.positions[i], rod.radii[i]).touching;
        }
        const bool corrected =
            !touching && solver.newton_correction(rod, *current_drag, geometry, walls, ws.correction);
        if (!corrected && !halves_ready) take_half_steps(solver, rod, *current_drag, h, geometry, walls, ws);
        if (!corrected) quiet_at_wall = r.wall_contact && ws.halves_moved <= quiet_move;
        double difference = 0.0, moved = 0.0;
        for (int i = 0; i < n; ++i) {
          const Eigen::Vector3d change = corrected ? Eigen::Vector3d(ws.correction.segment<3>(6 * i))
                                                   : Eigen::Vector3d(ws.half.positions[i] - rod.positions[i]);
          difference = std::max(difference, change.norm());
          moved = std::max(moved, (rod.positions[i] - ws.substep_positions[i]).norm());
        }
        // Error floor: 1e-6 d (a relative test otherwise: lags are systematic
        // and add up); while a sphere touches a wall the Hertz impact
        // (overlap time scale ~1e-8 s) is a near-discontinuity the step cannot
        // follow, and the error is bounded by the overlap limit instead.
        const double floor = touching ? 0.5 * limits.max_overlap * d : 1e-6 * d * limits.max_step_error;
        a.step_error = difference / std::max(moved, floor / limits.max_step_error);
        if (!std::isfinite(a.step_error)) a.step_error = HUGE_VAL;
        const bool finest = level * 2 > limits.max_substeps;
        const bool accept = a.step_error <= limits.max_step_error || (finest && !limits.refuse_unresolved_error);
        if (accept) {
          if (a.step_error > limits.max_step_error) {
            ++report.unresolved_substeps;
            report.unresolved_error = std::max(report.unresolved_error, a.step_error);
          }
          // Keep the more accurate state: corrected, or the two half steps.
          if (corrected) {
            solver.displace(rod, ws.correction);
          } else {
            rod.positions = ws.half.positions;
            rod.orientations = ws.half.orientations;
          }
        } else {
          std::ostringstream m;
          m.precision(3);
          m << "the linearised step's Newton error is " << a.step_error << " of its displacement (limit "
            << limits.max_step_error << ")";
          a.problem = m.str();
        }
      }
      long shrink = 2;  // factor of the next substep level
      if (a.problem.empty() && limits.adaptive) {
        // Local truncation error h^2/2 |x''| of backward Euler, x'' from the
        // mean velocities of this substep and of the previous one.
        const double h_before = report.substeps == 0 ? dt : previous_h;
        const bool have_before = report.substeps > 0 || static_cast<int>(rod.velocities.size()) == n;
        double error = 0.0, moved = 0.0;
        for (int i = 0; i < n; ++i) {
          const Eigen::Vector3d v = (rod.positions[i] - ws.substep_positions[i]) / h;
          const Eigen::Vector3d v_before = report.substeps > 0 ? ws.previous_velocities[i]
                                           : have_before      ? rod.velocities[i]
                                                              : Eigen::Vector3d::Zero();
          error = std::max(error, h * h * (v - v_before).norm() / (h + h_before));
          moved = std::max(moved, h * v.norm());
        }
        const bool touching = r.wall_contact || r.self_contact;
        const double floor = touching ? 0.5 * limits.max_overlap * d / limits.max_step_error : 1e-3 * d;
        a.truncation_error = error / std::max(moved, floor);
        if (!std::isfinite(a.truncation_error)) a.truncation_error = HUGE_VAL;
        const bool finest = level * 2 > limits.max_substeps;
        if (a.truncation_error > limits.displacement_tolerance && !finest) {
          // h^2 scaling with a safety factor 0.8: the level that should pass.
          const double wanted = std::sqrt(a.truncation_error / limits.displacement_tolerance) / 0.8;
          while (shrink < 64 && shrink < wanted && level * shrink * 2 <= limits.max_substeps) shrink *= 2;
          std::ostringstream m;
          m.precision(3);
          m << "the step's truncation error is " << a.truncation_error << " of its displacement (tolerance "
            << limits.displacement_tolerance << ")";
          a.problem = m.str();
        }
      }
      // Growing motion (StepGuardLimits::max_growth).
      if (a.problem.empty() && limits.max_growth > 0.0 && (report.substeps > 0 || velocities_given)) {
        const double h_before = report.substeps == 0 ? dt : previous_h;
        double now = 0.0, before = 0.0;  // squared speeds [m^2/s^2]
        for (int i = 0; i < n; ++i) {
          now += ((rod.positions[i] - ws.substep_positions[i]) / h).squaredNorm();
          before += (report.substeps > 0 ? ws.previous_velocities[i] : rod.velocities[i]).squaredNorm();
        }
        now = std::sqrt(now);
        before = std::sqrt(before);
        if (before > 0.0 && now > before && now * h > 1e-6 * d) {
          const double rate = (now - before) / before / (0.5 * (h + h_before));  // lambda [1/s]
          a.growth = rate * h;
          const bool finest = level * 2 > limits.max_substeps;
          if (a.growth > limits.max_growth && !finest) {
            const double wanted = a.growth / limits.max_growth / 0.8;
            while (shrink < 64 && shrink < wanted && level * shrink * 2 <= limits.max_substeps) shrink *= 2;
            a.problem = "the rod's speed grows at " + g3(rate) + " 1/s: " + g3(a.growth) +
                        " per step (limit max_growth " + g3(limits.max_growth) + ")";
          }
        }
      }
      // Wall friction at the step's end velocities (WallContactParameters::
      // friction_iterations) that did not converge: the step's friction is
      // off the law by more than the step-error limit.
      if (a.problem.empty() && walls && walls->friction_iterations > 0) {
        // (The half steps' figures are reset at each (sub)step's start.)
        const double mismatch = std::max(
            {ws.trial.friction_mismatch, ws.first_half_result.friction_mismatch, ws.half_result.friction_mismatch});
        if (mismatch > std::max(limits.max_step_error, walls->friction_tolerance)) {
          std::ostringstream m;
          m.precision(3);
          m << "wall friction at the step's end velocities did not converge in " << walls->friction_iterations
            << " repeats (friction force off the law by " << mismatch << " of itself)";
          a.problem = m.str();
        }
      }
      // The next (sub)step of this rod takes its half steps first when this
      // one was accepted quiet at a wall.
      ws.half_steps_first = a.problem.empty() && quiet_at_wall;
      if (!a.problem.empty()) {
        ++report.rejected_trials;
        if (level * 2 > limits.max_substeps) {
          std::ostringstream m;
          m.precision(3);
          m << "implicit rod step of dt = " << dt << " s refused: even substeps of " << h << " s (dt / " << level
            << ") fail the accuracy guard at t + " << done << " s: " << a.problem;
          const BondTurn turn = largest_bond_turn(ws.substep_positions, ws.substep_orientations, rod.bonds);
          if (a.bond_strain > limits.max_bond_strain && a.displacement <= limits.max_displacement &&
              a.strain_change <= limits.max_strain_change)
            m << "; the rod itself is over-strained (the loads stretch it beyond small-strain bonds at any step: "
                 "a stiffer rod (youngs_modulus) or a slower flow (the drag's inflow or viscosity))";
          else if (turn.degrees > kFoldedBondDegrees)
            m << "; the rod is folded at the substep's start: the bond between spheres " << turn.i << " and "
              << turn.j << " is turned " << turn.degrees << " deg against its spheres' frames (beam bonds are "
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
        restore(ws.substep_positions, ws.substep_orientations);
        level *= shrink;
        continue;
      }
      if (limits.adaptive || limits.max_growth > 0.0) {
        ws.previous_velocities.resize(n);
        for (int i = 0; i < n; ++i) ws.previous_velocities[i] = (rod.positions[i] - ws.substep_positions[i]) / h;
        previous_h = h;
      }
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
      done += h;
      ++report.substeps;
      if (done < dt * (1.0 - 1e-12) && drag_at) {
        drag_at(rod, ws.substep_drag);
        current_drag = &ws.substep_drag;
      }
    }
  } catch (...) {
    restore(ws.start_positions, ws.start_orientations);  // the rod unchanged
    throw;
  }
  for (int i = 0; i < n; ++i) total.velocities[i] = (rod.positions[i] - ws.start_positions[i]) / dt;
  if (report.substeps > 1) {
    // Displacement over the whole step, as the unguarded step reports it.
    total.largest_displacement = 0.0;
    for (int i = 0; i < n; ++i)
      total.largest_displacement =
          std::max(total.largest_displacement, (rod.positions[i] - ws.start_positions[i]).norm());
  }
  if (limits.report_bond_state) {
    const auto [strain, energy] = bond_strain_and_energy(rod);
    report.largest_bond_strain = strain;
    report.bond_energy = energy;
  }
}

}  // namespace hsrod
