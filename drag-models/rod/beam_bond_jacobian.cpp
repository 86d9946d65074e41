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

// Writes s m into the 3x3 block of `out` at (row, col) (s = +-1: exact).
// A plain loop: Eigen's assignment to a 3x3 block of a 12x12 matrix is an
// out-of-line slice loop (callgrind: ~1/8 of the bond Jacobian's instructions).
inline void put_block(BondJacobian& out, int row, int col, const Eigen::Matrix3d& m, bool negate = false) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out(row + r, col + c) = negate ? -m(r, c) : m(r, c);
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

namespace {

// The Jacobian's 3x3 pieces (the blocks of rows (F_i, T_i, F_j, T_j) are
// sums and negations of these).
struct BondJacobianPieces {
  Eigen::Matrix3d translation, df_dphi_i, df_dphi_j, dc_dx_i, dm_dphi_i, dc_dphi_i, dm_dphi_j, dc_dphi_j;
};

inline void loads_and_jacobian_pieces(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                      const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j,
                                      const BeamBondRest& rest, const BeamBondStiffness& k, BondLoads& loads,
                                      BondJacobianPieces& p) {
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
  const Eigen::Matrix3d jr_inv = jl_inv.transpose();  // J_l^-1(-theta) = J_l^-1(theta)^T
  const Eigen::Matrix3d jl_half = so3_left_jacobian(0.5 * theta);
  const Eigen::Matrix3d r_half = (q_mid * q_i.conjugate()).toRotationMatrix();  // Exp(theta / 2)
  const Eigen::Matrix3d e_cross = cross_matrix(expected);
  const Eigen::Matrix3d de_dphi_i = -e_cross * (r_half - 0.5 * jl_half * jr_inv);
  const Eigen::Matrix3d de_dphi_j = -0.5 * e_cross * (jl_half * jl_inv);

  // Product rule, block by block (columns x_i, phi_i, x_j, phi_j): with
  // d bond = (-I, 0, I, 0), d m = d bond - d e, d n = d e / L0,
  //   d F = -k_s d m - (k_n - k_s) ((n.m) I + n m^T) d n - (k_n - k_s) n n^T d m,
  //   d M = k_b d theta + (k_t - k_b) (((n.theta) I + n theta^T) d n + n n^T d theta).
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d axis_outer = axis * axis.transpose();
  const double axial_excess = k.axial - k.shear, twist_excess = k.twisting - k.bending;
  p.translation = k.shear * identity + axial_excess * axis_outer;  // -dF/dx_j = dF/dx_i
  const Eigen::Matrix3d force_rotation =
      p.translation - (axial_excess / rest_length) * (axial * identity + axis * mismatch.transpose());
  const Eigen::Matrix3d moment_theta = k.bending * identity + twist_excess * axis_outer;
  const Eigen::Matrix3d moment_axis = (twist_excess / rest_length) * (twist * identity + axis * theta.transpose());
  p.df_dphi_i = force_rotation * de_dphi_i;
  p.df_dphi_j = force_rotation * de_dphi_j;
  p.dm_dphi_i = -moment_theta * jr_inv + moment_axis * de_dphi_i;
  p.dm_dphi_j = moment_theta * jl_inv + moment_axis * de_dphi_j;
  // Couple -1/2 bond x F: d = 1/2 [F]x d bond - 1/2 [bond]x d F.
  const Eigen::Matrix3d half_bond = 0.5 * cross_matrix(bond), half_force = 0.5 * cross_matrix(force_on_j);
  p.dc_dx_i = -half_force - half_bond * p.translation;
  p.dc_dphi_i = -half_bond * p.df_dphi_i;
  p.dc_dphi_j = -half_bond * p.df_dphi_j;
}

// out -= m on the 3x3 block at (row, col) of a 6x6 block: out + (-m) in
// IEEE arithmetic, the same as adding the negated Jacobian's block.
inline void subtract_block(Eigen::Matrix<double, 6, 6>& out, int row, int col, const Eigen::Matrix3d& m) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out(row + r, col + c) -= m(r, c);
}

}  // namespace

void beam_bond_loads_and_jacobian(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                  const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j,
                                  const BeamBondRest& rest, const BeamBondStiffness& k, BondLoads& loads,
                                  BondJacobian& jacobian) {
  BondJacobianPieces p;
  loads_and_jacobian_pieces(x_i, q_i, x_j, q_j, rest, k, loads, p);
  const Eigen::Matrix3d &translation = p.translation, &df_dphi_i = p.df_dphi_i, &df_dphi_j = p.df_dphi_j,
                        &dc_dx_i = p.dc_dx_i, &dm_dphi_i = p.dm_dphi_i, &dc_dphi_i = p.dc_dphi_i,
                        &dm_dphi_j = p.dm_dphi_j, &dc_dphi_j = p.dc_dphi_j;
  // Rows (F_i, T_i, F_j, T_j) = (-F, M + c, F, -M + c); dc/dx_j = -dc/dx_i.
  put_block(jacobian, 0, 0, translation, true);
  put_block(jacobian, 0, 3, df_dphi_i, true);
  put_block(jacobian, 0, 6, translation);
  put_block(jacobian, 0, 9, df_dphi_j, true);
  put_block(jacobian, 3, 0, dc_dx_i);
  put_block(jacobian, 3, 3, dm_dphi_i + dc_dphi_i);
  put_block(jacobian, 3, 6, dc_dx_i, true);
  put_block(jacobian, 3, 9, dm_dphi_j + dc_dphi_j);
  put_block(jacobian, 6, 0, translation);
  put_block(jacobian, 6, 3, df_dphi_i);
  put_block(jacobian, 6, 6, translation, true);
  put_block(jacobian, 6, 9, df_dphi_j);
  put_block(jacobian, 9, 0, dc_dx_i);
  put_block(jacobian, 9, 3, -dm_dphi_i + dc_dphi_i);
  put_block(jacobian, 9, 6, dc_dx_i, true);
  put_block(jacobian, 9, 9, -dm_dphi_j + dc_dphi_j);
}

void beam_bond_loads_and_add_stiffness(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                       const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j,
                                       const BeamBondRest& rest, const BeamBondStiffness& k, BondLoads& loads,
                                       Eigen::Matrix<double, 6, 6>& k_ii, Eigen::Matrix<double, 6, 6>& k_ij,
                                       Eigen::Matrix<double, 6, 6>& k_ji, Eigen::Matrix<double, 6, 6>& k_jj) {
  BondJacobianPieces p;
  loads_and_jacobian_pieces(x_i, q_i, x_j, q_j, rest, k, loads, p);
  // K = -J block by block (the blocks of beam_bond_loads_and_jacobian).
  subtract_block(k_ii, 0, 0, -p.translation);
  subtract_block(k_ii, 0, 3, -p.df_dphi_i);
  subtract_block(k_ii, 3, 0, p.dc_dx_i);
  subtract_block(k_ii, 3, 3, p.dm_dphi_i + p.dc_dphi_i);
  subtract_block(k_ij, 0, 0, p.translation);
  subtract_block(k_ij, 0, 3, -p.df_dphi_j);
  subtract_block(k_ij, 3, 0, -p.dc_dx_i);
  subtract_block(k_ij, 3, 3, p.dm_dphi_j + p.dc_dphi_j);
  subtract_block(k_ji, 0, 0, p.translation);
  subtract_block(k_ji, 0, 3, p.df_dphi_i);
  subtract_block(k_ji, 3, 0, p.dc_dx_i);
  subtract_block(k_ji, 3, 3, -p.dm_dphi_i + p.dc_dphi_i);
  subtract_block(k_jj, 0, 0, -p.translation);
  subtract_block(k_jj, 0, 3, p.df_dphi_j);
  subtract_block(k_jj, 3, 0, -p.dc_dx_i);
  subtract_block(k_jj, 3, 3, -p.dm_dphi_j + p.dc_dphi_j);
}

}  // namespace hsrod
