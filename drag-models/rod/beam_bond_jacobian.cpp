#include "rod/beam_bond_jacobian.h"

#include <cmath>

namespace hsrod {

namespace {

// [v]x, the matrix of v x (.)
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

// Below this angle [rad] the Jacobians' coefficients come from their Taylor
// series (to t^4: truncation < 1e-13 relative), above it from the closed
// forms (cancellation < 1e-12 relative there).
constexpr double kSeriesAngle = 1e-2;

}  // namespace

Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& v) {
  const double t2 = v.squaredNorm(), t = std::sqrt(t2);
  double a, b;  // (1 - cos t)/t^2, (t - sin t)/t^3
  if (t < kSeriesAngle) {
    a = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
    b = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0;
  } else {
    const double s = std::sin(0.5 * t);
    a = 2.0 * s * s / t2;
    b = (t - std::sin(t)) / (t2 * t);
  }
  const Eigen::Matrix3d k = cross_matrix(v);
  return Eigen::Matrix3d::Identity() + a * k + b * k * k;
}

Eigen::Matrix3d so3_left_jacobian_inverse(const Eigen::Vector3d& v) {
  const double t2 = v.squaredNorm(), t = std::sqrt(t2);
  double c;  // 1/t^2 - (1 + cos t)/(2 t sin t)
  if (t < kSeriesAngle) c = 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
  else c = 1.0 / t2 - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  const Eigen::Matrix3d k = cross_matrix(v);
  return Eigen::Matrix3d::Identity() - 0.5 * k + c * k * k;
}

void beam_bond_loads_and_jacobian(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                  const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j,
                                  const BeamBondRest& rest, const BeamBondStiffness& k, BondLoads& loads,
                                  BondJacobian& jacobian) {
  // Loads: the same operations as evaluate_beam_bond without dashpots.
  const Eigen::Quaterniond q_rel = q_i.conjugate() * q_j * rest.rest_relative_rotation.conjugate();
  const Eigen::Vector3d theta_body = rotation_vector(q_rel);
  const Eigen::Vector3d theta = q_i * theta_body;  // [rad], lab
  const Eigen::Quaterniond q_mid = q_i * quaternion_from_rotation_vector(0.5 * theta_body);
  const Eigen::Vector3d expected = q_mid * rest.rest_vector_in_frame_i;  // e [m]
  const double rest_length = rest.rest_vector_in_frame_i.norm();
  const Eigen::Vector3d axis = expected / rest_length;  // n
  const Eigen::Vector3d bond = x_j - x_i;
  const Eigen::Vector3d mismatch = bond - expected;  // m
  const double axial = axis.dot(mismatch);          // n.m [m]
  const Eigen::Vector3d mismatch_axial = axis * axial;
  const Eigen::Vector3d mismatch_shear = mismatch - mismatch_axial;
  const double twist = axis.dot(theta);  // n.theta [rad]
  const Eigen::Vector3d theta_twist = axis * twist;
  const Eigen::Vector3d theta_bend = theta - theta_twist;
  const Eigen::Vector3d force_on_j = -k.axial * mismatch_axial - k.shear * mismatch_shear;
  const Eigen::Vector3d moment = k.bending * theta_bend + k.twisting * theta_twist;
  const Eigen::Vector3d couple = -0.5 * bond.cross(force_on_j);
  loads << -force_on_j, moment + couple, force_on_j, -moment + couple;

  // Derivatives of theta and e with respect to phi_i, phi_j (3x3 each).
  const Eigen::Matrix3d jl_inv = so3_left_jacobian_inverse(theta);
  const Eigen::Matrix3d jr_inv = so3_left_jacobian_inverse(-theta);
  const Eigen::Matrix3d jl_half = so3_left_jacobian(0.5 * theta);
  const Eigen::Matrix3d r_half = (q_mid * q_i.conjugate()).toRotationMatrix();  // Exp(theta / 2)
  const Eigen::Matrix3d e_cross = cross_matrix(expected);
  const Eigen::Matrix3d de_dphi_i = -e_cross * (r_half - 0.5 * jl_half * jr_inv);
  const Eigen::Matrix3d de_dphi_j = -0.5 * e_cross * (jl_half * jl_inv);

  // 3x12 derivatives with respect to (x_i, phi_i, x_j, phi_j).
  using Row3 = Eigen::Matrix<double, 3, 12>;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  Row3 d_bond = Row3::Zero(), d_expected = Row3::Zero(), d_theta = Row3::Zero();
  d_bond.block<3, 3>(0, 0) = -identity;
  d_bond.block<3, 3>(0, 6) = identity;
  d_expected.block<3, 3>(0, 3) = de_dphi_i;
  d_expected.block<3, 3>(0, 9) = de_dphi_j;
  d_theta.block<3, 3>(0, 3) = -jr_inv;
  d_theta.block<3, 3>(0, 9) = jl_inv;
  const Row3 d_axis = d_expected / rest_length;
  const Row3 d_mismatch = d_bond - d_expected;
  const Eigen::Matrix3d axis_outer = axis * axis.transpose();

  const Row3 d_force = -k.shear * d_mismatch -
                       (k.axial - k.shear) * ((axial * identity + axis * mismatch.transpose()) * d_axis +
                                              axis_outer * d_mismatch);
  const Row3 d_moment = k.bending * d_theta + (k.twisting - k.bending) *
                                                  ((twist * identity + axis * theta.transpose()) * d_axis +
                                                   axis_outer * d_theta);
  const Row3 d_couple = 0.5 * cross_matrix(force_on_j) * d_bond - 0.5 * cross_matrix(bond) * d_force;
  jacobian.block<3, 12>(0, 0) = -d_force;
  jacobian.block<3, 12>(3, 0) = d_moment + d_couple;
  jacobian.block<3, 12>(6, 0) = d_force;
  jacobian.block<3, 12>(9, 0) = -d_moment + d_couple;
}

}  // namespace hsrod
