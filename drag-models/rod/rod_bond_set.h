// The bonds of a rod as one material: the one place where the bond fix's
// E, nu, bond thickness and damping become the stiffness of a bond between
// two spheres (rod/beam_bond.h) and the rod's bending stiffness EI.
// fix rod/bonds owns one and hands it out (FixRodBonds::bond_set()); the
// implicit step, the `auto` policy and the wall contacts read it.
#pragma once

#include "rod/beam_bond.h"

namespace hsrod {

struct RodBondSet {
  double youngs_modulus = 0.0;     // E [Pa]
  double poisson_ratio = 0.3;      // nu [-]
  double damping_ratio = 0.0;      // fraction of critical damping of each spring [-]
  double bond_radius_ratio = 1.0;  // bond diameter / smaller sphere diameter [-]

  // Bond diameter between spheres of radii r_i, r_j [m]: ratio * 2 min(r_i, r_j).
  double bond_diameter(double radius_i, double radius_j) const;
  // Material of that bond; `with_damping` false drops the dashpots (the
  // implicit overdamped step does not apply them).
  BeamBondMaterial material(double radius_i, double radius_j, bool with_damping = true) const;
  // Spring constants of that bond at its rest length [m].
  BeamBondStiffness stiffness(double radius_i, double radius_j, double rest_length) const;
  // Bending stiffness E I of the bond section of a rod of spheres of diameter d [N m^2],
  // I = pi (ratio d)^4 / 64 (circular section).
  double bending_stiffness(double sphere_diameter) const;
};

}  // namespace hsrod
