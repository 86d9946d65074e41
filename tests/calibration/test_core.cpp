// Unit tests of the OpenFOAM-free calibration core: sphere set, prescribed
// motion, stability/cost report. Test suites are prefixed "calibration_" so
// that `ctest -R calibration` selects them.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "sphere_set.h"
#include "stability_report.h"

using namespace hsrod::calib;

TEST(calibration_SphereSet, ReadsColumnsByName) {
  const auto s = SphereSet::from_text(
      "# comment\nd,id,x,y,z,vx\n3e-6,4,1e-6,2e-6,3e-6,0.5\n3e-6,5,4e-6,2e-6,3e-6,0\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.spheres()[0].id, 4);
  EXPECT_DOUBLE_EQ(s.spheres()[0].x[2], 3e-6);
  EXPECT_DOUBLE_EQ(s.spheres()[0].v[0], 0.5);
  EXPECT_DOUBLE_EQ(s.spheres()[1].omega[2], 0.0);
}

TEST(calibration_SphereSet, RejectsBadInput) {
  EXPECT_THROW(SphereSet::from_text("id,x,y,z\n1,0,0,0\n"), std::runtime_error);      // no d
  EXPECT_THROW(SphereSet::from_text("id,x,y,z,d\n1,0,0,0,-1\n"), std::runtime_error); // d <= 0
  EXPECT_THROW(SphereSet::from_text("id,x,y,z,d\n1,0,0,zero,1\n"), std::runtime_error);
  EXPECT_THROW(SphereSet::from_text("id,x,y,z,d\n1,0,0\n"), std::runtime_error);
  EXPECT_THROW(parse_motion_mode("wobble"), std::invalid_argument);
}

TEST(calibration_SphereSet, RigidVelocityIsVPlusOmegaCrossR) {
  Sphere s;
  s.x = {1, 0, 0};
  s.v = {0.1, 0, 0};
  s.omega = {0, 0, 2};
  const Vec3 u = s.rigid_velocity({1, 1, 0});  // r = (0,1,0): omega x r = (-2,0,0)
  EXPECT_DOUBLE_EQ(u[0], 0.1 - 2.0);
  EXPECT_DOUBLE_EQ(u[1], 0.0);
}

TEST(calibration_SphereSet, PrescribedMotion) {
  auto s = SphereSet::from_text("id,x,y,z,d,vx\n1,0,0,0,1e-6,2\n");
  s.set_motion(MotionMode::ConstantVelocity);
  s.set_time(0.25);
  EXPECT_DOUBLE_EQ(s.spheres()[0].x[0], 0.5);
  s.set_path_table_text("t,id,x,y,z\n0,1,0,0,0\n1,1,4,2,0\n2,1,4,2,0\n");
  s.set_motion(MotionMode::Table);
  s.set_time(0.5);
  EXPECT_DOUBLE_EQ(s.spheres()[0].x[0], 2.0);
  EXPECT_DOUBLE_EQ(s.spheres()[0].v[1], 2.0);
  s.set_time(1.5);
  EXPECT_DOUBLE_EQ(s.spheres()[0].v[0], 0.0);
  EXPECT_THROW(s.set_path_table_text("t,id,x,y,z\n0,2,0,0,0\n"), std::runtime_error);
}

TEST(calibration_SphereSet, ForceCsvHasOneLinePerSphere) {
  auto s = SphereSet::from_text("id,x,y,z,d\n1,0,0,0,1\n2,1,0,0,1\n");
  s.spheres()[1].force = {1.5, 0, 0};
  std::ostringstream os;
  SphereSet::write_force_header(os);
  s.write_forces(os, 0.1);
  const std::string out = os.str();
  EXPECT_NE(out.find("t,id,x,y,z,vx,vy,vz,Fx,Fy,Fz,Tx,Ty,Tz"), std::string::npos);
  EXPECT_NE(out.find("0.1,2,1,0,0,0,0,0,1.5,0,0,0,0,0"), std::string::npos);
}

TEST(calibration_StabilityReport, ResolutionAndCouplingCriteria) {
  RunParameters p;
  p.d_min = 3e-6;
  p.h_sphere = 3e-6 / 8;
  p.u_ref = 0.05;
  p.dt = 1e-6;
  p.nu = 1e-6;
  p.rho_f = 1000;
  p.rho_p = 1170;
  p.dt_dem = 1e-9;
  p.coupling_interval = 10;
  p.v_particle = 0.05;
  auto r = make_report(p);
  EXPECT_NEAR(r.cells_per_diameter, 8.0, 1e-12);
  EXPECT_NEAR(r.courant, 0.05 * 1e-6 / (3e-6 / 8), 1e-12);
  // tau_p = rho_p d^2 / (18 mu) = 1170 * 9e-12 / 18e-3 = 5.85e-7 s
  EXPECT_NEAR(r.tau_p, 5.85e-7, 1e-12);
  EXPECT_NEAR(r.solid_fluid_ratio, 1e-8 / 5.85e-7, 1e-9);
  EXPECT_TRUE(r.errors.empty());

  p.coupling_interval = 2000;  // dt_c = 2e-6 s > 2 tau_p
  r = make_report(p);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_NE(r.errors[0].find("solid-fluid"), std::string::npos);

  // explicit-coupling gain G = dt_c/tau_p + (1/2 + (1 + h/d)^3 - 1) rho_f/rho_p
  p.coupling_interval = 10;
  p.coupled = true;
  r = make_report(p);
  const double shell = std::pow(1.0 + 1.0 / 8.0, 3) - 1.0;
  EXPECT_NEAR(r.amplification, 1e-8 / 5.85e-7 + (0.5 + shell) * 1000.0 / 1170.0, 1e-9);
  EXPECT_TRUE(r.errors.empty());  // G = 0.85: warning only
  EXPECT_FALSE(r.warnings.empty());
  p.h_sphere = 3e-6 / 4.8;        // coarser: G >= 1 -> error
  p.min_cells_per_diameter = 4.0;
  r = make_report(p);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_NE(r.errors[0].find("explicit coupling unstable"), std::string::npos);
  p.coupled = false;
  p.min_cells_per_diameter = 6.0;

  p.h_sphere = 3e-6 / 3;  // 3 cells per diameter < 6
  r = make_report(p);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_NE(r.errors[0].find("too coarse"), std::string::npos);
}
