// Stability limit of integrating the drag explicitly.
//
// Velocity Verlet on m dv/dt = -zeta v is stable for dt < 2 m / zeta; for a
// rod, zeta is bounded by the largest eigenvalue of its resistance R, which
// Gershgorin's theorem bounds by the largest absolute row sum (of the sphere's
// 3x3 block for local models, of the sphere's rows of the full R when coupled).
// The rotation gives 2 I / r with I = 2/5 m (d/2)^2 and r the rotational
// resistance.
#pragma once

#include "hydro/hydrodynamic_model.h"

#include <vector>

namespace hsrod {

// Smallest limit over the spheres of one rod [s]; `masses` [kg] per sphere,
// `drag` the rod's load (from any model), spheres of diameter rod.sphere_diameter.
double explicit_drag_limit(const RodGeometry& rod, const RodDrag& drag, const std::vector<double>& masses);

}  // namespace hsrod
