// Levels 1-4 with the calibrated confinement table (the fit of levels 1-2 to
// the resolved rodIbFoam campaign, calibration/data/confinement_campaign.txt,
// hsrod_fit_campaign) against the resolved runs themselves (calibration/data/
// resolved_campaign_series.csv, calibration/tools/campaign_analysis.py):
//  - the built-in table (ConfinementTable::default_table()) is this fit;
//  - level 2 reproduces the total friction and the held-in-flow load of
//    rigid rods of every resolved length (the table's 10-sphere columns and
//    level 2's rod-length law) along and across the flow within 10 %, their
//    force-free velocity within 3 % and r = U_perp / U_par within 1 %, at
//    every calibrated beta (0.1-0.75), and the drift anisotropy r - 1 within
//    10 % of itself or 3e-4 (the size and direction of a tilted rod's drift);
//  - the same for the rods left out of the fit (role "heldout": 7 spheres at
//    beta 0.25, 10 at beta 0.5, 15 at beta 0.3; betas 0.25 and 0.5 and the
//    length 15 are in no fitted case): the table is a fit (smooth forms in
//    beta and n), not a lookup;
//  - a lone sphere at every level is the resolved confined sphere (1 %);
//    level 4 may refuse a beta where its default window grid is too coarse
//    for the sphere, with an error naming the remedy.
#include <gtest/gtest.h>

#include <algorithm>

#include <string>
#include <vector>

#include "level_crosscheck.h"
#include "resolved_campaign.h"

using namespace hsrod::calib;

namespace {

using Resolved = ResolvedRod;

std::vector<Resolved> resolved_series() {
  return read_resolved_series(std::string(HSROD_TEST_DATA_DIR) + "/../../calibration/data/resolved_campaign_series.csv");
}

const hsrod::ConfinementTable& calibrated_table() {
  static const hsrod::ConfinementTable table = hsrod::ConfinementTable::read(
      std::string(HSROD_TEST_DATA_DIR) + "/../../calibration/data/confinement_campaign.txt");
  return table;
}

void expect_rod(const Resolved& s, const std::string& level) {
  const hsrod::ConfinementTable& table = calibrated_table();
  const RowResponse m = row_response(level, s.beta, s.n, s.spacing, table);
  const std::string where = level + " beta " + std::to_string(s.beta) + " n " + std::to_string(s.n) + " (" + s.role + ")";
  EXPECT_NEAR(m.R_par() / s.q.at("R_par"), 1.0, 0.10) << where << " friction along";
  EXPECT_NEAR(m.R_perp() / s.q.at("R_perp"), 1.0, 0.10) << where << " friction across";
  EXPECT_NEAR(m.D_par() / s.q.at("D_par"), 1.0, 0.10) << where << " held load along";
  EXPECT_NEAR(m.D_perp() / s.q.at("D_perp"), 1.0, 0.10) << where << " held load across";
  EXPECT_NEAR(m.lambda_par() / s.q.at("lambda_par"), 1.0, 0.03) << where << " free velocity along";
  EXPECT_NEAR(m.lambda_perp() / s.q.at("lambda_perp"), 1.0, 0.03) << where << " free velocity across";
  EXPECT_NEAR(m.r() / s.q.at("r"), 1.0, 0.01) << where << " r = U_perp / U_par";
  std::printf("%s: R_par %+.2f %% R_perp %+.2f %% D_par %+.2f %% D_perp %+.2f %% lambda_par %+.2f %% lambda_perp "
              "%+.2f %% r - 1 = %.5f (resolved %.5f)\n",
              where.c_str(), 100 * (m.R_par() / s.q.at("R_par") - 1), 100 * (m.R_perp() / s.q.at("R_perp") - 1),
              100 * (m.D_par() / s.q.at("D_par") - 1), 100 * (m.D_perp() / s.q.at("D_perp") - 1),
              100 * (m.lambda_par() / s.q.at("lambda_par") - 1), 100 * (m.lambda_perp() / s.q.at("lambda_perp") - 1),
              m.r() - 1, s.q.at("r") - 1);
}

}  // namespace

TEST(calibration_CalibratedLevels, BuiltInTableIsTheShippedFit) {
  const hsrod::ConfinementTable built_in = hsrod::ConfinementTable::default_table();
  const auto& shipped = calibrated_table().rows();
  ASSERT_EQ(built_in.rows().size(), shipped.size());
  for (std::size_t k = 0; k < shipped.size(); ++k) {
    const auto& a = built_in.rows()[k];
    const auto& b = shipped[k];
    EXPECT_NEAR(a.beta, b.beta, 1e-12);
    EXPECT_NEAR(a.c.sphere_friction, b.c.sphere_friction, 1e-8) << "beta " << b.beta;
    EXPECT_NEAR(a.c.sphere_driving, b.c.sphere_driving, 1e-8) << "beta " << b.beta;
    EXPECT_NEAR(a.c.parallel_friction, b.c.parallel_friction, 1e-8) << "beta " << b.beta;
    EXPECT_NEAR(a.c.perpendicular_friction, b.c.perpendicular_friction, 1e-8) << "beta " << b.beta;
    EXPECT_NEAR(a.c.parallel_driving, b.c.parallel_driving, 1e-8) << "beta " << b.beta;
    EXPECT_NEAR(a.c.perpendicular_driving, b.c.perpendicular_driving, 1e-8) << "beta " << b.beta;
  }
}

TEST(calibration_CalibratedLevels, Level2ReproducesTheResolvedRigidRods) {
  int rods = 0, tens = 0;
  for (const auto& s : resolved_series())
    if (s.n > 1 && s.spacing == 1.0 && s.role == "fit") {
      expect_rod(s, "local");
      ++rods;
      tens += s.n == 10;
    }
  EXPECT_GE(tens, 7) << "resolved 10-sphere rods at every calibrated beta (0.1, 0.15, 0.2, 0.3, 0.45, 0.6, 0.75) expected";
  EXPECT_GE(rods, 21) << "resolved rods of 2, 5 and 10 spheres at each calibrated beta expected";
}

// With a constant held-load growth k_held beta^2 (r fit chi2/dof 57) level
// 2's r at beta 0.75 grows too slowly with the rod's length: N = 5 r - 1 =
// 0.047 against 0.063 resolved (-1.4 % on r), N = 10 0.064 against 0.094
// (-2.8 %). With k(beta), k_held(beta) polynomials, and beta 0.75 resolved on
// meshes 6-12 (the sphere-wall gap is 1-2 cells), r is within 0.1 %.
TEST(calibration_CalibratedLevels, Level2RAtBeta075Within1Percent) {
  int rods = 0;
  for (const auto& s : resolved_series())
    if (s.n > 1 && s.spacing == 1.0 && s.beta > 0.7) {
      expect_rod(s, "local");
      ++rods;
    }
  EXPECT_GE(rods, 3);
}

// The lateral drift of a tilted rod is set by r - 1 (a few 1e-4 at beta
// 0.1-0.2, 0.09 at 0.75 for N = 10): level 2 must get its size and sign, not
// only r within 1 % (which any r - 1 below 0.01 meets). Tolerance: 10 % of the
// resolved r - 1, or three times the fit's uncertainty floor on r where r - 1
// is that small (calibration/tools/campaign_analysis.py RATIO_FLOOR = 1e-4:
// 3e-4; worst today beta 0.3 N = 5, r - 1 = 0.00141 against 0.00119).
TEST(calibration_CalibratedLevels, Level2DriftAnisotropyAsResolved) {
  const hsrod::ConfinementTable& table = calibrated_table();
  int rods = 0;
  for (const auto& s : resolved_series()) {
    if (s.n < 2 || s.spacing != 1.0) continue;
    const RowResponse m = row_response("local", s.beta, s.n, s.spacing, table);
    const double resolved = s.q.at("r") - 1.0;
    EXPECT_NEAR(m.r() - 1.0, resolved, std::max(3e-4, 0.1 * std::abs(resolved)))
        << "beta " << s.beta << " n " << s.n << " (" << s.role << ")";
    ++rods;
  }
  EXPECT_GE(rods, 25);
}

// beta 0.05, below the fitted range (0.1-0.75; the resolved campaign starts
// at 0.05): the resolved rows of calibration/campaign/beta005 (meshes d/h = 6
// and 8, values on 8; lateral faces 2 H: calibration/data/
// resolved_beta005_series.csv) against levels 2-4 with the shipped table and
// near field, extrapolated: totals within 10 %, free velocities within 3 %,
// r within 1 % (measured on mesh 8: level 2 totals -3.1..+3.2 %, level 3
// -1.8..-0.4 %, level 4 -2.1..-0.8 %, velocities <= 0.23 %, r - 1 within
// 1.5e-3; the mesh-8 loads are 0.2-1.1 % below mesh 6's).
TEST(calibration_CalibratedLevels, LevelsTwoToFourAtBeta005AsResolved) {
  const auto rows = read_resolved_series(std::string(HSROD_TEST_DATA_DIR) +
                                         "/../../calibration/data/resolved_beta005_series.csv");
  int rods = 0;
  for (const auto& s : rows) {
    if (s.n < 2) continue;
    ++rods;
    for (const std::string level : {"local", "nonlocal", "twoway"}) expect_rod(s, level);
  }
  EXPECT_GE(rods, 1) << "a resolved beta 0.05 rod expected";
}

TEST(calibration_CalibratedLevels, Level2PredictsHeldOutRods) {
  int rods = 0;
  for (const auto& s : resolved_series())
    if (s.n > 1 && s.spacing == 1.0 && s.role == "heldout") {
      expect_rod(s, "local");
      ++rods;
    }
  EXPECT_GE(rods, 3) << "held-out rods expected: beta 0.25 N = 7, beta 0.5 N = 10, beta 0.3 N = 15";
}

TEST(calibration_CalibratedLevels, LoneSphereAtEveryLevelIsTheResolvedConfinedSphere) {
  const hsrod::ConfinementTable& table = calibrated_table();
  int spheres = 0;
  for (const auto& s : resolved_series()) {
    if (s.n != 1) continue;
    ++spheres;
    for (const std::string level : {"isotropic", "local", "nonlocal", "twoway"}) {
      RowResponse m;
      try {
        m = row_response(level, s.beta, 1, 1.0, table);
      } catch (const std::exception& e) {
        // Level 4 refuses a window grid too coarse for the sphere (its
        // footprint more mobile than the sphere: beta >= 0.6 at the default
        // 4 cells per d): reported as such, with the remedy named.
        std::printf("%s at beta %.2f refuses: %s\n", level.c_str(), s.beta, e.what());
        EXPECT_EQ(level, "twoway") << e.what();
        EXPECT_NE(std::string(e.what()).find("refine the grid"), std::string::npos) << e.what();
        continue;
      }
      EXPECT_NEAR(m.R_par() / s.q.at("R_par"), 1.0, 0.01) << level << " beta " << s.beta;
      EXPECT_NEAR(m.D_par() / s.q.at("D_par"), 1.0, 0.01) << level << " beta " << s.beta;
      EXPECT_NEAR(m.R_perp() / m.R_par(), 1.0, 1e-9) << level << ": a lone sphere is isotropic";
    }
  }
  EXPECT_GE(spheres, 2);
}

// beta 0.83 (the paper's Hele-Shaw scene, Fig. 3: a rod of 15 spheres), above
// the fitted range (0.1-0.75): the resolved rows of calibration/campaign/
// beta-high (meshes d/h = 12 and 16, values on 16: calibration/data/
// resolved_beta_high_series.csv) against levels 2-4 with the shipped table and
// near field, at the tolerances of every calibrated beta above. Not met
// (examples/hele-shaw/README.md): level 3's perpendicular loads on the
// 15-sphere rod are 44-49 % high and its r 6.8 %; level 4's loads 18-20 %,
// level 2's r -1.2 %. Enabled once the table is refitted over beta 0.83-0.9.
TEST(calibration_CalibratedLevels, DISABLED_LevelsTwoToFourAtTheFigThreeConfinementAsResolved) {
  const auto rows = read_resolved_series(std::string(HSROD_TEST_DATA_DIR) +
                                         "/../../calibration/data/resolved_beta_high_series.csv");
  int rods = 0;
  for (const auto& s : rows) {
    if (s.n < 2 || s.beta > 0.85) continue;  // level 4's table stops at beta 0.85
    ++rods;
    for (const std::string level : {"local", "nonlocal", "twoway"}) expect_rod(s, level);
  }
  EXPECT_GE(rods, 4) << "resolved beta 0.83 rods of 2, 5, 10 and 15 spheres expected";
}
