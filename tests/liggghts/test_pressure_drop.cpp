// compute hele_shaw/pressure_drop through LIGGGHTS: the background drop of
// the straight channel equals the closed form, the pore scene's equals the
// grid solution's inlet-outlet difference (read from the solved arrays), and a
// rod held across the pore entrance at level 4 raises it, far more than the
// same rod held in the wide channel upstream.
#include "liggghts_session.h"

#include "compute.h"
#include "fix_hele_shaw_drag.h"

#include "flow/grid_brinkman_flow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using hsrod_test::LiggghtsSession;
using hsrod_test::num;

namespace {

constexpr double L = 600e-6, W = 200e-6, H = 20e-6, mu = 1e-3;  // [m], [Pa s]

void scene(LiggghtsSession &s, const std::string &rod, const std::string &drag_keywords) {
  setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
              "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 " + rod,
              "fix drag all hele_shaw/drag viscosity 1e-3 fluid_density 1170 timestep_check no " + drag_keywords,
              "compute dp all hele_shaw/pressure_drop drag", "thermo_style custom step c_dp c_dp[2] c_dp[3]",
              "velocity all set 0 0 0", "timestep 1e-9", "run 0"});
}

const double *pressure_drop(LiggghtsSession &s) {
  auto *modify = s.lammps()->modify;
  auto *c = modify->compute[modify->find_compute("dp")];
  c->compute_vector();
  return c->vector;  // total, background, rods, Q
}

}  // namespace

TEST(PressureDrop, StraightChannelEqualsClosedForm) {
  const double U = 0.03;
  LiggghtsSession s;
  scene(s, "centre 150e-6 100e-6 10e-6", "mean_velocity " + num(U) + " model isotropic");
  const double *dp = pressure_drop(s);
  // Developed Brinkman channel: dp/dx = -k^2 mu U / (1 - tanh(a)/a), k = sqrt(12)/H, a = k W/2.
  const double k = std::sqrt(12.0) / H, a = k * W / 2;
  const double exact = k * k * mu * U / (1.0 - std::tanh(a) / a) * L;
  std::printf("straight channel: background drop %.10g Pa, closed form %.10g Pa\n", dp[1], exact);
  EXPECT_NEAR(dp[1], exact, 1e-9 * exact);  // p is linear in x: the flux weighting is exact
  EXPECT_NEAR(dp[3], U * W * H, 1e-15 * U * W * H);
}

TEST(PressureDrop, EmptyPoreSceneMatchesGridInletOutletDifference) {
  LiggghtsSession s;
  scene(s, "centre 150e-6 100e-6 10e-6", "channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 reynolds 2 model isotropic");
  auto *drag = dynamic_cast<LAMMPS_NS::FixHeleShawDrag *>(s.fix("drag"));
  const auto *grid = dynamic_cast<const hsrod::GridBrinkmanFlow *>(&drag->flow());
  ASSERT_NE(grid, nullptr);
  // The grid's inlet pressure per row, at the inlet face x = 0: linear through
  // the first two cell centres (1.5 p_0 - 0.5 p_1), weighted with the
  // imposed inlet velocities of the solve; p = 0 on the outlet.
  const hsrod::MacGrid &g = grid->field().grid();
  const hsrod::ExtendedLattice lat = hsrod::extended_u_lattice(g);
  const auto &p = grid->field().p_ext();  // column ii = i + 1
  const auto &u = grid->field().u_ext();
  double pu = 0.0, uu = 0.0;
  for (int j = 0; j < g.ny; j++) {
    const double p_inlet = 1.5 * p[1 * g.ny + j] - 0.5 * p[2 * g.ny + j];
    pu += p_inlet * u[lat.index(0, j)];
    uu += u[lat.index(0, j)];
  }
  const double U = grid->mean_velocity();
  const double grid_drop = pu / uu * mu * U / H;
  const double *dp = pressure_drop(s);
  // The same channel without the pore, closed form.
  const double k = std::sqrt(12.0) / H, a = k * W / 2;
  const double straight = k * k * mu * U / (1.0 - std::tanh(a) / a) * L;
  std::printf("pore scene: background drop %.8g Pa, grid inlet-outlet %.8g Pa (rel. diff %.2e); "
              "straight channel %.6g Pa, pore excess %.6g Pa\n",
              dp[1], grid_drop, dp[1] / grid_drop - 1.0, straight, dp[1] - straight);
  // Quadrature of the interpolated field vs the grid's node sum across a
  // nearly uniform inlet pressure (measured 1.1e-8).
  EXPECT_NEAR(dp[1] / grid_drop, 1.0, 1e-6);
  EXPECT_GT(dp[1], 1.5 * straight);  // the pore dominates the resistance of the channel
}

TEST(PressureDrop, RodHeldAcrossThePoreRaisesItAtLevel4) {
  const std::string pore = "channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 reynolds 2 model twoway";
  // Rod along y (angle 0, across the flow), held at rest: at the pore entrance
  // x = 270 um (open width 41 um for the 30 um rod) and upstream in the wide
  // channel at x = 100 um.
  double at_pore[4], upstream[4];
  {
    LiggghtsSession s;
    scene(s, "centre 270e-6 100e-6 10e-6 angle 0", pore);
    std::copy(pressure_drop(s), pressure_drop(s) + 4, at_pore);
  }
  {
    LiggghtsSession s;
    scene(s, "centre 100e-6 100e-6 10e-6 angle 0", pore);
    std::copy(pressure_drop(s), pressure_drop(s) + 4, upstream);
  }
  std::printf("level 4, rod held across the flow: background %.6g Pa; rise %.6g Pa at the pore entrance "
              "(%.3f %%), %.6g Pa upstream (%.4f %%), ratio %.1f\n",
              at_pore[1], at_pore[2], 100 * at_pore[2] / at_pore[1], upstream[2], 100 * upstream[2] / upstream[1],
              at_pore[2] / upstream[2]);
  EXPECT_EQ(at_pore[1], upstream[1]);  // same background
  EXPECT_GT(upstream[2], 0.0);         // a held rod always costs pressure
  EXPECT_NEAR(at_pore[0], at_pore[1] + at_pore[2], 1e-12 * at_pore[0]);
  // At the entrance the flow is ~4x faster than upstream and the held load
  // grows with it: the rise, F . u / Q, grows ~ u^2.
  EXPECT_GT(at_pore[2], 5.0 * upstream[2]);
}
