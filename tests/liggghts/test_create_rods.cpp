// create_rods: a suspension seeded in the paper's pore scene (Table 1 lower
// half) lands whole, at the gap mid-plane, every sphere in the fluid clear of
// the side walls and pore cylinders, no two rods closer than min_gap sphere
// to sphere (checked on the atoms LIGGGHTS holds, independently of the
// seeding's capsule test), and the same seed gives the same atoms; fix
// rod/implicit then runs (it refuses overlapping rods).
#include "liggghts_session.h"

#include "fix_hele_shaw_drag.h"
#include "hydro/rod_hydrodynamics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

constexpr double kD = 3e-6, kGap = 0.3e-6;  // sphere diameter, min_gap [m]

std::vector<std::string> pore_suspension(int rods, const std::string &layout, const std::string &processors) {
  return {"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
          "newton off", "processors " + processors, "communicate single cutoff 1e-5 vel yes",
          "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
          "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 "
          "viscosity 1e-3 mean_velocity 0.03 model local",
          "create_rods " + std::to_string(rods) + " drag drag spheres 10 diameter 3e-6 type 1 density 1170 layout " +
              layout + " seed 7 min_gap " + hsrod_test::num(kGap)};
}

}  // namespace

TEST(CreateRods, SuspensionInThePoreSceneIsWholeClearOfWallsAndOfEachOther) {
  hsrod_test::LiggghtsSession s;
  s.commands(pore_suspension(120, "random", "1 1 1"));
  ASSERT_EQ(s.natoms(), 1200);
  const auto x = s.gather("x");
  auto *drag = dynamic_cast<LAMMPS_NS::FixHeleShawDrag *>(s.fix("drag"));
  ASSERT_NE(drag, nullptr);
  const hsrod::ChannelGeometry &g = drag->hydrodynamics().geometry();
  double wall_gap = 1e300, rod_gap = 1e300;
  for (int i = 0; i < 1200; ++i) {
    EXPECT_NEAR(x[i].z(), 10e-6, 1e-15) << "sphere " << i << " off the mid-plane";
    wall_gap = std::min(wall_gap, g.signed_distance(x[i].x(), x[i].y()) - 0.5 * kD);
    for (int j = (i / 10 + 1) * 10; j < 1200; ++j) rod_gap = std::min(rod_gap, (x[i] - x[j]).norm() - kD);
  }
  EXPECT_GE(wall_gap, kGap * (1 - 1e-9));
  EXPECT_GE(rod_gap, kGap * (1 - 1e-9));
  // Within a rod the spheres touch (spacing d): each rod is one straight chain.
  for (int r = 0; r < 120; ++r)
    for (int k = 1; k < 10; ++k) EXPECT_NEAR((x[10 * r + k] - x[10 * r + k - 1]).norm(), kD, 1e-12);
  s.commands({"fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3",
              "fix step all rod/implicit bonds bonds drag drag", "timestep 2e-6", "run 5"});
  EXPECT_EQ(s.natoms(), 1200);
}

TEST(CreateRods, LatticeAndSeedAreReproducible) {
  hsrod_test::LiggghtsSession a, b;
  a.commands(pore_suspension(60, "lattice", "1 1 1"));
  b.commands(pore_suspension(60, "lattice", "1 1 1"));
  ASSERT_EQ(a.natoms(), 600);
  const auto xa = a.gather("x"), xb = b.gather("x");
  for (int i = 0; i < 600; ++i) EXPECT_EQ(xa[i], xb[i]);
}
