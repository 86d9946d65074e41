// Background (rod-free) flow of a scene: the depth-averaged Brinkman field
//     mu lap(u) - (12 mu / H^2) u - grad p = 0,   div u = 0
// in the planform, no-slip on walls and obstacles, the developed Brinkman
// profile at the inlet x_lo and p = 0 at the outlet x_hi (Brinkman model of
// a Hele-Shaw cell). u is the gap-averaged velocity; the 3-D field is
// u(x, y) * 6 (z/H)(1 - z/H) with z measured from the lower gap wall (z = 0)
// to the upper one (z = H).
//
// Conventions shared by all implementations:
//  - points outside the fluid (inside a wall or obstacle) have zero velocity;
//  - beyond the inlet or outlet plane the flow is taken as the flow at that
//    plane (x is clamped to [x_lo, x_hi]: the developed profile continues).
#pragma once

#include "geometry/channel_geometry.h"

#include <Eigen/Core>

#include <string>

namespace hsrod {

class BackgroundFlow {
 public:
  virtual ~BackgroundFlow() = default;

  // Gap-averaged velocity (u_x, u_y) [m/s] at the planform point (x, y) [m].
  virtual Eigen::Vector2d velocity(double x, double y) const = 0;
  // Gradient of the gap-averaged velocity, G(a, b) = d u_a / d x_b [1/s].
  virtual Eigen::Matrix2d velocity_gradient(double x, double y) const = 0;
  // Both at once, the same values as velocity() and velocity_gradient(): a
  // drag model needs both at every sphere in every step, and a grid flow
  // then finds the wall distance and the interpolation stencil once.
  virtual void velocity_and_gradient(double x, double y, Eigen::Vector2d& u, Eigen::Matrix2d& g) const {
    u = velocity(x, y);
    g = velocity_gradient(x, y);
  }
  // Gap pressure [Pa], gauge, 0 at the outlet.
  virtual double pressure(double x, double y) const = 0;
  // Mean gap-averaged inlet velocity U = Q / (W H) [m/s].
  virtual double mean_velocity() const = 0;
  // The scene planform this flow was computed for.
  virtual const ChannelGeometry& geometry() const = 0;
  // One line saying which model this is (and for grids: size, cache use).
  virtual std::string description() const = 0;

  // 3-D velocity [m/s] at (x, y, z) [m], z in [0, H] from the lower gap wall:
  // (u_x, u_y, 0) * 6 (z/H)(1 - z/H); zero for z outside [0, H].
  Eigen::Vector3d velocity3d(double x, double y, double z) const;
  // Gradient of velocity3d, G(a, b) = d u_a / d x_b [1/s] (3x3).
  Eigen::Matrix3d velocity_gradient3d(double x, double y, double z) const;

  // Parabolic gap profile 6 (z/H)(1 - z/H) [-] (gap average 1, peak 3/2 at z = H/2).
  static double gap_profile(double z, double gap_height);
};

}  // namespace hsrod
