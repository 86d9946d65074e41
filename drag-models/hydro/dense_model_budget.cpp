#include "hydro/dense_model_budget.h"

#include <sstream>

namespace hsrod {

double nonlocal_model_bytes(long spheres) {
  const double m = 3.0 * static_cast<double>(spheres);
  return kNonlocalDenseMatrices * m * m * sizeof(double);
}

bool nonlocal_model_fits(long spheres, double limit_bytes) {
  return nonlocal_model_bytes(spheres) <= limit_bytes;
}

std::string nonlocal_model_budget_problem(long spheres, double limit_bytes) {
  if (nonlocal_model_fits(spheres, limit_bytes)) return "";
  std::ostringstream m;
  m.precision(3);
  m << "model nonlocal (level 3) for a rod of " << spheres << " spheres needs dense " << 3 * spheres << " x "
    << 3 * spheres << " matrices: predicted " << nonlocal_model_bytes(spheres) / 1e9 << " GB (limit "
    << limit_bytes / 1e9 << " GB); use model local (level 2) or isotropic, or raise the memory limit (keyword memory_limit)";
  return m.str();
}

}  // namespace hsrod
