#include "flow/uniform_flow.h"

#include <algorithm>
#include <utility>

namespace hsrod {

UniformFlow::UniformFlow(ChannelGeometry geometry, Eigen::Vector2d velocity, std::string description)
    : geometry_(std::move(geometry)), velocity_(velocity), description_(std::move(description)) {}

UniformFlow UniformFlow::wide_slit(double gap_height, Eigen::Vector2d velocity) {
  return UniformFlow(ChannelGeometry(1.0, 1.0, gap_height, -0.5, -0.5), velocity, "uniform stream in a wide slit");
}

Eigen::Vector2d UniformFlow::velocity(double x, double y) const {
  // Beyond the inlet and outlet planes the stream continues (BackgroundFlow's convention).
  const double x_in = std::clamp(x, geometry_.x_lo(), geometry_.x_hi());
  return geometry_.is_fluid(x_in, y) ? velocity_ : Eigen::Vector2d::Zero();
}

}  // namespace hsrod
