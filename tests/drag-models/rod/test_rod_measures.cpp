// The paper's eqs. (1)-(2) on hand-computed configurations.
#include "rod/rod_measures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hsrod;

TEST(RodMeasures, AngleEq1AllQuadrants) {
  const double pi = 3.14159265358979323846;
  const Eigen::Vector2d o(0, 0);
  EXPECT_NEAR(rod_angle_eq1(Eigen::Vector2d(0, 1), o), 0.0, 1e-15);        // along y: perpendicular to flow
  EXPECT_NEAR(rod_angle_eq1(Eigen::Vector2d(1, 1), o), pi / 4, 1e-15);
  EXPECT_NEAR(rod_angle_eq1(Eigen::Vector2d(1, 0), o), pi / 2, 1e-15);     // aligned with the flow
  EXPECT_NEAR(rod_angle_eq1(Eigen::Vector2d(1, -1), o), 3 * pi / 4, 1e-15);
  EXPECT_NEAR(rod_angle_eq1(Eigen::Vector2d(-1, -1), o), -3 * pi / 4, 1e-15);
  EXPECT_NEAR(rod_angle_eq1(Eigen::Vector2d(-1, 1), o), -pi / 4, 1e-15);
}

TEST(RodMeasures, DeflectionEq2) {
  // Ends on the x axis 10 apart, middle sphere lifted by 2: delta = 2 / L_Rod.
  const std::vector<Eigen::Vector2d> centres = {{0, 0}, {5, 2}, {10, 0}};
  EXPECT_NEAR(relative_deflection_eq2({0, 0}, {10, 0}, centres, 11.0), 2.0 / 11.0, 1e-15);
  const std::vector<Eigen::Vector2d> straight = {{0, 0}, {5, 5}, {10, 10}};
  EXPECT_NEAR(relative_deflection_eq2({0, 0}, {10, 10}, straight, 14.0), 0.0, 1e-15);
}
