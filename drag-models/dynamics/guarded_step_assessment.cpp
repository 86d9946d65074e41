// The checks of one (sub)step without taking it: sphere displacement, bond
// strain and its change, bond load against drag load, wall crossings and new
// overlaps (assess_step, for the guard's phases), and the reported residual.
#include "dynamics/guarded_step_internal.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace hsrod {
namespace {

using guard_detail::g3;

// A sphere's path is checked for walls at samples this far apart [radii]:
// a wall the path only clips between two samples goes unseen; closer
// samples cost a distance evaluation each.
constexpr double kPathSampleSpacing = 0.25;
// At most this many samples per path: bounds the cost of a wild step
// (hundreds of diameters, refused for its displacement anyway).
constexpr int kMaxPathSamples = 64;
// The planform's distance shortcut needs the path shorter than the start's
// distance by this relative margin: far above the distances' rounding, far
// below any clearance that matters.
constexpr double kPlanformClearMargin = 1e-9;

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

// Displacement, bond strain and its change, and the largest bond load
// change against the largest drag force of the step: the figures that need
// no walls.
void assess_motion(const std::vector<Eigen::Vector3d>& x0, const OverdampedRod& after, const RodDrag& drag, double dt,
                   StepAssessment& a) {
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
}

// Walls: the new centre, and the path (sampled every kPathSampleSpacing
// radii). The planform's signed distance is 1-Lipschitz (a minimum of
// distances), so a path shorter in the plane than the start's distance to
// the walls (by a margin far above rounding) has every sample off them: only
// the gap walls are then checked along it (the same answers, fewer
// distances; the start's distance is kept for the overlap check).
void find_wall_crossing(const std::vector<Eigen::Vector3d>& x0, const OverdampedRod& after,
                        const ChannelGeometry& geometry, const WallContactParameters* walls, StepAssessment& a) {
  std::vector<double>& start_distance = thread_local_start_distance();
  KnownDistances& known = thread_local_known_distances();
  const int n = after.size();
  start_distance.assign(n, 0.0);
  known.reset(&geometry, n);
  for (int i = 0; i < n && a.crossing_sphere < 0; ++i) {
    const Eigen::Vector3d step = after.positions[i] - x0[i];
    const int samples = std::clamp(static_cast<int>(std::ceil(step.norm() / (kPathSampleSpacing * after.radii[i]))), 1,
                                   kMaxPathSamples);
    const double d0 = known.of(i, x0[i]);
    start_distance[i] = d0;
    known.keep(2 * i, x0[i], d0);
    const double reach = step.head<2>().norm();
    const bool planform_clear = d0 - reach > kPlanformClearMargin * (std::fabs(d0) + reach);
    for (int k = 1; k <= samples; ++k) {
      const Eigen::Vector3d p = x0[i] + step * (double(k) / samples);
      if ((planform_clear ? in_gap_wall(p, geometry, walls) : in_wall(p, geometry, walls)) &&
          !in_wall(x0[i], geometry, walls)) {
        a.crossing_sphere = i;
        break;
      }
    }
  }
}

// New wall overlap beyond max_overlap radii (after find_wall_crossing found
// no crossing: it keeps the start distances).
void find_new_wall_overlap(const std::vector<Eigen::Vector3d>& x0, const OverdampedRod& after,
                           const ChannelGeometry& geometry, const WallContactParameters* walls,
                           const StepGuardLimits& limits, StepAssessment& a) {
  const std::vector<double>& start_distance = thread_local_start_distance();
  KnownDistances& known = thread_local_known_distances();
  const int n = after.size();
  for (int i = 0; i < n; ++i) {
    const double radius = after.radii[i];
    auto overlap = [&](const Eigen::Vector3d& p, double planform_distance) {
      double o = radius - planform_distance;
      if (walls && walls->gap_walls) {
        o = std::max(o, radius - (p.z() - walls->gap_bottom));
        o = std::max(o, radius - (walls->gap_bottom + geometry.gap_height() - p.z()));
      }
      return o;
    };
    const Eigen::Vector3d& p1 = after.positions[i];
    const double d1 = geometry.signed_distance(p1.x(), p1.y());
    known.keep(2 * i + 1, p1, d1);
    const double grown = overlap(p1, d1) - std::max(0.0, overlap(x0[i], start_distance[i]));
    if (grown > limits.max_overlap * radius) {
      a.crossing_sphere = i;
      break;
    }
  }
}

// Spheres of two rods (a cluster stepped together) pressed into each other
// beyond max_overlap radii in one step: the Hertz contact, linearised at
// the step's start, cannot stop an approach it did not see.
void find_rod_interpenetration(const std::vector<Eigen::Vector3d>& x0, const OverdampedRod& after,
                               const StepGuardLimits& limits, StepAssessment& a) {
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

// The first limit the figures exceed, in words (a.problem).
void name_problem(const StepGuardLimits& limits, StepAssessment& a) {
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

}  // namespace

namespace guard_detail {

std::string g3(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

StepAssessment assess_step(const std::vector<Eigen::Vector3d>& x0, const OverdampedRod& after, const RodDrag& drag,
                           double dt, const ChannelGeometry* geometry, const WallContactParameters* walls,
                           const StepGuardLimits& limits) {
  StepAssessment a;
  assess_motion(x0, after, drag, dt, a);
  if (limits.check_walls && geometry) find_wall_crossing(x0, after, *geometry, walls, a);
  if (limits.check_walls && geometry && a.crossing_sphere < 0)
    find_new_wall_overlap(x0, after, *geometry, walls, limits, a);
  if (walls && walls->rod_contact && !after.rod_of_sphere.empty() && a.crossing_sphere < 0)
    find_rod_interpenetration(x0, after, limits, a);
  if (a.displacement > limits.max_displacement || a.strain_change > limits.max_strain_change ||
      a.bond_strain > limits.max_bond_strain || a.crossing_sphere >= 0 || a.interpenetrating_sphere >= 0)
    name_problem(limits, a);
  return a;
}

}  // namespace guard_detail

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

StepAssessment assess_rod_step(const OverdampedRod& before, const OverdampedRod& after,
                               const OverdampedStepResult& result, const RodDrag& drag, double dt,
                               const ChannelGeometry* geometry, const WallContactParameters* walls,
                               const StepGuardLimits& limits) {
  (void)result;
  StepAssessment a = guard_detail::assess_step(before.positions, after, drag, dt, geometry, walls, limits);
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

}  // namespace hsrod
