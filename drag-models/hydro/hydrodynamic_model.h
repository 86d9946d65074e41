// The reduced hydrodynamic models of hsrod behind one interface
// (DESIGN.md, "Hydrodynamic force on the rods (a ladder of fidelity)").
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

// Hydrodynamic load of one rod, affine in the sphere velocities.
struct RodDrag {
  std::vector<Eigen::Matrix3d> resistance;        // per-sphere blocks of R [N s/m] (local models)
  Eigen::MatrixXd coupled_resistance;             // full R (3n x 3n) [N s/m] when non-local, else empty
  std::vector<Eigen::Vector3d> driving_force;     // [N]
  std::vector<double> rotational_resistance;      // [N m s]
  std::vector<Eigen::Vector3d> driving_torque;    // [N m]

  bool coupled() const { return coupled_resistance.size() > 0; }
  void resize(int n);
  // F = driving - R v for all spheres (v: 3n).
  Eigen::VectorXd forces(const Eigen::VectorXd& velocities) const;
};

struct HydrodynamicParameters {
  double viscosity = 1e-3;        // mu [Pa s]
  double gap_height = 0.0;        // H [m]
  double sphere_diameter = 0.0;   // d [m]
  double beta() const { return sphere_diameter / gap_height; }
};

class HydrodynamicModel {
 public:
  virtual ~HydrodynamicModel() = default;
  virtual std::string name() const = 0;
  virtual int level() const = 0;  // rung of the fidelity ladder, 1..4
  virtual void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const = 0;
  // One line on the work done so far, for models that do more than a fixed
  // amount per call (level 4: window solves); "" for the others.
  virtual std::string work_summary() const { return ""; }
};

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
