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
  c.nonlocal.coefficients[0][0] = {-1.244189445, 0.6640329496, -0.2880815111};  // friction ln_blend_length
  c.nonlocal.coefficients[0][1] = {0.07071037897, 0.0406239039, -0.7008334489};  // friction reflection
  c.nonlocal.coefficients[0][2] = {0.2875895984, -0.9805589005, 1.410768468};  // friction reflection_along
  c.nonlocal.coefficients[0][3] = {-0.0824276006, 2.002044648, -2.434653601};  // friction ln_blend_length_along
  c.nonlocal.coefficients[1][0] = {-1.263988352, 1.409148931, 1.270286771};  // driving ln_blend_length
  c.nonlocal.coefficients[1][1] = {0.0438157968, 0.6725678922, -0.8492346426};  // driving reflection
  c.nonlocal.coefficients[1][2] = {0.3025776129, -1.119870306, 1.316755543};  // driving reflection_along
  c.nonlocal.coefficients[1][3] = {-0.4825263217, 1.137148516, -1.773620028};  // driving ln_blend_length_along
  c.twoway.active = true;
  c.twoway.beta_min = 0.1;
  c.twoway.beta_max = 0.75;
  c.twoway.coefficients[0][0] = {-1.383616268, 0.0634577672, -0.6231339237};  // friction ln_blend_length
  c.twoway.coefficients[0][1] = {0.0647411775, 0.2055478645, -1.548145984};  // friction reflection
  c.twoway.coefficients[0][2] = {0.2656716562, -1.072965246, 2.160825548};  // friction reflection_along
  c.twoway.coefficients[0][3] = {-0.1739906619, 1.75108908, -2.633750955};  // friction ln_blend_length_along
  c.twoway.coefficients[1][0] = {-1.377847317, 0.8485207355, 1.833682819};  // driving ln_blend_length
  c.twoway.coefficients[1][1] = {0.06480401458, 0.7772685423, -0.9779242835};  // driving reflection
  c.twoway.coefficients[1][2] = {0.2505968328, -1.306866362, 1.862101799};  // driving reflection_along
  c.twoway.coefficients[1][3] = {-0.5102602902, 0.7563776744, -2.003125849};  // driving ln_blend_length_along
  c.source = "hsrod_fit_near_field on resolved_campaign_series.csv (resolved rodIbFoam rigid rows, per-sphere profiles and free velocities, finest mesh), degree 2 in beta, table: built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";
  return c;
}

}  // namespace hsrod
