// Grid solver forced onto a straight channel, checked against the closed
// form: accuracy at the default grid, convergence order, wall layer.
#include "flow/make_background_flow.h"
#include "geometry/pore_constriction.h"

#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace hsrod {
namespace {

constexpr double um = 1e-6;

// Relative L2 error of u_x over the planform, sampled on a regular grid of
// points that is unrelated to the solver grid (what a user of velocity() sees).
double relative_l2_error(const BackgroundFlow& numeric, const BackgroundFlow& exact) {
  const ChannelGeometry& g = exact.geometry();
  double err2 = 0.0, ref2 = 0.0;
  const int nx = 7, ny = 4001;
  for (int a = 0; a < nx; ++a)
    for (int b = 0; b < ny; ++b) {
      const double x = g.x_lo() + (a + 0.5) / nx * g.length();
      const double y = g.y_lo() + (b + 0.5) / ny * g.width();
      const Eigen::Vector2d d = numeric.velocity(x, y) - exact.velocity(x, y);
      err2 += d.squaredNorm();
      ref2 += exact.velocity(x, y).squaredNorm();
    }
  return std::sqrt(err2 / ref2);
}

BackgroundFlowOptions forced_grid(int cells_per_wall_layer = 3) {
  BackgroundFlowOptions o;
  o.force_grid = true;
  o.grid.use_cache = false;
  o.grid.cells_per_wall_layer = cells_per_wall_layer;
  return o;
}

TEST(GridBrinkmanStraight, MatchesClosedFormAtDefaultGrid) {
  // A 200 um long piece of the paper's channel without the pore (W = 200 um,
  // H = 20 um), default grid (3 cells per wall layer, as for the pore scene).
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = make_straight_channel(200 * um, s.width, s.gap_height);
  const Inflow inflow = Inflow::mean_velocity(0.03);
  const auto numeric = make_background_flow(g, s.fluid, inflow, forced_grid());
  const StraightChannelFlow exact(g, s.fluid, inflow);
  ASSERT_NE(dynamic_cast<const GridBrinkmanFlow*>(numeric.get()), nullptr);
  const double err = relative_l2_error(*numeric, exact);
  std::printf("straight channel, default grid (%s): relative L2 error %.3e\n",
              numeric->description().c_str(), err);
  EXPECT_LT(err, 0.01);  // required accuracy: < 1 %
  // The straight-channel solution has no transverse velocity at all.
  EXPECT_LT(std::abs(numeric->velocity(70 * um, 37 * um).y()), 1e-12);
  // Pressure gradient of the grid matches the closed form (linear p, p = 0 at the
  // outlet); the discrete wall stencil changes it at O(h^2), ~0.1 % here.
  const double dp_grid = numeric->pressure(50 * um, 100 * um) -
                         numeric->pressure(150 * um, 100 * um);
  const double dp_exact = exact.pressure(50 * um, 100 * um) -
                          exact.pressure(150 * um, 100 * um);
  EXPECT_NEAR(dp_grid / dp_exact, 1.0, 0.005);
  EXPECT_NEAR(numeric->pressure(200 * um, 100 * um), 0.0, 1e-9 * std::abs(dp_exact));
}

TEST(GridBrinkmanStraight, ConvergesAtSecondOrder) {
  // Refinement series on a short piece of the paper's channel (the solution
  // does not depend on x). Nominal order of the scheme: 2 (MAC + Shortley-
  // Weller wall stencil, cubic interpolation of the solution).
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = make_straight_channel(20 * um, s.width, s.gap_height);
  const Inflow inflow = Inflow::mean_velocity(0.03);
  const StraightChannelFlow exact(g, s.fluid, inflow);
  std::vector<double> h, err;
  std::printf("  cells/wall layer   h [um]   rel. L2 error   observed order\n");
  for (int c : {1, 2, 4, 8}) {
    const auto numeric = make_background_flow(g, s.fluid, inflow, forced_grid(c));
    h.push_back(static_cast<const GridBrinkmanFlow&>(*numeric).cell_size_y());
    err.push_back(relative_l2_error(*numeric, exact));
    const std::size_t n = err.size();
    if (n == 1)
      std::printf("  %16d %8.4f %15.3e\n", c, h.back() / um, err.back());
    else
      std::printf("  %16d %8.4f %15.3e %16.2f\n", c, h.back() / um, err.back(),
                  std::log(err[n - 2] / err[n - 1]) / std::log(h[n - 2] / h[n - 1]));
  }
  for (std::size_t n = 2; n < err.size(); ++n) {
    const double order = std::log(err[n - 1] / err[n]) / std::log(h[n - 1] / h[n]);
    // Measured 1.90 and 1.87: pre-asymptotic in h / delta, within 0.3 of 2.
    EXPECT_GT(order, 1.7) << "refinement step " << n;
    EXPECT_LT(order, 2.3) << "refinement step " << n;
  }
}

TEST(GridBrinkmanStraight, WallLayerHasBrinkmanDecay) {
  // u / u_centre = 1 - exp(-lambda y) with lambda = sqrt(12)/H. The discrete
  // operator decays with (2/h) asinh(k h / 2) = k (1 - (kh)^2/24 + ...):
  // -0.5 % at 3 cells per layer, so 2 % is a safe bound that still catches a
  // wrong friction coefficient (12) or a misplaced wall.
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry g = make_straight_channel(40 * um, s.width, s.gap_height);
  const auto numeric = make_background_flow(g, s.fluid, Inflow::mean_velocity(0.03), forced_grid());
  const double k = std::sqrt(12.0) / s.gap_height;
  const double u_c = numeric->velocity(20 * um, 0.5 * s.width).x();
  for (double yk : {0.5, 1.0, 2.0, 3.0}) {
    const double y = yk / k;
    const double rate = -std::log(1.0 - numeric->velocity(20 * um, y).x() / u_c) / y;
    EXPECT_NEAR(rate / k, 1.0, 0.02) << "y k = " << yk;
  }
}

}  // namespace
}  // namespace hsrod
