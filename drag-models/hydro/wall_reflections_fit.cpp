// The level-3 near-wall law fitted on top of the walls' images and their multiple reflections
// (hydro/wall_proximity.h, wall_proximity_with_reflections): the parameters of
// calibration/data/wall_proximity_fit_reflections.json, level "nonlocal+reflections"
// (hsrod_fit_wall_proximity --levels; test calibration_WallReflections.BuiltInLawIsTheFit).
#include "hydro/wall_proximity.h"

namespace hsrod {

const WallProximityLaw& wall_proximity_with_reflections() {
  static const WallProximityLaw fitted = [] {
    WallProximityLaw w;
    w.active = true;
    w.normal = 0.7643680797101751;
    w.along = 0.2280160141066446;
    w.screening = 0.36723634640541725;
    w.normal_row_gain = 0.29810984481450764;
    w.along_row_gain = -0.04342815200628692;
    w.normal_held = 8.990639811350919;
    w.along_held = 0.09198798492453492;
    w.squeeze = -0.17758806051995776;
    w.squeeze_held = -0.00921749702792513;
    w.beta_min = 0.15;
    w.beta_max = 0.3;
    return w;
  }();
  return fitted;
}

}  // namespace hsrod
