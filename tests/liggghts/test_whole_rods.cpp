// Whole-rod accounting of fix rod/implicit: a rod that
// reaches the outlet is held there whole instead of LIGGGHTS dropping its
// spheres one by one as they leave the box (with LIGGGHTS' default
// `thermo_modify lost ignore` a partial rod would go on; measures would then
// read a fragment).
#include "liggghts_session.h"

#include "atom.h"

#include <gtest/gtest.h>

#include <algorithm>

using hsrod_test::LiggghtsSession;

TEST(WholeRods, RodReachingTheOutletIsHeldThereWhole) {
  LiggghtsSession s;
  // Straight channel 600 um long (closed-form flow at Re = 2; the rod
  // drifts at ~1.3 cm/s, ~0.05 um per step of 4 us): the rod's front sphere
  // is 6.5 um before the outlet, ~130 steps.
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
              "boundary f f f", "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 580e-6 100e-6 10e-6 angle 0",
              "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1",
              "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 viscosity 1e-3 "
              "fluid_density 1170 reynolds 2 model local",
              "fix step all rod/implicit bonds bonds drag drag", "timestep 4e-6", "run 300"});
  ASSERT_EQ(s.natoms(), 10);
  const auto held = s.gather("x");
  double front = 0.0;
  for (const auto &x : held) front = std::max(front, x.x());
  std::printf("front sphere at x = %.4g um (box end 600 um)\n", front * 1e6);
  EXPECT_LE(front, 600e-6);
  EXPECT_GT(front, 600e-6 - 3e-6);  // it got there: within one diameter of the end
  EXPECT_EQ(s.fix("step")->compute_vector(7), 1.0);
  s.command("run 20");
  const auto later = s.gather("x");
  ASSERT_EQ(s.natoms(), 10);
  for (size_t i = 0; i < later.size(); i++) EXPECT_EQ((later[i] - held[i]).norm(), 0.0);
}

// The rod is held where its front centre reaches the outlet, whatever the
// step: with steps of 4 us (0.05 um each) and of 400 us (~5 um, beyond the
// last whole step by up to that) the front sphere ends on the face (1e-9
// of the box inside it), and the two held rods agree to well below a step's motion.
TEST(WholeRods, HeldRodEndsAtTheFaceIndependentOfTheStep) {
  std::vector<std::vector<Eigen::Vector3d>> held;
  for (const char *dt : {"4e-6", "4e-4"}) {
    LiggghtsSession s;
    s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
                "boundary f f f", "newton off", "communicate single cutoff 1e-5 vel yes",
                "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
                "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 580e-6 100e-6 10e-6 angle 0",
                "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1",
                "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 viscosity 1e-3 "
                "fluid_density 1170 reynolds 2 model local",
                "fix step all rod/implicit bonds bonds drag drag", std::string("timestep ") + dt,
                std::string("run ") + (dt[3] == '6' ? "300" : "3")});
    ASSERT_EQ(s.natoms(), 10);
    EXPECT_EQ(s.fix("step")->compute_vector(7), 1.0);
    held.push_back(s.gather("x"));
    double front = 0.0;
    for (const auto &x : held.back()) front = std::max(front, x.x());
    std::printf("dt %s s: front sphere at x = %.9g um (box end 600 um)\n", dt, front * 1e6);
    EXPECT_NEAR(front, 600e-6, 1e-12);  // 1e-9 of the box inside the face
    EXPECT_LT(front, 600e-6);
  }
  double largest = 0.0;
  for (size_t i = 0; i < held[0].size(); i++) largest = std::max(largest, (held[0][i] - held[1][i]).norm());
  std::printf("held rods at the two steps differ by at most %.3g um\n", largest * 1e6);
  EXPECT_LT(largest, 0.05e-6);  // below one small step's motion
}
