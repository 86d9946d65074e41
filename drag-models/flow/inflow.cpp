#include "flow/inflow.h"

#include "common/math_constants.h"
#include "flow/brinkman_profile.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsrod {
namespace {

void require_positive(double value, const char* what) {
  if (!std::isfinite(value) || value <= 0.0) {
    std::ostringstream msg;
    msg << "Inflow: " << what << " must be a finite number > 0 (got " << value << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

Inflow Inflow::mean_velocity(double mean_velocity) {
  require_positive(mean_velocity, "mean velocity U [m/s]");
  return Inflow(Kind::kMeanVelocity, mean_velocity);
}

Inflow Inflow::flow_rate(double flow_rate) {
  require_positive(flow_rate, "flow rate Q [m^3/s]");
  return Inflow(Kind::kFlowRate, flow_rate);
}

double Inflow::mean_velocity_in(const ChannelGeometry& geometry) const {
  return kind_ == Kind::kMeanVelocity ? value_
                                      : value_ / (geometry.width() * geometry.gap_height());
}

double hydraulic_diameter(const ChannelGeometry& geometry) {
  const double w = geometry.width(), h = geometry.gap_height();
  return 4.0 * w * h / (2.0 * w + 2.0 * h);
}

double mean_velocity_for_channel_reynolds(double reynolds, const ChannelGeometry& geometry,
                                          const FluidProperties& fluid) {
  fluid.validate();
  if (!std::isfinite(reynolds) || reynolds <= 0.0 || fluid.density <= 0.0) {
    std::ostringstream msg;
    msg << "mean_velocity_for_channel_reynolds: need Re > 0 and rho_f > 0 (got Re = " << reynolds
        << ", rho_f = " << fluid.density << " kg/m^3)";
    throw std::invalid_argument(msg.str());
  }
  const double u_max = reynolds * fluid.dynamic_viscosity / (fluid.density * hydraulic_diameter(geometry));
  const BrinkmanChannelProfile profile(geometry.width(), geometry.gap_height());
  const double centreline = u_max / 1.5;  // gap average of the parabola = 2/3 of its peak
  return centreline / profile.centreline_to_mean();
}

void check_inflow_regime(double mean_velocity, const ChannelGeometry& geometry, const FluidProperties& fluid) {
  const double reynolds = fluid.density * mean_velocity * hydraulic_diameter(geometry) / fluid.dynamic_viscosity;
  const double sphere_force = 3.0 * kPi * fluid.dynamic_viscosity * geometry.gap_height() * mean_velocity;
  std::ostringstream msg;
  msg << "mean inflow velocity U = " << mean_velocity << " m/s (channel Reynolds number rho U D_h / mu = " << reynolds
      << ", mu = " << fluid.dynamic_viscosity << " Pa s, rho_f = " << fluid.density << " kg/m3)";
  if (!(std::isfinite(mean_velocity) && mean_velocity > 0.0 && std::isfinite(reynolds) &&
        std::isfinite(sphere_force))) {
    msg << " is not representable: the drag on a sphere, 3 pi mu H U = " << sphere_force
        << " N, overflows double precision";
    throw std::invalid_argument(msg.str());
  }
  if (reynolds > kLaminarChannelReynolds) {
    msg << " exceeds the laminar limit Re = " << kLaminarChannelReynolds
        << " of channel flow: the model is creeping (Stokes-Brinkman) flow";
    throw std::invalid_argument(msg.str());
  }
  if (mean_velocity > kIncompressibleSpeed) {
    msg << " exceeds " << kIncompressibleSpeed
        << " m/s (Mach 0.3 in water): the model is incompressible flow";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace hsrod
