// Closed-form straight-channel Brinkman flow: normalisation, momentum balance,
// the side-wall layer, the 3-D gap profile and the paper's Reynolds number.
#include "flow/inflow.h"
#include "flow/straight_channel_flow.h"
#include "geometry/pore_constriction.h"

#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hsrod {
namespace {

constexpr double um = 1e-6;

TEST(StraightChannelFlow, MeanVelocityAndFlowRate) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = s.straight_geometry();
  const double u_mean = 0.03;  // m/s
  const StraightChannelFlow flow(g, s.fluid, Inflow::mean_velocity(u_mean));
  EXPECT_DOUBLE_EQ(flow.mean_velocity(), u_mean);
  // Q = H * integral u dy must equal U W H; the midpoint rule with 20000
  // points has a relative error ~ (dy/delta)^2/24 ~ 4e-9 here.
  const double q = test::flow_rate_through(flow, 0.5 * s.length, 20000);
  EXPECT_NEAR(q / (u_mean * s.width * s.gap_height), 1.0, 1e-7);
  // Flow rate input: U = Q / (W H).
  const StraightChannelFlow by_rate(g, s.fluid, Inflow::flow_rate(q));
  EXPECT_NEAR(by_rate.mean_velocity() / u_mean, 1.0, 1e-7);
}

TEST(StraightChannelFlow, SatisfiesBrinkmanMomentumBalance) {
  // mu u'' - 12 mu / H^2 u = dp/dx at every y (second difference with step
  // 0.01 um: truncation ~ (k dy)^2 / 12 ~ 3e-8 relative).
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const StraightChannelFlow flow(s.straight_geometry(), s.fluid, Inflow::mean_velocity(0.03));
  const double mu = s.fluid.dynamic_viscosity, h = s.gap_height, dy = 0.01 * um;
  for (double y : {0.5 * um, 3 * um, 10 * um, 57 * um, 100 * um, 190 * um}) {
    const double u0 = flow.velocity(0, y).x();
    const double upp =
        (flow.velocity(0, y + dy).x() - 2 * u0 + flow.velocity(0, y - dy).x()) / (dy * dy);
    const double residual = mu * upp - 12 * mu / (h * h) * u0 - flow.pressure_gradient();
    EXPECT_LT(std::abs(residual), 1e-6 * std::abs(flow.pressure_gradient())) << "y = " << y;
  }
  // p = 0 at the outlet, linear upstream.
  EXPECT_DOUBLE_EQ(flow.pressure(s.length, 50 * um), 0.0);
  EXPECT_NEAR(flow.pressure(0.0, 50 * um), -flow.pressure_gradient() * s.length, 1e-9);
}

TEST(StraightChannelFlow, SideWallLayerDecaysWithBrinkmanLength) {
  // For W >> H, u / u_centre = 1 - exp(-sqrt(12) y / H) near a side wall
  // (the corrections are O(exp(-sqrt(12) W / (2H))) = 3e-8 for W/H = 10).
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const StraightChannelFlow flow(s.straight_geometry(), s.fluid, Inflow::mean_velocity(0.03));
  const double k = std::sqrt(12.0) / s.gap_height;
  const double u_c = flow.velocity(0, 0.5 * s.width).x();
  for (double y : {0.5 / k, 1.0 / k, 2.0 / k, 4.0 / k}) {
    EXPECT_NEAR(flow.velocity(0, y).x() / u_c, 1.0 - std::exp(-k * y), 1e-7) << "y k = " << y * k;
    EXPECT_NEAR(flow.velocity(0, s.width - y).x() / u_c, 1.0 - std::exp(-k * y), 1e-7);
  }
  // Wall shear rate du/dy(0) = k u_c tanh(a) / (1 - 1/cosh a) = k u_c (1 + O(4 e^-a)),
  // a = k W / 2 = 17.3: within 1e-6.
  EXPECT_NEAR(flow.velocity_gradient(0, 1e-12).coeff(0, 1) / (k * u_c), 1.0, 1e-6);
  EXPECT_NEAR(flow.profile().wall_layer_length(), s.gap_height / std::sqrt(12.0), 1e-18);
}

TEST(StraightChannelFlow, ProfileLimits) {
  // Narrow channel (W << H): plane Poiseuille across y, centre/mean = 3/2
  // (+ a^2/10 correction, a = sqrt(12) W / (2H) = 0.017: 3e-5).
  const BrinkmanChannelProfile narrow(1 * um, 100 * um);
  EXPECT_NEAR(narrow.centreline_to_mean(), 1.5, 1e-4);
  EXPECT_NEAR(narrow.shape(0.25 * um), 1.5 * 0.75, 1e-4);  // 6 s (1 - s) at s = 1/4
  // Very wide channel (Hele-Shaw example: W/H ~ 54, and beyond): finite, plug-like.
  const BrinkmanChannelProfile wide(3.5e-3, 1 * um);
  EXPECT_TRUE(std::isfinite(wide.shape(1.75e-3)));
  EXPECT_NEAR(wide.shape(1.75e-3), 1.0 / (1.0 - 2.0 / (std::sqrt(12.0) * 3500)), 1e-12);
  EXPECT_EQ(wide.shape(-1e-9), 0.0);
}

TEST(StraightChannelFlow, Velocity3dHasParabolicGapProfile) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const StraightChannelFlow flow(s.straight_geometry(), s.fluid, Inflow::mean_velocity(0.03));
  const double x = 100 * um, y = 80 * um, h = s.gap_height;
  const Eigen::Vector2d u = flow.velocity(x, y);
  EXPECT_NEAR(flow.velocity3d(x, y, 0.5 * h).x(), 1.5 * u.x(), 1e-15);  // mid-plane: 3/2
  EXPECT_EQ(flow.velocity3d(x, y, 0.0).norm(), 0.0);                     // no slip on z = 0
  EXPECT_EQ(flow.velocity3d(x, y, h).norm(), 0.0);                       // and z = H
  EXPECT_EQ(flow.velocity3d(x, y, -1 * um).norm(), 0.0);                 // outside the gap
  // Gap average of the 3-D field is the 2-D field (Simpson is exact for the parabola).
  const double avg = (flow.velocity3d(x, y, 0).x() + 4 * flow.velocity3d(x, y, 0.5 * h).x() +
                      flow.velocity3d(x, y, h).x()) / 6.0;
  EXPECT_NEAR(avg, u.x(), 1e-15);
  // Shear across the gap at the lower plate: du/dz = 6 u / H.
  EXPECT_NEAR(flow.velocity_gradient3d(x, y, 0.0)(0, 2), 6 * u.x() / h, 1e-9);
}

TEST(StraightChannelFlow, PaperReynoldsNumberGivesMeanVelocity) {
  // Re = D_h u_max rho / mu with u_max the peak of the 3-D inlet profile.
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = s.straight_geometry();
  const double u_mean = mean_velocity_for_channel_reynolds(s.reynolds, g, s.fluid);
  const StraightChannelFlow flow(g, s.fluid, Inflow::mean_velocity(u_mean));
  const double u_max = flow.velocity3d(0, 0.5 * s.width, 0.5 * s.gap_height).x();
  const double re = hydraulic_diameter(g) * u_max * s.fluid.density / s.fluid.dynamic_viscosity;
  EXPECT_NEAR(re, s.reynolds, 1e-12);
  // D_h = 4 W H / (2W + 2H) = 36.4 um; U = 2.95 cm/s (documented in inflow.h).
  EXPECT_NEAR(hydraulic_diameter(g), 4 * 200 * 20 / 440.0 * um, 1e-15);
  EXPECT_NEAR(u_mean, 0.02953, 1e-5);
}

TEST(StraightChannelFlow, RejectsBadInput) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  test::expect_invalid_argument([] { Inflow::mean_velocity(-0.1); }, {"mean velocity U", "> 0"});
  test::expect_invalid_argument([] { Inflow::flow_rate(0.0); }, {"flow rate Q", "> 0"});
  FluidProperties bad = s.fluid;
  bad.dynamic_viscosity = -1e-3;
  test::expect_invalid_argument(
      [&] { StraightChannelFlow(s.straight_geometry(), bad, Inflow::mean_velocity(0.03)); },
      {"dynamic_viscosity mu", "> 0"});
  test::expect_invalid_argument(
      [&] { StraightChannelFlow(s.geometry(), s.fluid, Inflow::mean_velocity(0.03)); },
      {"obstacles"});
}

}  // namespace
}  // namespace hsrod
