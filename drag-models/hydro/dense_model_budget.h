// Bounded work for the dense (non-local) hydrodynamic models: level 3
// couples every pair of spheres of a rod, so one evaluation holds dense 3n x 3n matrices (the coupling, its factorisation, the resistance and
// its symmetric part; the implicit step copies the resistance into a dense
// system and factorises it). A rod of N = 10 000 spheres needs 7.2 GB per
// matrix: such a request is refused (or a cheaper model chosen) from this
// prediction, before anything is allocated.
#pragma once

#include <string>

namespace hsrod {

// Dense 3n x 3n double matrices alive at once in one level-3 evaluation plus
// the implicit step's dense solve (nonlocal_model.cpp, overdamped_rod_step.cpp).
inline constexpr int kNonlocalDenseMatrices = 6;

// Predicted peak memory [bytes] of the level-3 model and its implicit step
// for a rod of `spheres` spheres: kNonlocalDenseMatrices (3n)^2 doubles.
double nonlocal_model_bytes(long spheres);

// True when the level-3 model for `spheres` spheres fits `limit_bytes`.
bool nonlocal_model_fits(long spheres, double limit_bytes);

// "" when it fits, else the rod size, the matrix size, the predicted
// memory, the limit and the alternatives (NonlocalRodModel::resource_problem).
std::string nonlocal_model_budget_problem(long spheres, double limit_bytes);

}  // namespace hsrod
