// The error model of `auto` (hydro/auto_model_choice.h) on a made-up record
// whose answers are known by hand: interpolation in n and beta, clamping and
// its flag outside the record, the cheapest level within the tolerance, the
// most accurate one when none is, non-local levels only for a rod that bends.
// (The built-in record itself is checked against the resolved runs in
// tests/calibration/test_auto_error_record.cpp.)
#include "hydro/auto_model_choice.h"

#include "hydro/model_registry.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

using namespace hsrod;

namespace {
constexpr double kD = 3e-6, kMu = 1e-3;

// level, beta, n, force, velocity, r
const std::vector<LevelErrorRow> kRecord = {
    {1, 0.1, 1, 0.01, 0.001, 0.0}, {1, 0.1, 10, 1.00, 0.004, 0.0}, {1, 0.3, 1, 0.03, 0.003, 0.0},
    {1, 0.3, 10, 1.40, 0.008, 0.0}, {2, 0.1, 1, 0.01, 0.001, 0.0}, {2, 0.1, 10, 0.02, 0.002, 0.001},
    {2, 0.3, 1, 0.03, 0.003, 0.0},  {2, 0.3, 10, 0.20, 0.010, 0.002}, {3, 0.1, 10, 0.30, 0.004, 0.004},
    {3, 0.3, 10, 0.15, 0.040, 0.004}, {4, 0.1, 10, 0.05, 0.003, 0.003}, {4, 0.3, 10, 0.12, 0.002, 0.003},
};
}  // namespace

TEST(AutoErrorModel, InterpolatesLinearlyInNAndBetaAndFlagsClamping) {
  auto e = expected_level_error(kRecord, 1, 0.1, 10);
  EXPECT_TRUE(e.known);
  EXPECT_FALSE(e.extrapolated);
  EXPECT_DOUBLE_EQ(e.force, 1.00);
  e = expected_level_error(kRecord, 1, 0.2, 10);  // midway in beta
  EXPECT_NEAR(e.force, 1.20, 1e-12);
  EXPECT_NEAR(e.velocity, 0.006, 1e-12);
  e = expected_level_error(kRecord, 1, 0.1, 4);  // n = 4: a third of the way from 1 to 10
  EXPECT_NEAR(e.force, 0.01 + (4 - 1) / 9.0 * 0.99, 1e-12);
  EXPECT_FALSE(e.extrapolated);
  e = expected_level_error(kRecord, 2, 0.2, 4);  // both
  EXPECT_NEAR(e.force, 0.5 * ((0.01 + 3 / 9.0 * 0.01) + (0.03 + 3 / 9.0 * 0.17)), 1e-12);
  e = expected_level_error(kRecord, 2, 0.5, 10);  // beyond the record: clamped, flagged
  EXPECT_TRUE(e.extrapolated);
  EXPECT_DOUBLE_EQ(e.force, 0.20);
  e = expected_level_error(kRecord, 2, 0.3, 20);
  EXPECT_TRUE(e.extrapolated);
  EXPECT_DOUBLE_EQ(e.force, 0.20);
  EXPECT_DOUBLE_EQ(e.total(), 0.20);
  EXPECT_FALSE(expected_level_error(kRecord, 5, 0.2, 10).known);
}

TEST(AutoErrorModel, ChoosesTheCheapestLevelWithinTheToleranceElseTheMostAccurate) {
  const hsrod_test::UniformStream stream;
  const double beta = 0.1;
  const auto level3 = make_hydrodynamic_model("nonlocal", {kMu, kD / beta, kD}, ConfinementTable::default_table());
  const std::vector<RodGeometry> lone = {hsrod_test::straight_rod(1, kD, 0.0)};
  const std::vector<RodGeometry> rod = {hsrod_test::straight_rod(10, kD, 0.0)};
  // lone sphere: level 1 is within 10 %
  auto c = choose_auto_model(lone, stream, beta, *level3, 0.0, 0.01, 0.10, kRecord);
  EXPECT_EQ(c.model, find_model_level(1)->name);
  EXPECT_NEAR(c.expected_error, 0.01, 1e-12);
  // 10-sphere rod at beta 0.1: level 1 100 %, level 2 2 % -> level 2
  c = choose_auto_model(rod, stream, beta, *level3, 0.0, 0.01, 0.10, kRecord);
  EXPECT_EQ(c.model, find_model_level(2)->name);
  EXPECT_TRUE(c.within_tolerance);
  ASSERT_EQ(c.level_errors.size(), 4u);
  EXPECT_NEAR(c.level_errors[0], 1.00, 1e-12);
  EXPECT_NEAR(c.level_errors[3], 0.05, 1e-12);
  // at beta 0.3: level 2 20 %, level 3 15 %, level 4 12 %: none within 10 % -> level 4, said so
  c = choose_auto_model(rod, stream, 0.3, *level3, 0.0, 0.01, 0.10, kRecord);
  EXPECT_EQ(c.model, find_model_level(4)->name);
  EXPECT_FALSE(c.within_tolerance);
  EXPECT_NE(c.summary.find("no allowed level within the tolerance"), std::string::npos) << c.summary;
  // a looser tolerance takes the cheapest again
  c = choose_auto_model(rod, stream, 0.3, *level3, 0.0, 0.01, 0.25, kRecord);
  EXPECT_EQ(c.model, find_model_level(2)->name);
  EXPECT_NE(c.summary.find(", level 2 20.0 %,"), std::string::npos) << c.summary;
}

TEST(AutoErrorModel, RodThatBendsGetsANonLocalLevelOnly) {
  const hsrod_test::UniformStream stream;
  const double beta = 0.1;
  const auto level3 = make_hydrodynamic_model("nonlocal", {kMu, kD / beta, kD}, ConfinementTable::default_table());
  const std::vector<RodGeometry> across = {hsrod_test::straight_rod(10, kD, 0.5 * 3.14159265358979)};
  // soft bonds: the missed deflection exceeds 1 % -> levels 3-4 only; level 4 (5 %) is within 10 %
  auto c = choose_auto_model(across, stream, beta, *level3, 1e-19, 0.01, 0.10, kRecord);
  EXPECT_TRUE(c.flexible);
  EXPECT_GT(c.estimated_deflection, 0.01);
  EXPECT_EQ(c.model, find_model_level(4)->name);
  EXPECT_NE(c.summary.find("non-local levels only"), std::string::npos) << c.summary;
  // with a tolerance of 50 % level 3 (30 %) is the cheapest allowed one
  c = choose_auto_model(across, stream, beta, *level3, 1e-19, 0.01, 0.50, kRecord);
  EXPECT_EQ(c.model, find_model_level(3)->name);
  // stiff bonds: nothing to miss -> level 2
  c = choose_auto_model(across, stream, beta, *level3, 1e-10, 0.01, 0.10, kRecord);
  EXPECT_LT(c.estimated_deflection, 0.01);
  EXPECT_EQ(c.model, find_model_level(2)->name);
}
