#include "dynamics/wall_contact.h"

#include <algorithm>
#include <cmath>

namespace hsrod {

namespace {
// Adds a Hertz contact of overlap delta along the unit normal n (into the fluid).
void add_hertz(WallContact& c, double effective_modulus, double radius, double delta, const Eigen::Vector3d& n) {
  if (delta <= 0.0) return;
  const double root = std::sqrt(radius * delta);
  c.force += (4.0 / 3.0) * effective_modulus * root * delta * n;
  c.stiffness += 2.0 * effective_modulus * root * n * n.transpose();
  c.touching = true;
  if (c.points < static_cast<int>(c.point.size())) c.point[c.points++] = {n, (4.0 / 3.0) * effective_modulus * root * delta};
}

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

Eigen::Matrix<double, 3, 6> slip_operator(const Eigen::Vector3d& n, double radius) {
  Eigen::Matrix<double, 3, 6> g;
  g.leftCols<3>() = Eigen::Matrix3d::Identity() - n * n.transpose();
  g.rightCols<3>() = radius * cross_matrix(n);
  return g;
}
}  // namespace

double wall_slip_speed(const WallContactPoint& contact, double radius, const Vector6d& velocity) {
  return (slip_operator(contact.normal, radius) * velocity).norm();
}

Eigen::Vector3d wall_slip(const WallContactPoint& contact, double radius, const Vector6d& velocity) {
  return slip_operator(contact.normal, radius) * velocity;
}

Eigen::Vector3d wall_friction_force(const WallContactPoint& contact, double mu, double slip_velocity,
                                    const Eigen::Vector3d& slip) {
  if (!(mu > 0.0) || !(contact.normal_force > 0.0)) return Eigen::Vector3d::Zero();
  return -mu * contact.normal_force / std::max(slip.norm(), slip_velocity) * slip;
}

Eigen::Matrix<double, 3, 6> wall_slip_operator(const WallContactPoint& contact, double radius) {
  return slip_operator(contact.normal, radius);
}

Matrix6d wall_friction_resistance_at_slip(const WallContactPoint& contact, double radius, double mu,
                                          double slip_velocity, double slip) {
  if (!(mu > 0.0) || !(contact.normal_force > 0.0)) return Matrix6d::Zero();
  const Eigen::Matrix<double, 3, 6> g = slip_operator(contact.normal, radius);
  const double coefficient = mu * contact.normal_force / std::max(slip, slip_velocity);
  return coefficient * g.transpose() * g;
}

Matrix6d wall_friction_resistance(const WallContactPoint& contact, double radius, double mu, double slip_velocity,
                                  const Vector6d& previous_velocity) {
  return wall_friction_resistance_at_slip(contact, radius, mu, slip_velocity,
                                          wall_slip_speed(contact, radius, previous_velocity));
}

Matrix12d sphere_friction_resistance(const WallContactPoint& contact, double ri, double rj, double mu,
                                     double slip_velocity, const Vector12d& previous_velocity) {
  if (!(mu > 0.0) || !(contact.normal_force > 0.0)) return Matrix12d::Zero();
  const Eigen::Vector3d& n = contact.normal;
  const Eigen::Matrix3d tangential = Eigen::Matrix3d::Identity() - n * n.transpose();
  Eigen::Matrix<double, 3, 12> g;
  g.block<3, 3>(0, 0) = tangential;
  g.block<3, 3>(0, 3) = ri * cross_matrix(n);
  g.block<3, 3>(0, 6) = -tangential;
  g.block<3, 3>(0, 9) = rj * cross_matrix(n);
  const double slip = (g * previous_velocity).norm();
  const double coefficient = mu * contact.normal_force / std::max(slip, slip_velocity);
  return coefficient * g.transpose() * g;
}

WallContact sphere_contact(const WallContactParameters& p, const Eigen::Vector3d& xi, double ri,
                           const Eigen::Vector3d& xj, double rj) {
  WallContact c;
  const Eigen::Vector3d offset = xi - xj;
  const double distance = offset.norm();
  const double overlap = ri + rj - distance;
  if (overlap <= 0.0 || distance <= 0.0) return c;
  const double pair_modulus = 0.5 * p.effective_modulus();  // two equal elastic spheres
  add_hertz(c, pair_modulus, ri * rj / (ri + rj), overlap, offset / distance);
  return c;
}

WallContact wall_contact(const ChannelGeometry& geometry, const WallContactParameters& p, const Eigen::Vector3d& x,
                         double radius) {
  WallContact c;
  const double e = p.effective_modulus();
  if (p.planform_walls) {
    const double distance = geometry.signed_distance(x.x(), x.y());
    if (distance < radius) {
      const Eigen::Vector2d n = geometry.wall_normal(x.x(), x.y());
      add_hertz(c, e, radius, radius - distance, Eigen::Vector3d(n.x(), n.y(), 0.0));
    }
  }
  if (p.gap_walls) {
    add_hertz(c, e, radius, radius - (x.z() - p.gap_bottom), Eigen::Vector3d::UnitZ());
    add_hertz(c, e, radius, radius - (p.gap_bottom + geometry.gap_height() - x.z()), -Eigen::Vector3d::UnitZ());
  }
  return c;
}

}  // namespace hsrod
