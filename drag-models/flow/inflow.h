// Inflow of a scene: the fully developed Brinkman profile enters at x_lo with
// a given mean gap-averaged velocity U, or flow rate Q = U W H.
#pragma once

#include "flow/fluid_properties.h"
#include "geometry/channel_geometry.h"

namespace hsrod {

class Inflow {
 public:
  // Mean gap-averaged inlet velocity U [m/s], > 0 (flow towards +x).
  static Inflow mean_velocity(double mean_velocity);
  // Volumetric flow rate Q [m^3/s], > 0; U = Q / (W H).
  static Inflow flow_rate(double flow_rate);

  // Mean inlet velocity U [m/s] in the given channel.
  double mean_velocity_in(const ChannelGeometry& geometry) const;

 private:
  enum class Kind { kMeanVelocity, kFlowRate };
  Inflow(Kind kind, double value) : kind_(kind), value_(value) {}
  Kind kind_;
  double value_;  // m/s or m^3/s
};

// Hydraulic diameter of the inlet cross-section D_h = 4 W H / (2 W + 2 H) [m]
// (Braesel et al. 2024, below Table 1).
double hydraulic_diameter(const ChannelGeometry& geometry);

// Mean inlet velocity U [m/s] for the paper's channel Reynolds number
// Re = D_h u_max rho_f / mu (Braesel et al. 2024, below Table 1), where u_max
// is the peak of the 3-D inlet profile: the gap-averaged centreline velocity of
// the developed Brinkman profile times 3/2 (parabolic gap profile). For the
// pore scene (W = 200 um, H = 20 um, rho_f = 1170 kg/m^3, mu = 1 mPa s) Re = 2
// gives u_max = 4.70 cm/s and U = 2.95 cm/s.
double mean_velocity_for_channel_reynolds(double reynolds, const ChannelGeometry& geometry,
                                          const FluidProperties& fluid);

// The regime the model holds in: incompressible creeping (Stokes-Brinkman)
// flow. Laminar channel flow ends near Re = rho U D_h / mu = 2300 (mean
// velocity; the classical transition of duct flow), and a liquid is
// incompressible only well below its speed of sound (Mach 0.3 of water's
// 1480 m/s, the slowest common liquids ~900 m/s, gives 444 m/s).
inline constexpr double kLaminarChannelReynolds = 2300.0;  // [-]
inline constexpr double kIncompressibleSpeed = 444.0;      // [m/s]

// Throws std::invalid_argument when a mean inflow velocity U [m/s] is not
// finite, would make the flow turbulent or compressible, or gives forces
// 3 pi mu H U on a sphere of the gap's size that overflow: each message
// states U, the Reynolds number and the limit.
void check_inflow_regime(double mean_velocity, const ChannelGeometry& geometry, const FluidProperties& fluid);

}  // namespace hsrod
