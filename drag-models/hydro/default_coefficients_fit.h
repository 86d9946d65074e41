// The fitted parameters of the built-in confinement table (default_coefficients.cpp), written by
//   hsrod_fit_campaign calibration/data/campaign_fit_points.csv OUT_TABLE --cpp drag-models/hydro/default_coefficients_fit.h
// Do not edit: regenerate when the campaign or the forms change (test
// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit). Forms: hydro/confinement_forms.h;
// standard errors after //.
#pragma once

namespace hsrod::default_fit {

constexpr double k_sphere_friction[3] = {1.001251534, 0.3146154453, 0.366575572};  // +- 0.018 0.13 0.18
constexpr double k_sphere_driving[2] = {0.3407676584, 0.06817443258};  // +- 0.01 0.019
constexpr double k_par_friction[3] = {0.2188676601, 0.4192659598, -0.1545650838};  // +- 0.0049 0.023 0.026
constexpr double k_par_shielding[1] = {0.09803593675};  // +- 0.0084
constexpr double k_perp_friction[3] = {0.3597082113, 1.509173796, -1.393033429};  // +- 0.014 0.13 0.18
constexpr double k_perp_growth[2] = {0.2579601241, 0.07214004579};  // +- 0.021 0.034
constexpr double k_par_velocity[3] = {0.05915032376, 0.1673906639, 0.3327657976};  // +- 0.016 0.071 0.067
constexpr double k_perp_velocity[3] = {0.03789280715, 0.18795166, 0.299686797};  // +- 0.0025 0.013 0.014
constexpr double k_perp_held_growth[4] = {0.2487653951, 0.1271459794, -0.1568914594, 0.1729847923};  // +- 0.0015 0.009 0.018 0.012
constexpr const char* k_source =
    "built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";

}  // namespace hsrod::default_fit
