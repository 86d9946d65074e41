// The fitted parameters of the built-in confinement table (default_coefficients.cpp), written by
//   hsrod_fit_campaign /tmp/calibcol/pts.csv OUT_TABLE --cpp drag-models/hydro/default_coefficients_fit.h
// Do not edit: regenerate when the campaign or the forms change (test
// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit). Forms: hydro/confinement_forms.h;
// standard errors after //.
#pragma once

namespace hsrod::default_fit {

constexpr double k_sphere_friction[1] = {1.004};  // +- 0.012
constexpr double k_sphere_driving[1] = {0.3333333333};  // +- 0.014
constexpr double k_par_friction[2] = {0.2610634784, 0.3373040675};  // +- 0.019 0.078
constexpr double k_perp_friction[3] = {0.4461190365, 0.6191262157, 0.3609451816};  // +- 0.013 0.082 0.019
constexpr double k_par_velocity[2] = {0.03294500441, 0.3545407004};  // +- 0.026 0.093
constexpr double k_velocity_ratio[3] = {0.02207859562, 0.3330621967, 0.3572623259};  // +- 0.0021 0.008 0.00039
constexpr const char* k_source =
    "built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.15-0.30, extrapolated outside";

}  // namespace hsrod::default_fit
