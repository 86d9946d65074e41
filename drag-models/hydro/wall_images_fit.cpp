// The level-3 near-wall law fitted on top of the walls' images
// (hydro/wall_proximity.h, wall_proximity_with_images): the parameters of
// calibration/data/wall_proximity_fit_images.json, level "nonlocal+images"
// (hsrod_fit_wall_proximity --levels; test calibration_WallImages.BuiltInLawIsTheFit).
#include "hydro/wall_proximity.h"

namespace hsrod {

const WallProximityLaw& wall_proximity_with_images() {
  static const WallProximityLaw fitted = [] {
    WallProximityLaw w;
    w.active = true;
    w.normal = 0.7621995742656094;
    w.along = 0.39756129300290194;
    w.screening = 0.36723634640541725;
    w.normal_row_gain = 0.29221913189692816;
    w.along_row_gain = -0.18796527060950152;
    w.normal_held = 8.215616166440157;
    w.along_held = 0.23209979078553733;
    w.squeeze = -0.17558422520037098;
    w.squeeze_held = -0.009165164006219414;
    w.beta_min = 0.15;
    w.beta_max = 0.3;
    return w;
  }();
  return fitted;
}

}  // namespace hsrod
