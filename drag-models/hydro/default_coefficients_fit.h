// The fitted parameters of the built-in confinement table (default_coefficients.cpp), written by
//   hsrod_fit_campaign calibration/data/campaign_fit_points.csv OUT_TABLE --cpp drag-models/hydro/default_coefficients_fit.h
// Do not edit: regenerate when the campaign or the forms change (test
// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit). Forms: hydro/confinement_forms.h;
// standard errors after //.
#pragma once

namespace hsrod::default_fit {

constexpr double k_sphere_friction[3] = {1.001251534, 0.3146154453, 0.366575572};  // +- 0.018 0.13 0.18
constexpr double k_sphere_driving[2] = {0.3407676584, 0.06817443258};  // +- 0.01 0.019
constexpr double k_par_friction[3] = {0.2158388961, 0.4280055182, -0.1633440301};  // +- 0.0043 0.022 0.025
constexpr double k_par_shielding[1] = {0.1020073263};  // +- 0.0078
constexpr double k_perp_friction[3] = {0.3690553073, 1.435375266, -1.3052045};  // +- 0.015 0.14 0.19
constexpr double k_perp_growth[2] = {0.270524822, 0.05350465922};  // +- 0.022 0.036
constexpr double k_par_velocity[3] = {0.05458361297, 0.1853677267, 0.3173463095};  // +- 0.015 0.065 0.063
constexpr double k_perp_velocity[3] = {0.03735215587, 0.1899775722, 0.2977648265};  // +- 0.0024 0.012 0.014
constexpr double k_perp_held_growth[4] = {0.2637337942, 0.09568910263, -0.1367836652, 0.1632838727};  // +- 0.0011 0.007 0.015 0.011
constexpr const char* k_source =
    "built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";

}  // namespace hsrod::default_fit
