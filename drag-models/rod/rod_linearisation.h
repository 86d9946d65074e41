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

// Bond forces/torques (6n) for a displacement/rotation vector `dof` (6n).
Eigen::VectorXd rod_bond_loads(const RodLayout& layout, const BeamBondMaterial& bond,
                               const Eigen::VectorXd& dof);

// Diagonal of the lumped mass matrix: m for translations, m d^2/10 for rotations.
Eigen::VectorXd rod_mass_diagonal(const RodLayout& layout, const SphereMaterial& sphere);

}  // namespace hsrod
