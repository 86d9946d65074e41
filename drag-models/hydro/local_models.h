// Levels 1-2 of the fidelity ladder (hydrodynamic_model.h): local drag laws.
#pragma once

#include "hydro/hydrodynamic_model.h"
#include "hydro/wall_proximity.h"

#include <optional>

namespace hsrod {

class LocalDragBase : public HydrodynamicModel {
 public:
  LocalDragBase(const HydrodynamicParameters& parameters, const ConfinementTable& table);
  // The near-wall correction this model applies (hydro/wall_proximity.h):
  // the built-in fit for its level unless replaced by set_wall_proximity
  // (calibration tools: a law being fitted, or WallProximityCalibration::off();
  // call before the first evaluate).
  const WallProximityLaw& wall_proximity() const;
  void set_wall_proximity(const WallProximityLaw& law) { wall_override_ = law; }

 protected:
  HydrodynamicParameters parameters_;
  ConfinementCoefficients coefficients_;  // at this run's beta
  double sphere_friction_;      // zeta = 3 pi mu d * sphere_friction(beta) [N s/m]
  double rotational_friction_;  // pi mu d^3 [N m s]
  // Rotational friction and driving torque (free-space, half the mid-plane vorticity) of every sphere.
  void add_rotation(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const;
  // Per sphere: the in-plane flow velocity u(x_i) into out.driving_force
  // (for the model to turn into its driving force) and the rotational
  // friction and driving torque (free-space, half the mid-plane vorticity).
  void sample_flow(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const;
  // Level 1's law on every sphere: F_i = zeta (lambda u(x_i) - v_i), with rotation.
  void isolated_spheres(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const;
  // Obstruction part zeta_o of the sphere friction (levels 3-4): the
  // isolated sphere's force-free velocity lambda u fixes it, zeta_o =
  // zeta lambda / (3/2); the rest, zeta - zeta_o, is film friction with the
  // gap walls (see nonlocal_model.h).
  double obstruction_friction() const;
  // Adds the near-wall correction to the finished load (every level's evaluate ends with it).
  void apply_wall_proximity(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const;

 private:
  std::optional<WallProximityLaw> wall_override_;
};

// Level 1: every sphere is an isolated confined sphere,
// F_i = zeta(beta) (lambda(beta) u(x_i) - v_i); free-space Stokes for beta -> 0.
class IsotropicSphereModel : public LocalDragBase {
 public:
  using LocalDragBase::LocalDragBase;
  std::string name() const override { return "isotropic"; }
  int level() const override { return 1; }
  using HydrodynamicModel::evaluate;
  void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState* state) const override;
};

// Level 2: confined resistive-force theory along the local tangent.
class LocalRodModel : public LocalDragBase {
 public:
  using LocalDragBase::LocalDragBase;
  std::string name() const override { return "local"; }
  int level() const override { return 2; }
  using HydrodynamicModel::evaluate;
  void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState* state) const override;
};

}  // namespace hsrod
