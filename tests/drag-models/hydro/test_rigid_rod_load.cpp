// The in-plane rigid-body reduction of a rod's load (hydro/rigid_rod_load.h):
// its 3x3 resistance and driving reproduce the per-sphere loads of the model
// for any rigid motion (levels 1-3, a tilted rod in the shear of a channel
// flow), its free velocity leaves the rod force- and torque-free, and in a
// uniform stream it equals the free translation of the existing transport
// tests (straight rods have no torque there), with drift angle 0 for the
// isotropic level and towards the trailing end for the anisotropic ones.
#include "common/math_constants.h"
#include "flow/straight_channel_flow.h"
#include "hydro/rigid_rod_load.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hsrod;

namespace {
using hsrod::kPi;
constexpr double kD = 3e-6, kMu = 1e-3, kH = 10e-6;  // beta = 0.3

std::unique_ptr<HydrodynamicModel> model(const std::string& name) {
  static const ConfinementTable table = ConfinementTable::default_table();
  return make_hydrodynamic_model(name, {kMu, kH, kD}, table);
}

// Per-sphere load of the model for the rigid motion q, reduced to (F_x, F_y, T_z).
Eigen::Vector3d sphere_loads(const RodGeometry& rod, const RodDrag& drag, const RigidRodLoad& rigid,
                             const Eigen::Vector3d& q) {
  const Eigen::VectorXd forces = drag.forces(rigid_sphere_velocities(rod, rigid.centre, q));
  std::vector<Eigen::Vector3d> torques(rod.size());
  for (int i = 0; i < rod.size(); ++i)
    torques[i] = drag.driving_torque[i] - drag.rotational_resistance[i] * Eigen::Vector3d(0, 0, q.z());
  return rod_in_plane_load(rod, rigid.centre, forces, torques);
}
}  // namespace

TEST(RigidRodLoad, ResistanceReproducesPerSphereLoadsForRigidMotions) {
  // Channel W = 60 um, H = 10 um, U = 1 cm/s; rod of 10 spheres tilted 30 deg,
  // 12 um off the centre line: sheared, non-uniform driving.
  const ChannelGeometry channel(200e-6, 60e-6, kH);
  const StraightChannelFlow flow(channel, {kMu, 1000.0}, Inflow::mean_velocity(0.01));
  RodGeometry rod = hsrod_test::straight_rod(10, kD, 30 * kPi / 180);
  for (auto& p : rod.positions) p += Eigen::Vector3d(100e-6, 42e-6, 0.5 * kH);
  for (const std::string name : {"isotropic", "local", "nonlocal"}) {
    RodDrag drag;
    model(name)->evaluate(rod, flow, drag);
    const RigidRodLoad rigid = rigid_rod_load(rod, drag);
    const double f_scale = rigid.driving.head<2>().norm(), t_scale = f_scale * 10 * kD;
    for (const Eigen::Vector3d& q : {Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(0, 0.01, 0),
                                    Eigen::Vector3d(0, 0, 300.0), Eigen::Vector3d(0.004, -0.007, -150.0)}) {
      const Eigen::Vector3d expected = sphere_loads(rod, drag, rigid, q), got = rigid.load(q);
      EXPECT_NEAR(got.x(), expected.x(), 1e-12 * f_scale) << name;
      EXPECT_NEAR(got.y(), expected.y(), 1e-12 * f_scale) << name;
      EXPECT_NEAR(got.z(), expected.z(), 1e-12 * t_scale) << name;
    }
    // Free rigid motion: no net force or torque on the rod.
    const Eigen::Vector3d residual = sphere_loads(rod, drag, rigid, rigid.free_velocity);
    EXPECT_LT(residual.head<2>().norm(), 1e-10 * f_scale) << name;
    EXPECT_LT(std::fabs(residual.z()), 1e-10 * t_scale) << name;
    // Above the centre line the flow slows towards the upper wall (vorticity
    // -du/dy > 0): the rod turns counter-clockwise.
    EXPECT_GT(rigid.free_velocity.z(), 0.0) << name;
    EXPECT_TRUE(rigid.resistance.isApprox(rigid.resistance.transpose(), 1e-12)) << name;
  }
}

TEST(RigidRodLoad, FreeVelocityInUniformStreamEqualsFreeTranslation) {
  const hsrod_test::UniformStream stream;
  for (const std::string name : {"isotropic", "local", "nonlocal"}) {
    const auto m = model(name);
    const RodGeometry rod = hsrod_test::straight_rod(10, kD, 45 * kPi / 180);
    RodDrag drag;
    m->evaluate(rod, stream, drag);
    const RigidRodLoad rigid = rigid_rod_load(rod, drag);
    const Eigen::Vector3d translation = hsrod_test::free_rigid_translation(*m, rod, stream).velocity;
    EXPECT_NEAR(rigid.free_velocity.x(), translation.x(), 1e-12) << name;
    EXPECT_NEAR(rigid.free_velocity.y(), translation.y(), 1e-12) << name;
    EXPECT_NEAR(rigid.free_velocity.z(), 0.0, 1e-9) << name;  // 1/s; no torque on a straight rod
    const double drift = drift_angle(rigid, stream);
    std::printf("%s: free velocity (%.5f, %.5f) m/s, drift angle %.3f deg\n", name.c_str(),
                rigid.free_velocity.x(), rigid.free_velocity.y(), drift * 180 / kPi);
    if (name == "isotropic") EXPECT_NEAR(drift, 0.0, 1e-12);
    // Sphere 0 (downstream end) is towards +y: the trailing end is towards -y.
    else EXPECT_LT(drift, 0.0) << name;
  }
}
