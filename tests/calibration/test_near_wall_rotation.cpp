// Levels 3-4 against the resolved rows turning beside a side wall and a pore
// cylinder (campaign "near-wall-rotation";
// calibration/data/resolved_near_wall_rotation_per_sphere.csv, written by
// calibration/tools/geometry_cases.py; calibration/validation/crosscheck_near_wall.md).
//  - the resolved rows parallel to the wall turn with no force normal to it
//    (their mirror symmetry x -> 2 x_c - x);
//  - the rod torque of level 3 with the walls' images and of level 4, each
//    with its near-wall law, is within 10 % of the resolved one on every case
//    (the near-wall target of the other cross-checks; measured worst 6.1 % and
//    9.2 %, the reference's mesh change 0.6 %);
//  - the coupling force is not: a row turning parallel to the wall 0.5 d from
//    it is pushed along the wall with +2.6 (3 pi mu d U), level 3 with images
//    gives a third of it (+0.89); the 10 % target is a disabled test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hydro/confinement_coefficients.h"
#include "scene_crosscheck.h"

namespace {

using hsrod::calib::SceneCase;

const std::string kCases = std::string(HSROD_TEST_DATA_DIR) +
                           "/../../calibration/data/resolved_near_wall_rotation_per_sphere.csv";

hsrod::WallProximityCalibration as_shipped(const std::string& level) {
  hsrod::WallProximityCalibration wall = hsrod::WallProximityCalibration::built_in();
  if (level == "nonlocal+images") wall.nonlocal = hsrod::wall_proximity_with_images();
  return wall;
}

double total(const std::vector<Eigen::Vector2d>& f, int k) {
  double s = 0.0;
  for (const auto& v : f) s += v[k];
  return s;
}

TEST(NearWallRotation, RowsAlongTheWallTurnWithoutNormalForce) {
  int checked = 0;
  for (const SceneCase& c : hsrod::calib::read_scene_cases(kCases)) {
    if (c.row_angle_deg != 0.0) continue;
    // |F_y| against the along-wall force and the per-sphere normal forces (~10)
    EXPECT_LT(std::abs(total(c.resolved, 1)), 0.05) << c.name << " " << c.load;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST(NearWallRotation, LevelsThreeWithImagesAndFourGetTheRodTorqueWithinTenPercent) {
  const auto table = hsrod::ConfinementTable::default_table();
  int checked = 0;
  for (const SceneCase& c : hsrod::calib::read_scene_cases(kCases)) {
    const double resolved = hsrod::calib::rod_torque(c.positions, c.d, c.resolved, c.resolved_torque);
    for (const std::string level : {"nonlocal+images", "twoway"}) {
      const auto m = hsrod::calib::scene_sphere_loads(level, c, table, hsrod::NearFieldCalibration::built_in(),
                                                      as_shipped(level));
      const double model = hsrod::calib::rod_torque(c.positions, c.d, m.forces, m.torques);
      EXPECT_NEAR(model / resolved, 1.0, 0.10) << level << " " << c.name << " " << c.load;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 20);
}

TEST(NearWallRotation, DISABLED_LevelThreeWithImagesGetsTheAlongWallPushOfATurningRowWithinTenPercent) {
  const auto table = hsrod::ConfinementTable::default_table();
  for (const SceneCase& c : hsrod::calib::read_scene_cases(kCases)) {
    if (c.name != "wall_a0_g0.5_b0.300_n10" || c.load != "rotation") continue;
    const double resolved = total(c.resolved, 0);
    const auto m = hsrod::calib::scene_sphere_loads("nonlocal+images", c, table, hsrod::NearFieldCalibration::built_in(),
                                                    as_shipped("nonlocal+images"));
    EXPECT_NEAR(resolved, 2.6, 0.1);  // mesh 8; mesh 6 gives 2.605
    // not met: measured 0.89 / 2.595 = 0.34
    EXPECT_NEAR(total(m.forces, 0) / resolved, 1.0, 0.10);
    return;
  }
  FAIL() << "no wall_a0_g0.5 rotation case in " << kCases;
}

}  // namespace
