#include "hydro/rigid_rod_load.h"

#include <Eigen/Dense>

#include <cmath>

namespace hsrod {
namespace {

// J_i (3 x 3): rigid motion (V_x, V_y, Omega) -> velocity of sphere i.
Eigen::Matrix3d rigid_map(const Eigen::Vector3d& position, const Eigen::Vector2d& centre) {
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  j(0, 0) = 1.0;
  j(1, 1) = 1.0;
  j(0, 2) = -(position.y() - centre.y());
  j(1, 2) = position.x() - centre.x();
  return j;
}

Eigen::Vector2d centroid(const RodGeometry& rod) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const Eigen::Vector3d& p : rod.positions) c += p.head<2>();
  return c / rod.size();
}

}  // namespace

RigidRodLoad rigid_rod_load(const RodGeometry& rod, const RodDrag& drag) {
  const int n = rod.size();
  RigidRodLoad out;
  out.centre = centroid(rod);
  Eigen::MatrixXd j(3 * n, 3);
  for (int i = 0; i < n; ++i) j.block<3, 3>(3 * i, 0) = rigid_map(rod.positions[i], out.centre);
  Eigen::MatrixXd rj(3 * n, 3);
  if (drag.coupled()) {
    rj = drag.coupled_resistance * j;
  } else {
    for (int i = 0; i < n; ++i) rj.block<3, 3>(3 * i, 0) = drag.resistance[i] * j.block<3, 3>(3 * i, 0);
  }
  out.resistance = j.transpose() * rj;
  for (int i = 0; i < n; ++i) {
    out.driving += j.block<3, 3>(3 * i, 0).transpose() * drag.driving_force[i];
    out.driving.z() += drag.driving_torque[i].z();
    out.resistance(2, 2) += drag.rotational_resistance[i];
  }
  out.resistance = 0.5 * (out.resistance + out.resistance.transpose());
  out.free_velocity = out.resistance.ldlt().solve(out.driving);
  return out;
}

Eigen::VectorXd rigid_sphere_velocities(const RodGeometry& rod, const Eigen::Vector2d& centre,
                                        const Eigen::Vector3d& q) {
  Eigen::VectorXd v(3 * rod.size());
  for (int i = 0; i < rod.size(); ++i) v.segment<3>(3 * i) = rigid_map(rod.positions[i], centre) * q;
  return v;
}

Eigen::Vector3d rod_in_plane_load(const RodGeometry& rod, const Eigen::Vector2d& centre,
                                  const Eigen::VectorXd& forces, const std::vector<Eigen::Vector3d>& torques) {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (int i = 0; i < rod.size(); ++i) {
    total += rigid_map(rod.positions[i], centre).transpose() * forces.segment<3>(3 * i);
    total.z() += torques[i].z();
  }
  return total;
}

double drift_angle(const RigidRodLoad& load, const BackgroundFlow& flow) {
  const Eigen::Vector2d u = flow.velocity(load.centre.x(), load.centre.y());
  const Eigen::Vector2d v = load.free_velocity.head<2>();
  if (u.norm() == 0.0 || v.norm() == 0.0) return 0.0;
  return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

}  // namespace hsrod
