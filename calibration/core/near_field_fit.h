// hsrod calibration: fit of the near-field coupling of levels 3-4
// (drag-models/hydro/near_field_coupling.h) to the resolved per-sphere loads
// of rigid rows of spheres (calibration/data/resolved_campaign_{series,profiles}.csv).
//
// Residuals: for every fitted row (role "fit", n > 1) and each of its four
// per-sphere profiles (friction and held load, along and across the flow),
// (model_i - resolved_i) / (mean_i |resolved_i| sqrt(n)), so that each
// profile's sum of squares is its squared RMS error (the measure of the
// cross-check, crosscheck_levels.cpp) and every profile weighs the same;
// plus, per row, the relative errors of the force-free velocities along and
// across and of r = U_perp / U_par, each over its stated tolerance scale
// (kVelocityScale, kRatioScale): the velocities are ratios of the held load
// to the friction, resolved far better than either (mesh change 0.15-0.5 %,
// r 1e-5..2e-4), and the profiles alone leave them 3-14 % off.
// Parameters: the law of hydro/near_field_coupling.h (NearFieldLaw), for the
// friction and the held load each the blend lengths (as ln kappa, ln
// kappa_e) and the reflections alpha, alpha_e, each a polynomial of the
// given degree in (beta - 0.3): 8 (degree + 1) parameters. Eigen's Levenberg-Marquardt
// (unsupported/Eigen/NonLinearOptimization, MINPACK's lmder with a
// forward-difference Jacobian); standard errors from s^2 (J^T J)^-1 with
// s^2 = chi^2 / (m - p).
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
RowResponse near_field_response(const NearFieldCase& c, const NearFieldAtBeta& coupling);

// The response of one case with the near field of `law` at the case's beta.
RowResponse near_field_response(const NearFieldCase& c, const NearFieldLaw& law);

// RMS error of each profile (over its mean magnitude) and of the totals.
struct CaseErrors {
  double profile_rms[4] = {0, 0, 0, 0};  // friction_par, friction_perp, driving_par, driving_perp
  double total[4] = {0, 0, 0, 0};        // R_par, R_perp, D_par, D_perp: model / resolved - 1
  double lambda[2] = {0, 0};             // force-free velocity along, across: model / resolved - 1
  double ratio = 0.0;                    // r = U_perp / U_par: model / resolved - 1
  double r = 1.0;                        // the model's r
  double worst_profile() const;
  double worst_total() const;
};
CaseErrors case_errors(const NearFieldCase& c, const RowResponse& m);

// Weights of the velocity residuals (above): residual = relative error /
// scale x kProfileScale, so a free-velocity error of kVelocityScale, or an
// error of r of kRatioScale, costs as much as a profile RMS of kProfileScale.
constexpr double kProfileScale = 0.03;   // typical profile RMS the near field reaches [-]
constexpr double kVelocityScale = 0.005;  // free velocity: 0.5 % costs as much as a 3 % profile RMS [-]
constexpr double kRatioScale = 0.003;     // r: 0.3 % costs as much as a 3 % profile RMS [-]

struct NearFieldFit {
  NearFieldLaw law;
  std::vector<double> parameters, std_error;  // in the order [load][parameter][power]
  double rms_profile_residual = 0.0;  // over all fitted profile points (of the profile mean)
  double worst_fitted_velocity = 0.0, worst_fitted_ratio = 0.0;  // relative errors over the fitted rows
  int points = 0, rows = 0, degree = 0;
  int status = 0;  // Levenberg-Marquardt's
  double beta_min = 0.0, beta_max = 0.0;
};

// Fits the cases with role "fit" with a law of the given degree in beta
// (from the constant coupling `start` for friction and driving); beta_range
// of the law: the fitted rows' betas.
NearFieldFit fit_near_field(const std::vector<NearFieldCase>& cases, const NearFieldCoupling& start, int degree);

}  // namespace hsrod::calib
