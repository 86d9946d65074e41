#include "dynamics/implicit_conditioning.h"

namespace hsrod {

double implicit_stiffness_ratio(double timestep, double drag_limit, double bond_limit) {
  return 2.0 * timestep * drag_limit / (bond_limit * bond_limit);
}

double largest_well_conditioned_modulus(double youngs_modulus, double stiffness_ratio) {
  return youngs_modulus / (stiffness_ratio / kMaxImplicitStiffnessRatio);  // no overflow at E ~ 1e300
}

}  // namespace hsrod
