// Time scales that bound an explicit (velocity-Verlet) step of a bonded rod.
// For the paper's pore scene they range from 22 ns (axial bond, E = 15 MPa) to
// 2.3 us (Hertz contact, E = 15 kPa); this computes them for the rod of a run.
#pragma once

#include "rod/beam_bond.h"
#include "rod/rod_layout.h"

#include <string>

namespace hsrod {

struct SphereMaterial {
  double diameter = 0.0;        // d [m]
  double density = 0.0;         // rho_p [kg/m^3]
  double youngs_modulus = 0.0;  // E [Pa]
  double poisson_ratio = 0.0;   // nu [-]

  double mass() const;                    // m = rho pi d^3 / 6 [kg]
  double moment_of_inertia() const;       // I_s = m d^2 / 10 [kg m^2]
};

struct RodStabilityLimits {
  double rayleigh_time = 0.0;        // Hertz contact: pi r sqrt(rho/G) / (0.1631 nu + 0.8766) [s]
  double axial_bond_time = 0.0;      // sqrt(m / k_n) [s]
  double bending_bond_time = 0.0;    // sqrt(I_s / k_b) [s]
  double stokes_relaxation_time = 0.0;  // m / (3 pi mu d) [s], 0 when no viscosity given
  double highest_bond_frequency = 0.0;  // omega_max of the linearised rod [rad/s]
  // Velocity Verlet (fix nve/sphere) is unstable above this step: 2 / omega_max
  // for undamped bonds, lower with bond damping (see velocity_verlet_limit).
  double explicit_bond_limit = 0.0;  // [s]
  // Whether explicit_bond_limit includes the bond dashpots' reduction (it
  // is 2 / omega_max when not: compute_stability_limits(..., false)).
  bool damping_included = true;

  // A human-readable table (one line per limit) for the run's log.
  std::string table(double timestep) const;
};

// `viscosity` [Pa s] may be 0 (no fluid). The highest bond frequency comes
// from the generalised eigenproblem K v = omega^2 M v of the rod's bonds
// linearised about the straight rest state (all 6 dof per sphere).
// `with_damping` false skips the dashpots' reduction of the explicit limit
// (an eigenvalue bisection on the one-step map, ~7e8 instructions, most of
// a short run's start-up): for callers whose bonds are integrated
// implicitly, where the explicit limit does not bind.
// Throws std::invalid_argument when the modulus puts omega_max out of
// double precision's range (the limits would all read 0 s).
RodStabilityLimits compute_stability_limits(const RodLayout& layout, const SphereMaterial& sphere,
                                            const BeamBondMaterial& bond, double viscosity, bool with_damping = true);

}  // namespace hsrod
