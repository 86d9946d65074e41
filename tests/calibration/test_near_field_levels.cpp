// Levels 3 and 4 with the near-field coupling (drag-models/hydro/
// near_field_coupling.h, fitted by hsrod_fit_near_field: friction and held
// load each with its own pair mobility, blend lengths along and across the
// line of centres, every parameter quadratic in beta) against the resolved
// rodIbFoam campaign itself (calibration/data/resolved_campaign_
// {series,profiles}.csv: rigid rows of touching spheres at the mid-plane,
// finest mesh), with the built-in confinement table (the fit of levels 1-2,
// whose sphere columns levels 3-4 use):
//  - every fitted rod (n = 2, 5, 10 at beta 0.1, 0.15, 0.2, 0.3, 0.45, 0.6,
//    0.75): total friction and held-in-flow load along and across the flow
//    within 10 %, each per-sphere profile (friction and held load, along and
//    across) within 10 % RMS of its mean magnitude, force-free velocity along
//    and across within 3 %, r = U_perp / U_par within 1 %;
//  - the rods left out of the fit (7 spheres at beta 0.25, 10 at beta 0.5,
//    15 at beta 0.3: betas and a length in no fitted row) predicted within
//    the same tolerances;
//  - the built-in near field is the shipped file calibration/data/near_field_coupling.txt.
// Measured (shipped fit): totals within 5.3 %, profile RMS within
// 5.4 % (both the held-out N = 15 rod across), free velocity within 1.01 %,
// r within 0.43 % (held-out N = 15), at both levels; the fit's report is in
// the file's comments.
// Level 4 may refuse a beta where its default window grid is too coarse for
// the sphere (an error naming the remedy): reported, not counted.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "level_crosscheck.h"
#include "near_field_fit.h"
#include "resolved_campaign.h"

using namespace hsrod::calib;

namespace {

const std::string kData = std::string(HSROD_TEST_DATA_DIR) + "/../../calibration/data/";

struct Checked {
  int rods = 0, tens = 0;
};

// Every check on every row of the role (one evaluation of the level per row).
Checked expect_level(const std::string& level, const std::string& role) {
  const auto series = read_resolved_series(kData + "resolved_campaign_series.csv");
  const auto profiles = read_resolved_profiles(kData + "resolved_campaign_profiles.csv");
  const hsrod::ConfinementTable table = hsrod::ConfinementTable::default_table();
  Checked checked;
  for (const NearFieldCase& c : near_field_cases(level, series, profiles, table)) {
    const ResolvedRod& s = c.resolved;
    if (s.role != role) continue;  // every spacing in the record (pairs at 2 d and 4 d when recorded)
    // The registered model (built-in near field), not the fit's shortcut.
    RowResponse m;
    try {
      m = row_response(level, s.beta, s.n, s.spacing, table);
    } catch (const std::exception& e) {
      std::printf("%s at beta %.2f n %d refuses: %s\n", level.c_str(), s.beta, s.n, e.what());
      EXPECT_EQ(level, "twoway") << e.what();
      EXPECT_NE(std::string(e.what()).find("refine the grid"), std::string::npos) << e.what();
      continue;
    }
    const CaseErrors e = case_errors(c, m);
    const std::string where = level + " beta " + std::to_string(s.beta) + " n " + std::to_string(s.n) + " (" + role + ")";
    const char* total_names[4] = {"friction along", "friction across", "held load along", "held load across"};
    const char* profile_names[4] = {"friction along", "friction across", "held load along", "held load across"};
    for (int q = 0; q < 4; ++q) {
      EXPECT_LT(std::abs(e.total[q]), 0.10) << where << " total " << total_names[q];
      EXPECT_LT(e.profile_rms[q], 0.10) << where << " per-sphere profile RMS, " << profile_names[q];
    }
    EXPECT_LT(std::abs(e.lambda[0]), 0.03) << where << " free velocity along";
    EXPECT_LT(std::abs(e.lambda[1]), 0.03) << where << " free velocity across";
    EXPECT_LT(std::abs(e.ratio), 0.01) << where << " r = U_perp / U_par";
    std::printf("%s: totals %+.1f/%+.1f/%+.1f/%+.1f %%, profile RMS %.1f/%.1f/%.1f/%.1f %%, free velocity %+.2f/%+.2f %%, "
                "r %.4f (resolved %.4f)\n",
                where.c_str(), 100 * e.total[0], 100 * e.total[1], 100 * e.total[2], 100 * e.total[3],
                100 * e.profile_rms[0], 100 * e.profile_rms[1], 100 * e.profile_rms[2], 100 * e.profile_rms[3],
                100 * e.lambda[0], 100 * e.lambda[1], m.r(), s.at("r"));
    ++checked.rods;
    checked.tens += s.n == 10;
  }
  return checked;
}

}  // namespace

TEST(calibration_NearFieldLevels, Level3ReproducesTheResolvedRodsSphereBySphere) {
  const Checked c = expect_level("nonlocal", "fit");
  EXPECT_GE(c.rods, 21) << "resolved rods of 2, 5 and 10 spheres at seven beta expected";
  EXPECT_GE(c.tens, 7);
}

TEST(calibration_NearFieldLevels, Level4ReproducesTheResolvedRodsSphereBySphere) {
  const Checked c = expect_level("twoway", "fit");
  EXPECT_GE(c.rods, 15) << "resolved rods of 2, 5 and 10 spheres at five beta or more expected";
  EXPECT_GE(c.tens, 5);
}

TEST(calibration_NearFieldLevels, Level3PredictsTheHeldOutRods) {
  EXPECT_GE(expect_level("nonlocal", "heldout").rods, 3) << "held-out rods: beta 0.25 N = 7, 0.5 N = 10, 0.3 N = 15";
}

TEST(calibration_NearFieldLevels, Level4PredictsTheHeldOutRods) {
  EXPECT_GE(expect_level("twoway", "heldout").rods, 3) << "held-out rods: beta 0.25 N = 7, 0.5 N = 10, 0.3 N = 15";
}

TEST(calibration_NearFieldLevels, BuiltInNearFieldIsTheShippedFit) {
  const auto shipped = hsrod::NearFieldCalibration::read(kData + "near_field_coupling.txt");
  const auto built_in = hsrod::NearFieldCalibration::built_in();
  for (int level = 0; level < 2; ++level) {
    const hsrod::NearFieldLaw& a = level == 0 ? built_in.nonlocal : built_in.twoway;
    const hsrod::NearFieldLaw& b = level == 0 ? shipped.nonlocal : shipped.twoway;
    EXPECT_EQ(a.active, b.active);
    EXPECT_NEAR(a.beta_min, b.beta_min, 1e-12);
    EXPECT_NEAR(a.beta_max, b.beta_max, 1e-12);
    for (int load = 0; load < 2; ++load)
      for (int q = 0; q < 4; ++q) {
        ASSERT_EQ(a.coefficients[load][q].size(), b.coefficients[load][q].size());
        for (std::size_t j = 0; j < a.coefficients[load][q].size(); ++j)
          EXPECT_NEAR(a.coefficients[load][q][j], b.coefficients[load][q][j], 1e-8);
      }
  }
  EXPECT_EQ(built_in.source, shipped.source);
}
