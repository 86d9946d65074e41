// Small-displacement (linearised) mechanics of a rod about its straight
// rest layout: stiffness from the beam bonds, lumped sphere masses. Used for
// the stability limit (highest eigenfrequency) and for checking the bond
// model against Euler-Bernoulli theory.
#pragma once

#include "rod/beam_bond.h"
#include "rod/rod_layout.h"

#include <Eigen/Core>

namespace hsrod {

struct SphereMaterial;

// Dense 6n x 6n stiffness (dof per sphere: displacement [m], rotation
// vector [rad]); loads are forces [N] and torques [N m]. Central
// differences of the full nonlinear bond law, symmetrised.
Eigen::MatrixXd linearised_bond_stiffness(const RodLayout& layout, const BeamBondMaterial& bond);

// Rest state of a layout bond: spheres at their layout positions with
// identity orientations (the state create_rod makes).
BeamBondRest layout_rest_state(const RodLayout& layout, const std::pair<int, int>& bond);

// Bond forces/torques (6n) for a displacement/rotation vector `dof` (6n).
Eigen::VectorXd rod_bond_loads(const RodLayout& layout, const BeamBondMaterial& bond,
                               const Eigen::VectorXd& dof);

// Dense 6n x 6n damping matrix C (loads = -C velocities) of the bond
// dashpots at the rest state, for spheres of `sphere` material.
Eigen::MatrixXd linearised_bond_damping(const RodLayout& layout, const BeamBondMaterial& bond,
                                        const SphereMaterial& sphere);

// Largest timestep [s] for which LIGGGHTS' velocity Verlet (fix nve/sphere:
// half kick, drift, forces from the new positions and the half-step
// velocities, half kick) is stable on the linear system M a = -K x - C v:
// bisection on the spectral radius of the one-step map. Undamped it is
// 2 / omega_max; damping evaluated at the lagged half-step velocity lowers it.
double velocity_verlet_limit(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& damping,
                             const Eigen::VectorXd& mass_diagonal);

// Diagonal of the lumped mass matrix: m for translations, m d^2/10 for rotations.
Eigen::VectorXd rod_mass_diagonal(const RodLayout& layout, const SphereMaterial& sphere);

}  // namespace hsrod
