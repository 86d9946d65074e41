// The shipped near-field fit (hydro/near_field_coupling.h), written by
//   build/hsrod_fit_near_field (calibration/tools/fit_near_field.cpp)
// Do not edit: equals calibration/data/near_field_coupling.txt (test
// calibration_NearFieldLevels.BuiltInNearFieldIsTheShippedFit).
#include "hydro/near_field_coupling.h"

namespace hsrod {

NearFieldCalibration NearFieldCalibration::built_in() {
  NearFieldCalibration c;
  c.nonlocal.active = true;
  c.nonlocal.beta_min = 0.1;
  c.nonlocal.beta_max = 0.75;
  c.nonlocal.coefficients[0][0] = {-1.269531499, 0.6509552287, -0.06831310912};  // friction ln_blend_length
  c.nonlocal.coefficients[0][1] = {0.0529625649, 0.2044446508, -0.9054127502};  // friction reflection
  c.nonlocal.coefficients[0][2] = {0.2975483918, -1.010083628, 1.362633808};  // friction reflection_along
  c.nonlocal.coefficients[0][3] = {-0.1194318856, 2.179701486, -2.311075669};  // friction ln_blend_length_along
  c.nonlocal.coefficients[1][0] = {-1.275275506, 1.354237642, 1.47709233};  // driving ln_blend_length
  c.nonlocal.coefficients[1][1] = {0.04040249236, 0.774281943, -1.050422426};  // driving reflection
  c.nonlocal.coefficients[1][2] = {0.3042602278, -1.140178618, 1.367338874};  // driving reflection_along
  c.nonlocal.coefficients[1][3] = {-0.4722103781, 1.231019339, -2.180554787};  // driving ln_blend_length_along
  c.twoway.active = true;
  c.twoway.beta_min = 0.1;
  c.twoway.beta_max = 0.75;
  c.twoway.coefficients[0][0] = {-1.406005021, 0.03047046298, -0.3859624924};  // friction ln_blend_length
  c.twoway.coefficients[0][1] = {0.05146672751, 0.3583876245, -1.677501195};  // friction reflection
  c.twoway.coefficients[0][2] = {0.2729512227, -1.100248187, 2.053614281};  // friction reflection_along
  c.twoway.coefficients[0][3] = {-0.1902119061, 1.936931631, -2.651234951};  // friction ln_blend_length_along
  c.twoway.coefficients[1][0] = {-1.38496628, 0.7790890508, 2.059418739};  // driving ln_blend_length
  c.twoway.coefficients[1][1] = {0.06886773523, 0.8547752242, -1.158515386};  // driving reflection
  c.twoway.coefficients[1][2] = {0.2488414165, -1.319876722, 1.891488139};  // driving reflection_along
  c.twoway.coefficients[1][3] = {-0.4805856228, 0.8892913548, -2.469459598};  // driving ln_blend_length_along
  c.source = "hsrod_fit_near_field on resolved_campaign_series.csv (resolved rodIbFoam rigid rows, per-sphere profiles and free velocities, finest mesh), degree 2 in beta, table: built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";
  return c;
}

}  // namespace hsrod
