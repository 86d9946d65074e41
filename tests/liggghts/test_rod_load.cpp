// compute hele_shaw/rod_load through LIGGGHTS: for a rod moving rigidly
// (translation and rotation set on its spheres), the per-rod 3x3 resistance
// and held load give the force and torque that the drag fix applies to the
// spheres (its per-atom force output and the torques it adds), levels 2-4 in
// the pore scene; the free rigid velocity leaves the rod unloaded.
#include "liggghts_session.h"

#include "atom.h"
#include "compute.h"

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

using hsrod_test::LiggghtsSession;
using hsrod_test::num;

namespace {

struct Load {
  double fx, fy, tz;
};

// Sets the rigid motion (V_x, V_y, Omega) about the rod's centroid on every
// sphere (serial test: all atoms are local) and returns the centroid.
Eigen::Vector2d set_rigid_motion(LiggghtsSession &s, double vx, double vy, double omega) {
  LAMMPS_NS::Atom *atom = s.lammps()->atom;
  Eigen::Vector2d c(0, 0);
  for (int i = 0; i < atom->nlocal; i++) c += Eigen::Vector2d(atom->x[i][0], atom->x[i][1]) / atom->nlocal;
  for (int i = 0; i < atom->nlocal; i++) {
    atom->v[i][0] = vx - omega * (atom->x[i][1] - c.y());
    atom->v[i][1] = vy + omega * (atom->x[i][0] - c.x());
    atom->v[i][2] = 0.0;
    atom->omega[i][0] = atom->omega[i][1] = 0.0;
    atom->omega[i][2] = omega;
  }
  return c;
}

// What the drag fix applied: sum of its per-atom forces, and the z-torque
// about c of those forces plus the torques it added to the spheres.
Load applied(LiggghtsSession &s, const Eigen::Vector2d &c) {
  LAMMPS_NS::Atom *atom = s.lammps()->atom;
  double **f = s.fix("drag")->array_atom;
  Load l{0, 0, 0};
  for (int i = 0; i < atom->nlocal; i++) {
    l.fx += f[i][0];
    l.fy += f[i][1];
    l.tz += (atom->x[i][0] - c.x()) * f[i][1] - (atom->x[i][1] - c.y()) * f[i][0] + atom->torque[i][2];
  }
  return l;
}

}  // namespace

TEST(RodLoad, RigidResistanceReproducesPerSphereLoadsOfTheDragFix) {
  for (const std::string model : {"local", "nonlocal", "twoway"}) {
    setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
    LiggghtsSession s;
    s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
                "boundary f f f", "newton off", "communicate single cutoff 1e-5 vel yes",
                "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
                "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 240e-6 108e-6 10e-6 angle 30",
                "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 "
                "viscosity 1e-3 fluid_density 1170 reynolds 2 timestep_check no model " + model,
                "compute load all hele_shaw/rod_load drag", "thermo_style custom step c_load[1][4] c_load[1][16]",
                "timestep 1e-9"});
    const double vx = 0.02, vy = -0.004, omega = 900.0;  // m/s, m/s, 1/s
    const Eigen::Vector2d c = set_rigid_motion(s, vx, vy, omega);
    s.command("run 0");  // the drag fix applies its load in setup (explicit use)
    const Load sphere = applied(s, c);
    auto *modify = s.lammps()->modify;
    LAMMPS_NS::Compute *comp = modify->compute[modify->find_compute("load")];
    comp->compute_array();
    const double *r = comp->array[0];
    // Columns (0-based): 1-2 centre, 3-5 load now, 6-11 R (xx xy xw yy yw ww), 12-14 held, 15-17 free.
    const double rigid_fx = r[12] - (r[6] * vx + r[7] * vy + r[8] * omega);
    const double rigid_fy = r[13] - (r[7] * vx + r[9] * vy + r[10] * omega);
    const double rigid_tz = r[14] - (r[8] * vx + r[10] * vy + r[11] * omega);
    const double f_scale = std::hypot(r[12], r[13]), t_scale = f_scale * 30e-6;
    std::printf("%s: rod load (%.5g, %.5g) N, %.5g N m; from R and held load (%.5g, %.5g) N, %.5g N m; "
                "free velocity (%.4g, %.4g) m/s, %.4g 1/s, drift %.2f deg, speed ratio %.3f\n",
                model.c_str(), sphere.fx, sphere.fy, sphere.tz, rigid_fx, rigid_fy, rigid_tz, r[15], r[16], r[17],
                r[18], r[19]);
    EXPECT_NEAR(r[1], c.x(), 1e-15);
    EXPECT_NEAR(rigid_fx, sphere.fx, 1e-9 * f_scale) << model;
    EXPECT_NEAR(rigid_fy, sphere.fy, 1e-9 * f_scale) << model;
    EXPECT_NEAR(rigid_tz, sphere.tz, 1e-9 * t_scale) << model;
    EXPECT_NEAR(r[3], sphere.fx, 1e-9 * f_scale) << model;  // the compute's own "load now" columns
    EXPECT_NEAR(r[4], sphere.fy, 1e-9 * f_scale) << model;
    EXPECT_NEAR(r[5], sphere.tz, 1e-9 * t_scale) << model;
    // The motion is not the free one: the rod is loaded (> 10 % of the held load).
    EXPECT_GT(std::hypot(sphere.fx, sphere.fy), 0.1 * f_scale) << model;
    // Resistance: symmetric positive definite.
    Eigen::Matrix3d R;
    R << r[6], r[7], r[8], r[7], r[9], r[10], r[8], r[10], r[11];
    EXPECT_GT(R.ldlt().vectorD().minCoeff(), 0.0) << model;
  }
}

// The drag fix's per-atom loads split: columns 1-3 total, 4-6 driving, 7-9
// friction (-R v), 10-12 torque. Explicit use with a rigid motion: friction +
// driving = total per sphere; summed over the rod, driving is the held load
// and friction is -R_rigid q of compute hele_shaw/rod_load (an independent
// reduction of the model's R); the torque column is what the fix added to
// the spheres. Implicit use (fix rod/implicit): the split of the step's load
// adds up too, and the friction dissipates (sum F_fric . v = -v R v < 0).
TEST(LoadsSplit, FrictionPlusDrivingIsTotalAndFrictionIsResistanceTimesVelocity) {
  setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
  const std::vector<std::string> scene = {
      "units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
      "newton off", "communicate single cutoff 1e-5 vel yes", "region box block 0 600e-6 0 200e-6 0 20e-6 units box",
      "create_box 1 box", "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 240e-6 108e-6 10e-6 angle 30"};
  const std::string drag = "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 "
                           "viscosity 1e-3 fluid_density 1170 reynolds 2 model nonlocal";
  {
    LiggghtsSession s;
    s.commands(scene);
    s.commands({drag + " timestep_check no", "compute load all hele_shaw/rod_load drag", "timestep 1e-9"});
    const double vx = 0.02, vy = -0.004, omega = 900.0;
    set_rigid_motion(s, vx, vy, omega);
    s.command("run 0");
    LAMMPS_NS::Atom *atom = s.lammps()->atom;
    double **f = s.fix("drag")->array_atom;
    ASSERT_EQ(s.fix("drag")->size_peratom_cols, 12);
    double driving[2] = {0, 0}, friction[2] = {0, 0}, scale = 0.0;
    for (int i = 0; i < atom->nlocal; i++) {
      for (int a = 0; a < 3; a++) {
        scale = std::max(scale, std::fabs(f[i][a]));
        EXPECT_NEAR(f[i][3 + a] + f[i][6 + a], f[i][a], 1e-12 * std::fabs(f[i][3 + a])) << "atom " << i;
        EXPECT_EQ(f[i][9 + a], atom->torque[i][a]);  // only the drag fix adds torques here
      }
      for (int a = 0; a < 2; a++) {
        driving[a] += f[i][3 + a];
        friction[a] += f[i][6 + a];
      }
    }
    auto *modify = s.lammps()->modify;
    LAMMPS_NS::Compute *comp = modify->compute[modify->find_compute("load")];
    comp->compute_array();
    const double *r = comp->array[0];
    const double fric_x = -(r[6] * vx + r[7] * vy + r[8] * omega), fric_y = -(r[7] * vx + r[9] * vy + r[10] * omega);
    const double f_scale = std::hypot(r[12], r[13]);
    std::printf("explicit: driving (%.6g, %.6g) N vs held load (%.6g, %.6g) N; friction (%.6g, %.6g) N vs -R q "
                "(%.6g, %.6g) N\n", driving[0], driving[1], r[12], r[13], friction[0], friction[1], fric_x, fric_y);
    EXPECT_NEAR(driving[0], r[12], 1e-9 * f_scale);
    EXPECT_NEAR(driving[1], r[13], 1e-9 * f_scale);
    EXPECT_NEAR(friction[0], fric_x, 1e-9 * f_scale);
    EXPECT_NEAR(friction[1], fric_y, 1e-9 * f_scale);
    EXPECT_GT(std::hypot(friction[0], friction[1]), 0.1 * f_scale);  // a real friction, not a round-off
  }
  {
    LiggghtsSession s;
    s.commands(scene);
    s.commands({"fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1", drag,
                "fix step all rod/implicit bonds bonds drag drag", "timestep 2e-6", "run 5"});
    LAMMPS_NS::Atom *atom = s.lammps()->atom;
    double **f = s.fix("drag")->array_atom;
    double dissipation = 0.0, driving_power = 0.0;
    for (int i = 0; i < atom->nlocal; i++) {
      for (int a = 0; a < 3; a++) {
        EXPECT_NEAR(f[i][3 + a] + f[i][6 + a], f[i][a], 1e-12 * std::fabs(f[i][3 + a]) + 1e-25) << "atom " << i;
        dissipation += f[i][6 + a] * atom->v[i][a];
        driving_power += f[i][3 + a] * atom->v[i][a];
      }
    }
    std::printf("implicit: friction power %.4g W, driving power %.4g W\n", dissipation, driving_power);
    EXPECT_LT(dissipation, 0.0);     // -v R v, R positive definite
    EXPECT_GT(driving_power, 0.0);   // the flow drives the rod forwards
  }
}
