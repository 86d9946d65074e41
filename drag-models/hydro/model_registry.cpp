// The registration of every hydrodynamic model: one line per model.
// A new model is a class (hydro/), a line here and its reference data in
// the contract test (tests/drag-models/hydro/test_model_contract.cpp).
#include "hydro/model_registry.h"

#include "hydro/local_models.h"
#include "hydro/nonlocal_model.h"
#include "hydro/twoway_near_field.h"

#include <stdexcept>

namespace hsrod {

namespace {
template <class Model>
std::unique_ptr<HydrodynamicModel> make_plain(const HydrodynamicParameters& p, const ConfinementTable& table,
                                              const ModelOptions&) {
  return std::make_unique<Model>(p, table);
}

std::unique_ptr<HydrodynamicModel> make_nonlocal(const HydrodynamicParameters& p, const ConfinementTable& table,
                                                 const ModelOptions& options) {
  auto model = std::make_unique<NonlocalRodModel>(p, table);
  model->set_wall_reflection(options.wall_reflection);
  if (options.wall_reflection == WallReflection::images) model->set_wall_proximity(wall_proximity_with_images());
  if (options.wall_reflection == WallReflection::reflections)
    model->set_wall_proximity(wall_proximity_with_reflections());
  return model;
}

std::unique_ptr<HydrodynamicModel> make_twoway(const HydrodynamicParameters& p, const ConfinementTable& table,
                                               const ModelOptions& options) {
  return std::make_unique<NearFieldTwoWayModel>(p, table, options.window);
}
}  // namespace

const std::vector<ModelEntry>& registered_models() {
  static const std::vector<ModelEntry> models = {
      {"isotropic", 1, "isolated confined sphere: F_i = zeta(beta) (lambda(beta) u(x_i) - v_i)",
       make_plain<IsotropicSphereModel>},
      {"local", 2, "local anisotropic rod: confined resistive-force theory along the tangent",
       make_plain<LocalRodModel>},
      {"nonlocal", 3, "non-local rod: spheres coupled through the depth-averaged Brinkman Green's function",
       make_nonlocal},
      {"twoway", 4, "two-way gap-averaged Brinkman: the rod as a moving obstacle in a window flow with walls",
       make_twoway},
  };
  return models;
}

const ModelEntry* find_model(const std::string& name) {
  for (const ModelEntry& m : registered_models())
    if (m.name == name) return &m;
  return nullptr;
}

const ModelEntry* find_model_level(int level) {
  for (const ModelEntry& m : registered_models())
    if (m.level == level) return &m;
  return nullptr;
}

std::vector<std::string> hydrodynamic_model_names() {
  std::vector<std::string> names;
  for (const ModelEntry& m : registered_models()) names.push_back(m.name);
  return names;
}

std::string valid_model_names(const std::string& extra) {
  std::vector<std::string> names = hydrodynamic_model_names();
  if (!extra.empty()) names.push_back(extra);
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) out += k + 1 == names.size() ? " or " : ", ";
    out += names[k];
  }
  return out;
}

std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& p,
                                                           const ConfinementTable& table) {
  return make_hydrodynamic_model(name, p, table, TwoWayWindowOptions{});
}

std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& p,
                                                           const ConfinementTable& table,
                                                           const TwoWayWindowOptions& window) {
  ModelOptions options;
  options.window = window;
  return make_hydrodynamic_model(name, p, table, options);
}

std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& p,
                                                           const ConfinementTable& table, const ModelOptions& options) {
  if (!(p.viscosity > 0.0)) throw std::invalid_argument("viscosity must be > 0 Pa s");
  if (!(p.gap_height > 0.0) || !(p.sphere_diameter > 0.0))
    throw std::invalid_argument("gap height and sphere diameter must be > 0 m");
  if (p.beta() >= 1.0)
    throw std::invalid_argument("confinement beta = d/H = " + std::to_string(p.beta()) +
                                " must be < 1 (the sphere does not fit in the gap)");
  const ModelEntry* entry = find_model(name);
  if (!entry)
    throw std::invalid_argument("unknown hydrodynamic model '" + name + "' (expected " + valid_model_names() + ")");
  return entry->make(p, table, options);
}

}  // namespace hsrod
