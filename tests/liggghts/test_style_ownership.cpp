// fix rod/implicit and its two partner fixes: the
// integrator names fix rod/bonds and fix hele_shaw/drag by ID, and each
// partner decides at its own init() whether an integrator takes over its
// work (liggghts-package/src/implicit_partners.h). Checked here by what a
// script sees: the drag's global force follows the implicit steps, and an
// unfixed integrator hands the drag back to the explicit path.
#include "liggghts_session.h"

#include "fix_hele_shaw_drag.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using hsrod_test::LiggghtsSession;

namespace {

constexpr int kSpheres = 10;

// A 10-sphere rod in a straight channel (closed-form flow, no grid solve),
// mid-gap, far from the side walls.
void start_rod(LiggghtsSession &s) {
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
              "boundary f f f", "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 150e-6 100e-6 10e-6 angle 10",
              "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1",
              "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 viscosity 1e-3 "
              "fluid_density 1170 reynolds 2 model local"});
}

Eigen::Vector3d drag_total(LiggghtsSession &s) {
  LAMMPS_NS::Fix *drag = s.fix("drag");
  return Eigen::Vector3d(drag->compute_vector(0), drag->compute_vector(1), drag->compute_vector(2));
}

}  // namespace

// Overdamped motion balances the forces: the hydrodynamic force on the rod
// is minus the applied force (bond forces are internal), at every step.
// The drag fix's global total must follow a change of the applied force
// (it was summed once and then kept: the second value was the first one's).
TEST(ImplicitPartners, DragTotalFollowsTheImplicitSteps) {
  LiggghtsSession s;
  start_rod(s);
  s.commands({"fix step all rod/implicit bonds bonds drag drag", "timestep 4e-6",
              "fix push all addforce 1e-12 0 0", "run 10"});
  const Eigen::Vector3d first = drag_total(s);
  EXPECT_NEAR(first.x(), -kSpheres * 1e-12, 1e-6 * kSpheres * 1e-12);
  EXPECT_NEAR(first.y(), 0.0, 1e-6 * kSpheres * 1e-12);
  s.commands({"unfix push", "fix push all addforce 0 3e-12 0", "run 10"});
  const Eigen::Vector3d second = drag_total(s);
  EXPECT_NEAR(second.x(), 0.0, 1e-6 * kSpheres * 3e-12);
  EXPECT_NEAR(second.y(), -kSpheres * 3e-12, 1e-6 * kSpheres * 3e-12);
}

// After `unfix` of the integrator the drag fix applies its force again: a
// rod held at rest in the stream is pushed downstream, and the atoms'
// total force (bond forces cancel) is the drag fix's total.
TEST(ImplicitPartners, UnfixedIntegratorHandsTheDragBack) {
  LiggghtsSession s;
  start_rod(s);
  s.commands({"fix step all rod/implicit bonds bonds drag drag", "timestep 4e-6", "run 5"});
  s.commands({"unfix step", "velocity all set 0 0 0", "fix move all nve/sphere", "timestep 1e-9", "run 1"});
  const auto *drag = dynamic_cast<LAMMPS_NS::FixHeleShawDrag *>(s.fix("drag"));
  ASSERT_NE(drag, nullptr);
  EXPECT_FALSE(drag->applied_by_integrator());
  Eigen::Vector3d forces = Eigen::Vector3d::Zero();
  for (const auto &f : s.gather("f")) forces += f;
  const Eigen::Vector3d total = drag_total(s);
  std::printf("held rod after unfix: sum of atom forces %.4g %.4g %.4g N, drag total %.4g %.4g %.4g N\n", forces.x(),
              forces.y(), forces.z(), total.x(), total.y(), total.z());
  // The driving of a rod at (nearly) rest in a ~5 cm/s stream: ~zeta U ~ 1e-9 N per sphere.
  EXPECT_GT(total.x(), 1e-10 * kSpheres);
  EXPECT_NEAR(forces.x(), total.x(), 1e-9 * std::abs(total.x()));
  EXPECT_NEAR(forces.y(), total.y(), 1e-9 * std::abs(total.x()));
}

// Under fix rod/implicit, fix rod/bonds' energy and largest strain
// (f_bonds[1], f_bonds[2]) must not read 0: a 19 % transient strain would go
// unseen. After a soft rod bent in the flow for 60 implicit steps, both must
// equal what the explicit path computes from the same positions and
// orientations (a zero-step run after the integrator is unfixed).
TEST(ImplicitPartners, BondEnergyAndStrainReportedUnderTheImplicitStep) {
  LiggghtsSession s;
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
              "boundary f f f", "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 150e-6 100e-6 10e-6 angle 0",
              "fix bonds all rod/bonds youngs_modulus 15e3 poisson_ratio 0.3",
              "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 viscosity 1e-3 "
              "fluid_density 1170 reynolds 2 model nonlocal",
              "fix step all rod/implicit bonds bonds drag drag", "timestep 4e-6", "run 60"});
  LAMMPS_NS::Fix *bonds = s.fix("bonds");
  const double implicit_energy = bonds->compute_vector(0), implicit_strain = bonds->compute_vector(1);
  s.commands({"unfix step", "fix nve all nve/sphere", "timestep 1e-8", "run 0 post no"});
  const double explicit_energy = bonds->compute_vector(0), explicit_strain = bonds->compute_vector(1);
  std::printf("bond energy %.6g J (explicit path %.6g J), largest strain %.6g (%.6g)\n", implicit_energy,
              explicit_energy, implicit_strain, explicit_strain);
  ASSERT_GT(explicit_energy, 0.0);
  ASSERT_GT(explicit_strain, 1e-8);  // the rod did deform (C shape of level 3)
  EXPECT_NEAR(implicit_energy, explicit_energy, 1e-9 * explicit_energy);
  EXPECT_NEAR(implicit_strain, explicit_strain, 1e-9 * explicit_strain);
  EXPECT_NEAR(bonds->compute_scalar(), explicit_energy, 1e-9 * explicit_energy);
}
