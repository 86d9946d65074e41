#include "hydro/hydrodynamic_model.h"
#include "hydro/local_models.h"
#include "hydro/nonlocal_model.h"
#include "hydro/twoway_window_model.h"

#include <stdexcept>

namespace hsrod {

std::vector<std::string> hydrodynamic_model_names() { return {"isotropic", "local", "nonlocal", "twoway"}; }

std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& p,
                                                           const ConfinementTable& table) {
  return make_hydrodynamic_model(name, p, table, TwoWayWindowOptions{});
}

std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& p,
                                                           const ConfinementTable& table,
                                                           const TwoWayWindowOptions& window) {
  if (!(p.viscosity > 0.0)) throw std::invalid_argument("viscosity must be > 0 Pa s");
  if (!(p.gap_height > 0.0) || !(p.sphere_diameter > 0.0))
    throw std::invalid_argument("gap height and sphere diameter must be > 0 m");
  if (p.beta() >= 1.0)
    throw std::invalid_argument("confinement beta = d/H = " + std::to_string(p.beta()) +
                                " must be < 1 (the sphere does not fit in the gap)");
  if (name == "isotropic") return std::make_unique<IsotropicSphereModel>(p, table);
  if (name == "local") return std::make_unique<LocalRodModel>(p, table);
  if (name == "nonlocal") return std::make_unique<NonlocalRodModel>(p, table);
  if (name == "twoway") return std::make_unique<TwoWayWindowModel>(p, table, window);
  throw std::invalid_argument("unknown hydrodynamic model '" + name +
                              "' (expected isotropic, local, nonlocal or twoway)");
}

}  // namespace hsrod
