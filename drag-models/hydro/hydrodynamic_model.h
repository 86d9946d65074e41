// The reduced hydrodynamic models of hsrod behind one interface
// (a ladder of fidelity: 1-2 local, 3 non-local, 4 two-way; model_registry.h).
//
// Every model gives the hydrodynamic load on the spheres of one rod as an
// affine function of their velocities,
//     F = driving - R v,         T_i = driving_torque_i - r_i omega_i,
// with R symmetric positive definite (3n x 3n; block diagonal for local
// models, dense for non-local ones). This form serves explicit integration
// (evaluate F from v) and the implicit overdamped step (R enters the matrix).
#pragma once

#include "flow/background_flow.h"
#include "hydro/confinement_coefficients.h"
#include "hydro/twoway_window_options.h"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace hsrod {

// One rod as the hydrodynamic models see it.
struct RodGeometry {
  std::vector<Eigen::Vector3d> positions;  // sphere centres [m], ordered section by section
  int spheres_per_section = 1;             // 1, or R*L for multi-sphere sections
  double sphere_diameter = 0.0;            // d [m]
  int id = 0;                              // names the rod across calls (models that keep per-rod state)

  int size() const { return static_cast<int>(positions.size()); }
  int sections() const { return size() / spheres_per_section; }
  int section_of(int sphere) const { return sphere / spheres_per_section; }
  // Unit in-plane tangent at each section (central differences of section
  // centres, one-sided at the ends), towards increasing section index.
  std::vector<Eigen::Vector3d> section_tangents() const;
};

// Several rods as one set of spheres (rod after rod), for the models that
// couple rods through one evaluation (evaluate_rods): the first rod's
// diameter, `id` naming the set.
RodGeometry joined_rods(const std::vector<RodGeometry>& rods, int id);

// Hydrodynamic load of one rod, affine in the sphere velocities.
struct RodDrag {
  std::vector<Eigen::Matrix3d> resistance;        // per-sphere blocks of R [N s/m] (local models)
  Eigen::MatrixXd coupled_resistance;             // full R (3n x 3n) [N s/m] when non-local, else empty
  std::vector<Eigen::Vector3d> driving_force;     // [N]
  std::vector<double> rotational_resistance;      // [N m s]
  std::vector<Eigen::Vector3d> driving_torque;    // [N m]

  bool coupled() const { return coupled_resistance.size() > 0; }
  void resize(int n);

  // The sphere load law, in one place for every fix, compute and step:
  //   F = driving - R v,   T_i = driving_torque_i - r_i omega_i.
  // F for all spheres (v: 3n).
  Eigen::VectorXd forces(const Eigen::VectorXd& velocities) const;
  // F per sphere into `out` (resized to n); `scratch` holds the stacked v and
  // R v of a coupled R, so a caller that keeps both allocates only once.
  void forces(const std::vector<Eigen::Vector3d>& velocities, std::vector<Eigen::Vector3d>& out,
              Eigen::VectorXd& scratch) const;
  // T_i at angular velocity omega_i [rad/s].
  Eigen::Vector3d torque(int i, const Eigen::Vector3d& angular_velocity) const {
    return driving_torque[i] - rotational_resistance[i] * angular_velocity;
  }
};

// The caller's bounds on the work of one evaluation (a model's own limits,
// e.g. level 4's max_window_cells, live in its options).
struct ResourceLimits {
  double dense_memory_bytes = 2e9;  // largest dense matrices of a non-local model [bytes] (keyword memory_limit)
};

struct HydrodynamicParameters {
  double viscosity = 1e-3;        // mu [Pa s]
  double gap_height = 0.0;        // H [m]
  double sphere_diameter = 0.0;   // d [m]
  double beta() const { return sphere_diameter / gap_height; }
};

// What a model keeps between evaluations of the same rods (level 4: each
// rod's window, factorisation and stored resistance, keyed by
// RodGeometry::id). Owned by the caller (RodHydrodynamics for the fixes), so
// that models stay immutable and shareable and the state is in plain sight.
class ModelState {
 public:
  virtual ~ModelState() = default;
  // One line on the work done through this state, for models that do more
  // than a fixed amount per call (level 4: window solves); "" for the others.
  virtual std::string work_summary() const { return ""; }
};

// A model: immutable once built (every evaluate is const; what changes
// from call to call lives in a ModelState the caller owns).
class HydrodynamicModel {
 public:
  virtual ~HydrodynamicModel() = default;
  virtual std::string name() const = 0;
  virtual int level() const = 0;  // rung of the fidelity ladder, 1..4
  // A fresh state for this model's rods; null for models that keep none.
  virtual std::unique_ptr<ModelState> make_state() const { return nullptr; }
  // The load on `rod`; `state` (from make_state(); null for models without
  // one) is read and advanced. A stateful model given null uses a fresh one.
  virtual void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState* state) const = 0;
  // The state as plain numbers for restart files, and back (`state` from
  // make_state(); the flow gives the scene a restored state is rebuilt in).
  // Models without state save nothing. restore_state throws
  // std::invalid_argument for data it did not write.
  virtual std::vector<double> save_state(const ModelState& state) const;
  virtual void restore_state(ModelState& state, const std::vector<double>& data, const BackgroundFlow& flow) const;
  // Without kept state (level 4: a full window solve for this call).
  void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const;

  // Several rods at once: the load on all their
  // spheres, rod after rod in the order given. A model whose rods interact
  // hydrodynamically (interaction_reach() > 0: level 3) couples the spheres
  // of different rods; the default evaluates each rod alone (with its
  // state) and joins the loads (R block-diagonal over the rods).
  virtual void evaluate_rods(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                             ModelState* state) const;
  // Distance [m] between sphere centres of two rods beyond which their
  // hydrodynamic interaction is dropped (the rods are evaluated apart);
  // 0: the model has no interaction between rods.
  virtual double interaction_reach() const { return 0.0; }
  // "" when this model can evaluate `rod` in `flow` within `limits`, else
  // why not: the predicted work, the limit and the settings that lower it.
  // Asked before the first evaluation, so that a run too large is refused
  // (or, under `auto`, a cheaper level chosen) before anything is allocated.
  virtual std::string resource_problem(const RodGeometry& /*rod*/, const BackgroundFlow& /*flow*/,
                                       const ResourceLimits& /*limits*/) const {
    return "";
  }
};

// The loads of rods evaluated apart, joined rod after rod into one load
// (R block-diagonal: dense when any part is coupled).
void join_rod_drags(const std::vector<RodDrag>& parts, RodDrag& out);

// The model registered under `name` (hydro/model_registry.h lists them).
// Throws std::invalid_argument for an unknown name or beta outside the table.
// `window` configures level 4 (hydro/twoway_window_model.h); other levels ignore it.
std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& parameters,
                                                           const ConfinementTable& table);
std::unique_ptr<HydrodynamicModel> make_hydrodynamic_model(const std::string& name,
                                                           const HydrodynamicParameters& parameters,
                                                           const ConfinementTable& table,
                                                           const TwoWayWindowOptions& window);

// Names accepted by make_hydrodynamic_model (the registry's), by level.
std::vector<std::string> hydrodynamic_model_names();

}  // namespace hsrod
