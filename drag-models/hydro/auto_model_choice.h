// The `auto` policy of the model keyword: the cheapest level whose error
// against level 3 stays within a tolerance for this scene.
//
// Level 2's rigid-rod friction and drift are fitted to resolved runs
// (default_coefficients.cpp), so it suffices unless the rod bends: the
// bending load level 3 adds (the force per
// sphere on the rod held at its start, minus the rod mean, across the rod)
// times the compliance L^3 / (48 EI) of a simply supported beam
// (Euler-Bernoulli, mid-span load) estimates the deflection that level 2
// misses, as a fraction of the rod length L.
#pragma once

#include "hydro/hydrodynamic_model.h"

#include <string>
#include <vector>

namespace hsrod {

struct AutoModelChoice {
  std::string model;                   // registered name (hydro/model_registry.h)
  double estimated_deflection = 0.0;   // largest deflection level 2 misses, over L [-] (0 for rigid spheres)
  bool flexible = false;               // false: no bonds, the spheres are rigid (no bending to miss)
};

// `bending_stiffness` EI [N m^2] of the rod's bonds, or <= 0 for unbonded
// (rigid) spheres; `level3` the non-local model at the scene's beta;
// `tolerance` the accepted deflection error over L [-].
AutoModelChoice choose_auto_model(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow,
                                  const HydrodynamicModel& level3, double bending_stiffness, double tolerance);

}  // namespace hsrod
