// Regularised Coulomb wall friction (dynamics/wall_contact.h) against the
// law written out by hand: sliding, sticking, rolling without slip.
#include "dynamics/wall_contact.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

using namespace hsrod;

namespace {
constexpr double r = 1.5e-6;     // sphere radius [m]
constexpr double mu = 0.5;       // friction coefficient [-]
constexpr double vs = 1e-6;      // slip velocity [m/s]
constexpr double fn = 2e-9;      // normal force [N]

WallContactPoint floor_contact() { return {Eigen::Vector3d::UnitZ(), fn}; }

Vector6d velocity(const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
  Vector6d u;
  u << v, w;
  return u;
}
}  // namespace

TEST(WallFriction, SlidingGivesCoulombForceAgainstTheSlipAndItsTorque) {
  const Vector6d u = velocity(Eigen::Vector3d(3e-3, -4e-3, 0.0), Eigen::Vector3d::Zero());  // |v_t| = 5 mm/s
  const Vector6d load = -wall_friction_resistance(floor_contact(), r, mu, vs, u) * u;
  const Eigen::Vector3d force = load.head<3>(), torque = load.tail<3>();
  EXPECT_NEAR(force.norm(), mu * fn, 1e-12 * mu * fn);
  EXPECT_NEAR(force.normalized().dot(Eigen::Vector3d(-0.6, 0.8, 0.0)), 1.0, 1e-12);
  // Torque of the force at the contact point r_c = -r n about the centre.
  const Eigen::Vector3d expected_torque = (-r * Eigen::Vector3d::UnitZ()).cross(force);
  EXPECT_LT((torque - expected_torque).norm(), 1e-12 * expected_torque.norm());
}

TEST(WallFriction, NormalVelocityCausesNoFriction) {
  const Vector6d u = velocity(Eigen::Vector3d(0.0, 0.0, 1e-2), Eigen::Vector3d::Zero());
  const Matrix6d resistance = wall_friction_resistance(floor_contact(), r, mu, vs, u);
  EXPECT_LT((resistance * u).norm(), 1e-20);
}

TEST(WallFriction, BelowTheSlipVelocityFrictionIsViscousStick) {
  // |v_t| = 0.3 v_s: F = mu F_n v_t / v_s.
  const Vector6d u = velocity(Eigen::Vector3d(0.3 * vs, 0.0, 0.0), Eigen::Vector3d::Zero());
  const Vector6d load = -wall_friction_resistance(floor_contact(), r, mu, vs, u) * u;
  EXPECT_NEAR(load[0], -mu * fn * 0.3, 1e-12 * mu * fn);
  // The secant about u0 = 0 is the same stick law.
  const Vector6d at_rest = -wall_friction_resistance(floor_contact(), r, mu, vs, Vector6d::Zero()) * u;
  EXPECT_NEAR(at_rest[0], load[0], 1e-12 * mu * fn);
}

TEST(WallFriction, RollingWithoutSlipIsFree) {
  // Contact point velocity v + omega x (-r n) = 0 for v = r omega x n.
  const Eigen::Vector3d omega(0.0, 2e3, 0.0);
  const Eigen::Vector3d v = r * omega.cross(Eigen::Vector3d::UnitZ());
  const Vector6d u = velocity(v, omega);
  const Matrix6d resistance = wall_friction_resistance(floor_contact(), r, mu, vs, velocity(v, Eigen::Vector3d::Zero()));
  EXPECT_LT((resistance * u).norm(), 1e-12 * mu * fn);
}

TEST(WallFriction, ResistanceIsSymmetricPositiveSemidefiniteOnAnInclinedWall) {
  const Eigen::Vector3d n = Eigen::Vector3d(-0.6, 0.8, 0.0);
  const WallContactPoint contact{n, fn};
  const Vector6d u0 = velocity(Eigen::Vector3d(1e-3, 2e-3, 0.0), Eigen::Vector3d(0.0, 0.0, 1e2));
  const Matrix6d resistance = wall_friction_resistance(contact, r, mu, vs, u0);
  EXPECT_LT((resistance - resistance.transpose()).norm(), 1e-14 * resistance.norm());
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(resistance);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), -1e-12 * eigen.eigenvalues().maxCoeff());
  // At u0 the force magnitude is exactly mu F_n.
  EXPECT_NEAR((resistance * u0).head<3>().norm(), mu * fn, 1e-12 * mu * fn);
}

TEST(WallFriction, WallContactReportsEachWallsNormalForce) {
  const ChannelGeometry channel(100e-6, 50e-6, 3.2e-6);
  WallContactParameters p;
  p.youngs_modulus = 15e6;
  p.friction_coefficient = mu;
  // Sphere pressed 0.1 um into the bottom gap wall and 0.2 um into the side wall y = 0.
  const WallContact c = wall_contact(channel, p, Eigen::Vector3d(50e-6, r - 0.2e-6, r - 0.1e-6), r);
  ASSERT_EQ(c.points, 2);
  const double e = p.effective_modulus();
  const double side = 4.0 / 3.0 * e * std::sqrt(r * 0.2e-6) * 0.2e-6;
  const double bottom = 4.0 / 3.0 * e * std::sqrt(r * 0.1e-6) * 0.1e-6;
  EXPECT_NEAR(c.point[0].normal_force, side, 1e-9 * side);
  EXPECT_NEAR(c.point[0].normal.y(), 1.0, 1e-12);
  EXPECT_NEAR(c.point[1].normal_force, bottom, 1e-9 * bottom);
  EXPECT_NEAR(c.point[1].normal.z(), 1.0, 1e-12);
}

TEST(WallFriction, ZeroCoefficientOrNoLoadGivesNoFriction) {
  const Vector6d u = velocity(Eigen::Vector3d(1e-3, 0.0, 0.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(wall_friction_resistance(floor_contact(), r, 0.0, vs, u).norm(), 0.0);
  EXPECT_EQ(wall_friction_resistance({Eigen::Vector3d::UnitZ(), 0.0}, r, mu, vs, u).norm(), 0.0);
}
