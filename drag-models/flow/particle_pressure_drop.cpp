#include "flow/particle_pressure_drop.h"

#include <stdexcept>

namespace hsrod {

Eigen::Vector3d sphere_mean_background_velocity(const BackgroundFlow& flow, const Eigen::Vector3d& position,
                                                double radius, double z_bottom) {
  const ChannelGeometry& g = flow.geometry();
  const double h = g.gap_height(), z = position.z() - z_bottom;
  if (z < 0.0 || z > h || !g.is_fluid(position.x(), position.y())) return Eigen::Vector3d::Zero();
  // (1 + a^2/6 d^2/dz^2) g(z) with g'' = -12 / H^2.
  const double profile = BackgroundFlow::gap_profile(z, h) - 2.0 * radius * radius / (h * h);
  const Eigen::Vector2d u = flow.velocity(position.x(), position.y());
  return Eigen::Vector3d(profile * u.x(), profile * u.y(), 0.0);
}

double particle_pressure_drop(const BackgroundFlow& flow, const std::vector<ParticleLoad>& loads, double z_bottom,
                              double flow_rate) {
  if (!(flow_rate > 0.0)) throw std::invalid_argument("particle_pressure_drop: flow_rate must be > 0 m^3/s");
  double power = 0.0;  // sum F . <u0> [W]
  for (const ParticleLoad& p : loads)
    power += p.force.dot(sphere_mean_background_velocity(flow, p.position, p.radius, z_bottom));
  return power / flow_rate;
}

}  // namespace hsrod
