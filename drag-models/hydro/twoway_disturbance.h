// The flow disturbed by the rods at level 4, for field output:
// each rod's window (hydro/twoway_window_model.h) solved for the reaction of
// the obstruction forces its spheres felt at their last evaluation.
//
// Level 4 splits a sphere's in-plane load into film friction with the gap
// walls, -zeta_f v (it does not act on the planform flow), and the
// obstruction force P = R_o (c <u_bg> - v), whose reaction -P, spread over
// the sphere's footprint, drives the window flow u', p'. From a load as the
// drag fix stores it (total F and friction -R v, R = R_o + zeta_f I in-plane,
// the same evaluation), v = -R^-1 friction and P = F + zeta_f v: no new
// evaluation of the model and no advance of its state.
#pragma once

#include "flow/window_flow_field.h"
#include "hydro/twoway_window_model.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

// One rod's last load, sphere by sphere in the model's order.
struct RodLoadSample {
  int id = 0;                                   // RodGeometry::id (the molecule ID)
  std::vector<Eigen::Vector3d> positions;       // sphere centres [m]
  std::vector<Eigen::Vector3d> total_force;     // hydrodynamic force on each sphere [N]
  std::vector<Eigen::Vector3d> friction_force;  // its friction part -(R v) [N]
};

// In-plane obstruction forces P [N] (x, y per sphere) of `rod` from its
// stored load and the window state's resistance R_o of that rod. Throws
// std::invalid_argument if the state has no resistance of that size.
Eigen::VectorXd twoway_obstruction_forces(const TwoWayWindowModel& model, const TwoWayWindowState& state,
                                          const RodLoadSample& rod);

// The disturbance flow of each rod that has a window in `state` (rods
// without one, e.g. not yet evaluated, are skipped), in the scene `geometry`.
std::vector<WindowFlowField> twoway_disturbances(const TwoWayWindowModel& model, const TwoWayWindowState& state,
                                                 const std::vector<RodLoadSample>& rods,
                                                 const ChannelGeometry& geometry);

}  // namespace hsrod
