// Closed-form background flow of a straight channel (no grid, no solve): the
// developed depth-averaged Brinkman profile (flow/brinkman_profile.h) at every
// x, and a linear pressure dp/dx = -12 mu U / (H^2 (1 - tanh(a)/a)), p = 0 at
// the outlet. The gap-averaged inertia term (6/5) rho (u.grad)u vanishes for
// this field, so it is exact with or without inertia.
#pragma once

#include "flow/background_flow.h"
#include "flow/brinkman_profile.h"
#include "flow/fluid_properties.h"
#include "flow/inflow.h"

namespace hsrod {

class StraightChannelFlow final : public BackgroundFlow {
 public:
  // Throws std::invalid_argument if the geometry has obstacles.
  StraightChannelFlow(const ChannelGeometry& geometry, const FluidProperties& fluid,
                      const Inflow& inflow);

  Eigen::Vector2d velocity(double x, double y) const override;
  Eigen::Matrix2d velocity_gradient(double x, double y) const override;
  double pressure(double x, double y) const override;
  double mean_velocity() const override { return mean_velocity_; }
  const ChannelGeometry& geometry() const override { return geometry_; }
  std::string description() const override;

  const BrinkmanChannelProfile& profile() const { return profile_; }
  // dp/dx [Pa/m] (negative for flow towards +x).
  double pressure_gradient() const { return pressure_gradient_; }

 private:
  ChannelGeometry geometry_;
  BrinkmanChannelProfile profile_;
  double mean_velocity_;      // U [m/s]
  double pressure_gradient_;  // dp/dx [Pa/m]
};

}  // namespace hsrod
