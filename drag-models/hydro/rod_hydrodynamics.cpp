#include "hydro/rod_hydrodynamics.h"

#include "flow/inflow.h"
#include "flow/make_background_flow.h"
#include "geometry/pillar_array.h"
#include "geometry/pore_constriction.h"
#include "hydro/cross_rod_disturbance.h"
#include "hydro/explicit_drag_limit.h"
#include "hydro/nonlocal_model.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace hsrod {

RodHydrodynamics::RodHydrodynamics(const SceneSpec& scene, const ModelSpec& model, const SolveControl& flow_control)
    : spec_(model), gap_bottom_(scene.origin.z()) {
  if (spec_.name != "auto" && !find_model(spec_.name))
    throw std::invalid_argument("unknown model '" + spec_.name + "' (expected " + valid_model_names("auto") + ")");
  if (spec_.spheres_per_section < 1) throw std::invalid_argument("section must be >= 1");
  std::vector<ZCylinder> cylinders = scene.cylinders;
  if (scene.pore_radius >= 0.0) {
    const ChannelGeometry pore = make_pore_constriction(scene.length, scene.width, scene.gap_height, scene.pore_radius,
                                                        scene.pore_x, scene.origin.x(), scene.origin.y());
    for (const auto& c : pore.cylinders()) cylinders.push_back(c);
  }
  if (scene.pillars.radius > 0.0)
    for (const auto& c : pillar_array(scene.pillars, scene.length, scene.width, scene.origin.x(), scene.origin.y()))
      cylinders.push_back(c);
  geometry_ = std::make_unique<ChannelGeometry>(scene.length, scene.width, scene.gap_height, scene.origin.x(),
                                                scene.origin.y(), cylinders);
  Inflow inflow = Inflow::mean_velocity(1.0);
  switch (scene.inflow_kind) {
    case SceneSpec::InflowKind::mean_velocity: inflow = Inflow::mean_velocity(scene.inflow_value); break;
    case SceneSpec::InflowKind::flow_rate: inflow = Inflow::flow_rate(scene.inflow_value); break;
    case SceneSpec::InflowKind::reynolds:
      inflow = Inflow::mean_velocity(mean_velocity_for_channel_reynolds(scene.inflow_value, *geometry_, scene.fluid));
      break;
  }
  // Before the flow solve: an inflow outside the model's regime, named by
  // the keyword that set it (reynolds 1e300 would fail later as a
  // sphere moving inf d per step).
  try {
    check_inflow_regime(inflow.mean_velocity_in(*geometry_), *geometry_, scene.fluid);
  } catch (const std::invalid_argument& e) {
    static const char* const kKeyword[] = {"mean_velocity", "flow_rate", "reynolds"};
    std::ostringstream msg;
    msg << "inflow " << kKeyword[static_cast<int>(scene.inflow_kind)] << " " << scene.inflow_value;
    if (scene.inflow_kind == SceneSpec::InflowKind::reynolds)  // U = Re mu / (rho_f D_h) ...: both set it
      msg << " (with viscosity " << scene.fluid.dynamic_viscosity << " and fluid_density " << scene.fluid.density << ")";
    msg << ": " << e.what();
    throw std::invalid_argument(msg.str());
  }
  BackgroundFlowOptions options;
  options.grid.include_inertia = scene.inertia;
  options.grid.control = flow_control;
  flow_ = make_background_flow(*geometry_, scene.fluid, inflow, options);
  viscosity_ = scene.fluid.dynamic_viscosity;
}

RodHydrodynamics::~RodHydrodynamics() = default;

bool RodHydrodynamics::in_fluid(const Eigen::Vector3d& x) const {
  return !(geometry_->signed_distance(x[0], x[1]) < 0.0 || x[2] < gap_bottom_ ||
           x[2] > gap_bottom_ + geometry_->gap_height());
}

RodGeometry RodHydrodynamics::rod_geometry(int id, std::vector<Eigen::Vector3d> positions,
                                           double sphere_diameter) const {
  RodGeometry g;
  g.positions = std::move(positions);
  g.spheres_per_section = spec_.spheres_per_section;
  g.sphere_diameter = sphere_diameter;
  g.id = id;
  return g;
}

namespace {
// The first rod `model` cannot evaluate within its resources: why ("" if none).
std::string first_resource_problem(const HydrodynamicModel& model, const std::vector<RodGeometry>& rods,
                                   const BackgroundFlow& flow, const ResourceLimits& limits) {
  for (const RodGeometry& rod : rods) {
    std::string problem = model.resource_problem(rod, flow, limits);
    if (!problem.empty()) return problem;
  }
  return "";
}
}  // namespace

const ModelChoiceReport& RodHydrodynamics::choose_model(double d, const std::vector<RodGeometry>& rods,
                                                        double bending_stiffness) {
  if (model_) return report_;
  const double gap = geometry_->gap_height();
  if (d >= gap) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "sphere diameter %g m >= gap height %g m (beta = d/H must be < 1)", d, gap);
    throw std::invalid_argument(msg);
  }
  const ConfinementTable table = spec_.coefficients_file.empty() ? ConfinementTable::default_table()
                                                                 : ConfinementTable::read(spec_.coefficients_file);
  const HydrodynamicParameters parameters{viscosity_, gap, d};
  ModelChoiceReport report;
  report.name = spec_.name;
  if (spec_.name == "auto") {
    const auto level3 = find_model_level(3)->make(parameters, table, spec_.options);
    const std::string too_large = first_resource_problem(*level3, rods, *flow_, spec_.limits);
    if (too_large.empty()) {
      report.automatic = true;
      report.automatic_choice = choose_auto_model(rods, *flow_, d / gap, *level3, bending_stiffness,
                                                  spec_.tolerance, spec_.error_tolerance);
      report.name = report.automatic_choice.model;
    } else {
      report.name = find_model_level(2)->name;
      report.note = "auto: level 3 not estimated, level 2 chosen: " + too_large;
    }
  }
  auto model = make_hydrodynamic_model(report.name, parameters, table, spec_.options);
  const std::string too_large = first_resource_problem(*model, rods, *flow_, spec_.limits);
  if (!too_large.empty()) throw std::invalid_argument(too_large);
  model_ = std::move(model);
  state_ = model_->make_state();
  if (!pending_state_.empty()) {
    restore_state(std::move(pending_state_));
    pending_state_.clear();
  }
  report.level = model_->level();
  report.beta = d / gap;
  report.coefficients_source = table.source();
  report_ = report;
  return report_;
}

void RodHydrodynamics::loads(const RodGeometry& rod, RodDrag& out) {
  if (!model_) throw std::logic_error("RodHydrodynamics::loads before choose_model");
  model_->evaluate(rod, *flow_, out, state_.get());
}

void RodHydrodynamics::loads(const std::vector<RodGeometry>& rods, RodDrag& out) {
  if (!model_) throw std::logic_error("RodHydrodynamics::loads before choose_model");
  model_->evaluate_rods(rods, *flow_, out, state_.get());
}

const NonlocalRodModel* RodHydrodynamics::nonlocal_model() const {
  return dynamic_cast<const NonlocalRodModel*>(model_.get());
}

void RodHydrodynamics::loads_apart(const std::vector<RodGeometry>& rods, RodDrag& out, UnitObstruction& unit) {
  const NonlocalRodModel* level3 = nonlocal_model();
  if (!level3)
    throw std::invalid_argument("rods solved apart need the level-3 model nonlocal, not " +
                                (model_ ? model_->name() : std::string("none")));
  level3->evaluate_alone(rods, *flow_, out, state_.get(), unit);
  add_cross_rod_disturbance(unit, out);
}

double RodHydrodynamics::interaction_reach() const {
  if (!model_) throw std::logic_error("RodHydrodynamics::interaction_reach before choose_model");
  return model_->interaction_reach();
}

double RodHydrodynamics::explicit_drag_limit(const RodGeometry& rod, const std::vector<double>& masses) {
  RodDrag drag;
  loads(rod, drag);
  return hsrod::explicit_drag_limit(rod, drag, masses);
}

std::vector<double> RodHydrodynamics::save_state() const {
  return state_ ? model_->save_state(*state_) : std::vector<double>{};
}

void RodHydrodynamics::restore_state(std::vector<double> data) {
  if (!model_) {
    pending_state_ = std::move(data);
    return;
  }
  if (data.empty()) return;
  if (!state_) throw std::invalid_argument("restart data of a model state, but model " + model_->name() + " keeps none");
  model_->restore_state(*state_, data, *flow_);
}

std::string RodHydrodynamics::work_summary() const { return state_ ? state_->work_summary() : ""; }

}  // namespace hsrod
