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
//    as shipped gives a third of it (+0.89); the 10 % target is a disabled test;
//  - the neighbour-pair squeeze term (WallProximityLaw::pair_squeeze), fitted
//    on that one push, gives the push of the row turning 1 d from the wall and,
//    by reciprocity, the torque of the static campaign's row dragged along the
//    wall 1 d from it (both held out of its fit).
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

const std::string kStaticCases = std::string(HSROD_TEST_DATA_DIR) +
                                 "/../../calibration/data/resolved_near_wall_per_sphere.csv";

// level 3 with images or reflections, their shipped law and the fitted pair squeeze
hsrod::WallProximityCalibration with_pair_squeeze(const std::string& level) {
  hsrod::WallProximityCalibration wall = hsrod::WallProximityCalibration::built_in();
  wall.nonlocal = level == "nonlocal+images" ? hsrod::wall_proximity_with_images()
                                             : hsrod::wall_proximity_with_reflections();
  wall.nonlocal.pair_squeeze =
      level == "nonlocal+images" ? hsrod::kPairSqueezeOnImages : hsrod::kPairSqueezeOnReflections;
  return wall;
}

// moment of the sphere forces about the centroid over 3 pi mu d^2 U (the static
// table has no per-sphere torques; the model's are zero without spin)
double force_moment(const SceneCase& c, const std::vector<Eigen::Vector2d>& f) {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& x : c.positions) centre += x.head<2>() / static_cast<double>(c.positions.size());
  double t = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Eigen::Vector2d r = (c.positions[i].head<2>() - centre) / c.d;
    t += r.x() * f[i].y() - r.y() * f[i].x();
  }
  return t;
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
    // not met as shipped: measured 0.89 / 2.595 = 0.34 (the pair squeeze, fitted on this
    // very case and not shipped, would meet it by construction: not a test)
    EXPECT_NEAR(total(m.forces, 0) / resolved, 1.0, 0.10);
    return;
  }
  FAIL() << "no wall_a0_g0.5 rotation case in " << kCases;
}

TEST(NearWallRotation, PairSqueezeFittedHalfADiameterFromTheWallGivesTheHeldOutPushOneDiameterAway) {
  const auto table = hsrod::ConfinementTable::default_table();
  int checked = 0;
  for (const SceneCase& c : hsrod::calib::read_scene_cases(kCases)) {
    if (c.load != "rotation" || c.row_angle_deg != 0.0 || c.geometry != "wall") continue;
    for (const std::string level : {"nonlocal+images", "nonlocal+reflections"}) {
      const auto m = hsrod::calib::scene_sphere_loads(level, c, table, hsrod::NearFieldCalibration::built_in(),
                                                      with_pair_squeeze(level));
      const double ratio = total(m.forces, 0) / total(c.resolved, 0);
      if (c.gap_over_d == 0.5) {
        EXPECT_NEAR(ratio, 1.0, 1e-6) << level << ": the constant is not the fit";  // the fit case
      } else {
        // held out: the near-wall target (the reference's mesh change of the push at 0.5 d
        // is 0.4 %); measured -6.8 % (images), -6.3 % (reflections); without the term -48 %
        EXPECT_NEAR(ratio, 1.0, 0.10) << level << " " << c.name;
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4);
}

TEST(NearWallRotation, PairSqueezeGivesTheHeldOutTorqueOfARowDraggedAlongTheWallByReciprocity) {
  // R_{x Omega} = R_{Omega x}: the term that pushes a turning row along the wall turns a
  // row dragged along it. Static campaign, row of 5 at beta 0.3, 1 d from the wall, dragged
  // at -U (cos 45, sin 45): resolved force moment -0.574 (3 pi mu d^2 U). Tolerance: the
  // near-wall target, 5x the moment's mesh change at 0.25 d (-0.017 of -0.82; 1 d ran on
  // one mesh). Measured -0.574; without the term -0.22 (-61 %).
  const auto table = hsrod::ConfinementTable::default_table();
  for (const SceneCase& c : hsrod::calib::read_scene_cases(kStaticCases)) {
    if (c.name != "wall_a0_g1_b0.300_n5" || c.load != "friction") continue;
    const double resolved = force_moment(c, c.resolved);
    EXPECT_NEAR(resolved, -0.574, 0.005);
    for (const std::string level : {"nonlocal+images", "nonlocal+reflections"}) {
      const auto m = hsrod::calib::scene_sphere_loads(level, c, table, hsrod::NearFieldCalibration::built_in(),
                                                      with_pair_squeeze(level));
      EXPECT_NEAR(force_moment(c, m.forces) / resolved, 1.0, 0.10) << level;
    }
    return;
  }
  FAIL() << "no wall_a0_g1_b0.300_n5 friction case in " << kStaticCases;
}

}  // namespace
