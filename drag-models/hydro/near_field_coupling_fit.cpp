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
  c.nonlocal.coefficients[0][0] = {-1.288844878, 0.6290852955, 0.3028385338};  // friction ln_blend_length
  c.nonlocal.coefficients[0][1] = {0.0644036133, 0.132306328, -0.6110294845};  // friction reflection
  c.nonlocal.coefficients[0][2] = {0.2942589461, -1.000244833, 1.196959795};  // friction reflection_along
  c.nonlocal.coefficients[0][3] = {-0.08488215469, 2.153011539, -1.659495688};  // friction ln_blend_length_along
  c.nonlocal.coefficients[1][0] = {-1.297572181, 1.355319591, 1.567970971};  // driving ln_blend_length
  c.nonlocal.coefficients[1][1] = {0.04427227321, 0.7404257936, -0.9956667091};  // driving reflection
  c.nonlocal.coefficients[1][2] = {0.3022160034, -1.132698736, 1.335026409};  // driving reflection_along
  c.nonlocal.coefficients[1][3] = {-0.4786800746, 1.163676148, -1.684051315};  // driving ln_blend_length_along
  c.twoway.active = true;
  c.twoway.beta_min = 0.1;
  c.twoway.beta_max = 0.75;
  c.twoway.coefficients[0][0] = {-1.451407041, -0.6995763515, 1.68727377};  // friction ln_blend_length
  c.twoway.coefficients[0][1] = {0.03949687003, -0.4762839451, 0.2451057008};  // friction reflection
  c.twoway.coefficients[0][2] = {0.3174397344, -0.5138811698, 0.5226805262};  // friction reflection_along
  c.twoway.coefficients[0][3] = {-0.1534045591, 0.8577218932, -0.8384158137};  // friction ln_blend_length_along
  c.twoway.coefficients[1][0] = {-1.282326672, -0.4372091405, 2.99922862};  // driving ln_blend_length
  c.twoway.coefficients[1][1] = {0.1989092999, -0.3611066326, 0.5437581072};  // driving reflection
  c.twoway.coefficients[1][2] = {0.2305069342, -0.747474141, 0.9197732227};  // driving reflection_along
  c.twoway.coefficients[1][3] = {0.1978390143, 0.5566812276, -3.425163292};  // driving ln_blend_length_along
  c.source = "hsrod_fit_near_field on resolved_campaign_series.csv (resolved rodIbFoam rigid rows, per-sphere profiles and free velocities, finest mesh), degree 2 in beta, table: built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";
  return c;
}

}  // namespace hsrod
