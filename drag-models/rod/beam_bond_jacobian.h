// Closed-form linearisation of the undamped beam bond (rod/beam_bond.h) for
// implicit steps: its loads (F_i, T_i, F_j, T_j) and their 12x12 Jacobian
// d loads / d (x_i, phi_i, x_j, phi_j), where phi are lab-frame rotation
// increments, q -> exp(phi) q (the convention of the implicit step).
//
// Derivation (notation of beam_bond.cpp): with Q = q_j r^-1 q_i^-1 the lab
// relative rotation, theta = Log Q, and the expected bond vector
// e = Exp(theta / 2) q_i a (a = rest vector in i's frame),
//     d theta = J_l^-1(theta) dphi_j - J_r^-1(theta) dphi_i,
//     d e     = -[e]x (R(theta/2) - 1/2 J_l(theta/2) J_r^-1(theta)) dphi_i
//               - 1/2 [e]x J_l(theta/2) J_l^-1(theta) dphi_j,
// with the left and right Jacobians of SO(3), Log(Exp(d) Exp(theta)) =
// theta + J_l^-1 d, Log(Exp(theta) Exp(d)) = theta + J_r^-1 d, J_r(theta) =
// J_l(-theta) (Sola, Deray & Atchuthan 2018, "A micro Lie theory for state
// estimation in robotics", arXiv:1812.01537, the SO(3) example). The spring laws F = -k_s m - (k_n - k_s) n (n.m),
// m = x_j - x_i - e, n = e / L0, M = k_b theta + (k_t - k_b) n (n.theta) and
// the shared couple -1/2 (x_j - x_i) x F are then differentiated by the
// product rule. Checked against central differences of evaluate_beam_bond
// (tests/drag-models/rod/test_beam_bond_jacobian.cpp).
#pragma once

#include "rod/beam_bond.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hsrod {

using BondLoads = Eigen::Matrix<double, 12, 1>;      // (F_i [N], T_i [N m], F_j, T_j), lab frame
using BondJacobian = Eigen::Matrix<double, 12, 12>;  // d loads / d (x_i [m], phi_i [rad], x_j, phi_j)

void beam_bond_loads_and_jacobian(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                  const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j,
                                  const BeamBondRest& rest, const BeamBondStiffness& stiffness, BondLoads& loads,
                                  BondJacobian& jacobian);

// The same loads, and the stiffness K = -jacobian added block by block to the
// 6x6 blocks of sphere rows/columns (i, i), (i, j), (j, i), (j, j) without
// forming the 12x12 matrix (the same numbers as adding -jacobian's blocks).
void beam_bond_loads_and_add_stiffness(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                       const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j,
                                       const BeamBondRest& rest, const BeamBondStiffness& stiffness,
                                       BondLoads& loads, Eigen::Matrix<double, 6, 6>& k_ii,
                                       Eigen::Matrix<double, 6, 6>& k_ij, Eigen::Matrix<double, 6, 6>& k_ji,
                                       Eigen::Matrix<double, 6, 6>& k_jj);

// Left Jacobian of SO(3), J_l(v) = I + (1 - cos t)/t^2 [v]x + (t - sin t)/t^3 [v]x^2, t = |v|,
// and its inverse J_l^-1(v) = I - [v]x / 2 + (1/t^2 - (1 + cos t)/(2 t sin t)) [v]x^2 (t < pi).
Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& v);
Eigen::Matrix3d so3_left_jacobian_inverse(const Eigen::Vector3d& v);

}  // namespace hsrod
