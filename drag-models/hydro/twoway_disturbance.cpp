#include "hydro/twoway_disturbance.h"

#include <Eigen/LU>

#include <stdexcept>
#include <string>

namespace hsrod {

Eigen::VectorXd twoway_obstruction_forces(const TwoWayWindowModel& model, const TwoWayWindowState& state,
                                          const RodLoadSample& rod) {
  const int n = static_cast<int>(rod.positions.size());
  if (static_cast<int>(rod.total_force.size()) != n || static_cast<int>(rod.friction_force.size()) != n)
    throw std::invalid_argument("twoway disturbance: rod " + std::to_string(rod.id) + ": one load per sphere needed");
  const auto it = state.rods.find(rod.id);
  if (it == state.rods.end() || it->second.obstruction.rows() != 2 * n)
    throw std::invalid_argument("twoway disturbance: no stored resistance of " + std::to_string(n) +
                                " spheres for rod " + std::to_string(rod.id));
  const double zeta_f = model.film_friction();
  Eigen::MatrixXd resistance = it->second.obstruction;  // R_o, then R = R_o + zeta_f I
  resistance.diagonal().array() += zeta_f;
  Eigen::VectorXd total(2 * n), friction(2 * n);
  for (int i = 0; i < n; ++i) {
    total.segment<2>(2 * i) = rod.total_force[i].head<2>();
    friction.segment<2>(2 * i) = rod.friction_force[i].head<2>();
  }
  const Eigen::VectorXd velocity = -resistance.partialPivLu().solve(friction);  // v used in that load [m/s]
  return total + zeta_f * velocity;
}

std::vector<WindowFlowField> twoway_disturbances(const TwoWayWindowModel& model, const TwoWayWindowState& state,
                                                 const std::vector<RodLoadSample>& rods,
                                                 const ChannelGeometry& geometry) {
  std::vector<WindowFlowField> fields;
  for (const RodLoadSample& rod : rods) {
    const BrinkmanWindow* window = state.window_of(rod.id);
    if (!window) continue;
    const Eigen::VectorXd obstruction = twoway_obstruction_forces(model, state, rod);
    fields.emplace_back(*window, model.fluid_node_forces(*window, rod.positions, obstruction), geometry);
  }
  return fields;
}

}  // namespace hsrod
