// Levels 1 and 2 of the ladder: local drag laws, one 3x3 block per sphere.
#include "hydro/local_models.h"
#include "common/math_constants.h"

#include <algorithm>
#include <cmath>

namespace hsrod {

namespace {
Eigen::Vector3d in_plane(const Eigen::Vector2d& u) { return Eigen::Vector3d(u.x(), u.y(), 0.0); }

// Spheres sit at the mid-plane, where the parabolic gap profile is 3/2 of
// the gap average: they spin with half the mid-plane vorticity.
Eigen::Vector3d midplane_spin(const BackgroundFlow& flow, double x, double y) {
  const Eigen::Matrix2d g = flow.velocity_gradient(x, y);
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

double LocalDragBase::obstruction_friction() const {
  return sphere_friction_ * std::min(1.0, coefficients_.sphere_driving / 1.5);
}

void LocalDragBase::add_rotation(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const {
  for (int i = 0; i < rod.size(); ++i) {
    out.rotational_resistance[i] = rotational_friction_;
    out.driving_torque[i] = rotational_friction_ * midplane_spin(flow, rod.positions[i].x(), rod.positions[i].y());
  }
}

void IsotropicSphereModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState*) const {
  isolated_spheres(rod, flow, out);
}

void LocalDragBase::isolated_spheres(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const {
  out.resize(rod.size());
  const double zeta = sphere_friction_;
  const double lambda = coefficients_.sphere_driving;
  for (int i = 0; i < rod.size(); ++i) {
    const Eigen::Vector3d u = in_plane(flow.velocity(rod.positions[i].x(), rod.positions[i].y()));
    out.resistance[i] = zeta * Eigen::Matrix3d::Identity();
    out.driving_force[i] = zeta * lambda * u;
  }
  add_rotation(rod, flow, out);
}

void LocalRodModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState*) const {
  // A rod of one section has no tangent: it is the isolated sphere of level 1
  // (the rod columns of the table are those of a 10-sphere rod).
  if (rod.sections() < 2) {
    isolated_spheres(rod, flow, out);
    return;
  }
  out.resize(rod.size());
  const auto tangents = rod.section_tangents();
  const ConfinementCoefficients& c = coefficients_;
  for (int i = 0; i < rod.size(); ++i) {
    const Eigen::Vector3d& t = tangents[rod.section_of(i)];
    const Eigen::Matrix3d along = t * t.transpose();
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - along;
    const Eigen::Vector3d u = in_plane(flow.velocity(rod.positions[i].x(), rod.positions[i].y()));
    // Resistive-force theory with confinement: friction and driving differ
    // along and across the local tangent (Berthet et al. 2013).
    out.resistance[i] = sphere_friction_ * (c.parallel_friction * along + c.perpendicular_friction * across);
    out.driving_force[i] = sphere_friction_ * (c.parallel_friction * c.parallel_driving * along +
                                               c.perpendicular_friction * c.perpendicular_driving * across) * u;
  }
  add_rotation(rod, flow, out);
}

}  // namespace hsrod
