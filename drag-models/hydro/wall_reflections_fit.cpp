// The level-3 near-wall law fitted on top of the walls' images and their
// multiple reflections, friction terms only (--friction-only: the held-load
// terms were what stopped the rod turning in the dynamic pore passage,
// calibration/validation/crosscheck_near_wall.md)
// (hydro/wall_proximity.h, wall_proximity_with_reflections): the parameters of
// calibration/data/wall_proximity_fit_reflections.json, level "nonlocal+reflections"
// (hsrod_fit_wall_proximity --levels; test calibration_WallReflections.BuiltInLawIsTheFit).
#include "hydro/wall_proximity.h"

namespace hsrod {

const WallProximityLaw& wall_proximity_with_reflections() {
  static const WallProximityLaw fitted = [] {
    WallProximityLaw w;
    w.active = true;
    w.normal = 0.7720225684264698;
    w.along = 0.22706279524366177;
    w.screening = 0.36319724214183857;
    w.normal_row_gain = 0.2883276730495079;
    w.along_row_gain = -0.041033253020882836;
    w.normal_held = 0.0;
    w.along_held = 0.0;
    w.squeeze = -0.17851323878222217;
    w.squeeze_held = 0.0;
    w.beta_min = 0.15;
    w.beta_max = 0.3;
    return w;
  }();
  return fitted;
}

}  // namespace hsrod
