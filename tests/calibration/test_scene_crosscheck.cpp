// Levels 1-4 against the resolved cases beyond straight rows in a wide slit
// (campaign "geometry": bent rods, rows near a side wall and beside a pore
// cylinder; calibration/data/resolved_geometry_per_sphere.csv, written by
// calibration/tools/geometry_cases.py from calibration/campaign/geometry).
//  - the scene cross-check's plumbing (frames, load directions, units) gives
//    the same per-sphere forces as the established row cross-check for a
//    straight row in the wide slit;
//  - the resolved data are what their symmetry says: rows parallel to the
//    wall, held in the channel flow, carry mirror-symmetric loads;
//  - accuracy: where the levels are within the 10 % (bent rods at
//    levels 3-4; level 4 from ~1 H off the wall), an enabled test; near the
//    wall (gaps 0.5-1.5 d) they are not: a disabled test with the figures.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "level_crosscheck.h"
#include "scene_crosscheck.h"

namespace {

using hsrod::calib::SceneCase;

const std::string kData = std::string(HSROD_TEST_DATA_DIR) + "/../../calibration/data/";

SceneCase straight_row_in_slit(const std::string& load, int n, double beta) {
  SceneCase c;
  c.name = "straight";
  c.geometry = "bent";  // the wide slit
  c.load = load;
  c.beta = beta;
  c.drag_angle_deg = 45.0;
  c.d = 3e-6;
  c.mu = 1e-3;
  c.U = 1e-3;
  for (int i = 0; i < n; ++i) c.positions.emplace_back((i - 0.5 * (n - 1)) * c.d, 0.0, 0.0);
  return c;
}

TEST(calibration_SceneCrossCheck, StraightRowInTheSlitEqualsTheRowCrossCheck) {
  const auto table = hsrod::ConfinementTable::default_table();
  const double c45 = std::sqrt(0.5);
  for (const char* level : {"isotropic", "local", "nonlocal", "twoway"}) {
    const auto row = hsrod::calib::row_response(level, 0.3, 10, 1.0, table);
    const auto fric = hsrod::calib::scene_forces(level, straight_row_in_slit("friction", 10, 0.3), table);
    const auto held = hsrod::calib::scene_forces(level, straight_row_in_slit("driving", 10, 0.3), table);
    ASSERT_EQ(fric.size(), 10u);
    const double tol = std::string(level) == "twoway" ? 2e-3 : 1e-9;  // level 4: its window's grid follows the load
    for (int i = 0; i < 10; ++i) {
      EXPECT_NEAR(fric[i].x(), row.friction_par[i] * c45, tol * std::abs(row.friction_par[i])) << level << " sphere " << i;
      EXPECT_NEAR(fric[i].y(), row.friction_perp[i] * c45, tol * std::abs(row.friction_perp[i])) << level << " sphere " << i;
      EXPECT_NEAR(held[i].x(), row.driving_par[i] * c45, tol * std::abs(row.driving_par[i])) << level << " sphere " << i;
      EXPECT_NEAR(held[i].y(), row.driving_perp[i] * c45, tol * std::abs(row.driving_perp[i])) << level << " sphere " << i;
    }
  }
}

TEST(calibration_SceneCrossCheck, ResolvedRowsAlongTheWallHeldInFlowAreMirrorSymmetric) {
  const auto cases = hsrod::calib::read_scene_cases(kData + "resolved_geometry_per_sphere.csv");
  int checked = 0;
  for (const SceneCase& c : cases) {
    if (c.geometry == "bent" || c.row_angle_deg != 0.0 || c.load != "driving") continue;
    const int n = static_cast<int>(c.resolved.size());
    double mean = 0.0;
    for (const auto& f : c.resolved) mean += f.norm() / n;
    for (int i = 0; i < n; ++i) {
      // x -> 2 x_c - x maps the row and the channel onto themselves (the pore's cylinders too)
      EXPECT_NEAR(c.resolved[i].x(), c.resolved[n - 1 - i].x(), 2e-3 * mean) << c.name << " sphere " << i;
      EXPECT_NEAR(c.resolved[i].y(), -c.resolved[n - 1 - i].y(), 2e-3 * mean) << c.name << " sphere " << i;
    }
    ++checked;
  }
  EXPECT_GE(checked, 5);  // wall gaps 0.5, 1.5, 3 d; pore gaps 0.5, 1.5 d
}

// Largest |total error| (components carrying >= 20 % of |F|) and profile RMS of
// `level` over the cases selected by `take`.
template <class Take>
std::pair<double, double> worst(const std::string& level, Take take, int* count) {
  const auto table = hsrod::ConfinementTable::default_table();
  double tot = 0.0, rms = 0.0;
  *count = 0;
  for (const SceneCase& c : hsrod::calib::read_scene_cases(kData + "resolved_geometry_per_sphere.csv")) {
    if (!take(c)) continue;
    const auto m = hsrod::calib::scene_forces(level, c, table);
    Eigen::Vector2d tm = Eigen::Vector2d::Zero(), tr = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < m.size(); ++i) {
      tm += m[i];
      tr += c.resolved[i];
    }
    for (int k = 0; k < 2; ++k)
      if (std::abs(tr[k]) >= 0.2 * tr.norm()) tot = std::max(tot, std::abs(tm[k] / tr[k] - 1.0));
    rms = std::max(rms, hsrod::calib::profile_rms(m, c.resolved));
    ++*count;
  }
  return {tot, rms};
}

TEST(calibration_SceneCrossCheck, BentRodsAtLevelsThreeAndFourWithinTenPercent) {
  for (const char* level : {"nonlocal", "twoway"}) {
    int n = 0;
    const auto [tot, rms] = worst(level, [](const SceneCase& c) { return c.geometry == "bent"; }, &n);
    ASSERT_GE(n, 2) << "no bent-rod cases in the table";
    EXPECT_LT(tot, 0.10) << level;  // measured: 6.3 / 6.7 % (C- and L-shaped N = 10, beta 0.3)
    EXPECT_LT(rms, 0.10) << level;  // measured: 4.6 / 5.4 %
  }
}

TEST(calibration_SceneCrossCheck, LevelFourWithinTenPercentAboutOneGapHeightFromTheWall) {
  int n = 0;
  const auto [tot, rms] =
      worst("twoway", [](const SceneCase& c) { return c.geometry == "wall" && c.gap_over_d * c.beta >= 0.85; }, &n);
  ASSERT_GE(n, 4) << "no wall cases at gap >= 0.85 H in the table";
  EXPECT_LT(tot, 0.10);  // measured: 5.7 % (wall-normal friction of a row parallel to the wall, gap 3 d = 0.9 H)
  EXPECT_LT(rms, 0.10);  // measured: 6.1 %
}

// NOT met (calibration/validation/crosscheck_walls.md): with the near-wall
// correction (hydro/wall_proximity.h, applied at level 4) level 4's totals
// are within 8.0 % near walls and pores (test calibration_WallProximity.*),
// its per-sphere profiles within 10.9 % (worst: row of 5 along the wall at
// beta 0.15, gap 0.5 d, friction; 10.2 % beside the pore cylinder). Levels
// 2-3 are 54 % / 54 % off (wall-normal friction at 0.5 d); their own fits of
// the correction (wall_proximity_fit.json, not applied) would reach 23 % / 22 %
// only: rows across the pore throat or normal to the wall (F_x -17..-20 %
// even 1.5 d off the cylinder) miss the depth-averaged flow's reflection off
// the walls, a channel-wide blockage a per-sphere near-wall term does not
// carry, and the fitted terms push the dynamic pore passage the wrong way;
// level 2 has no end effects either (profile RMS 27 % for bent rods).
TEST(calibration_SceneCrossCheck, DISABLED_LevelsTwoToFourWithinTenPercentNearWallsAndPores) {
  for (const char* level : {"local", "nonlocal", "twoway"}) {
    int n = 0;
    const auto [tot, rms] = worst(level, [](const SceneCase& c) { return c.geometry != "bent"; }, &n);
    EXPECT_LT(tot, 0.10) << level;
    EXPECT_LT(rms, 0.10) << level;
  }
}

}  // namespace
