// Built-in confinement coefficients (ConfinementTable::default_table()): the
// fit of levels 1 and 2 to the resolved rodIbFoam campaign (issue 14), not
// derived from another reduced level.
//
// Resolved runs: calibration/tools/hsrod_campaign.py (rigid rows of N = 1,
// 2, 5, 10 touching spheres at the mid-plane of a wide slit, dragged through
// fluid at rest and held in plane Poiseuille flow, along and across their
// axis from one run at 45 degrees; meshes d/h = 6 and 8; beta = 0.15, 0.3; held out: N = 7 at 0.25),
// recorded in calibration/data/resolved_campaign_series.csv with their
// provenance in calibration/data/campaign_summary.json.
// Fit: hsrod_fit_campaign (calibration/tools/fit_campaign.cpp, Eigen
// Levenberg-Marquardt, weighted by the mesh uncertainty of each run);
// parameters, standard errors and residuals in
// calibration/data/confinement_campaign_fit.json; the rows below are
// calibration/data/confinement_campaign.txt (test
// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit).
// Forms (hydro/confinement_forms.h):
//  - sphere_friction  Faxen's series with a free leading coefficient p0 (Faxen: 1.004)
//  - sphere_driving   3/2 (1 - p0 beta^2) (Faxen's law: 1/3)
//    (both fitted p0 are within two standard errors of Faxen's, so the
//    published values are kept: Happel & Brenner 1965, eq. 7-4.28)
//  - rod friction per sphere over the lone sphere's, rod of n spheres:
//    c_inf + (1 - c_inf - g)/n + g n, c_inf = p0 + p1 beta, g = 0 along the
//    axis, k beta^2 across (pressure build-up in front of the chain)
//  - rod held load per sphere: the same n-law about h_inf = c_inf lambda_inf
//    with c_1 = lambda_s and g lambda_s, lambda_inf = 3/2 (1 - beta (q0 + q1
//    beta)) (3/2 as beta -> 0, Berthet et al. 2013)
// Table columns are those of a rod of 10 spheres (level 2 applies the n-law
// to other rods, hydro/local_models.cpp). Rows beta = 0 .. 0.85; outside
// the fitted beta range the forms are extrapolated (their beta -> 0 limits
// are exact for the sphere and for the rod's driving, not for the rod's
// friction, whose 3-D Stokes limit the campaign did not reach).
#include "hydro/confinement_coefficients.h"
#include "hydro/confinement_forms.h"

namespace hsrod {

namespace {
// hsrod_fit_campaign output (standard errors after //)
constexpr double k_sphere_friction[1] = {1.004};                    // fit 1.016 +- 0.012: Faxen's kept
constexpr double k_sphere_driving[1] = {0.3333333333};              // fit 0.349 +- 0.033: Faxen's kept
constexpr double k_par_friction[2] = {0.2610634365, 0.3373042344};  // +- 0.019 0.078
constexpr double k_perp_friction[3] = {0.446118978, 0.6191263478, 0.3609452145};  // +- 0.013 0.082 0.019
constexpr double k_par_held[2] = {0.02039667278, 0.3830550357};     // +- 0.4 1.4
constexpr double k_perp_held[2] = {0.02614539455, 0.3651089871};    // +- 0.11 0.39
}  // namespace

double perpendicular_growth_coefficient() { return k_perp_friction[2]; }

ConfinementTable ConfinementTable::default_table() {
  using namespace confinement_form;
  std::vector<Row> rows;
  for (int k = 0; k <= 17; ++k) {
    const double beta = 0.05 * k;  // 0 .. 0.85
    ConfinementCoefficients c;
    c.sphere_friction = sphere_friction(beta, k_sphere_friction[0]);
    c.sphere_driving = sphere_driving(beta, k_sphere_driving[0]);
    const double ls = c.sphere_driving, g = rod_growth(beta, k_perp_friction[2]);
    const double par_inf = polynomial(k_par_friction, 2, beta), perp_inf = polynomial(k_perp_friction, 2, beta);
    c.parallel_friction = rod_n_law(par_inf, 1.0, 0.0, 10);
    c.perpendicular_friction = rod_n_law(perp_inf, 1.0, g, 10);
    c.parallel_driving = rod_n_law(par_inf * rod_driving_inf(beta, k_par_held, 2), ls, 0.0, 10) / c.parallel_friction;
    c.perpendicular_driving =
        rod_n_law(perp_inf * rod_driving_inf(beta, k_perp_held, 2), ls, g * ls, 10) / c.perpendicular_friction;
    rows.push_back({beta, c});
  }
  return ConfinementTable(std::move(rows), "built-in: hsrod_fit_campaign on the resolved campaign of 2026-12-01 "
                          "(calibration/data/campaign_summary.json); sphere columns Faxen's (not rejected by the runs); "
                          "rod columns (n = 10) fitted over beta 0.15-0.30, extrapolated outside");
}

}  // namespace hsrod
