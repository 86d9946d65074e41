#include "rod/rod_layout.h"
#include "rod/rod_measures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace hsrod;

TEST(RodLayout, ChainHasNMinusOneBondsAndTheRequestedAngle) {
  RodSpec spec;
  spec.number_of_sections = 10;
  spec.sphere_diameter = 3e-6;
  spec.angle = 10.0 * 3.14159265358979323846 / 180.0;
  spec.centre = Eigen::Vector3d(1e-4, 2e-4, 1e-5);
  const auto layout = make_rod_layout(spec);
  ASSERT_EQ(layout.spheres.size(), 10u);
  EXPECT_EQ(layout.bonds.size(), 9u);
  EXPECT_EQ(layout.max_bonds_per_sphere, 2);
  const auto& a = layout.spheres.front().position;
  const auto& b = layout.spheres.back().position;
  EXPECT_NEAR((a - b).norm(), 9 * 3e-6, 1e-18);
  EXPECT_NEAR(rod_angle_eq1(a.head<2>(), b.head<2>()), spec.angle, 1e-12);
  EXPECT_NEAR(0.5 * (a + b).x(), 1e-4, 1e-18);
}

TEST(RodLayout, TwoByTwoSectionsBondAlongAndAcross) {
  RodSpec spec;
  spec.number_of_sections = 5;
  spec.sphere_diameter = 3e-6;
  spec.section_rows = 2;
  spec.section_layers = 2;
  const auto layout = make_rod_layout(spec);
  EXPECT_EQ(layout.spheres.size(), 20u);
  // 4 axial chains of 4 bonds + 4 edges per section.
  EXPECT_EQ(layout.bonds.size(), 4u * 4u + 5u * 4u);
  for (const auto& b : layout.bonds) {
    const double length = (layout.spheres[b.first].position - layout.spheres[b.second].position).norm();
    EXPECT_NEAR(length, 3e-6, 1e-15);
  }
}

TEST(RodLayout, RejectsBadInput) {
  RodSpec spec;
  spec.number_of_sections = 1;
  spec.sphere_diameter = 3e-6;
  EXPECT_THROW(make_rod_layout(spec), std::invalid_argument);
  spec.number_of_sections = 3;
  spec.sphere_diameter = -1;
  EXPECT_THROW(make_rod_layout(spec), std::invalid_argument);
  EXPECT_THROW(parse_section("2y2"), std::invalid_argument);
  EXPECT_EQ(parse_section("2x2"), std::make_pair(2, 2));
}
