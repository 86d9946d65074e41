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
  c.nonlocal.coefficients[0][0] = {-1.296286811, 0.6912197516, 0.1983953755};  // friction ln_blend_length
  c.nonlocal.coefficients[0][1] = {0.06254896269, 0.1347072516, -0.6068119769};  // friction reflection
  c.nonlocal.coefficients[0][2] = {0.2943741736, -0.9898990303, 1.172708424};  // friction reflection_along
  c.nonlocal.coefficients[0][3] = {-0.09393747684, 2.170140223, -1.652722765};  // friction ln_blend_length_along
  c.nonlocal.coefficients[1][0] = {-1.304627653, 1.409120747, 1.486497211};  // driving ln_blend_length
  c.nonlocal.coefficients[1][1] = {0.04229227017, 0.7448020824, -0.9940324301};  // driving reflection
  c.nonlocal.coefficients[1][2] = {0.3021909378, -1.120504173, 1.305461043};  // driving reflection_along
  c.nonlocal.coefficients[1][3] = {-0.4854555863, 1.179478038, -1.683633546};  // driving ln_blend_length_along
  c.twoway.active = true;
  c.twoway.beta_min = 0.1;
  c.twoway.beta_max = 0.75;
  c.twoway.coefficients[0][0] = {-1.461247181, -0.5751034031, 1.462419409};  // friction ln_blend_length
  c.twoway.coefficients[0][1] = {0.03584805274, -0.4519788209, 0.2267961068};  // friction reflection
  c.twoway.coefficients[0][2] = {0.3182940949, -0.5122125399, 0.5003321751};  // friction reflection_along
  c.twoway.coefficients[0][3] = {-0.161628723, 0.9599811936, -0.9745751601};  // friction ln_blend_length_along
  c.twoway.coefficients[1][0] = {-1.292530446, -0.2971661564, 2.692095431};  // driving ln_blend_length
  c.twoway.coefficients[1][1] = {0.196578549, -0.3421828334, 0.4986214579};  // driving reflection
  c.twoway.coefficients[1][2] = {0.2307267668, -0.7502792376, 0.9390237024};  // driving reflection_along
  c.twoway.coefficients[1][3] = {0.1847908001, 0.6637969227, -3.562097588};  // driving ln_blend_length_along
  c.source = "hsrod_fit_near_field on resolved_campaign_series.csv (resolved rodIbFoam rigid rows, per-sphere profiles and free velocities, finest mesh), degree 2 in beta, table: built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";
  return c;
}

}  // namespace hsrod
