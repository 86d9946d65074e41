#include "hydro/explicit_drag_limit.h"

#include <algorithm>

namespace hsrod {

double explicit_drag_limit(const RodGeometry& rod, const RodDrag& drag, const std::vector<double>& masses) {
  double limit = 1e300;
  const double radius = 0.5 * rod.sphere_diameter;
  for (int k = 0; k < rod.size(); k++) {
    double zeta = 0.0;  // Gershgorin bound of the largest eigenvalue of R [N s/m]
    if (drag.coupled()) {
      for (int a = 0; a < 3; a++) zeta = std::max(zeta, drag.coupled_resistance.row(3 * k + a).cwiseAbs().sum());
    } else {
      zeta = drag.resistance[k].cwiseAbs().rowwise().sum().maxCoeff();
    }
    const double m = masses[k];
    const double inertia = 0.4 * m * radius * radius;  // solid sphere [kg m^2]
    limit = std::min(limit, 2.0 * m / zeta);
    limit = std::min(limit, 2.0 * inertia / drag.rotational_resistance[k]);
  }
  return limit;
}

}  // namespace hsrod
