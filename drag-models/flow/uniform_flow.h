// A uniform gap-averaged stream over a planform: the rod-free flow far from
// walls (a wide slit, a planform much larger than the rod), or fluid at rest
// in a channel whose walls and cylinders only the wall-aware models see.
// It is the reference flow of the model tests and the cross-check tools; a
// scene's real flow comes from make_background_flow().
#pragma once

#include "flow/background_flow.h"

#include <Eigen/Core>

#include <string>

namespace hsrod {

class UniformFlow : public BackgroundFlow {
 public:
  // velocity: the gap-averaged stream (u_x, u_y) [m/s] in the fluid; zero
  // inside walls and cylinders (the convention of every BackgroundFlow).
  UniformFlow(ChannelGeometry geometry, Eigen::Vector2d velocity, std::string description = "uniform stream");
  // A wide slit of gap height H [m]: a 1 m x 1 m planform centred on the
  // origin, so that no window or wall law of a micrometre rod reaches a wall.
  static UniformFlow wide_slit(double gap_height, Eigen::Vector2d velocity);

  Eigen::Vector2d velocity(double x, double y) const override;
  Eigen::Matrix2d velocity_gradient(double, double) const override { return Eigen::Matrix2d::Zero(); }
  double pressure(double, double) const override { return 0.0; }
  double mean_velocity() const override { return velocity_.norm(); }
  const ChannelGeometry& geometry() const override { return geometry_; }
  std::string description() const override { return description_; }

 private:
  ChannelGeometry geometry_;
  Eigen::Vector2d velocity_;  // [m/s]
  std::string description_;
};

}  // namespace hsrod
