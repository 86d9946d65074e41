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

TEST(calibration_CurveFit, BadInputRefused) {
  const auto one = [](double) { return 1.0; };
  std::vector<CurvePoint> pts = {{0.3, 1, 1.4, 0.01}};
  EXPECT_THROW(fit_curve(CurveForm::RodColumn, pts, {1.0, 0.4}), std::invalid_argument);  // 1 point, 2 params
  pts.push_back({0.2, 1, 1.2, 0.0});
  EXPECT_THROW(fit_curve(CurveForm::SphereFriction, pts, {1.0}), std::invalid_argument);  // sigma 0
  pts.back().sigma = 0.01;
  EXPECT_THROW(fit_curve(CurveForm::RodColumnGrowth, pts, {0.4}), std::invalid_argument);  // no k
  EXPECT_THROW(fit_curve(CurveForm::RodHeld, pts, {0.1, 0.0}, one), std::invalid_argument);  // no c_inf, g
}
