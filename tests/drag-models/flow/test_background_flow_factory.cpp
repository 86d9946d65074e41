// What the factory and the cache skip: no grid for a straight channel, no
// second solve for a cached planform.
#include "flow/flow_cache.h"
#include "flow/make_background_flow.h"
#include "geometry/pore_constriction.h"

#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace hsrod {
namespace {

constexpr double um = 1e-6;

TEST(BackgroundFlowFactory, StraightChannelNeverBuildsTheGrid) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const long built = GridBrinkmanFlow::instances_created();
  const long solved = GridBrinkmanFlow::total_solves();
  const auto flow = make_background_flow(s.straight_geometry(), s.fluid, Inflow::mean_velocity(0.03));
  EXPECT_NE(dynamic_cast<const StraightChannelFlow*>(flow.get()), nullptr) << flow->description();
  EXPECT_EQ(GridBrinkmanFlow::instances_created(), built);
  EXPECT_EQ(GridBrinkmanFlow::total_solves(), solved);
  // Inertia does not change that (it vanishes for the developed profile).
  BackgroundFlowOptions o;
  o.grid.include_inertia = true;
  const auto again = make_background_flow(s.straight_geometry(), s.fluid, Inflow::mean_velocity(0.03), o);
  EXPECT_NE(dynamic_cast<const StraightChannelFlow*>(again.get()), nullptr);
  EXPECT_EQ(GridBrinkmanFlow::instances_created(), built);
}

TEST(BackgroundFlowFactory, PoreSceneUsesTheGridAndForceGridIsHonoured) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  BackgroundFlowOptions o;
  o.grid.use_cache = false;
  o.grid.cell_size = 5 * um;  // coarse: only the choice of model is tested here
  const auto pore = make_background_flow(s.geometry(), s.fluid, Inflow::mean_velocity(0.03), o);
  EXPECT_NE(dynamic_cast<const GridBrinkmanFlow*>(pore.get()), nullptr);
  o.force_grid = true;
  const auto forced = make_background_flow(s.straight_geometry(), s.fluid, Inflow::mean_velocity(0.03), o);
  EXPECT_NE(dynamic_cast<const GridBrinkmanFlow*>(forced.get()), nullptr);
}

TEST(BackgroundFlowFactory, CachedPoreSceneIsNotSolvedAgain) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const test::TempDir cache;
  BackgroundFlowOptions o;
  o.grid.cache_dir = cache.path().string();  // default grid
  const Inflow inflow = Inflow::mean_velocity(0.03);

  const long solved_before = GridBrinkmanFlow::total_solves();
  const auto first = make_background_flow(s.geometry(), s.fluid, inflow, o);
  const auto& f1 = dynamic_cast<const GridBrinkmanFlow&>(*first);
  EXPECT_EQ(f1.solves_performed(), 1);
  EXPECT_FALSE(f1.loaded_from_cache());
  EXPECT_TRUE(f1.cache_error().empty()) << f1.cache_error();
  EXPECT_TRUE(std::filesystem::exists(f1.cache_file())) << f1.cache_file();
  EXPECT_EQ(GridBrinkmanFlow::total_solves(), solved_before + 1);

  const auto second = make_background_flow(s.geometry(), s.fluid, inflow, o);
  const auto& f2 = dynamic_cast<const GridBrinkmanFlow&>(*second);
  EXPECT_TRUE(f2.loaded_from_cache()) << f2.description();
  EXPECT_EQ(f2.solves_performed(), 0);
  EXPECT_EQ(GridBrinkmanFlow::total_solves(), solved_before + 1);
  for (double x : {100 * um, 297 * um, 300 * um, 410 * um})
    for (double y : {3 * um, 88 * um, 100 * um, 150 * um}) {
      EXPECT_EQ(f1.velocity(x, y), f2.velocity(x, y));  // bit-identical
      EXPECT_EQ(f1.pressure(x, y), f2.pressure(x, y));
    }

  // Without inertia the stored field is dimensionless: another mean velocity
  // and viscosity reuse it, scaled (u ~ U, p ~ mu U).
  FluidProperties other = s.fluid;
  other.dynamic_viscosity *= 2.0;
  const auto scaled = make_background_flow(s.geometry(), other, Inflow::mean_velocity(0.06), o);
  const auto& f3 = dynamic_cast<const GridBrinkmanFlow&>(*scaled);
  EXPECT_TRUE(f3.loaded_from_cache());
  EXPECT_DOUBLE_EQ(f3.velocity(297 * um, 88 * um).x(), 2.0 * f1.velocity(297 * um, 88 * um).x());
  EXPECT_DOUBLE_EQ(f3.pressure(200 * um, 88 * um), 4.0 * f1.pressure(200 * um, 88 * um));
  EXPECT_EQ(GridBrinkmanFlow::total_solves(), solved_before + 1);
}

TEST(BackgroundFlowFactory, ChangedSceneOrDamagedCacheIsSolvedAgain) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const test::TempDir cache;
  GridBrinkmanOptions o;
  o.cache_dir = cache.path().string();
  o.cell_size = 4 * um;  // coarse for speed; the cache logic does not depend on it
  const Inflow inflow = Inflow::mean_velocity(0.03);
  const GridBrinkmanFlow first(s.geometry(), s.fluid, inflow, o);
  ASSERT_EQ(first.solves_performed(), 1);
  // Another pore radius is another scene.
  const ChannelGeometry wider = make_pore_constriction(s.length, s.width, s.gap_height, 80 * um, s.x_pore);
  const GridBrinkmanFlow other(wider, s.fluid, inflow, o);
  EXPECT_EQ(other.solves_performed(), 1);
  EXPECT_NE(other.cache_file(), first.cache_file());
  // A damaged file is ignored, solved again and rewritten.
  { std::ofstream(first.cache_file(), std::ios::binary | std::ios::trunc) << "not a field"; }
  const GridBrinkmanFlow repaired(s.geometry(), s.fluid, inflow, o);
  EXPECT_EQ(repaired.solves_performed(), 1);
  const GridBrinkmanFlow reloaded(s.geometry(), s.fluid, inflow, o);
  EXPECT_TRUE(reloaded.loaded_from_cache());
  // Caching can be switched off.
  o.use_cache = false;
  const GridBrinkmanFlow uncached(s.geometry(), s.fluid, inflow, o);
  EXPECT_EQ(uncached.solves_performed(), 1);
  EXPECT_TRUE(uncached.cache_file().empty());
}

TEST(BackgroundFlowFactory, RejectsBadGridOptions) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  GridBrinkmanOptions o;
  o.use_cache = false;
  o.cell_size = -1 * um;
  test::expect_invalid_argument(
      [&] { GridBrinkmanFlow(s.geometry(), s.fluid, Inflow::mean_velocity(0.03), o); },
      {"cell_size", ">= 0"});
  o.cell_size = 0.01 * um;  // 6e4 x 2e4 cells
  test::expect_invalid_argument(
      [&] { GridBrinkmanFlow(s.geometry(), s.fluid, Inflow::mean_velocity(0.03), o); },
      {"exceeds max_cells"});
}

// A corrupt cache file is solved anew with a notice saying why (the next
// test: the cache directory is pruned to its size limit).
TEST(BackgroundFlowFactory, DamagedCacheFileIsReportedAndSolvedAnew) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const test::TempDir cache;
  GridBrinkmanOptions o;
  o.cache_dir = cache.path().string();
  o.cell_size = 4 * um;
  const Inflow inflow = Inflow::mean_velocity(0.03);
  const GridBrinkmanFlow first(s.geometry(), s.fluid, inflow, o);
  EXPECT_TRUE(first.cache_notice().empty()) << first.cache_notice();
  // Flip one byte of the stored velocity: the checksum no longer matches.
  {
    std::fstream f(first.cache_file(), std::ios::binary | std::ios::in | std::ios::out);
    f.seekp(-64, std::ios::end);
    const char byte = 0x55;
    f.write(&byte, 1);
  }
  const GridBrinkmanFlow repaired(s.geometry(), s.fluid, inflow, o);
  EXPECT_EQ(repaired.solves_performed(), 1);
  EXPECT_NE(repaired.cache_notice().find("not used (corrupt (checksum mismatch)), solved anew"), std::string::npos)
      << repaired.cache_notice();
  EXPECT_NE(repaired.description().find("corrupt (checksum mismatch)"), std::string::npos) << repaired.description();
  // Truncated: said as well.
  std::filesystem::resize_file(first.cache_file(), 100);
  const GridBrinkmanFlow again(s.geometry(), s.fluid, inflow, o);
  EXPECT_NE(again.cache_notice().find("not used (truncated)"), std::string::npos) << again.cache_notice();
}

TEST(BackgroundFlowFactory, CacheIsPrunedToItsSizeLimitLeastRecentlyUsedFirst) {
  const test::PaperPoreScene s = test::load_paper_pore_scene();
  const test::TempDir cache;
  GridBrinkmanOptions o;
  o.cache_dir = cache.path().string();
  o.cell_size = 4 * um;
  const Inflow inflow = Inflow::mean_velocity(0.03);
  // Three scenes (pore radii 85, 80, 75 um) of about the same file size.
  auto scene = [&](double radius) {
    return make_pore_constriction(s.length, s.width, s.gap_height, radius * um, s.x_pore);
  };
  const GridBrinkmanFlow a(scene(85), s.fluid, inflow, o);
  const double one_file = static_cast<double>(std::filesystem::file_size(a.cache_file()));
  const GridBrinkmanFlow b(scene(80), s.fluid, inflow, o);
  // a is used again (loaded): now b is the least recently used.
  std::filesystem::last_write_time(b.cache_file(), std::filesystem::last_write_time(a.cache_file()) -
                                                       std::chrono::seconds(10));
  const GridBrinkmanFlow a_again(scene(85), s.fluid, inflow, o);
  ASSERT_TRUE(a_again.loaded_from_cache());
  // A limit of 2.5 files: storing the third removes exactly b.
  o.cache_size_limit = 2.5 * one_file;
  const GridBrinkmanFlow c(scene(75), s.fluid, inflow, o);
  EXPECT_NE(c.cache_notice().find("removed 1 least recently used cache file(s)"), std::string::npos)
      << c.cache_notice();
  EXPECT_TRUE(std::filesystem::exists(a.cache_file()));
  EXPECT_FALSE(std::filesystem::exists(b.cache_file()));
  EXPECT_TRUE(std::filesystem::exists(c.cache_file()));
  // Under the limit nothing more goes.
  const GridBrinkmanFlow b_again(scene(80), s.fluid, inflow, o);
  EXPECT_EQ(b_again.solves_performed(), 1);
  EXPECT_NE(b_again.cache_notice().find("removed 1"), std::string::npos) << b_again.cache_notice();
  EXPECT_TRUE(std::filesystem::exists(b_again.cache_file()));
}

}  // namespace
}  // namespace hsrod
