#include "flow/straight_channel_flow.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace hsrod {

StraightChannelFlow::StraightChannelFlow(const ChannelGeometry& geometry,
                                         const FluidProperties& fluid, const Inflow& inflow)
    : geometry_(geometry),
      profile_(geometry.width(), geometry.gap_height()),
      mean_velocity_(inflow.mean_velocity_in(geometry)) {
  fluid.validate();
  if (!geometry.is_straight())
    throw std::invalid_argument(
        "StraightChannelFlow: the geometry has obstacles; use GridBrinkmanFlow or "
        "make_background_flow for this planform");
  pressure_gradient_ = profile_.pressure_gradient_factor() * fluid.dynamic_viscosity * mean_velocity_;
}

Eigen::Vector2d StraightChannelFlow::velocity(double /*x*/, double y) const {
  return Eigen::Vector2d(mean_velocity_ * profile_.shape(y - geometry_.y_lo()), 0.0);
}

Eigen::Matrix2d StraightChannelFlow::velocity_gradient(double /*x*/, double y) const {
  const double s = y - geometry_.y_lo();
  Eigen::Matrix2d g = Eigen::Matrix2d::Zero();
  if (s > 0.0 && s < geometry_.width()) g(0, 1) = mean_velocity_ * profile_.shape_slope(s);
  return g;
}

double StraightChannelFlow::pressure(double x, double /*y*/) const {
  const double xc = std::clamp(x, geometry_.x_lo(), geometry_.x_hi());
  return pressure_gradient_ * (xc - geometry_.x_hi());
}

std::string StraightChannelFlow::description() const {
  std::ostringstream s;
  s << "closed-form Brinkman channel profile (no grid): W = " << geometry_.width()
    << " m, H = " << geometry_.gap_height() << " m, U = " << mean_velocity_
    << " m/s, wall layer H/sqrt(12) = " << profile_.wall_layer_length() << " m";
  return s.str();
}

}  // namespace hsrod
