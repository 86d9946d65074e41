// The one list of hsrod's hydrodynamic models (the fidelity ladder of
// hydrodynamic_model.h): each model is registered once, with its name (the `model`
// keyword of fix hele_shaw/drag), its level, a one-line description and its
// factory, in model_registry.cpp. Everything that needs to know the models
// reads this list: make_hydrodynamic_model, the fix's keyword check and the
// error listing the valid names, the `auto` policy (hydro/auto_model_choice.h),
// the contract test over all models and the check of the doc page's table.
// In the spirit of OpenFOAM's run-time selection tables, but an explicit
// list (no static registration objects, which a static library may drop).
#pragma once

#include "hydro/hydrodynamic_model.h"
#include "hydro/nonlocal_model.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hsrod {

// Settings a model may take beyond the physical parameters (each model reads its own part).
struct ModelOptions {
  TwoWayWindowOptions window;  // level 4 (twoway)
  // Level 3 (nonlocal): the walls' images in the coupling (hydro/wall_images.h);
  // with images or reflections, the near-wall law fitted on top of them
  // (wall_proximity_with_images, wall_proximity_with_reflections).
  WallReflection wall_reflection = WallReflection::none;
};

struct ModelEntry {
  std::string name;         // keyword value, e.g. "nonlocal"
  int level = 0;            // rung of the fidelity ladder, 1..4
  std::string description;  // one line, for docs and messages
  std::function<std::unique_ptr<HydrodynamicModel>(const HydrodynamicParameters&, const ConfinementTable&,
                                                   const ModelOptions&)>
      make;
};

// The model registered under `name` with its options (throws std::invalid_argument
// as make_hydrodynamic_model does).
std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& parameters,
                                                           const ConfinementTable& table, const ModelOptions& options);

// All registered models, by increasing level.
const std::vector<ModelEntry>& registered_models();

// The entry called `name`, or null.
const ModelEntry* find_model(const std::string& name);

// The entry of the given level, or null.
const ModelEntry* find_model_level(int level);

// "isotropic, local, nonlocal, twoway" followed by " or <last_extra>" when
// extra is given, e.g. valid_model_names("auto") for the fix's error message.
std::string valid_model_names(const std::string& extra = "");

}  // namespace hsrod
