// Bounded work of the background-flow solve: a solve predicted
// over the limits is refused before it starts, with the figures; the
// prediction follows measured solves; a cancel callback ends a solve.
#include "flow/grid_brinkman_flow.h"
#include "geometry/pore_constriction.h"

#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

namespace hsrod {
namespace {

constexpr double um = 1e-6;

ChannelGeometry thin_pore(double beta) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  return make_pore_constriction(s.length, s.width, 3e-6 / beta, s.pore_radius, s.x_pore);
}

TEST(GridSolveBudget, ResolvedThinGapIsRefusedBeforeAnyWorkWithTheFigures) {
  // The thin-gap pore scene: beta 0.85, the layer-resolving grid is
  // 1767 x 589 cells; a solve would run ~13 min and pass 10 GB.
  GridBrinkmanOptions o;
  o.use_cache = false;
  o.wall_layer = GridBrinkmanOptions::WallLayer::kResolved;
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const auto start = std::chrono::steady_clock::now();
  try {
    GridBrinkmanFlow flow(thin_pore(0.85), s.fluid, Inflow::mean_velocity(0.03), o);
    FAIL() << "expected GridSolveTooLarge";
  } catch (const GridSolveTooLarge& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("1767 x 589 cells"), std::string::npos) << m;
    EXPECT_NE(m.find("GB"), std::string::npos) << m;
    EXPECT_NE(m.find("limit of 2 GB"), std::string::npos) << m;
  }
  // Refused from the prediction alone: nothing of solver size was built.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(GridSolveBudget, PredictionBracketsMeasuredSolves) {
  // Measured (flow/README.md, "Bounded work"): the default pore grid,
  // 320 x 107 cells, 83 190 unknowns, 196 MB peak; 600 x 200 cells (1 um),
  // 291 750 unknowns, 1044 MB. The model must count the unknowns to within
  // 1 % and stay within [1x, 1.5x] of the measured memory.
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const ChannelGeometry scaled = scaled_planform(s.geometry());
  struct Case { double cell; long unknowns; double megabytes; };
  for (const Case c : {Case{1.875 * um, 83190, 196.5}, Case{1.0 * um, 291750, 1044.4}}) {
    GridBrinkmanOptions o;
    o.cell_size = c.cell;
    const GridSolveEstimate e = estimate_grid_solve(scaled, make_mac_grid(s.geometry(), o), false);
    EXPECT_NEAR(static_cast<double>(e.unknowns) / c.unknowns, 1.0, 0.01) << e.summary();
    EXPECT_GE(e.memory_bytes / (c.megabytes * 1e6), 1.0) << e.summary();
    EXPECT_LE(e.memory_bytes / (c.megabytes * 1e6), 1.5) << e.summary();
  }
}

TEST(GridSolveBudget, UserLimitsAreHonouredBothWays) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  GridBrinkmanOptions o;
  o.use_cache = false;
  o.max_memory_bytes = 50e6;  // below the ~250 MB the default pore grid needs
  test::expect_invalid_argument(
      [&] { GridBrinkmanFlow f(s.geometry(), s.fluid, Inflow::mean_velocity(0.03), o); },
      {"320 x 107 cells", "limit of 0.05 GB"});
  o.max_memory_bytes = 2e9;
  o.max_predicted_seconds = 0.1;
  test::expect_invalid_argument(
      [&] { GridBrinkmanFlow f(s.geometry(), s.fluid, Inflow::mean_velocity(0.03), o); },
      {"predicted time exceeds the limit of 0.1 s"});
}

TEST(GridSolveBudget, CancelCallbackEndsTheSolveDuringTheFactorisation) {
  // The callback turns true once the factorisation has started (the glue
  // sets such a flag from its SIGINT/SIGTERM handler): the solve ends with
  // FlowSolveCancelled well before the factorisation would have finished.
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  GridBrinkmanOptions o;
  o.use_cache = false;
  o.cell_size = 1.3 * um;  // ~170 000 unknowns: several seconds of factorisation
  std::atomic<bool> factorising{false};
  std::vector<std::string> progress;
  o.control.progress = [&](const std::string& line) {
    progress.push_back(line);
    if (line.find("factorising") != std::string::npos) factorising = true;
  };
  std::chrono::steady_clock::time_point asked;
  o.control.cancel_requested = [&] {
    if (!factorising) return false;
    if (asked == std::chrono::steady_clock::time_point{}) asked = std::chrono::steady_clock::now();
    return std::chrono::steady_clock::now() - asked > std::chrono::milliseconds(100);
  };
  EXPECT_THROW(GridBrinkmanFlow(s.geometry(), s.fluid, Inflow::mean_velocity(0.03), o),
               FlowSolveCancelled);
  const double latency =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  EXPECT_LT(latency, 1.0);  // the bound: honoured within ~1 s
  ASSERT_FALSE(progress.empty());
  EXPECT_NE(progress.front().find("unknowns"), std::string::npos) << progress.front();
}

}  // namespace
}  // namespace hsrod
