// Curve fits over beta and n of the campaign's coefficients
// (calibration/core/confinement_fit.h, Eigen Levenberg-Marquardt; forms in
// drag-models/hydro/confinement_forms.h): synthetic points made from known
// parameters must give them back, with standard errors that cover the truth
// when the points carry noise.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "confinement_fit.h"
#include "hydro/confinement_forms.h"

using namespace hsrod::calib;
namespace form = hsrod::confinement_form;

namespace {
// deterministic +-1 pattern for "noise"
double sign(int k) { return (k * 7 + 3) % 5 < 2 ? -1.0 : 1.0; }
}  // namespace

TEST(calibration_CurveFit, SphereFormsRecoverFaxenCoefficients) {
  std::vector<CurvePoint> fr, dr;
  for (double b : {0.1, 0.15, 0.2, 0.3, 0.45, 0.6}) {
    fr.push_back({b, 1, form::sphere_friction(b, 1.004), 1e-3});
    dr.push_back({b, 1, 1.5 * (1.0 - b * b / 3.0), 1e-3});
  }
  const CurveFit f = fit_curve(CurveForm::SphereFriction, fr, {0.5});
  EXPECT_NEAR(f.params[0], 1.004, 1e-6);
  EXPECT_LT(f.max_relative, 1e-8);
  // Faxen's full series at beta = 0.3 (Happel & Brenner 1965 eq. 7-4.28)
  EXPECT_NEAR(f(0.3), 1.0 / 0.711376, 1e-5);
  const CurveFit d = fit_curve(CurveForm::SphereDriving, dr, {0.0});
  EXPECT_NEAR(d.params[0], 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(d(0.0), 1.5, 1e-12);  // the beta -> 0 limit is built in
  // two parameters: the beta^3 coefficient of the series, a beta^4 term of the law
  const CurveFit f2 = fit_curve(CurveForm::SphereFriction, fr, {0.5, 0.0});
  EXPECT_NEAR(f2.params[0], 1.004, 1e-6);
  EXPECT_NEAR(f2.params[1], 0.418, 1e-5);
  const CurveFit d2 = fit_curve(CurveForm::SphereDriving, dr, {0.0, 0.1});
  EXPECT_NEAR(d2.params[0], 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(d2.params[1], 0.0, 1e-5);
}

TEST(calibration_CurveFit, RodNLawRecoveredWithUncertaintiesCoveringTheTruth) {
  // c(beta, n) = c_inf + (1 - c_inf - g)/n + g n, c_inf = 0.30 + 0.40 beta,
  // g = 0.35 beta^2, 0.5 % noise
  std::vector<CurvePoint> pts;
  int k = 0;
  for (double b : {0.15, 0.2, 0.3, 0.45})
    for (int n : {2, 5, 10}) {
      const double v = form::rod_n_law(0.30 + 0.40 * b, 1.0, 0.35 * b * b, n) * (1.0 + 0.005 * sign(k++));
      pts.push_back({b, n, v, 0.005 * v});
    }
  const CurveFit f = fit_curve(CurveForm::RodColumnGrowth, pts, {0.5, 0.0, 0.0});
  ASSERT_EQ(f.params.size(), 3u);
  EXPECT_LT(std::abs(f.params[0] - 0.30), 3.0 * f.std_errors[0]);
  EXPECT_LT(std::abs(f.params[1] - 0.40), 3.0 * f.std_errors[1]);
  EXPECT_LT(std::abs(f.params[2] - 0.35), 3.0 * f.std_errors[2]);
  EXPECT_GT(f.std_errors[0], 0.0);
  EXPECT_LT(f.rms_relative, 0.008);
  EXPECT_NEAR(f(0.3, 1), 1.0, 1e-12);  // a lone sphere is the lone sphere
  // the asymptote inverts the n-law of a 10-sphere rod
  EXPECT_NEAR(form::rod_n_law_asymptote(f(0.3, 10), 1.0, f.growth_at(0.3), 10), f.asymptote(0.3), 1e-12);

  // held load about h_inf = c_inf lambda_inf, lambda_inf = 1.5 (1 - 0.2 beta)
  const auto lone = [](double b) { return 1.5 * (1.0 - b * b / 3.0); };
  const auto c_inf = [](double b) { return 0.30 + 0.40 * b; };
  const auto g = [](double b) { return 0.35 * b * b; };
  std::vector<CurvePoint> held;
  for (double b : {0.15, 0.3, 0.45})
    for (int n : {2, 5, 10})
      held.push_back({b, n, form::rod_n_law(c_inf(b) * 1.5 * (1.0 - 0.2 * b), lone(b), g(b) * lone(b), n), 1e-3});
  const CurveFit h = fit_curve(CurveForm::RodHeld, held, {0.0, 0.0}, lone, c_inf, g);
  EXPECT_NEAR(h.params[0], 0.2, 1e-6);
  EXPECT_NEAR(h.params[1], 0.0, 1e-6);
  EXPECT_NEAR(h.asymptote(0.0), 1.5, 1e-12);
}

TEST(calibration_CurveFit, RodVelocitiesAndTheirRatioRecovered) {
  // Synthetic rods: friction n-laws c_inf,par = 0.26 + 0.34 beta, c_inf,perp
  // = 0.45 + 0.62 beta with g = 0.36 beta^2; velocities with lambda_inf =
  // 1.5 (1 - beta (0.03 + 0.35 beta)) along, 1.5 (1 - beta (0.02 + 0.33
  // beta)) across, held growth k_held = 0.357 across: the lambda_par fit and
  // the fit of r = lambda_perp / lambda_par give the parameters back, and
  // the velocities keep their n = 1 limit (the lone sphere).
  const auto lone = [](double b) { return 1.5 * (1.0 - b * b / 3.0); };
  const auto par_inf = [](double b) { return 0.26 + 0.34 * b; };
  const auto perp_inf = [](double b) { return 0.45 + 0.62 * b; };
  const auto g = [](double b) { return 0.36 * b * b; };
  const auto zero = [](double) { return 0.0; };
  const double qp[2] = {0.03, 0.35}, qq[2] = {0.02, 0.33};
  std::vector<CurvePoint> vel, ratio;
  for (double b : {0.1, 0.2, 0.3, 0.45, 0.6})
    for (int n : {2, 5, 10}) {
      const double lp = form::rod_velocity(par_inf(b), form::rod_driving_inf(b, qp, 2), lone(b), 0.0, 0.0, n);
      const double lq = form::rod_velocity(perp_inf(b), form::rod_driving_inf(b, qq, 2), lone(b), g(b), 0.357 * b * b, n);
      vel.push_back({b, n, lp, 1e-3});
      ratio.push_back({b, n, lq / lp, 1e-4});
    }
  const CurveFit pv = fit_curve(CurveForm::RodVelocity, vel, {0.0, 0.0}, lone, par_inf, zero);
  EXPECT_NEAR(pv.params[0], 0.03, 1e-6);
  EXPECT_NEAR(pv.params[1], 0.35, 1e-6);
  EXPECT_NEAR(pv(0.3, 1), lone(0.3), 1e-12);
  const CurveFit qv = fit_curve(CurveForm::RodVelocityRatio, ratio, {0.0, 0.0, 0.3}, lone, perp_inf, g,
                                [&pv](double b, int n) { return pv(b, n); });
  ASSERT_EQ(qv.params.size(), 3u);
  EXPECT_NEAR(qv.params[0], 0.02, 1e-5);
  EXPECT_NEAR(qv.params[1], 0.33, 1e-5);
  EXPECT_NEAR(qv.params[2], 0.357, 1e-5);
  EXPECT_NEAR(qv.held_growth_at(0.5), 0.357 * 0.25, 1e-5);
  EXPECT_NEAR(qv.velocity(0.3, 1), lone(0.3), 1e-12);
  EXPECT_NEAR(qv.velocity(0.45, 10) / pv(0.45, 10), qv(0.45, 10), 1e-12);
}

TEST(calibration_CurveFit, ShieldingAndPolynomialGrowthsRecovered) {
  // The shipped layout (RodLayout): along the axis the 3-D shielding
  // e ln(n)/n (e = 0.10), across it g = beta^2 (0.26 + 0.07 beta), the held
  // growth g_held = beta^2 (0.25 + 0.13 beta - 0.16 beta^2); exact synthetic
  // rods of n = 2, 5, 10, 20 at six beta give every block back, the
  // asymptote inverts the n-law with its shielding, and n = 1 stays the lone
  // sphere.
  const auto lone = [](double b) { return 1.5 * (1.0 - b * b / 3.0); };
  const double cp[2] = {0.22, 0.42}, cq[2] = {0.36, 0.9}, kg[2] = {0.26, 0.07}, kh[3] = {0.25, 0.13, -0.16};
  const double qp[2] = {0.06, 0.30}, qq[2] = {0.04, 0.28};
  const double e = 0.10;
  std::vector<CurvePoint> par, perp, vel, ratio;
  for (double b : {0.1, 0.2, 0.3, 0.45, 0.6, 0.75})
    for (int n : {2, 5, 10, 20}) {
      const double g = form::rod_growth(b, kg, 2), gh = form::rod_growth(b, kh, 3);
      par.push_back({b, n, form::rod_n_law(form::polynomial(cp, 2, b), 1.0, 0.0, n, e), 1e-3});
      perp.push_back({b, n, form::rod_n_law(form::polynomial(cq, 2, b), 1.0, g, n), 1e-3});
      const double lp = form::rod_velocity(form::polynomial(cp, 2, b), form::rod_driving_inf(b, qp, 2), lone(b), 0, 0, n, e);
      const double lq = form::rod_velocity(form::polynomial(cq, 2, b), form::rod_driving_inf(b, qq, 2), lone(b), g, gh, n);
      vel.push_back({b, n, lp, 1e-3});
      ratio.push_back({b, n, lq / lp, 1e-4});
    }
  RodLayout along;
  along.shielding_terms = 1;
  const CurveFit pf = fit_curve(CurveForm::RodColumn, par, {0.3, 0.0, 0.0}, {}, {}, {}, {}, along);
  EXPECT_NEAR(pf.params[0], 0.22, 1e-6);
  EXPECT_NEAR(pf.params[1], 0.42, 1e-6);
  EXPECT_NEAR(pf.shielding_at(0.4), e, 1e-6);
  EXPECT_NEAR(pf(0.4, 1), 1.0, 1e-12);
  EXPECT_NEAR(form::rod_n_law_asymptote(pf(0.4, 10), 1.0, 0.0, 10, pf.shielding_at(0.4)), pf.asymptote(0.4), 1e-12);
  const RodLayout across{2, 0, 3};
  const CurveFit qf = fit_curve(CurveForm::RodColumnGrowth, perp, {0.3, 0.0, 0.3, 0.0}, {}, {}, {}, {}, across);
  EXPECT_NEAR(qf.params[2], 0.26, 1e-5);
  EXPECT_NEAR(qf.params[3], 0.07, 1e-5);
  EXPECT_NEAR(qf.growth_at(0.5), form::rod_growth(0.5, kg, 2), 1e-6);
  const CurveFit pv = fit_curve(CurveForm::RodVelocity, vel, {0.0, 0.0}, lone, [&](double b) { return pf.asymptote(b); },
                                [](double) { return 0.0; }, {}, {}, [&](double b) { return pf.shielding_at(b); });
  EXPECT_NEAR(pv.params[0], 0.06, 1e-5);
  EXPECT_NEAR(pv.params[1], 0.30, 1e-5);
  EXPECT_NEAR(pv(0.3, 1), lone(0.3), 1e-12);
  const CurveFit qv = fit_curve(CurveForm::RodVelocityRatio, ratio, {0.0, 0.0, 0.3, 0.0, 0.0}, lone,
                                [&](double b) { return qf.asymptote(b); }, [&](double b) { return qf.growth_at(b); },
                                [&pv](double b, int n) { return pv(b, n); }, across);
  ASSERT_EQ(qv.params.size(), 5u);
  EXPECT_NEAR(qv.params[0], 0.04, 1e-4);
  EXPECT_NEAR(qv.params[1], 0.28, 1e-4);
  EXPECT_NEAR(qv.held_growth_at(0.6), form::rod_growth(0.6, kh, 3), 1e-5);
  // a layout that leaves no polynomial term is refused
  EXPECT_THROW(fit_curve(CurveForm::RodColumnGrowth, perp, {0.3, 0.3}, {}, {}, {}, {}, across), std::invalid_argument);
}

TEST(calibration_CurveFit, BadInputRefused) {
  const auto one = [](double) { return 1.0; };
  std::vector<CurvePoint> pts = {{0.3, 1, 1.4, 0.01}};
  EXPECT_THROW(fit_curve(CurveForm::RodColumn, pts, {1.0, 0.4}), std::invalid_argument);  // 1 point, 2 params
  pts.push_back({0.2, 1, 1.2, 0.0});
  EXPECT_THROW(fit_curve(CurveForm::SphereFriction, pts, {1.0}), std::invalid_argument);  // sigma 0
  pts.back().sigma = 0.01;
  EXPECT_THROW(fit_curve(CurveForm::RodColumnGrowth, pts, {0.4}), std::invalid_argument);  // no k
  EXPECT_THROW(fit_curve(CurveForm::RodHeld, pts, {0.1, 0.0}, one), std::invalid_argument);  // no c_inf, g
  EXPECT_THROW(fit_curve(CurveForm::RodVelocityRatio, pts, {0.1, 0.3}, one, one, one), std::invalid_argument);  // no divisor
  EXPECT_THROW(fit_curve(CurveForm::SphereFriction, pts, {1.0, 0.4, 0.2, 0.1}), std::invalid_argument);  // 4 params
  EXPECT_THROW(fit_curve(CurveForm::SphereDriving, pts, {1.0, 0.4, 0.2}), std::invalid_argument);    // 3 params
}
