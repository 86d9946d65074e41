// Built-in confinement coefficients (ConfinementTable::default_table()): the
// fit of levels 1 and 2 to the resolved rodIbFoam campaign, not
// derived from another reduced level.
//
// Resolved runs: calibration/tools/hsrod_campaign.py (rigid rows of N = 1,
// 2, 5, 10 touching spheres at the mid-plane of a wide slit, dragged through
// fluid at rest and held in plane Poiseuille flow, along and across their
// axis from one run at 45 degrees; meshes d/h = 6 and 8; beta = 0.1 - 0.75;
// held out: N = 7 at beta 0.25, N = 10 at beta 0.5, N = 15 at beta 0.3),
// recorded in calibration/data/resolved_campaign_series.csv with their
// provenance in calibration/data/campaign_summary.json
// (calibration/campaign/README.md).
// Fit: hsrod_fit_campaign (calibration/tools/fit_campaign.cpp, Eigen
// Levenberg-Marquardt, weighted by the mesh uncertainty of each run), one
// command: calibration/campaign/refit.sh; parameters, standard errors and
// residuals in calibration/data/confinement_campaign_fit.json; the
// parameters in hydro/default_coefficients_fit.h (generated); the rows below
// are calibration/data/confinement_campaign.txt (test
// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit).
// Forms (hydro/confinement_forms.h):
//  - sphere_friction  Faxen's series, p0, the beta^3 coefficient p3 and the beta^5 coefficient p5
//  - sphere_driving   3/2 (1 - p0 beta^2 - p2 beta^4) (Faxen's law: 1/3, 0)
//    (Faxen's published values where the fit does not reject them)
//  - rod friction per sphere over the lone sphere's, rod of n spheres:
//    c_inf + (1 - c_inf - g)/n + g n + e ln(n)/n, c_inf polynomial in beta;
//    along the axis g = 0 and e = the 3-D shielding of near neighbours
//    (polynomial in beta), across it e = 0 and g = beta^2 k(beta) (pressure
//    build-up in front of the chain, k polynomial)
//  - rod force-free velocity: the held load per sphere (the n-law about
//    c_inf lambda_inf with the lone sphere's lambda_s, growth g_held lambda_s
//    and shielding e lambda_s) over the friction per sphere, lambda_inf =
//    3/2 (1 - beta q(beta)) (3/2 as beta -> 0, Berthet et al. 2013); along
//    the axis fitted to the resolved velocities, across the axis (with
//    g_held = beta^2 k_held(beta), k_held polynomial) to the resolved
//    r = U_perp / U_par
// Table columns are those of a rod of 10 spheres (level 2 applies the n-law
// to other rods, hydro/local_models.cpp). Rows beta = 0 .. 0.85; outside
// the fitted beta range the forms are extrapolated (their beta -> 0 limits
// are exact for the sphere and for the rod's velocity, not for the rod's
// friction, whose 3-D Stokes limit the campaign did not reach).
#include "hydro/confinement_coefficients.h"
#include "hydro/confinement_forms.h"
#include "hydro/default_coefficients_fit.h"

namespace hsrod {

namespace {
using namespace default_fit;  // the fitted parameters (hydro/default_coefficients_fit.h)

template <std::size_t N>
constexpr int terms(const double (&)[N]) { return static_cast<int>(N); }
}  // namespace

double perpendicular_growth(double beta) {
  return confinement_form::rod_growth(beta, k_perp_growth, terms(k_perp_growth));
}
double perpendicular_held_growth(double beta) {
  return confinement_form::rod_growth(beta, k_perp_held_growth, terms(k_perp_held_growth));
}
double parallel_shielding(double beta) {
  return confinement_form::polynomial(k_par_shielding, terms(k_par_shielding), beta);
}

ConfinementTable ConfinementTable::default_table() {
  using namespace confinement_form;
  std::vector<Row> rows;
  const int nf = terms(k_par_friction), nv = terms(k_par_velocity);
  static_assert(sizeof(k_perp_friction) == sizeof(k_par_friction), "c_inf along and across: one polynomial degree");
  static_assert(sizeof(k_perp_velocity) == sizeof(k_par_velocity), "lambda_inf along and across: one polynomial degree");
  for (int k = 0; k <= 17; ++k) {
    const double beta = 0.05 * k;  // 0 .. 0.85
    ConfinementCoefficients c;
    const int ns = terms(k_sphere_friction);
    c.sphere_friction = ns > 2   ? sphere_friction(beta, k_sphere_friction[0], k_sphere_friction[1], k_sphere_friction[ns > 2 ? 2 : 0])
                        : ns > 1 ? sphere_friction(beta, k_sphere_friction[0], k_sphere_friction[1])
                                 : sphere_friction(beta, k_sphere_friction[0]);
    c.sphere_driving = terms(k_sphere_driving) > 1 ? sphere_driving(beta, k_sphere_driving[0], k_sphere_driving[1])
                                                   : sphere_driving(beta, k_sphere_driving[0]);
    const double ls = c.sphere_driving, g = perpendicular_growth(beta), g_held = perpendicular_held_growth(beta);
    const double e = parallel_shielding(beta);
    const double par_inf = polynomial(k_par_friction, nf, beta), perp_inf = polynomial(k_perp_friction, nf, beta);
    c.parallel_friction = rod_n_law(par_inf, 1.0, 0.0, 10, e);
    c.perpendicular_friction = rod_n_law(perp_inf, 1.0, g, 10);
    c.parallel_driving = rod_velocity(par_inf, rod_driving_inf(beta, k_par_velocity, nv), ls, 0.0, 0.0, 10, e);
    c.perpendicular_driving = rod_velocity(perp_inf, rod_driving_inf(beta, k_perp_velocity, nv), ls, g, g_held, 10);
    rows.push_back({beta, c});
  }
  return ConfinementTable(std::move(rows), k_source);
}

}  // namespace hsrod
