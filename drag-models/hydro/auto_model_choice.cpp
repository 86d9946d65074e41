#include "hydro/auto_model_choice.h"

#include "hydro/model_registry.h"

#include <algorithm>
#include <cmath>

namespace hsrod {

AutoModelChoice choose_auto_model(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow,
                                  const HydrodynamicModel& level3, double bending_stiffness, double tolerance) {
  AutoModelChoice choice;
  choice.model = find_model_level(2)->name;
  choice.flexible = bending_stiffness > 0.0;
  if (!choice.flexible) return choice;
  double worst = 0.0;
  for (const RodGeometry& g : rods) {
    RodDrag drag;
    level3.evaluate(g, flow, drag);
    const int n = g.size();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& f : drag.driving_force) mean += f / n;
    const auto tangents = g.section_tangents();
    double bending_load = 0.0;  // [N]
    for (int k = 0; k < n; k++) {
      const Eigen::Vector3d t = tangents[g.section_of(k)];
      const Eigen::Vector3d excess = drag.driving_force[k] - mean;
      bending_load += (excess - t * t.dot(excess)).norm();
    }
    const double length = g.sections() * g.sphere_diameter;  // L [m]
    worst = std::max(worst, bending_load * std::pow(length, 3) /
                                (48.0 * bending_stiffness * g.spheres_per_section) / length);
  }
  choice.estimated_deflection = worst;
  if (worst > tolerance) choice.model = find_model_level(3)->name;
  return choice;
}

}  // namespace hsrod
