// The fitted parameters of the built-in confinement table (default_coefficients.cpp), written by
//   hsrod_fit_campaign calibration/data/campaign_fit_points.csv OUT_TABLE --cpp drag-models/hydro/default_coefficients_fit.h
// Do not edit: regenerate when the campaign or the forms change (test
// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit). Forms: hydro/confinement_forms.h;
// standard errors after //.
#pragma once

namespace hsrod::default_fit {

constexpr double k_sphere_friction[2] = {0.9977911111, 0.2399765254};  // +- 0.014 0.053
constexpr double k_sphere_driving[2] = {0.3472760812, 0.03228240774};  // +- 0.016 0.064
constexpr double k_par_friction[3] = {0.254918088, 0.411740543, -0.1750105475};  // +- 0.02 0.13 0.19
constexpr double k_perp_friction[4] = {0.3803377169, 1.285753801, -1.256237526, 0.3336278253};  // +- 0.017 0.12 0.19 0.01
constexpr double k_par_velocity[3] = {0.03959565978, 0.2567548896, 0.2237217179};  // +- 0.024 0.13 0.16
constexpr double k_velocity_ratio[4] = {0.01803941388, 0.3918932783, -0.01692739778, 0.3342732702};  // +- 0.0098 0.054 0.066 0.0008
constexpr const char* k_source =
    "built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.15-0.60, extrapolated outside";

}  // namespace hsrod::default_fit
