// Wall friction inside the implicit step: a sphere pressed onto the gap wall
// and pushed along it reaches the steady states the Coulomb law gives by
// hand (sliding, and rolling without slip below the friction limit), and a
// reversing load at a step 1000x the contact time scale does not chatter.
#include "common/math_constants.h"
#include "dynamics/overdamped_rod_step.h"
#include "hydro/hydrodynamic_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hsrod;

namespace {
using hsrod::kPi;
constexpr double d = 3e-6, r = 0.5 * d;           // sphere [m]
constexpr double viscosity = 1e-3;                // [Pa s]
const double zeta = 3 * kPi * viscosity * d;      // translational resistance [N s/m]
const double zeta_r = kPi * viscosity * d * d * d;  // rotational resistance [N m s]
constexpr double mu = 0.5;                        // friction coefficient
constexpr double press = 1e-9;                    // normal load onto the wall z = 0 [N]

struct PressedSphere {
  ChannelGeometry channel{200e-6, 200e-6, 20e-6};
  WallContactParameters walls;
  OverdampedRod rod;
  RodDrag drag;
  OverdampedRodSolver solver;
  explicit PressedSphere(double rotational_resistance) {
    walls.youngs_modulus = 15e6;
    walls.friction_coefficient = mu;
    walls.slip_velocity = 1e-6;
    rod.positions = {Eigen::Vector3d(100e-6, 100e-6, r)};
    rod.orientations = {Eigen::Quaterniond::Identity()};
    rod.radii = {r};
    rod.external_forces = {Eigen::Vector3d::Zero()};
    rod.external_torques = {Eigen::Vector3d::Zero()};
    drag.resize(1);
    drag.resistance[0] = zeta * Eigen::Matrix3d::Identity();
    drag.rotational_resistance[0] = rotational_resistance;
    drag.driving_force[0].setZero();
    drag.driving_torque[0].setZero();
  }
  OverdampedStepResult run(double tangential_load, double dt, int steps) {
    rod.external_forces[0] = Eigen::Vector3d(tangential_load, 0.0, -press);
    OverdampedStepResult result;
    for (int k = 0; k < steps; ++k) result = solver.step(rod, drag, dt, &channel, &walls);
    return result;
  }
};
}  // namespace

TEST(WallFrictionStep, SlidingSphereFeelsMuTimesTheNormalLoad) {
  PressedSphere s(zeta_r);
  const double load = 2.0 * mu * press;
  const auto result = s.run(load, 1e-6, 400);
  // Force balance: load - mu P = zeta v; torque of mu P at the contact: r mu P = zeta_r omega.
  EXPECT_NEAR(result.velocities[0].x(), (load - mu * press) / zeta, 1e-6 * load / zeta);
  EXPECT_NEAR(result.angular_velocities[0].y(), r * mu * press / zeta_r, 1e-6 * r * mu * press / zeta_r);
  EXPECT_NEAR(result.velocities[0].z(), 0.0, 1e-9);
  // It stays on the wall with the Hertz overlap of the load P.
  const double overlap = r - s.rod.positions[0].z();
  const double hertz = std::pow(3.0 * press / (4.0 * s.walls.effective_modulus() * std::sqrt(r)), 2.0 / 3.0);
  EXPECT_NEAR(overlap, hertz, 1e-3 * hertz);
}

TEST(WallFrictionStep, BelowTheLimitAFreeSphereRollsWithoutSlip) {
  // F_f < mu P: the contact sticks (slip < v_s) and the sphere rolls:
  // v = r omega, load = zeta v + F_f, r F_f = zeta_r omega -> v = load / (zeta + zeta_r / r^2).
  PressedSphere s(zeta_r);
  const double load = 0.3 * mu * press;
  const auto result = s.run(load, 1e-6, 400);
  const double v = load / (zeta + zeta_r / (r * r));
  EXPECT_NEAR(result.velocities[0].x(), v, 2e-3 * v);
  EXPECT_NEAR(r * result.angular_velocities[0].y(), v, 2e-3 * v);
  EXPECT_LT(std::fabs(result.velocities[0].x() - r * result.angular_velocities[0].y()), s.walls.slip_velocity);
}

TEST(WallFrictionStep, ASphereThatCannotRollSticksAndCreepsBelowTheSlipVelocity) {
  const double spin_resistance = 1e6 * zeta_r;
  PressedSphere s(spin_resistance);
  const double load = 0.3 * mu * press;
  const auto result = s.run(load, 1e-6, 400);
  // Viscous stick on the contact point's slip w = v - r omega: F = c w with
  // c = mu P / v_s; load - F = zeta v, r F = zeta_r' omega. Hence
  // w = load / (zeta + c + c zeta r^2 / zeta_r') and v = (load - c w) / zeta.
  const double c = mu * press / s.walls.slip_velocity;
  const double slip = load / (zeta + c + c * zeta * r * r / spin_resistance);
  const double v = (load - c * slip) / zeta;
  EXPECT_NEAR(result.velocities[0].x(), v, 2e-3 * v);
  EXPECT_LT(result.velocities[0].x(), s.walls.slip_velocity);
}

TEST(WallFrictionStep, ReversingLoadAtALargeStepDoesNotChatter) {
  // Settled on the wall at dt = 1 us, then dt = 1 ms: 1000x the time a
  // sliding sphere needs to cross the slip velocity band. After each
  // reversal the velocity must follow the load's sign at once and settle to
  // the sliding value, never flipping sign from step to step.
  PressedSphere s(1e6 * zeta_r);
  const double load = 2.0 * mu * press, dt = 1e-3;
  s.run(load, 1e-6, 400);
  for (int reversal = 0; reversal < 6; ++reversal) {
    const double sign = reversal % 2 ? -1.0 : 1.0;
    s.rod.external_forces[0] = Eigen::Vector3d(sign * load, 0.0, -press);
    for (int k = 0; k < 5; ++k) {
      const auto result = s.solver.step(s.rod, s.drag, dt, &s.channel, &s.walls);
      const double v = result.velocities[0].x();
      EXPECT_GE(sign * v, 0.0) << "reversal " << reversal << " step " << k;
      EXPECT_LE(sign * v, load / zeta * 1.0001);
      if (k == 4) {
        EXPECT_NEAR(v, sign * (load - mu * press) / zeta, 1e-6 * load / zeta);
      }
    }
  }
}

// Backward Euler takes the friction at the step's end velocities
// (WallContactParameters::friction_iterations). A sphere sliding at
// (2 mu P - mu P) / zeta whose load drops to 0.9 mu P must stick within the
// first step, however large: the law at the end velocity leaves only the
// viscous creep below v_s. The secant about the previous step's slip alone
// (friction_iterations 0) resists with c = mu P / v_slide = zeta and lets it
// slide on at 0.45 mu P / zeta (8 um in a 1 ms step).
TEST(WallFrictionStep, ASlidingSphereSticksInTheFirstLargeStepAfterTheLoadDrops) {
  const double spin_resistance = 1e6 * zeta_r, dt = 1e-3;
  const double creep_load = 0.9 * mu * press;
  const double c = mu * press / 1e-6;  // stick coefficient mu P / v_s
  const double slip = creep_load / (zeta + c + c * zeta * r * r / spin_resistance);
  const double creep = (creep_load - c * slip) / zeta;
  for (int iterations : {30, 0}) {
    PressedSphere s(spin_resistance);
    s.walls.friction_iterations = iterations;
    s.run(2.0 * mu * press, 1e-6, 400);
    const auto result = s.run(creep_load, dt, 1);
    if (iterations > 0) {
      EXPECT_NEAR(result.velocities[0].x(), creep, 1e-3 * creep);
      EXPECT_LE(result.friction_mismatch, s.walls.friction_tolerance);
      EXPECT_GT(result.friction_repeats, 0);
    } else {
      const double lagged = creep_load / (zeta + mu * press / (mu * press / zeta));
      EXPECT_NEAR(result.velocities[0].x(), lagged, 1e-3 * lagged);
      EXPECT_EQ(result.friction_repeats, 0);
    }
  }
}

// ... and a sticking sphere whose load rises to 2 mu P slides at
// (2 mu P - mu P) / zeta from the first step (the secant about the previous
// creep would resist with mu P / v_s and hold it nearly still).
TEST(WallFrictionStep, AStickingSphereSlidesFromTheFirstLargeStepAfterTheLoadRises) {
  PressedSphere s(1e6 * zeta_r);
  s.run(0.3 * mu * press, 1e-6, 400);
  const double load = 2.0 * mu * press;
  const auto result = s.run(load, 1e-3, 1);
  const double sliding = (load - mu * press) / zeta;
  EXPECT_NEAR(result.velocities[0].x(), sliding, 2e-3 * sliding);
  EXPECT_LE(result.friction_mismatch, s.walls.friction_tolerance);
}
