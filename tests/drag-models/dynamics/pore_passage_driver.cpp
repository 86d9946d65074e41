#include "common/math_constants.h"
#include "pore_passage_driver.h"

#include "dynamics/overdamped_rod_step.h"
#include "flow/inflow.h"
#include "flow/make_background_flow.h"
#include "geometry/pore_constriction.h"
#include "hydro/hydrodynamic_model.h"
#include "rod/rod_layout.h"
#include "rod/rod_measures.h"

#include <cmath>
#include <memory>

namespace hsrod_test {

namespace {
using hsrod::kPi;
constexpr double kLength = 600e-6, kWidth = 200e-6, kGap = 20e-6;  // [m]
constexpr double kPoreRadius = 85e-6, kPoreX = 300e-6;             // [m]
constexpr double kD = 3e-6;                                        // [m]

PassageSample sample(int step, const hsrod::OverdampedRod& rod) {
  PassageSample s;
  s.step = step;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  for (const auto& p : rod.positions) com += p / rod.size();
  s.x_centre = com.x();
  s.lateral = (com.y() - 0.5 * kWidth) / kWidth;
  s.angle_deg = hsrod::rod_angle_eq1(rod.positions.front().head<2>(), rod.positions.back().head<2>()) * 180.0 / kPi;
  return s;
}
}  // namespace

namespace {
std::vector<PassageSample> run_passage(const PassageCase& c, const hsrod::StepGuardLimits* limits,
                                       const std::string& cache_dir, PassageWork* work) {
  const hsrod::ChannelGeometry geometry = hsrod::make_pore_constriction(kLength, kWidth, kGap, kPoreRadius, kPoreX);
  const hsrod::FluidProperties fluid{1e-3, 1170.0};
  const auto inflow = hsrod::Inflow::mean_velocity(hsrod::mean_velocity_for_channel_reynolds(2.0, geometry, fluid));
  hsrod::BackgroundFlowOptions options;
  options.grid.cache_dir = cache_dir;
  const auto flow = hsrod::make_background_flow(geometry, fluid, inflow, options);

  hsrod::TwoWayWindowOptions window;
  window.cells_per_diameter = c.window_cells;
  const auto model = hsrod::make_hydrodynamic_model(c.model, {1e-3, kGap, kD},
                                                    hsrod::ConfinementTable::default_table(), window);

  hsrod::RodSpec spec;
  spec.number_of_sections = 10;
  spec.sphere_diameter = kD;
  spec.centre = Eigen::Vector3d(150e-6, 100e-6, 10e-6);
  spec.angle = 10.0 * kPi / 180.0;
  const hsrod::BeamBondMaterial material{c.youngs_modulus, 0.3, kD, 0.0};  // bond diameter = d (fix rod/bonds default)
  hsrod::OverdampedRod rod = hsrod::make_overdamped_rod(hsrod::make_rod_layout(spec), material, kD);

  hsrod::WallContactParameters walls;
  walls.youngs_modulus = c.youngs_modulus;
  walls.poisson_ratio = 0.3;
  walls.gap_bottom = 0.0;

  hsrod::RodGeometry rod_geometry;
  rod_geometry.sphere_diameter = kD;
  hsrod::RodDrag drag;
  hsrod::OverdampedRodSolver solver;
  // The model's state kept across steps, as fix hele_shaw/drag keeps it (RodHydrodynamics): level 4
  // re-solves its window only when the rod has moved (update_distance), not on every evaluation.
  const std::unique_ptr<hsrod::ModelState> model_state = model->make_state();
  hsrod::GuardWorkspace guard;
  auto drag_at = [&](const hsrod::OverdampedRod& moved, hsrod::RodDrag& out) {
    hsrod::RodGeometry g = rod_geometry;
    g.positions = moved.positions;
    model->evaluate(g, *flow, out, model_state.get());
  };
  std::vector<PassageSample> samples{sample(0, rod)};
  for (int step = 1; step <= c.steps; ++step) {
    rod_geometry.positions = rod.positions;
    model->evaluate(rod_geometry, *flow, drag, model_state.get());
    if (limits) {
      const hsrod::GuardedStepReport report =
          hsrod::guarded_rod_step(solver, rod, drag, drag_at, c.dt, &geometry, &walls, *limits, guard);
      rod.velocities = report.result.velocities;
      work->substeps += report.substeps;
      work->rejected_trials += report.rejected_trials;
    } else {
      solver.step(rod, drag, c.dt, &geometry, &walls);
    }
    if (step % c.sample_every == 0 || step == c.steps) samples.push_back(sample(step, rod));
  }
  return samples;
}
}  // namespace

std::vector<PassageSample> run_pore_passage(const PassageCase& c, const std::string& cache_dir) {
  return run_passage(c, nullptr, cache_dir, nullptr);
}

std::vector<PassageSample> run_guarded_pore_passage(const PassageCase& c, const hsrod::StepGuardLimits& limits,
                                                    const std::string& cache_dir, PassageWork& work) {
  return run_passage(c, &limits, cache_dir, &work);
}

}  // namespace hsrod_test
