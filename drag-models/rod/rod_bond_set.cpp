#include "rod/rod_bond_set.h"

#include "common/math_constants.h"

#include <algorithm>
#include <cmath>

namespace hsrod {

double RodBondSet::bond_diameter(double radius_i, double radius_j) const {
  return 2.0 * bond_radius_ratio * std::min(radius_i, radius_j);
}

BeamBondMaterial RodBondSet::material(double radius_i, double radius_j, bool with_damping) const {
  return BeamBondMaterial{youngs_modulus, poisson_ratio, bond_diameter(radius_i, radius_j),
                          with_damping ? damping_ratio : 0.0};
}

BeamBondStiffness RodBondSet::stiffness(double radius_i, double radius_j, double rest_length) const {
  return BeamBondStiffness::from_material(material(radius_i, radius_j), rest_length);
}

double RodBondSet::bending_stiffness(double sphere_diameter) const {
  const double bond_d = bond_radius_ratio * sphere_diameter;
  return youngs_modulus * kPi * std::pow(bond_d, 4) / 64.0;
}

}  // namespace hsrod
