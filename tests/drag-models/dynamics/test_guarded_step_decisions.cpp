// What the accuracy guard takes and refuses, against the plain step: a
// hopeless step in a fast stream is refused naming its figures (or the
// folded bond), with the rod unchanged; moderate steps are taken whole as
// the plain step; quiet steps at a wall are taken as their half steps only,
// to the same states bit for bit. Closed forms: test_guarded_step.cpp.
#include "common/math_constants.h"
#include "dynamics/guarded_step.h"
#include "hydro/hydrodynamic_model.h"
#include "rod/rod_layout.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace hsrod;

namespace {

// A straight 10-sphere rod (15 MPa, 3 um spheres) and its level-2 drag in a
// 1 m/s stream (hopeless steps: ~500 diameters per ms).
OverdampedRod ten_sphere_rod() {
  RodSpec spec;
  spec.number_of_sections = 10;
  spec.sphere_diameter = 3e-6;
  return make_overdamped_rod(make_rod_layout(spec), {15e6, 0.3, 3e-6, 0.0}, 3e-6);
}
RodDrag drag_in_a_fast_stream(const OverdampedRod& rod) {
  const auto model = make_hydrodynamic_model("local", {1e-3, 20e-6, 3e-6}, ConfinementTable::default_table());
  const hsrod_test::UniformStream stream;
  RodGeometry g;
  g.sphere_diameter = 3e-6;
  g.positions = rod.positions;
  RodDrag drag;
  model->evaluate(g, stream, drag);
  return drag;
}
// The message of a step of 1 ms the guard must refuse ("" if it was taken).
std::string refusal_of_a_1ms_step(OverdampedRod& rod, const RodDrag& drag) {
  OverdampedRodSolver solver;
  try {
    guarded_rod_step(solver, rod, drag, {}, 1e-3, nullptr, nullptr);
  } catch (const StepRefused& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(GuardedStep, HopelessStepIsRefusedWithTheFiguresAndTheRodIsUnchanged) {
  // dt = 1e-3 s in a 1 m/s stream: ~500 diameters per step; even 1024
  // substeps move 0.5 d each: refused, naming dt and the displacement.
  OverdampedRod rod = ten_sphere_rod();
  const RodDrag drag = drag_in_a_fast_stream(rod);
  const std::vector<Eigen::Vector3d> before = rod.positions;
  const std::string m = refusal_of_a_1ms_step(rod, drag);
  ASSERT_FALSE(m.empty()) << "expected StepRefused";
  EXPECT_NE(m.find("dt = 0.001 s refused"), std::string::npos) << m;
  EXPECT_NE(m.find("dt / 1024"), std::string::npos) << m;
  EXPECT_NE(m.find("limit 0.25 d"), std::string::npos) << m;
  EXPECT_EQ(rod.positions, before);
  OverdampedRodSolver solver;
  for (double bad : {0.0, -1e-6, std::numeric_limits<double>::quiet_NaN(), HUGE_VAL})
    EXPECT_THROW(guarded_rod_step(solver, rod, drag, {}, bad, nullptr, nullptr), std::invalid_argument) << bad;
}

// The same hopeless step of a rod whose end sphere has turned 180 deg
// against its neighbour (a beam bond wound past where its restoring torque
// flips: the soft rods refused at the pore cylinders, examples/regime-map):
// the refusal names the fold and says a smaller timestep does not undo it.
TEST(GuardedStep, RefusalOfAFoldedRodNamesTheFoldedBond) {
  OverdampedRod rod = ten_sphere_rod();
  rod.orientations[9] = Eigen::Quaterniond(Eigen::AngleAxisd(kPi * 179.0 / 180.0, Eigen::Vector3d::UnitZ()));
  const RodDrag drag = drag_in_a_fast_stream(rod);
  const std::string m = refusal_of_a_1ms_step(rod, drag);
  ASSERT_FALSE(m.empty()) << "expected StepRefused";
  EXPECT_NE(m.find("the bond between spheres 8 and 9 is turned 179 deg"), std::string::npos) << m;
  EXPECT_NE(m.find("a smaller timestep does not undo the fold"), std::string::npos) << m;
}

TEST(GuardedStep, ModerateStepsAreTakenWholeAndMatchThePlainStep) {
  // Where the plain step is accurate the guard changes nothing: the pore
  // scene's stiff rod (15 MPa) across a uniform stream at dt = 1e-5 s.
  RodSpec spec;
  spec.number_of_sections = 10;
  spec.sphere_diameter = 3e-6;
  spec.angle = 0.0;
  OverdampedRod a = make_overdamped_rod(make_rod_layout(spec), {15e6, 0.3, 3e-6, 0.0}, 3e-6);
  OverdampedRod b = a;
  const auto model = make_hydrodynamic_model("nonlocal", {1e-3, 20e-6, 3e-6}, ConfinementTable::default_table());
  // A slow stream (1 mm/s): 0.005 d per step.
  class Slow : public hsrod_test::UniformStream {
   public:
    Eigen::Vector2d velocity(double, double) const override { return {1e-3, 0.0}; }
  } stream;
  RodGeometry g;
  g.sphere_diameter = 3e-6;
  RodDrag drag;
  OverdampedRodSolver sa, sb;
  int substeps = 0;
  for (int k = 0; k < 20; ++k) {
    g.positions = a.positions;
    model->evaluate(g, stream, drag);
    sa.step(a, drag, 1e-5, nullptr, nullptr);
    g.positions = b.positions;
    model->evaluate(g, stream, drag);
    substeps += guarded_rod_step(sb, b, drag, {}, 1e-5, nullptr, nullptr).substeps;
  }
  EXPECT_EQ(substeps, 20);
  // (The guard keeps the step-doubled result: equal to the plain one to round-off.)
  for (int i = 0; i < 10; ++i) EXPECT_LT((a.positions[i] - b.positions[i]).norm(), 1e-8 * 3e-6);
}

TEST(GuardedStep, QuietStepsAtAWallSkipTheFullStepAndKeepTheSameStates) {
  // A rod of 2x2 sections (the aspect-ratio-5 rods of Figs. 10b/11b) pushed
  // against the side wall y = 0 comes to rest on it within a few steps (the
  // Hertz contact relaxes in ~1e-8 s); from then on every step starts at the
  // wall and goes to step doubling. Stepped with one workspace, the guard
  // takes these quiet steps as their two half steps only (2 solves, not 3);
  // with a fresh workspace per step it always takes the full step too. The
  // states must be the same to the last bit, and at rest the wall carries
  // the whole push (force balance).
  const double d = 3e-6, push = 1e-10, dt = 2e-6;
  RodSpec spec;
  spec.number_of_sections = 6;
  spec.sphere_diameter = d;
  spec.angle = 0.5 * kPi;  // along x
  spec.section_rows = 2;
  spec.section_layers = 2;
  spec.centre = Eigen::Vector3d(5e-4, 0.999 * 0.5 * d + 0.5 * d, 10e-6);  // lower row just touching y = 0
  const OverdampedRod start = make_overdamped_rod(make_rod_layout(spec), {15e6, 0.3, d, 0.0}, d);
  const int n = start.size();
  ASSERT_EQ(n, 24);
  ChannelGeometry channel(1e-3, 1e-4, 20e-6);
  WallContactParameters walls;
  walls.youngs_modulus = 15e6;
  RodDrag drag;
  drag.resize(n);
  for (int i = 0; i < n; ++i) {
    drag.resistance[i] = 3 * kPi * 1e-3 * d * Eigen::Matrix3d::Identity();
    drag.rotational_resistance[i] = kPi * 1e-3 * d * d * d;
  }
  OverdampedRod reused = start, fresh = start;
  for (OverdampedRod* rod : {&reused, &fresh}) {
    for (Eigen::Vector3d& f : rod->external_forces) f = Eigen::Vector3d(0, -push, 0);
    rod->velocities.assign(n, Eigen::Vector3d::Zero());  // as fix rod/implicit gives them
    rod->angular_velocities.assign(n, Eigen::Vector3d::Zero());
  }
  OverdampedRodSolver reused_solver, fresh_solver;
  GuardWorkspace workspace;
  const StepGuardLimits limits;
  const int steps = 200;
  double wall_force = 0.0;
  for (int k = 0; k < steps; ++k) {
    const std::vector<Eigen::Vector3d> before = reused.positions;
    const GuardedStepReport r = guarded_rod_step(reused_solver, reused, drag, {}, dt, &channel, &walls, limits, workspace);
    GuardWorkspace once;
    guarded_rod_step(fresh_solver, fresh, drag, {}, dt, &channel, &walls, limits, once);
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(reused.positions[i], fresh.positions[i]) << "step " << k << " sphere " << i;
      ASSERT_EQ(reused.orientations[i].coeffs(), fresh.orientations[i].coeffs()) << "step " << k << " sphere " << i;
      reused.velocities[i] = fresh.velocities[i] = (reused.positions[i] - before[i]) / dt;
    }
    wall_force = r.result.wall_force;
  }
  std::printf("2x2 rod at the wall: %ld of %d steps quiet; solves %ld (one workspace) against %ld (fresh)\n",
              workspace.quiet_steps, steps, reused_solver.statistics().steps, fresh_solver.statistics().steps);
  EXPECT_GT(workspace.quiet_steps, steps - 10);
  EXPECT_LT(reused_solver.statistics().steps, 2 * steps + 30);
  EXPECT_EQ(fresh_solver.statistics().steps, 3 * steps);
  EXPECT_NEAR(wall_force, n * push, 1e-6 * n * push);
}
