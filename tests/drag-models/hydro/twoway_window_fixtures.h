// The scene shared by the level-4 window tests: the pore scene's spheres in a
// wall-free uniform stream, and a level-4 model with a state of its own.
#pragma once

#include "flow/background_flow.h"
#include "hydro/twoway_window_model.h"

#include <memory>
#include <string>

namespace hsrod_test {

constexpr double kMu = 1e-3;   // Pa s
constexpr double kD = 3e-6;    // m, the pore scene's spheres
constexpr double kPi = 3.14159265358979323846;

// Uniform gap-averaged stream of 1 mm/s along x in a slit of gap H, with a
// planform large enough to hold any window (no walls).
class UniformSlitStream : public hsrod::BackgroundFlow {
 public:
  explicit UniformSlitStream(double gap) : geometry_(1.0, 1.0, gap, -0.5, -0.5) {}
  Eigen::Vector2d velocity(double, double) const override { return {1e-3, 0.0}; }
  Eigen::Matrix2d velocity_gradient(double, double) const override { return Eigen::Matrix2d::Zero(); }
  double pressure(double, double) const override { return 0.0; }
  double mean_velocity() const override { return 1e-3; }
  const hsrod::ChannelGeometry& geometry() const override { return geometry_; }
  std::string description() const override { return "uniform slit stream"; }

 private:
  hsrod::ChannelGeometry geometry_;
};

// Level 4 at confinement beta = d / H for the pore scene's spheres.
inline std::unique_ptr<hsrod::TwoWayWindowSession> level4(double beta, hsrod::TwoWayWindowOptions options = {}) {
  return std::make_unique<hsrod::TwoWayWindowSession>(hsrod::HydrodynamicParameters{kMu, kD / beta, kD},
                                                      hsrod::ConfinementTable::default_table(), options);
}

}  // namespace hsrod_test
