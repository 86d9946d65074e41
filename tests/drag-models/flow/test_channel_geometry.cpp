// Channel planform: queries on the paper's pore constriction and input validation.
#include "geometry/channel_geometry.h"
#include "geometry/pore_constriction.h"

#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hsrod {
namespace {

constexpr double um = 1e-6;

TEST(ChannelGeometry, PoreConstrictionHasPaperPoreWidth) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = s.geometry();
  EXPECT_FALSE(g.is_straight());
  EXPECT_TRUE(s.straight_geometry().is_straight());
  EXPECT_NEAR(g.gap_height(), 20 * um, 1e-12);  // H = 3 um / 0.15
  // Pore width d_pore = W - 2R = 30 um, exactly at x_pore and as the minimum over x.
  EXPECT_NEAR(g.open_width(s.x_pore), 30 * um, 1e-12);
  EXPECT_NEAR(g.narrowest_opening(), 30 * um, 1e-12);
  EXPECT_NEAR(pore_width(s.width, s.pore_radius), 30 * um, 1e-12);
  // Away from the pore the full width is open.
  EXPECT_DOUBLE_EQ(g.open_width(s.x_pore - 90 * um), s.width);
}

TEST(ChannelGeometry, FluidTestAndSignedDistance) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = s.geometry();
  const double yc = 0.5 * s.width;
  EXPECT_TRUE(g.is_fluid(s.x_pore, yc));
  EXPECT_FALSE(g.is_fluid(s.x_pore, yc + 16 * um));         // inside the upper cylinder
  EXPECT_FALSE(g.is_fluid(s.x_pore + 100 * um, -1 * um));   // outside the side wall
  EXPECT_FALSE(g.is_fluid(-1 * um, yc));                    // upstream of the inlet
  // Pore centre: 15 um from both cylinder surfaces.
  EXPECT_NEAR(g.signed_distance(s.x_pore, yc), 15 * um, 1e-12);
  // Inside the lower cylinder, 5 um below its surface: -5 um.
  EXPECT_NEAR(g.signed_distance(s.x_pore, 80 * um), -5 * um, 1e-12);
  // Near the lower side wall, far from the pore: distance to the wall, normal +y.
  EXPECT_NEAR(g.signed_distance(50 * um, 10 * um), 10 * um, 1e-12);
  EXPECT_TRUE(g.wall_normal(50 * um, 10 * um).isApprox(Eigen::Vector2d(0, 1)));
  // Normal on the cylinder points radially into the fluid.
  const Eigen::Vector2d n = g.wall_normal(s.x_pore - 60 * um, 70 * um);
  const Eigen::Vector2d radial = Eigen::Vector2d(-60 * um, 70 * um).normalized();
  EXPECT_NEAR((n - radial).norm(), 0.0, 1e-12);
}

TEST(ChannelGeometry, RayDistanceIsExactForWallsAndCylinders) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = s.geometry();
  const double inf = std::numeric_limits<double>::infinity();
  // From the pore centre straight up: the upper cylinder at 15 um.
  EXPECT_NEAR(g.ray_distance_to_wall({s.x_pore, 100 * um}, {0, 1}, 1.0), 15 * um, 1e-12);
  // Along +x at y = 10 um: the lower cylinder at x = x_pore - sqrt(R^2 - 10^2 um^2).
  const double x_hit = s.x_pore - std::sqrt(s.pore_radius * s.pore_radius - 100 * um * um);
  EXPECT_NEAR(g.ray_distance_to_wall({0.0, 10 * um}, {1, 0}, 1.0), x_hit, 1e-12);
  // Nothing within a short range; the side wall when looking down.
  EXPECT_EQ(g.ray_distance_to_wall({0.0, 10 * um}, {1, 0}, 100 * um), inf);
  EXPECT_NEAR(g.ray_distance_to_wall({0.0, 10 * um}, {0, -1}, 1.0), 10 * um, 1e-12);
}

TEST(ChannelGeometry, RejectsNonPositiveDimensions) {
  test::expect_invalid_argument([] { ChannelGeometry(600 * um, 200 * um, -20 * um); },
                                {"gap_height H", "> 0"});
  test::expect_invalid_argument([] { ChannelGeometry(0.0, 200 * um, 20 * um); },
                                {"length L", "> 0"});
  test::expect_invalid_argument(
      [] { make_pore_constriction(600 * um, -200 * um, 20 * um, 85 * um, 300 * um); },
      {"width W", "> 0"});
  test::expect_invalid_argument(
      [] { ChannelGeometry(600 * um, 200 * um, std::nan(""), 0.0, 0.0); }, {"gap_height H"});
}

TEST(ChannelGeometry, RejectsPoreRadiusAtOrAboveHalfWidth) {
  for (double r : {100 * um, 120 * um})
    test::expect_invalid_argument(
        [r] { make_pore_constriction(600 * um, 200 * um, 20 * um, r, 300 * um); },
        {"pore radius R", "0 <= R < W/2", "pore width"});
  test::expect_invalid_argument(
      [] { make_pore_constriction(600 * um, 200 * um, 20 * um, -1 * um, 300 * um); },
      {"pore radius R"});
  // R just below W/2 is a valid (very narrow) pore.
  EXPECT_NO_THROW(make_pore_constriction(600 * um, 200 * um, 20 * um, 99 * um, 300 * um));
}

TEST(ChannelGeometry, RejectsCylindersOutsideTheChannel) {
  test::expect_invalid_argument(
      [] { ChannelGeometry(600 * um, 200 * um, 20 * um, 0, 0, {{300 * um, -10 * um, 20 * um}}); },
      {"cylinder 0", "must lie inside the channel"});
  test::expect_invalid_argument(
      [] { ChannelGeometry(600 * um, 200 * um, 20 * um, 0, 0, {{700 * um, 100 * um, 20 * um}}); },
      {"cylinder 0", "must lie inside the channel"});
  // Crossing the inlet plane: the developed inlet profile would be cut.
  test::expect_invalid_argument(
      [] { ChannelGeometry(600 * um, 200 * um, 20 * um, 0, 0, {{10 * um, 100 * um, 20 * um}}); },
      {"clear of the inlet and outlet"});
  test::expect_invalid_argument(
      [] { make_pore_constriction(600 * um, 200 * um, 20 * um, 85 * um, 50 * um); },
      {"clear of the inlet and outlet"});
  // Two cylinders that together close the channel.
  test::expect_invalid_argument(
      [] {
        ChannelGeometry(600 * um, 200 * um, 20 * um, 0, 0,
                        {{300 * um, 50 * um, 60 * um}, {300 * um, 150 * um, 60 * um}});
      },
      {"close the channel"});
  test::expect_invalid_argument(
      [] { ChannelGeometry(600 * um, 200 * um, 20 * um, 0, 0, {{300 * um, 100 * um, -1 * um}}); },
      {"radius R", ">= 0"});
}

}  // namespace
}  // namespace hsrod
