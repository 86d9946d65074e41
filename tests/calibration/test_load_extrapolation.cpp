// Aitken extrapolation of the loads of a pseudo-time steady run
// (calibration/core/load_extrapolation.h), used by rodIbFoam's optional
// stop criterion steadyTolerance { Fextrapolated; Fwindow; }.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "load_extrapolation.h"

using namespace hsrod::calib;

namespace {

// Two spheres whose loads converge geometrically to known limits:
// X(n) = X_inf + A q^n with one dominant mode (per-iteration factor q).
std::vector<SphereLoad> geometric(int n, double q) {
  const double f = std::pow(q, n);
  SphereLoad a, b;
  a.force = {3.3e-11 + 4e-12 * f, -1e-13 * f, 2e-14 * f};
  a.torque = {0.0, 1e-18 * f, 5e-19 + 2e-18 * f};
  b.force = {2.1e-11 - 3e-12 * f, 6e-12 + 1e-12 * f, 0.0};
  b.torque = {1e-19 * f, 0.0, -4e-19 - 1e-18 * f};
  return {a, b};
}

}  // namespace

TEST(calibration_LoadExtrapolation, RecoversTheLimitOfAGeometricSequence) {
  LoadExtrapolation ex(10, 3e-6);
  for (int n = 0; n <= 30; ++n) {
    EXPECT_EQ(ex.ready(), n >= 31) << n;
    ex.add(geometric(n, 0.95));
  }
  ASSERT_TRUE(ex.ready());
  const auto x = ex.extrapolated();
  // after 30 iterations the raw load is still 0.95^30 = 21 % of A away
  EXPECT_NEAR(x[0].force[0], 3.3e-11, 1e-24);
  EXPECT_NEAR(x[1].force[0], 2.1e-11, 1e-24);
  EXPECT_NEAR(x[1].force[1], 6e-12, 1e-24);
  EXPECT_NEAR(x[0].torque[2], 5e-19, 1e-30);
  EXPECT_NEAR(x[1].torque[2], -4e-19, 1e-30);
  // an exact geometric series: the estimate does not move between windows,
  // while the raw loads are still far off
  EXPECT_LT(ex.relative_change(), 1e-9);
  EXPECT_NEAR(ex.relative_remainder(), 4e-12 * std::pow(0.95, 30) / 3.3e-11, 1e-3);
}

TEST(calibration_LoadExtrapolation, TwoModesConvergeToTheLimit) {
  // a fast and a slow mode: the estimate approaches the limit as the slow mode dominates
  LoadExtrapolation ex(10, 3e-6);
  double change_early = 0.0;
  for (int n = 0; n <= 200; ++n) {
    SphereLoad s;
    s.force = {1e-11 * (1.0 + 0.3 * std::pow(0.7, n) + 0.1 * std::pow(0.97, n)), 0.0, 0.0};
    ex.add({s});
    if (n == 40) change_early = ex.relative_change();
  }
  EXPECT_NEAR(ex.extrapolated()[0].force[0], 1e-11, 1e-11 * 1e-9);
  EXPECT_LT(ex.relative_change(), 1e-9);
  EXPECT_GT(change_early, 1e-6);  // not yet converged at 40 iterations
}

TEST(calibration_LoadExtrapolation, DivergingOrStalledHistoryGivesNoEstimate) {
  LoadExtrapolation ex(5, 3e-6);
  for (int n = 0; n <= 15; ++n) ex.add(geometric(n, 1.05));  // growing
  ASSERT_TRUE(ex.ready());
  EXPECT_TRUE(std::isinf(ex.relative_change()));
  EXPECT_TRUE(std::isinf(ex.relative_remainder()));
  EXPECT_DOUBLE_EQ(ex.extrapolated()[0].force[0], geometric(15, 1.05)[0].force[0]);  // latest raw loads
}

TEST(calibration_LoadExtrapolation, BadInputRefused) {
  EXPECT_THROW(LoadExtrapolation(0, 3e-6), std::invalid_argument);
  EXPECT_THROW(LoadExtrapolation(10, 0.0), std::invalid_argument);
  EXPECT_THROW(LoadExtrapolation(10, 3e-6, 1.0), std::invalid_argument);
  LoadExtrapolation ex(2, 3e-6);
  ex.add(geometric(0, 0.9));
  EXPECT_THROW(ex.add({SphereLoad{}}), std::invalid_argument);
}
