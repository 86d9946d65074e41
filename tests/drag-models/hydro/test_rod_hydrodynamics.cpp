// The facade RodHydrodynamics without LIGGGHTS: the scene it builds, the
// explicit drag limit against the closed form 2 m / zeta, and the `auto`
// policy (hydro/auto_model_choice.h) on rods whose answer is known.
#include "hydro/rod_hydrodynamics.h"

#include "hydro/auto_model_choice.h"
#include "flow/grid_brinkman_flow.h"

#include "common/math_constants.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace hsrod;

namespace {
constexpr double kMu = 1e-3, kD = 3e-6, kGap = 20e-6;

SceneSpec straight_channel() {
  SceneSpec scene;
  scene.length = 1e-3;
  scene.width = 200e-6;
  scene.gap_height = kGap;
  scene.origin = Eigen::Vector3d(0.0, 0.0, 5e-6);
  scene.fluid = FluidProperties{kMu, 1000.0};
  scene.inflow_kind = SceneSpec::InflowKind::mean_velocity;
  scene.inflow_value = 0.03;
  return scene;
}

ModelSpec model_named(const std::string& name) {
  ModelSpec spec;
  spec.name = name;
  return spec;
}

// Rod of n spheres centred mid-channel at angle theta [rad] to the flow.
RodGeometry centred_rod(const RodHydrodynamics& hydro, int n, double theta) {
  RodGeometry rod = hsrod_test::straight_rod(n, kD, theta);
  for (auto& x : rod.positions) x += Eigen::Vector3d(0.5e-3, 100e-6, 15e-6);
  return hydro.rod_geometry(1, rod.positions, kD);
}
}  // namespace

TEST(RodHydrodynamics, BuildsTheSceneAndKnowsTheFluidRegion) {
  RodHydrodynamics hydro(straight_channel(), model_named("local"));
  EXPECT_DOUBLE_EQ(hydro.gap_bottom(), 5e-6);
  EXPECT_DOUBLE_EQ(hydro.geometry().gap_height(), kGap);
  EXPECT_NEAR(hydro.flow().mean_velocity(), 0.03, 1e-12);
  EXPECT_TRUE(hydro.in_fluid(Eigen::Vector3d(0.5e-3, 100e-6, 15e-6)));
  EXPECT_FALSE(hydro.in_fluid(Eigen::Vector3d(0.5e-3, 100e-6, 4e-6)));   // below the gap
  EXPECT_FALSE(hydro.in_fluid(Eigen::Vector3d(0.5e-3, 201e-6, 15e-6)));  // beyond the side wall
  EXPECT_FALSE(hydro.has_model());
}

TEST(RodHydrodynamics, RefusesUnknownModelsAndSpheresThatDoNotFit) {
  EXPECT_THROW(RodHydrodynamics(straight_channel(), model_named("slender_body")), std::invalid_argument);
  RodHydrodynamics hydro(straight_channel(), model_named("isotropic"));
  EXPECT_THROW(hydro.choose_model(25e-6, {}, 0.0), std::invalid_argument);  // d > H
  EXPECT_FALSE(hydro.has_model());
}

// An isolated sphere with level 1: zeta = 3 pi mu d f(beta) (Faxen, mid-plane),
// rotational friction pi mu d^3; the limit is the smaller of 2 m / zeta and
// 2 I / (pi mu d^3) with I = m d^2 / 10.
TEST(RodHydrodynamics, ExplicitDragLimitOfAnIsolatedSphereIsTwoMassesOverFriction) {
  RodHydrodynamics hydro(straight_channel(), model_named("isotropic"));
  const auto& report = hydro.choose_model(kD, {}, 0.0);
  EXPECT_EQ(report.name, "isotropic");
  EXPECT_EQ(report.level, 1);
  const double mass = 1170.0 * kPi * kD * kD * kD / 6.0;
  const RodGeometry sphere = hydro.rod_geometry(7, {Eigen::Vector3d(0.5e-3, 100e-6, 15e-6)}, kD);
  const double zeta = 3.0 * kPi * kMu * kD * faxen_midplane_friction(kD / kGap);
  const double translation = 2.0 * mass / zeta;
  const double rotation = 2.0 * (0.1 * mass * kD * kD) / (kPi * kMu * kD * kD * kD);
  EXPECT_NEAR(hydro.explicit_drag_limit(sphere, {mass}), std::min(translation, rotation),
              1e-12 * std::min(translation, rotation));
}

// auto (the built-in cross-check record, beta = 0.15): a lone sphere is level
// 1 (every level is the confined sphere); rigid 10-sphere rods (no bonds)
// level 2, the cheapest level within 10 % of the resolved runs (level 1
// misses the chain's shielding); a rod along a uniform stream has no load
// across itself (symmetry) -> level 2 whatever its stiffness; a rod across
// the flow is loaded into a C (the non-local coupling's shielding of the
// middle): a non-local level for a soft rod, the more accurate of levels 3
// and 4 by the record, level 2 for a stiff one; the estimate scales as 1/EI.
TEST(RodHydrodynamics, AutoChoosesByTheRecordedErrorAndTheMissedBending) {
  const double soft = 1e-19, stiff = 1e-16;  // EI [N m^2]: 3 um bonds of E ~ 2.5e4 Pa and ~2.5e7 Pa
  const double beta = kD / kGap;
  {
    RodHydrodynamics hydro(straight_channel(), model_named("auto"));
    const auto& report = hydro.choose_model(kD, {centred_rod(hydro, 1, 0.0)}, 0.0);
    EXPECT_EQ(report.level, 1);
    EXPECT_LT(report.automatic_choice.expected_error, 0.02);
  }
  {
    RodHydrodynamics hydro(straight_channel(), model_named("auto"));
    const auto& report = hydro.choose_model(kD, {centred_rod(hydro, 10, 0.5 * kPi)}, 0.0);
    EXPECT_TRUE(report.automatic);
    EXPECT_FALSE(report.automatic_choice.flexible);
    EXPECT_EQ(report.name, "local");
    EXPECT_TRUE(report.automatic_choice.within_tolerance);
    EXPECT_NEAR(report.automatic_choice.expected_error,
                expected_level_error(level_error_record(), 2, beta, 10).total(), 1e-12);
    EXPECT_GT(report.automatic_choice.level_errors[0], 0.10) << "level 1 misses the shielding of a 10-sphere rod";
    std::printf("%s\n", report.automatic_choice.summary.c_str());
  }
  {
    RodHydrodynamics hydro(straight_channel(), model_named("auto"));
    const auto& report = hydro.choose_model(kD, {centred_rod(hydro, 10, 0.0)}, soft);
    EXPECT_LT(report.automatic_choice.estimated_deflection, 1e-9);
    EXPECT_EQ(report.name, "local");
  }
  double soft_estimate = 0.0;
  {
    RodHydrodynamics hydro(straight_channel(), model_named("auto"));
    const auto& report = hydro.choose_model(kD, {centred_rod(hydro, 10, 0.5 * kPi)}, soft);
    soft_estimate = report.automatic_choice.estimated_deflection;
    EXPECT_GT(soft_estimate, 0.01);
    // bending matters: the cheaper non-local level within the tolerance (the
    // summary's 10 %), else the more accurate of the two
    const auto& e = report.automatic_choice.level_errors;
    const double tolerance = 0.10;
    const int expected = e[2] <= tolerance ? 3 : e[3] <= tolerance ? 4 : (e[2] <= e[3] ? 3 : 4);
    EXPECT_EQ(report.level, expected);
    EXPECT_NE(report.automatic_choice.summary.find("tolerance 10 %"), std::string::npos) << report.automatic_choice.summary;
    std::printf("%s\n", report.automatic_choice.summary.c_str());
  }
  {
    RodHydrodynamics hydro(straight_channel(), model_named("auto"));
    const auto& report = hydro.choose_model(kD, {centred_rod(hydro, 10, 0.5 * kPi)}, stiff);
    EXPECT_NEAR(report.automatic_choice.estimated_deflection / soft_estimate, soft / stiff, 1e-9 * soft / stiff);
    EXPECT_EQ(report.name, "local");
  }
}

// Resource bounds are the facade's policy, asked of each model
// (HydrodynamicModel::resource_problem): 40 spheres at level 3 hold
// 6 (120)^2 doubles = 691 200 bytes, so a limit of 1e5 bytes refuses a
// requested `nonlocal` and makes `auto` skip level 3 for level 2 with a note;
// the default limit accepts both.
TEST(RodHydrodynamics, ModelResourcesRefuseARequestedModelAndSteerAuto) {
  {
    ModelSpec spec = model_named("nonlocal");
    spec.limits.dense_memory_bytes = 1e5;
    RodHydrodynamics hydro(straight_channel(), spec);
    const RodGeometry rod = centred_rod(hydro, 40, 0.5);
    try {
      hydro.choose_model(kD, {rod}, 0.0);
      FAIL() << "expected the level-3 model to be refused";
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("40 spheres"), std::string::npos) << m;
      EXPECT_NE(m.find("memory_limit"), std::string::npos) << m;
    }
    EXPECT_FALSE(hydro.has_model());
  }
  {
    ModelSpec spec = model_named("auto");
    spec.limits.dense_memory_bytes = 1e5;
    RodHydrodynamics hydro(straight_channel(), spec);
    const RodGeometry rod = centred_rod(hydro, 40, 0.5);
    const ModelChoiceReport& report = hydro.choose_model(kD, {rod}, 0.0);
    EXPECT_EQ(report.level, 2);
    EXPECT_FALSE(report.automatic);
    EXPECT_NE(report.note.find("level 3 not estimated"), std::string::npos) << report.note;
  }
  {
    RodHydrodynamics hydro(straight_channel(), model_named("nonlocal"));
    const RodGeometry rod = centred_rod(hydro, 40, 0.5);
    EXPECT_EQ(hydro.choose_model(kD, {rod}, 0.0).level, 3);
    EXPECT_TRUE(hydro.choose_model(kD, {rod}, 0.0).note.empty());
  }
}

// Level 4 refuses, before the run, a window above its max_window_cells.
TEST(RodHydrodynamics, TwoWayWindowAboveItsCellLimitIsRefusedBeforeTheRun) {
  ModelSpec spec = model_named("twoway");
  spec.options.window.max_window_cells = 100;
  RodHydrodynamics hydro(straight_channel(), spec);
  const RodGeometry rod = centred_rod(hydro, 10, 0.0);
  try {
    hydro.choose_model(kD, {rod}, 0.0);
    FAIL() << "expected the window to be refused";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("above the limit of 100"), std::string::npos) << m;
    EXPECT_NE(m.find("window_cells"), std::string::npos) << m;
  }
}

// The scene's pillars keyword: the facade's planform holds exactly the
// lattice's pillars (placed from the scene's origin), the flow is the grid
// solve, and two arrays differing only in the row shift get different cache
// files (the key lists every pillar).
TEST(RodHydrodynamics, PillarArrayBecomesThePlanformAndItsOwnCacheFile) {
  SceneSpec scene = straight_channel();
  scene.length = 300e-6;
  scene.width = 100e-6;
  scene.origin = Eigen::Vector3d(1e-4, 2e-5, 0.0);
  scene.pillars.radius = 10e-6;
  scene.pillars.x_first = 1e-4 + 100e-6;
  scene.pillars.x_last = 1e-4 + 180e-6;
  scene.pillars.spacing_x = 40e-6;
  scene.pillars.spacing_y = 40e-6;
  scene.pillars.row_shift = 0.1;
  const RodHydrodynamics hydro(scene, model_named("local"));
  const auto expected = pillar_array(scene.pillars, scene.length, scene.width, 1e-4, 2e-5);
  ASSERT_EQ(hydro.geometry().cylinders().size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_DOUBLE_EQ(hydro.geometry().cylinders()[k].center_x, expected[k].center_x);
    EXPECT_DOUBLE_EQ(hydro.geometry().cylinders()[k].center_y, expected[k].center_y);
  }
  const auto* grid = dynamic_cast<const GridBrinkmanFlow*>(&hydro.flow());
  ASSERT_NE(grid, nullptr);
  scene.pillars.row_shift = 0.2;
  const RodHydrodynamics shifted(scene, model_named("local"));
  const auto* shifted_grid = dynamic_cast<const GridBrinkmanFlow*>(&shifted.flow());
  ASSERT_NE(shifted_grid, nullptr);
  if (!grid->cache_file().empty()) {
    EXPECT_NE(grid->cache_file(), shifted_grid->cache_file());
  }
  // A pillar's centre is inside a wall: no flow there.
  EXPECT_EQ(hydro.flow().velocity(expected[0].center_x, expected[0].center_y).norm(), 0.0);
}
