// RodHydrodynamics: the one object a caller needs for the hydrodynamics of
// rods in a scene (the facade over geometry/, flow/ and hydro/).
//
// Built from plain specs (scene, fluid, inflow; model), it owns the channel
// geometry, the background flow, the chosen model with the `auto` policy
// (hydro/auto_model_choice.h) and the per-rod state of the models that keep
// one (level 4), and answers the two questions the LIGGGHTS styles ask:
//   loads(rod)                 the hydrodynamic load on the spheres of one rod,
//                              F = driving - R v (hydro/hydrodynamic_model.h);
//   explicit_drag_limit(rod)   the largest stable explicit step for its drag.
// No LIGGGHTS, no MPI: the fixes parse keywords into the specs, gather rods
// into RodGeometry, call these and scatter the result.
#pragma once

#include "flow/background_flow.h"
#include "flow/brinkman_grid_solver.h"
#include "flow/fluid_properties.h"
#include "geometry/channel_geometry.h"
#include "geometry/pillar_array.h"
#include "hydro/auto_model_choice.h"
#include "hydro/confinement_coefficients.h"
#include "hydro/hydrodynamic_model.h"
#include "hydro/model_registry.h"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace hsrod {

class NonlocalRodModel;
struct UnitObstruction;

// The scene as the hydrodynamics sees it.
struct SceneSpec {
  double length = 0.0, width = 0.0, gap_height = 0.0;  // L (x), W (y), H (z) [m]
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();    // inlet plane x, side wall y, lower gap wall z [m]
  double pore_radius = -1.0;                           // pore constriction: cylinder radius R [m]; < 0: none
  double pore_x = 0.0;                                 // x of the pore's cylinders [m]
  std::vector<ZCylinder> cylinders;                    // other z-cylinder obstacles
  PillarLattice pillars;                               // DLD pillar array (geometry/pillar_array.h); radius 0: none
  FluidProperties fluid;                               // mu [Pa s], rho_f [kg/m3]
  enum class InflowKind { mean_velocity, flow_rate, reynolds };
  InflowKind inflow_kind = InflowKind::mean_velocity;
  double inflow_value = 0.0;                           // U [m/s], Q [m3/s] or Re [-] (flow/inflow.h)
  bool inertia = false;                                // gap-averaged inertia in the background flow
};

// Which model, and its settings.
struct ModelSpec {
  std::string name = "auto";         // a registered name (hydro/model_registry.h) or "auto"
  double tolerance = 0.01;           // auto: accepted deflection error over L [-]
  double error_tolerance = 0.10;     // auto: accepted error of forces and velocities against resolved runs [-]
  std::string coefficients_file;     // confinement table; "" = built-in defaults
  ModelOptions options;              // per-model settings (level-4 window)
  ResourceLimits limits;             // the caller's bounds on one evaluation (level 3's dense memory)
  int spheres_per_section = 1;       // spheres per rod cross-section
};

// What choose_model() chose, for the caller's report.
struct ModelChoiceReport {
  std::string name;                  // registered name
  int level = 0;
  double beta = 0.0;                 // d / H
  std::string coefficients_source;   // the confinement table's source line
  bool automatic = false;            // chosen by the `auto` policy
  AutoModelChoice automatic_choice;  // when automatic
  std::string note;                  // a level `auto` skipped for its resources, and why ("" if none)
};

class RodHydrodynamics {
 public:
  // Builds the geometry and the background flow (a grid solve or the cache
  // for planforms with obstacles). Throws std::invalid_argument /
  // std::runtime_error with a message naming the problem. `flow_control`:
  // cancellation and progress hooks of a grid solve (a cancelled solve
  // throws FlowSolveCancelled, flow/brinkman_grid_solver.h).
  RodHydrodynamics(const SceneSpec& scene, const ModelSpec& model, const SolveControl& flow_control = {});
  ~RodHydrodynamics();
  RodHydrodynamics(const RodHydrodynamics&) = delete;
  RodHydrodynamics& operator=(const RodHydrodynamics&) = delete;

  const ChannelGeometry& geometry() const { return *geometry_; }
  const BackgroundFlow& flow() const { return *flow_; }
  double gap_bottom() const { return gap_bottom_; }  // z of the lower gap wall [m]
  double viscosity() const { return viscosity_; }     // mu [Pa s]
  // True when x [m] lies in the fluid: inside the planform and the gap.
  bool in_fluid(const Eigen::Vector3d& x) const;
  // A rod of this scene: sphere centres (ordered section by section) and diameter.
  RodGeometry rod_geometry(int id, std::vector<Eigen::Vector3d> positions, double sphere_diameter) const;

  // Builds the model for spheres of diameter d [m]: the one asked for, or
  // for `auto` the choice over `rods` (their current shapes) with the bonds'
  // bending stiffness EI [N m^2] (<= 0: unbonded rigid spheres). Every rod
  // is checked against the model's resources (spec.limits): a requested
  // model too large throws std::invalid_argument with the figures; under
  // `auto` a level 3 too large is not even estimated and level 2 is chosen
  // (ModelChoiceReport::note says so). Once only; later calls return the
  // first report. Throws for beta = d/H >= 1 or a bad table.
  const ModelChoiceReport& choose_model(double sphere_diameter, const std::vector<RodGeometry>& rods,
                                        double bending_stiffness);
  bool has_model() const { return static_cast<bool>(model_); }
  const HydrodynamicModel& model() const { return *model_; }
  // The state the model keeps for this scene's rods (null for models without).
  const ModelState* model_state() const { return state_.get(); }

  // Loads on this rod: F = driving - R v, torques (hydro/hydrodynamic_model.h).
  // Uses and advances the rod's state (keyed by rod.id) for models that keep one.
  void loads(const RodGeometry& rod, RodDrag& out);
  // Loads on several rods stepped together (spheres rod after rod): coupled
  // through the model's interaction between rods (level 3), else each alone
  // and joined (HydrodynamicModel::evaluate_rods).
  void loads(const std::vector<RodGeometry>& rods, RodDrag& out);
  // Rods solved apart (hydro/cross_rod_disturbance.h): the load of `rods`
  // (one rod or rods stepped together) alone, with the disturbance of the
  // other units (unit.driving_disturbance, unit.velocity_disturbance, set by
  // the caller) added; unit's resistances and lone driving are filled.
  // Throws std::invalid_argument unless the model is level 3 (nonlocal).
  void loads_apart(const std::vector<RodGeometry>& rods, RodDrag& out, UnitObstruction& unit);
  // The level-3 model whose rods can be solved apart; null for other models.
  const NonlocalRodModel* nonlocal_model() const;
  // Sphere-centre distance [m] within which the model couples two rods
  // (0: no interaction between rods).
  double interaction_reach() const;
  // Stability limit of integrating this rod's drag explicitly [s]
  // (hydro/explicit_drag_limit.h); masses [kg] per sphere.
  double explicit_drag_limit(const RodGeometry& rod, const std::vector<double>& masses);
  // Restart: the model's state for this scene's rods as plain numbers
  // (empty for models without state), and back. Data restored before
  // choose_model() is kept and applied when the model is built; throws
  // std::invalid_argument for data of another model.
  std::vector<double> save_state() const;
  void restore_state(std::vector<double> data);
  // One line on the work the model did ("" for fixed-cost models).
  std::string work_summary() const;

 private:
  ModelSpec spec_;
  double gap_bottom_;  // [m]
  double viscosity_;   // mu [Pa s]
  std::unique_ptr<ChannelGeometry> geometry_;
  std::unique_ptr<BackgroundFlow> flow_;
  std::unique_ptr<HydrodynamicModel> model_;
  std::unique_ptr<ModelState> state_;  // the rods' model state (null for models without)
  std::vector<double> pending_state_;  // restart data waiting for choose_model()
  ModelChoiceReport report_;
};

}  // namespace hsrod
