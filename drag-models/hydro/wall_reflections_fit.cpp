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
    w.normal = 0.7643578648436209;
    w.along = 0.22656447535431823;
    w.screening = 0.36723634640541725;
    w.normal_row_gain = 0.2981776570283201;
    w.along_row_gain = -0.04341334117571612;
    w.normal_held = 9.008863117613089;
    w.along_held = 0.0908625745519806;
    w.squeeze = -0.17770280129820004;
    w.squeeze_held = -0.009190830748239133;
    w.beta_min = 0.15;
    w.beta_max = 0.3;
    return w;
  }();
  return fitted;
}

}  // namespace hsrod
