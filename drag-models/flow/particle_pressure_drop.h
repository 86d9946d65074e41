// Additional pressure drop of the channel caused by the forces on particles
// (the spheres of the rods), from the Lorentz reciprocal theorem: for Stokes
// flow driven at a fixed flow rate Q, particles on which the fluid exerts the
// forces F_i raise the pressure drop between inlet and outlet by
//     dP_particles = (1 / Q) sum_i F_i . <u0>_i ,
// <u0>_i the undisturbed background velocity averaged over the surface of
// sphere i (Happel & Brenner, Low Reynolds Number Hydrodynamics, 1965, ch. 9:
// the additional pressure drop of a particle in a tube; Brenner 1966 for the
// general form). It is the extra power Q dP the pump spends against the
// particles' resistance. The background is the 3-D field u(x, y) g(z),
// g = 6 (z/H)(1 - z/H); the surface average of a sphere of radius a is
// (1 + a^2/6 lap) u0, exact in z for the parabola: u(x, y) (g(z) - 2 a^2 / H^2)
// (the in-plane Laplacian of u, which vanishes in the Hele-Shaw bulk, is
// neglected). Held spheres (F along the flow) raise the pressure drop;
// spheres carried freely by the flow (F ~ 0) hardly do.
// Valid for small particles (a << H) at rest or moving slowly in a flow driven
// at fixed Q; it is the model's estimate, not a solved pressure field.
#pragma once

#include "flow/background_flow.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

struct ParticleLoad {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // sphere centre [m]
  double radius = 0.0;                                 // a [m]
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     // hydrodynamic force on the sphere [N]
};

// Surface average <u0> [m/s] of the 3-D background velocity over a sphere of
// radius `radius` [m] centred at `position` [m]; z measured from `z_bottom`
// (the lower gap wall) [m]. Zero outside the fluid.
Eigen::Vector3d sphere_mean_background_velocity(const BackgroundFlow& flow, const Eigen::Vector3d& position,
                                                double radius, double z_bottom);

// dP_particles [Pa] for `loads` in a flow of rate `flow_rate` Q [m^3/s] (> 0).
double particle_pressure_drop(const BackgroundFlow& flow, const std::vector<ParticleLoad>& loads,
                              double z_bottom, double flow_rate);

}  // namespace hsrod
