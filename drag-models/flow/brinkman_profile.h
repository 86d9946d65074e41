// Fully developed depth-averaged Brinkman profile across a straight channel.
//
// The gap-averaged velocity u(y) of a channel of width W and gap H solves
//     mu u'' - (12 mu / H^2) u = dp/dx,   u(0) = u(W) = 0
// (Brinkman equation of the Hele-Shaw channel, Gondret & Rabaud, Phys. Fluids
// 9, 3267 (1997); the friction 12 mu / H^2 u is the gap average of the
// Poiseuille profile).
// With k = sqrt(12) / H and a = k W / 2 the solution scaled to the mean U is
//     u(y) / U = [1 - cosh(k (y - W/2)) / cosh(a)] / [1 - tanh(a) / a].
// Near a side wall (W >> H) u / u_centre = 1 - exp(-k y): the wall layer has
// the Brinkman length delta = H / sqrt(12).
#pragma once

namespace hsrod {

class BrinkmanChannelProfile {
 public:
  // width W [m] and gap_height H [m], both > 0.
  BrinkmanChannelProfile(double width, double gap_height);

  // u(y) / U_mean for y [m] measured from the lower side wall; 0 outside [0, W].
  double shape(double y) const;
  // d(u / U_mean)/dy [1/m] at y [m] (0 outside [0, W]).
  double shape_slope(double y) const;
  // u(W/2) / U_mean = (1 - 1/cosh(a)) / (1 - tanh(a)/a) [-]; -> 1 for W >> H,
  // 3/2 (plane Poiseuille) for W << H.
  double centreline_to_mean() const { return shape(0.5 * width_); }
  // dp/dx per unit mean velocity and viscosity: dp/dx = -k^2 mu U / (1 - tanh(a)/a)
  // [1/m^2]; multiply by mu U to get Pa/m.
  double pressure_gradient_factor() const { return -k_ * k_ / mean_factor_; }
  // Brinkman wall-layer length delta = H / sqrt(12) [m].
  double wall_layer_length() const { return 1.0 / k_; }

 private:
  double width_;        // W [m]
  double k_;            // sqrt(12) / H [1/m]
  double a_;            // k W / 2 [-]
  double mean_factor_;  // 1 - tanh(a)/a [-]
};

}  // namespace hsrod
