// Restarts of the implicit reduced model: a run split by write_restart /
// read_restart continues the unbroken run. What must survive: the bonds'
// rest states and orientations (fix rod/bonds, per atom), level 3's kept
// coupling, the level-4 windows and stored resistances (fix hele_shaw/drag's global restart data,
// RodHydrodynamics::save_state) and the wall-contact records (fix
// rod/implicit); the implicit step's per-rod workspace is rebuilt, which
// must not change the step.
#include "liggghts_session.h"

#include "variable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

using hsrod_test::LiggghtsSession;

namespace {

constexpr double kD = 3e-6;  // [m]

std::string drag_fix(const std::string &model) {
  return "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 viscosity 1e-3 "
         "fluid_density 1170 reynolds 2 model " + model;
}

// Keywords of fix rod/implicit and the timestep of a case (adaptive substeps
// under a 10x larger timestep, or the fixed default).
struct StepSettings {
  std::string keywords;
  std::string timestep = "4e-6";
};

void define_fixes(LiggghtsSession &s, const std::string &model, const StepSettings &step = {}) {
  s.commands({"fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1 timestep_check no",
              drag_fix(model), "fix step all rod/implicit bonds bonds drag drag " + step.keywords});
}

void start_pore_run(LiggghtsSession &s, const std::string &model, const StepSettings &step = {}) {
  setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
              "boundary f f f", "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 150e-6 100e-6 10e-6 angle 10"});
  define_fixes(s, model, step);
  s.commands({"timestep " + step.timestep, "run 40"});
}

// Largest distance between the sphere centres of the unbroken run and of
// the run restarted after 40 of its 80 steps [m].
double restart_difference(const std::string &model, const StepSettings &step = {}) {
  const auto dir = std::filesystem::temp_directory_path() / "hsrod_implicit_restart_test";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "rod.restart").string();
  LiggghtsSession straight;
  start_pore_run(straight, model, step);
  straight.command("run 40");
  const auto expected = straight.gather("x");
  {
    LiggghtsSession first;
    start_pore_run(first, model, step);
    first.command("write_restart " + file);
  }
  LiggghtsSession second;
  second.commands({"atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
                   "communicate single cutoff 1e-5 vel yes", "read_restart " + file});
  define_fixes(second, model, step);
  second.commands({"timestep " + step.timestep, "run 40"});  // LIGGGHTS 3.8 does not restore the timestep
  const auto restarted = second.gather("x");
  double worst = 0.0;
  for (size_t i = 0; i < expected.size(); i++) worst = std::max(worst, (restarted[i] - expected[i]).norm());
  return worst;
}

}  // namespace

TEST(ImplicitRestart, LevelTwoRunContinuesIdentically) {
  const double worst = restart_difference("local");
  std::printf("level 2 restart: largest position difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-12 * kD);
}

// Level 3 keeps its coupling solve between steps while the rod moves
// rigidly (NonlocalState): the kept inverses travel in the restart file, so
// the restarted run turns the same stored coupling as the unbroken one.
TEST(ImplicitRestart, LevelThreeRunContinuesIdenticallyWithItsKeptCoupling) {
  const double worst = restart_difference("nonlocal");
  std::printf("level 3 restart: largest position difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-12 * kD);
}

TEST(ImplicitRestart, LevelFourRunContinuesIdenticallyWithItsWindowsRestored) {
  const double worst = restart_difference("twoway window_cells 2");
  std::printf("level 4 restart: largest position difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-12 * kD);
}

// `time` must not restart at 0 after read_restart (LIGGGHTS 3.8 stores
// the step, not the simulated time). After 40 steps of 4 us, restarted, and
// 10 more steps, the run's time is 50 x 4 us, as in the unbroken run.
TEST(ImplicitRestart, SimulatedTimeContinuesAfterReadRestart) {
  const auto dir = std::filesystem::temp_directory_path() / "hsrod_implicit_restart_test";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "time.restart").string();
  {
    LiggghtsSession first;
    start_pore_run(first, "local");
    first.command("write_restart " + file);
  }
  LiggghtsSession second;
  second.commands({"atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
                   "communicate single cutoff 1e-5 vel yes", "read_restart " + file});
  define_fixes(second, "local");
  second.commands({"timestep 4e-6", "variable t equal time", "run 10"});
  char name[] = "v_t";
  const double time = second.lammps()->input->variable->compute_equal(name);
  EXPECT_NEAR(time, 50 * 4e-6, 1e-12 * 4e-6) << "simulated time after the restarted run [s]";
}

TEST(ImplicitRestart, AdaptiveSubstepsContinueIdentically) {
  // fix rod/implicit `adaptive yes` keeps no state between timesteps (its
  // substeps start from the restored velocities): a restart continues the
  // unbroken run (timestep 4e-5 s, 10x the fixed default).
  const double worst = restart_difference("local", {"adaptive yes", "4e-5"});
  std::printf("level 2 adaptive restart: largest position difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-12 * kD);
}
