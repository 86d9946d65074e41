// The closed-form beam-bond Jacobian (rod/beam_bond_jacobian.h) against
// central differences of the bond law (central_difference_jacobian below)
// on random deformed states, and its loads against evaluate_beam_bond.
#include "dynamics/overdamped_rod_step.h"
#include "rod/beam_bond_jacobian.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

using namespace hsrod;

namespace {

// Bond loads ordered (F_i, T_i, F_j, T_j).
Eigen::Matrix<double, 12, 1> bond_loads(const SphereState& si, const SphereState& sj, const RodBond& b) {
  const auto out = evaluate_beam_bond(si, sj, b.rest, b.stiffness, BeamBondDamping{});
  Eigen::Matrix<double, 12, 1> loads;
  loads << -out.force_on_j, out.torque_on_i, out.force_on_j, out.torque_on_j;
  return loads;
}

// A sphere moved by h along one of its 6 degrees of freedom (x, y, z, then
// a rotation about x, y, z applied in the world frame).
SphereState perturbed(const SphereState& s, int component, double h) {
  SphereState p = s;
  if (component < 3) {
    p.position[component] += h;
  } else {
    Eigen::Vector3d phi = Eigen::Vector3d::Zero();
    phi[component - 3] = h;
    p.orientation = (quaternion_from_rotation_vector(phi) * s.orientation).normalized();
  }
  return p;
}

// The loads and their 12x12 Jacobian d loads / d (x_i, phi_i, x_j, phi_j)
// by central differences (steps 1e-7 of the rest length and 1e-7 rad).
void central_difference_jacobian(const SphereState& si, const SphereState& sj, const RodBond& bond,
                                 Eigen::Matrix<double, 12, 1>& loads, Eigen::Matrix<double, 12, 12>& jacobian) {
  loads = bond_loads(si, sj, bond);
  const double length_step = 1e-7 * bond.rest.rest_length();  // [m]
  const double angle_step = 1e-7;                              // [rad]
  for (int c = 0; c < 12; ++c) {
    const int local = c % 6;
    const double h = local < 3 ? length_step : angle_step;
    const bool on_i = c < 6;
    const SphereState ip = on_i ? perturbed(si, local, h) : si;
    const SphereState im = on_i ? perturbed(si, local, -h) : si;
    const SphereState jp = on_i ? sj : perturbed(sj, local, h);
    const SphereState jm = on_i ? sj : perturbed(sj, local, -h);
    jacobian.col(c) = (bond_loads(ip, jp, bond) - bond_loads(im, jm, bond)) / (2.0 * h);
  }
}

Eigen::Quaterniond random_rotation(std::mt19937& rng, double largest_angle) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
  return quaternion_from_rotation_vector(axis * largest_angle * 0.5 * (1.0 + u(rng)));
}

// Rows and columns made dimensionless (rotations times L0, torques / L0)
// so that force and torque entries are compared on one scale.
BondJacobian scaled(const BondJacobian& j, double length) {
  BondJacobian s = j;
  for (int r = 0; r < 12; ++r)
    for (int c = 0; c < 12; ++c) {
      if (r % 6 >= 3) s(r, c) /= length;
      if (c % 6 >= 3) s(r, c) /= length;
    }
  return s;
}

}  // namespace

TEST(BeamBondJacobian, MatchesCentralDifferencesOnRandomStates) {
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double d = 3e-6;
  double worst = 0.0, worst_loads = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    // A bond made at a random orientation, then deformed: stretched or
    // compressed by up to 10 %, sheared by up to 0.2 d, ends turned by up to
    // 0.6 rad (bent and twisted), the whole pair rotated and moved.
    const Eigen::Quaterniond qi0 = random_rotation(rng, 3.0), qj0 = random_rotation(rng, 3.0);
    const Eigen::Vector3d xi0(u(rng) * d, u(rng) * d, u(rng) * d);
    const Eigen::Vector3d xj0 = xi0 + d * Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    RodBond bond;
    bond.rest = BeamBondRest::from_current(xi0, qi0, xj0, qj0);
    const double nu = 0.3;
    bond.stiffness = BeamBondStiffness::from_material({15e6, nu, d * (0.5 + 0.5 * std::fabs(u(rng))), 0.0}, d);
    SphereState si, sj;
    const Eigen::Quaterniond whole = random_rotation(rng, 3.0);
    si.position = whole * xi0 + Eigen::Vector3d(u(rng), u(rng), u(rng)) * d;
    si.orientation = (whole * random_rotation(rng, 0.6) * qi0).normalized();
    const Eigen::Vector3d axis = (xj0 - xi0).normalized();
    const Eigen::Vector3d shear = 0.2 * d * Eigen::Vector3d(u(rng), u(rng), u(rng));
    sj.position = si.position + whole * ((1.0 + 0.1 * u(rng)) * d * axis + shear);
    sj.orientation = (whole * random_rotation(rng, 0.6) * qj0).normalized();

    BondLoads loads_fd, loads;
    BondJacobian fd, analytic;
    central_difference_jacobian(si, sj, bond, loads_fd, fd);
    beam_bond_loads_and_jacobian(si.position, si.orientation, sj.position, sj.orientation, bond.rest,
                                 bond.stiffness, loads, analytic);
    const BondJacobian a = scaled(analytic, d), f = scaled(fd, d);
    worst = std::max(worst, (a - f).cwiseAbs().maxCoeff() / f.cwiseAbs().maxCoeff());
    worst_loads = std::max(worst_loads, (loads - loads_fd).norm() / loads_fd.norm());
  }
  std::printf("200 random bond states: largest |J_analytic - J_central| / max|J| = %.3g, loads %.3g\n", worst,
              worst_loads);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worst_loads, 1e-14);
}

TEST(BeamBondJacobian, SeriesAndClosedFormsOfTheSo3JacobiansJoin) {
  // J_l^-1 is the inverse of J_l at every angle, and both are continuous at
  // the switch to their Taylor series (1e-2 rad).
  for (double t : {1e-8, 1e-4, 0.0099999, 0.0100001, 0.3, 1.5, 3.0}) {
    const Eigen::Vector3d v = t * Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
    const Eigen::Matrix3d product = so3_left_jacobian(v) * so3_left_jacobian_inverse(v);
    EXPECT_LT((product - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-13) << "angle " << t;
  }
  const Eigen::Vector3d w = Eigen::Vector3d(0.3, 0.4, -0.2).normalized();
  EXPECT_LT((so3_left_jacobian(0.0099999999 * w) - so3_left_jacobian(0.0100000001 * w)).norm(), 1e-9);
  EXPECT_LT((so3_left_jacobian_inverse(0.0099999999 * w) - so3_left_jacobian_inverse(0.0100000001 * w)).norm(),
            1e-9);
}

TEST(BeamBondJacobian, StiffnessAddedFromItsPiecesEqualsTheNegatedJacobianBitForBit) {
  // The banded step adds K = -J to its 6x6 blocks straight from the 3x3
  // pieces; it must give the same numbers, to the last bit, as adding the
  // 12x12 Jacobian's negated blocks to blocks that already hold something.
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double d = 3e-6;
  int differing = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Quaterniond qi0 = random_rotation(rng, 3.0), qj0 = random_rotation(rng, 3.0);
    const Eigen::Vector3d xi0(u(rng) * d, u(rng) * d, u(rng) * d);
    const Eigen::Vector3d xj0 = xi0 + d * Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const BeamBondRest rest = BeamBondRest::from_current(xi0, qi0, xj0, qj0);
    const BeamBondStiffness k = BeamBondStiffness::from_material({15e6, 0.3, d, 0.0}, d);
    const Eigen::Vector3d xi = xi0 + 0.1 * d * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Vector3d xj = xj0 + 0.1 * d * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Quaterniond qi = (random_rotation(rng, 0.6) * qi0).normalized();
    const Eigen::Quaterniond qj = (random_rotation(rng, 0.6) * qj0).normalized();
    using Block = Eigen::Matrix<double, 6, 6>;
    const double scale = k.axial;
    Block start[4];
    for (Block& b : start) b = scale * Block::Random();
    if (trial % 2) start[1].setZero();  // the off-diagonal blocks start from zero in the step
    BondLoads loads, loads_direct;
    BondJacobian j;
    beam_bond_loads_and_jacobian(xi, qi, xj, qj, rest, k, loads, j);
    Block via_jacobian[4] = {start[0], start[1], start[2], start[3]};
    via_jacobian[0] += -j.block<6, 6>(0, 0);
    via_jacobian[1] += -j.block<6, 6>(0, 6);
    via_jacobian[2] += -j.block<6, 6>(6, 0);
    via_jacobian[3] += -j.block<6, 6>(6, 6);
    Block direct[4] = {start[0], start[1], start[2], start[3]};
    beam_bond_loads_and_add_stiffness(xi, qi, xj, qj, rest, k, loads_direct, direct[0], direct[1], direct[2],
                                      direct[3]);
    for (int b = 0; b < 4; ++b)
      for (int e = 0; e < 36; ++e)
        if (std::memcmp(&direct[b](e), &via_jacobian[b](e), sizeof(double)) != 0) ++differing;
    for (int e = 0; e < 12; ++e)
      if (std::memcmp(&loads(e), &loads_direct(e), sizeof(double)) != 0) ++differing;
  }
  EXPECT_EQ(differing, 0);
}
