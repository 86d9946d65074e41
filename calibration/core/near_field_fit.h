// hsrod calibration: fit of the near-field coupling of levels 3-4
// (drag-models/hydro/near_field_coupling.h) to the resolved per-sphere loads
// of rigid rows of spheres (calibration/data/resolved_campaign_{series,profiles}.csv).
//
// Residuals: for every fitted row (role "fit", n > 1) and each of its four
// per-sphere profiles (friction and held load, along and across the flow),
// (model_i - resolved_i) / (mean_i |resolved_i| sqrt(n)), so that each
// profile's sum of squares is its squared RMS error (the measure of the
// cross-check, crosscheck_levels.cpp) and every profile weighs the same.
// Parameters (blend length kappa, reflections alpha, alpha_e) by Eigen's
// Levenberg-Marquardt (unsupported/Eigen/NonLinearOptimization, MINPACK's
// lmder with a forward-difference Jacobian); standard errors from
// s^2 (J^T J)^-1 with s^2 = chi^2 / (m - 3).
//
// The level's load without near field is evaluated once per row; the fit
// adds the near field to it (hydro/twoway_near_field.h: add_near_field),
// which for level 3 is its own near-field coupling exactly.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hydro/near_field_coupling.h"
#include "level_crosscheck.h"
#include "resolved_campaign.h"

namespace hsrod::calib {

// One resolved row with its per-sphere profiles and the level's load without near field.
struct NearFieldCase {
  ResolvedRod resolved;
  std::map<std::string, std::vector<double>> profiles;  // friction_par, friction_perp, driving_par, driving_perp
  RowLoads depth_averaged;                              // the level's load, near field off
  double film_friction = 0.0;                           // zeta_f of the level [N s/m]
  double obstruction_friction = 0.0;                    // zeta_o of the level [N s/m]
};

// The rows of the series with their four profiles (rows without all four are skipped), n > 1 only,
// and the level's (nonlocal or twoway) load without near field at each, with `table`.
std::vector<NearFieldCase> near_field_cases(const std::string& level, const std::vector<ResolvedRod>& series,
                                            const std::map<ProfileKey, std::vector<double>>& profiles,
                                            const ConfinementTable& table);

// The response of one case with the given near field.
RowResponse near_field_response(const NearFieldCase& c, const NearFieldCoupling& coupling);

// RMS error of each profile (over its mean magnitude) and of the totals.
struct CaseErrors {
  double profile_rms[4] = {0, 0, 0, 0};  // friction_par, friction_perp, driving_par, driving_perp
  double total[4] = {0, 0, 0, 0};        // R_par, R_perp, D_par, D_perp: model / resolved - 1
  double lambda[2] = {0, 0};             // force-free velocity along, across: model / resolved - 1
  double worst_profile() const;
  double worst_total() const;
};
CaseErrors case_errors(const NearFieldCase& c, const RowResponse& m);

struct NearFieldFit {
  NearFieldCoupling coupling;
  double std_error[3] = {0, 0, 0};  // of blend_length, reflection, reflection_along
  Eigen::Matrix3d correlation = Eigen::Matrix3d::Identity();  // of the parameters
  double rms_residual = 0.0;     // over all fitted profile points
  int points = 0, rows = 0;
  int status = 0;                // Levenberg-Marquardt's
};

// Fits the cases with role "fit" from `start`.
NearFieldFit fit_near_field(const std::vector<NearFieldCase>& cases, const NearFieldCoupling& start);

}  // namespace hsrod::calib
