#include "hydro/cross_rod_disturbance.h"

#include "hydro/cross_rod_far_field.h"
#include "hydro/nonlocal_model.h"

#include <algorithm>
#include <stdexcept>

namespace hsrod {

void RodObstructionForces::start(int spheres) {
  const Eigen::Index size = 2 * spheres;
  if (driving.size() != size) driving.setZero(size);
  if (velocity.size() != size) velocity.setZero(size);
  clear_disturbance();
}

void RodObstructionForces::clear_disturbance() {
  driving_disturbance.setZero(driving.size());
  velocity_disturbance.setZero(driving.size());
}

void add_cross_rod_disturbance(const UnitObstruction& unit, RodDrag& out) {
  const Eigen::Index size = unit.friction.rows();
  if (unit.driving_disturbance.size() != size || unit.velocity_disturbance.size() != size ||
      2 * static_cast<Eigen::Index>(out.driving_force.size()) != size)
    throw std::invalid_argument("cross-rod disturbance: unit and load sizes differ");
  const Eigen::VectorXd extra = unit.friction * unit.velocity_disturbance - unit.held() * unit.driving_disturbance;
  for (Eigen::Index i = 0; i < size / 2; ++i) out.driving_force[i].head<2>() += extra.segment<2>(2 * i);
}

void unit_obstruction_forces(const UnitObstruction& unit, const std::vector<Eigen::Vector3d>& velocities,
                             Eigen::VectorXd& driving, Eigen::VectorXd& velocity) {
  const Eigen::Index size = unit.friction.rows();
  Eigen::VectorXd v(size);
  for (Eigen::Index i = 0; i < size / 2; ++i) v.segment<2>(2 * i) = velocities[i].head<2>();
  driving = unit.lone_driving - unit.held() * unit.driving_disturbance;
  velocity = unit.friction * (v - unit.velocity_disturbance);
}

double obstruction_change(const std::vector<RodObstructionForces>& before,
                          const std::vector<RodObstructionForces>& now) {
  double change = 0.0, largest = 0.0;
  for (std::size_t r = 0; r < now.size(); ++r) {
    const Eigen::VectorXd p = now[r].driving - now[r].velocity;
    for (Eigen::Index i = 0; i < p.size() / 2; ++i) largest = std::max(largest, p.segment<2>(2 * i).norm());
    if (r >= before.size() || before[r].driving.size() != p.size()) return 1.0;
    const Eigen::VectorXd q = before[r].driving - before[r].velocity;
    for (Eigen::Index i = 0; i < p.size() / 2; ++i)
      change = std::max(change, (p.segment<2>(2 * i) - q.segment<2>(2 * i)).norm());
  }
  return largest > 0.0 ? change / largest : change;
}

NonlocalState* NonlocalRodModel::own_state(ModelState* state) const {
  if (!state) return nullptr;
  auto* own = dynamic_cast<NonlocalState*>(state);
  if (!own) throw std::invalid_argument("nonlocal: the state given is not a level-3 state (make_state())");
  return own;
}

void NonlocalRodModel::evaluate_alone(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                                      ModelState* state, UnitObstruction& unit) const {
  if (wall_reflection_ != WallReflection::none)
    throw std::invalid_argument("nonlocal: rods solved apart (lagged or iterated coupling) carry no wall images "
                                "between rods; use wall_reflection none or the joint coupling");
  if (rods.empty()) throw std::invalid_argument("nonlocal: evaluate_alone needs at least one rod");
  NonlocalState* own = own_state(state);
  if (rods.size() == 1) {
    evaluate_with(rods.front(), flow, out, own, rods.front().id, &unit);
    return;
  }
  int smallest = rods.front().id;  // the key evaluate_rods keeps these rods' coupling under
  for (const RodGeometry& r : rods) smallest = std::min(smallest, r.id);
  evaluate_with(joined_rods(rods, rods.front().id), flow, out, own, -(1 + smallest), &unit);
}

void NonlocalRodModel::add_disturbance(const RodGeometry& target, RodObstructionForces& target_forces,
                                       const RodGeometry& source, const RodObstructionForces& source_forces) const {
  const bool own = own_driving();
  Eigen::Matrix2d m, md;
  for (int i = 0; i < target.size(); ++i) {
    for (int k = 0; k < source.size(); ++k) {
      // The block (i, k) solve_coupling puts into M for two spheres of one rod.
      const Eigen::Vector2d offset = (target.positions[i] - source.positions[k]).head<2>();
      if (offset.norm() <= 0.0) continue;
      pair_mobility(offset, m, own ? &md : nullptr);
      target_forces.velocity_disturbance.segment<2>(2 * i) += m * source_forces.velocity.segment<2>(2 * k);
      target_forces.driving_disturbance.segment<2>(2 * i) += (own ? md : m) * source_forces.driving.segment<2>(2 * k);
    }
  }
}

void NonlocalRodModel::set_far_field_scene(CrossRodFarField& far_field) const {
  far_field.set_scene(parameters_.viscosity, parameters_.gap_height, interaction_reach());
}

}  // namespace hsrod
