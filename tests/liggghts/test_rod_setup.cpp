// Making rods (create_rod, read_data, 2x2 sections), keeping bonded
// neighbours out of Hertz contacts, and the rod measures of compute
// rod/shape, all through LIGGGHTS.
#include "common/math_constants.h"
#include "liggghts_session.h"

#include "compute.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using hsrod_test::LiggghtsSession;
using hsrod_test::num;

namespace {

using hsrod::kPi;


const std::vector<std::string> kSetup = {"units si", "atom_style hybrid granular molecular",
                                         "atom_modify map array sort 0 0", "boundary f f f", "newton off",
                                         "communicate single cutoff 1e-5 vel yes"};

std::vector<Eigen::Vector3d> run_wiggle(LiggghtsSession &s) {
  s.commands({"group ends id 1 10", "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1",
              "fix integrate all nve/sphere", "velocity ends set 0.01 0.02 -0.01", "timestep 1e-8", "run 2000"});
  return s.gather("x");
}

double *rod_row(LiggghtsSession &s, const char *id, int row) {
  auto *modify = s.lammps()->modify;
  LAMMPS_NS::Compute *c = modify->compute[modify->find_compute(id)];
  c->compute_array();
  return c->array[row];
}

// Compressive stiffness of a 5-sphere rod clamped at sphere 1, with Hertz
// pair contacts on; exclude_pairs yes/no.
double compressive_stiffness_ratio(const std::string &exclude) {
  LiggghtsSession s;
  s.commands(hsrod_test::rod_box_header(1e-4));
  s.commands({"pair_style gran model hertz tangential history", "pair_coeff * *",
              "fix m1 all property/global youngsModulus peratomtype 15e6",
              "fix m2 all property/global poissonsRatio peratomtype 0.3",
              "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.6",
              "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5",
              "neighbor 1e-6 bin",
              "create_rod spheres 5 diameter 3e-6 type 1 density 1170 centre 0 0 0 angle 90",
              "group clamp id 1", "group free subtract all clamp", "group tip id 5",
              "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.3 exclude_pairs " + exclude,
              "fix integrate free nve/sphere", "fix settle free viscous 3e-9",
              // Only axial motion: at 1 % strain the free rod would buckle (P_cr = pi^2 EI / 4L^2).
              "fix axial free setforce NULL 0 0", "timestep 1e-8"});
  const double ea = 15e6 * kPi * 9e-12 / 4;
  const double push = 0.01 * ea;  // 1 % compressive strain [N]
  // create_rod puts sphere 1 at +x: pushing the tip towards +x compresses the rod.
  s.command("fix load tip addforce " + num(push) + " 0 0");
  s.command("run 20000");
  const auto x = s.gather("x");
  const double shortening = 4 * 3e-6 - (x[0] - x[4]).norm();
  return (push * 4 * 3e-6 / shortening) / ea;
}

}  // namespace

TEST(RodSetup, ReadDataRodMatchesCreateRod) {
  LiggghtsSession made;
  made.commands(kSetup);
  made.commands({"region box block -1e-4 1e-4 -1e-4 1e-4 -1e-4 1e-4 units box", "create_box 1 box",
                 "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 0 0 0 angle 90"});
  const auto expected = run_wiggle(made);

  LiggghtsSession read;
  read.commands(kSetup);
  read.command(std::string("read_data ") + HSROD_TEST_DATA_DIR + "/data/rod10.data");
  const auto got = run_wiggle(read);
  ASSERT_EQ(got.size(), expected.size());
  double worst = 0.0;
  for (size_t i = 0; i < got.size(); i++) worst = std::max(worst, (got[i] - expected[i]).norm());
  std::printf("read_data vs create_rod: largest position difference %.3g m\n", worst);
  // The only input difference is create_rod's cos(90 deg) ~ 6e-17 in y.
  EXPECT_LT(worst, 1e-9 * 3e-6);
}

TEST(RodSetup, BondedNeighboursFeelNoHertzContact) {
  const double with_exclusion = compressive_stiffness_ratio("yes");
  const double without_exclusion = compressive_stiffness_ratio("no");
  std::printf("compressive stiffness / EA at 1 %% strain: %.5f excluded, %.5f with Hertz between neighbours\n",
              with_exclusion, without_exclusion);
  EXPECT_NEAR(with_exclusion, 1.0, 0.01);
  // Hertz between overlapping neighbours would stiffen the rod measurably.
  EXPECT_GT(without_exclusion, 1.02);
}

TEST(RodSetup, ComputeRodShapeMeasuresAngleAndDisplacement) {
  LiggghtsSession s;
  s.commands(kSetup);
  s.commands({"region box block 0 6e-4 0 2e-4 0 2e-5 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 1e-4 1e-4 1e-5 angle 10 offset 2e-5",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 3e-4 1e-4 1e-5 angle -45 section 1",
              "compute shape all rod/shape channel_width 2e-4 channel_centre 1e-4"});
  const double *rod1 = rod_row(s, "shape", 0);
  EXPECT_EQ(rod1[0], 1.0);
  EXPECT_NEAR(rod1[6], 10.0, 1e-9);
  EXPECT_NEAR(rod1[7], 0.0, 1e-12);
  EXPECT_NEAR(rod1[8], 0.1, 1e-12);  // offset 20 um over W = 200 um
  EXPECT_NEAR(rod1[1], 1e-4, 1e-15);
  EXPECT_EQ(rod1[10], 10.0);
  const double *rod2 = rod_row(s, "shape", 1);
  EXPECT_NEAR(rod2[6], -45.0, 1e-9);
}

TEST(RodSetup, TwoByTwoSectionRodHoldsTogether) {
  LiggghtsSession s;
  s.commands(kSetup);
  s.commands({"region box block -1e-4 1e-4 -1e-4 1e-4 -1e-4 1e-4 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 0 0 0 angle 30 section 2x2",
              "compute shape all rod/shape section 4",
              "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1",
              "fix integrate all nve/sphere", "group end id 1 2 3 4", "velocity end set 0 0.02 0",
              "timestep 5e-9", "run 4000"});
  EXPECT_EQ(s.natoms(), 40);
  const double strain = s.fix("bonds")->compute_vector(1);
  EXPECT_LT(strain, 0.01);
  const double *rod = rod_row(s, "shape", 0);
  EXPECT_EQ(rod[10], 40.0);
  // The kicked end has swung: angle changed, and is finite and sane.
  EXPECT_GT(std::fabs(rod[6] - 30.0), 0.01);
  EXPECT_LT(std::fabs(rod[6] - 30.0), 30.0);
}
