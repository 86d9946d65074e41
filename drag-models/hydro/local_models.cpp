// Levels 1 and 2 of the ladder: local drag laws, one 3x3 block per sphere.
#include "hydro/local_models.h"
#include "common/math_constants.h"
#include "hydro/confinement_forms.h"

#include <algorithm>
#include <cmath>

namespace hsrod {

namespace {
Eigen::Vector3d in_plane(const Eigen::Vector2d& u) { return Eigen::Vector3d(u.x(), u.y(), 0.0); }

// Spheres sit at the mid-plane, where the parabolic gap profile is 3/2 of
// the gap average: they spin with half the mid-plane vorticity.
Eigen::Vector3d midplane_spin(const Eigen::Matrix2d& g) {
  return Eigen::Vector3d(0.0, 0.0, 0.5 * 1.5 * (g(1, 0) - g(0, 1)));
}
}  // namespace

LocalDragBase::LocalDragBase(const HydrodynamicParameters& p, const ConfinementTable& table)
    : parameters_(p), coefficients_(table.at(p.beta())) {
  const double d = p.sphere_diameter;
  sphere_friction_ = 3.0 * kPi * p.viscosity * d * coefficients_.sphere_friction;
  // Free-space rotational friction pi mu d^3 (no confinement correction).
  rotational_friction_ = kPi * p.viscosity * d * d * d;
}

const WallProximityLaw& LocalDragBase::wall_proximity() const {
  return wall_override_ ? *wall_override_ : WallProximityCalibration::built_in().for_level(level());
}

void LocalDragBase::apply_wall_proximity(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const {
  add_wall_proximity(wall_proximity(), rod, flow, parameters_.viscosity, parameters_.gap_height, out);
}

double LocalDragBase::obstruction_friction() const {
  return sphere_friction_ * std::min(1.0, coefficients_.sphere_driving / 1.5);
}

void LocalDragBase::add_rotation(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const {
  for (int i = 0; i < rod.size(); ++i) {
    out.rotational_resistance[i] = rotational_friction_;
    out.driving_torque[i] =
        rotational_friction_ * midplane_spin(flow.velocity_gradient(rod.positions[i].x(), rod.positions[i].y()));
  }
}

// One flow evaluation per sphere (velocity and gradient together,
// BackgroundFlow::velocity_and_gradient), the rotation as add_rotation.
void LocalDragBase::sample_flow(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const {
  Eigen::Vector2d u;
  Eigen::Matrix2d g;
  for (int i = 0; i < rod.size(); ++i) {
    flow.velocity_and_gradient(rod.positions[i].x(), rod.positions[i].y(), u, g);
    out.driving_force[i] = in_plane(u);
    out.rotational_resistance[i] = rotational_friction_;
    out.driving_torque[i] = rotational_friction_ * midplane_spin(g);
  }
}

void IsotropicSphereModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState*) const {
  isolated_spheres(rod, flow, out);
  apply_wall_proximity(rod, flow, out);
}

void LocalDragBase::isolated_spheres(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const {
  out.resize(rod.size());
  const double zeta = sphere_friction_;
  const double lambda = coefficients_.sphere_driving;
  sample_flow(rod, flow, out);
  for (int i = 0; i < rod.size(); ++i) {
    const Eigen::Vector3d u = out.driving_force[i];
    out.resistance[i] = zeta * Eigen::Matrix3d::Identity();
    out.driving_force[i] = zeta * lambda * u;
  }
}

void LocalRodModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState*) const {
  // A rod of one section has no tangent: it is the isolated sphere of level 1
  // (the rod columns of the table are those of a 10-sphere rod).
  if (rod.sections() < 2) {
    isolated_spheres(rod, flow, out);
    apply_wall_proximity(rod, flow, out);
    return;
  }
  out.resize(rod.size());
  const auto tangents = rod.section_tangents();
  const ConfinementCoefficients& c = coefficients_;
  // The table's rod columns are those of a rod of 10 sections; a rod of n
  // sections gets the n-law of hydro/confinement_forms.h,
  // c(n) = c_inf + (c_1 - c_inf - g)/n + g n + e ln(n)/n (two ends carry the
  // lone sphere's excess; along the axis the 3-D shielding of neighbours
  // closer than ~H adds e; across it the depth-averaged pressure in front of
  // the chain adds g), for the friction per sphere (c_1 = 1) and the held
  // load per sphere c lambda (c_1 = the lone sphere's lambda, its own growth
  // g_held lambda and shielding e lambda), so that n = 1 is the lone sphere
  // of level 1. The forms, g(beta), g_held(beta) and e(beta) are fitted to
  // the resolved campaign (calibration/data/confinement_campaign_fit.json).
  const int n = rod.sections();
  using confinement_form::rod_n_law;
  using confinement_form::rod_n_law_asymptote;
  const double beta = parameters_.beta(), ls = c.sphere_driving;
  const double g_perp = perpendicular_growth(beta), g_held = perpendicular_held_growth(beta);
  const double e_par = parallel_shielding(beta);
  const double c_par = rod_n_law(rod_n_law_asymptote(c.parallel_friction, 1.0, 0.0, 10, e_par), 1.0, 0.0, n, e_par);
  const double c_perp = rod_n_law(rod_n_law_asymptote(c.perpendicular_friction, 1.0, g_perp, 10), 1.0, g_perp, n);
  const double h_par = rod_n_law(rod_n_law_asymptote(c.parallel_friction * c.parallel_driving, ls, 0.0, 10, e_par * ls),
                                 ls, 0.0, n, e_par * ls);
  const double h_perp = rod_n_law(rod_n_law_asymptote(c.perpendicular_friction * c.perpendicular_driving, ls, g_held * ls, 10),
                                  ls, g_held * ls, n);
  sample_flow(rod, flow, out);
  for (int i = 0; i < rod.size(); ++i) {
    const Eigen::Vector3d& t = tangents[rod.section_of(i)];
    const Eigen::Matrix3d along = t * t.transpose();
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - along;
    const Eigen::Vector3d u = out.driving_force[i];  // the flow at the sphere (sample_flow)
    // Resistive-force theory with confinement: friction and driving differ
    // along and across the local tangent (Berthet et al. 2013).
    out.resistance[i] = sphere_friction_ * (c_par * along + c_perp * across);
    out.driving_force[i] = sphere_friction_ * (h_par * along + h_perp * across) * u;
  }
  apply_wall_proximity(rod, flow, out);
}

}  // namespace hsrod
