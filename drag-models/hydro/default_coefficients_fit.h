// The fitted parameters of the built-in confinement table (default_coefficients.cpp), written by
//   hsrod_fit_campaign calibration/data/campaign_fit_points.csv OUT_TABLE --cpp drag-models/hydro/default_coefficients_fit.h
// Do not edit: regenerate when the campaign or the forms change (test
// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit). Forms: hydro/confinement_forms.h;
// standard errors after //.
#pragma once

namespace hsrod::default_fit {

constexpr double k_sphere_friction[3] = {1.001355233, 0.3161428057, 0.3702041684};  // +- 0.018 0.13 0.18
constexpr double k_sphere_driving[2] = {0.3358640645, 0.09312878889};  // +- 0.011 0.022
constexpr double k_par_friction[3] = {0.2507835736, 0.4141244348, -0.14142721};  // +- 0.0098 0.064 0.075
constexpr double k_perp_friction[4] = {0.3659745944, 1.394992875, -1.294226748, 0.3149009053};  // +- 0.0085 0.064 0.081 0.0073
constexpr double k_par_velocity[3] = {0.06159419914, 0.137765383, 0.3697626326};  // +- 0.015 0.067 0.066
constexpr double k_velocity_ratio[4] = {0.04239997295, 0.2674976038, 0.1324780448, 0.3161088817};  // +- 0.0075 0.043 0.053 0.00076
constexpr const char* k_source =
    "built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";

}  // namespace hsrod::default_fit
