// The reduced model through LIGGGHTS on the paper's pore scene: the stiff
// rod (E = 15 MPa) runs stably with an implicit step far above the explicit
// limit and agrees with a 10x smaller step; level 4 passes the pore close to
// level 3; the soft rod deflects most at the outlet; the paper's outcome
// classes.
#include "liggghts_session.h"

#include "compute.h"
#include "fix_rod_bonds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

using hsrod_test::LiggghtsSession;
using hsrod_test::num;

namespace {


struct RodState {
  double x, angle, lateral, deflection, explicit_limit;
};

RodState measure(LiggghtsSession &s) {
  auto *modify = s.lammps()->modify;
  auto *c = modify->compute[modify->find_compute("shape")];
  c->compute_array();
  const double *row = c->array[0];
  auto *bonds = dynamic_cast<LAMMPS_NS::FixRodBonds *>(s.fix("bonds"));
  return {row[1], row[6], row[8], row[7], bonds->explicit_bond_limit()};
}

// Runs the pore scene; with `chunk` > 0, samples the rod every `chunk`
// steps and returns, in `peak`, the state of largest deflection.
RodState run_pore(const std::string &modulus, double dt, double duration, int chunk = 0, RodState *peak = nullptr,
                  const std::string &model = "auto") {
  setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
  LiggghtsSession s;
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
              "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 150e-6 100e-6 10e-6 angle 10",
              "fix bonds all rod/bonds youngs_modulus " + modulus + " poisson_ratio 0.3 damping 0.1",
              "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 "
              "viscosity 1e-3 fluid_density 1170 reynolds 2 model " + model,
              "fix step all rod/implicit bonds bonds drag drag",
              "compute shape all rod/shape channel_width 200e-6 channel_centre 100e-6", "timestep " + num(dt)});
  const long steps = std::lround(duration / dt);
  if (chunk <= 0) {
    s.command("run " + std::to_string(steps));
    return measure(s);
  }
  for (long done = 0; done < steps; done += chunk) {
    s.command("run " + std::to_string(chunk) + " pre no post no");
    const RodState now = measure(s);
    if (now.deflection > peak->deflection) *peak = now;
  }
  return measure(s);
}

}  // namespace

TEST(PoreScene, StiffRodStableFarAboveExplicitLimitAndConvergedInDt) {
  const double duration = 4.4e-3;  // the rod passes the pore and leaves it
  const RodState coarse = run_pore("15e6", 4e-6, duration);
  const RodState fine = run_pore("15e6", 4e-7, duration);
  const double d = 3e-6;
  std::printf("stiff rod through the pore, dt = 4e-6 s (%.0f x explicit limit %.3g s) vs 4e-7 s:\n"
              "  x %.6g vs %.6g m (diff %.3g d), angle %.3f vs %.3f deg, lateral %.5f vs %.5f W\n",
              4e-6 / coarse.explicit_limit, coarse.explicit_limit, coarse.x, fine.x, std::fabs(coarse.x - fine.x) / d,
              coarse.angle, fine.angle, coarse.lateral, fine.lateral);
  EXPECT_GT(4e-6 / coarse.explicit_limit, 100.0);
  EXPECT_GT(coarse.x, 450e-6);  // it went through the pore
  // Tolerances: the passage displaces the rod by ~370 um (120 d) and turns it
  // by ~70 deg and back; first-order time stepping with 10x dt agrees to:
  EXPECT_LT(std::fabs(coarse.x - fine.x), 0.05 * d);
  EXPECT_LT(std::fabs(coarse.angle - fine.angle), 1.0);
  EXPECT_LT(std::fabs(coarse.lateral - fine.lateral), 0.002);
  EXPECT_LT(coarse.deflection, 1e-3);  // the stiff rod does not bend
}

TEST(PoreScene, TwoWayLevelPassesThePoreCloseToLevel3) {
  // Level 4 adds the reflection of the rod's disturbance by the pore walls
  // (about 5 % more resistance within 3 screening lengths of a wall,
  // tests/drag-models/hydro) to level 3's interactions; over the passage
  // (120 d) it may lag level 3 by a fraction of a diameter and turn it by a
  // degree or two, not more.
  const double d = 3e-6, duration = 4.4e-3;
  // window_cells 2, the screening setting (2.8 s instead of 23 s here; it
  // moves x by 0.11 d against the default 4 cells per diameter).
  const RodState twoway = run_pore("15e6", 4e-6, duration, 0, nullptr, "twoway window_cells 2");
  const RodState nonlocal = run_pore("15e6", 4e-6, duration, 0, nullptr, "nonlocal");
  std::printf("pore passage level 4 vs level 3: x %.6g vs %.6g m (diff %.3g d), angle %.3f vs %.3f deg, "
              "lateral %.5f vs %.5f W\n", twoway.x, nonlocal.x, std::fabs(twoway.x - nonlocal.x) / d, twoway.angle,
              nonlocal.angle, twoway.lateral, nonlocal.lateral);
  EXPECT_GT(twoway.x, 450e-6);  // through the pore
  EXPECT_LT(std::fabs(twoway.x - nonlocal.x), 1.0 * d);
  EXPECT_LT(std::fabs(twoway.angle - nonlocal.angle), 2.0);
  // No bound on the lateral position between the two levels: since levels 3
  // and 4 have near fields of their own, each fitted to the resolved rods,
  // they end 0.0055 W apart here, and which is right is a
  // question for the resolved pore passage, not for one level against the
  // other: calibration/validation/pore_passage (and the disabled test
  // pore_passage_default_level_vs_resolved) records each level's lateral
  // position after the pore against the coupled rodIbFoam run.
}

TEST(PoreScene, SoftRodDeflectsMostAtThePoreOutlet) {
  // Braesel et al. 2024, Sec. 3.3.1: "During inflow, the rod deflects only
  // slightly, while a stronger deflection occurs during the outflow of the pore."
  RodState peak{0, 0, 0, 0, 0};
  run_pore("15e3", 4e-6, 4.4e-3, 10, &peak);
  std::printf("soft rod: largest deflection %.4f at x = %.4g m (pore centre 300 um)\n", peak.deflection, peak.x);
  EXPECT_GT(peak.deflection, 0.05);
  EXPECT_GT(peak.x, 300e-6);
  EXPECT_LT(peak.x, 420e-6);
}

namespace {
// Outcome class (compute rod/shape column 14) after `duration` for a rod of
// n spheres and Young's modulus E at angle alpha through the pore.
double pore_outcome(int n, double alpha_deg, double duration, const std::string &youngs_modulus = "15e6") {
  setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
  LiggghtsSession s;
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
              "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres " + std::to_string(n) + " diameter 3e-6 type 1 density 1170 centre 150e-6 100e-6 "
              "10e-6 angle " + num(alpha_deg),
              "fix bonds all rod/bonds youngs_modulus " + youngs_modulus + " poisson_ratio 0.3",
              "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 "
              "viscosity 1e-3 fluid_density 1170 reynolds 2 model local",
              "fix step all rod/implicit bonds bonds drag drag",
              "compute shape all rod/shape channel_width 200e-6 channel_centre 100e-6 mean_velocity 0.0295 "
              "contacts step pass_x 400e-6",
              "timestep 2e-6", "run " + std::to_string(std::lround(duration / 2e-6))});
  auto *modify = s.lammps()->modify;
  auto *c = modify->compute[modify->find_compute("shape")];
  c->compute_array();
  return c->array[0][13];
}
}  // namespace

TEST(PoreScene, OutcomeClassesOfThePaper) {
  // Braesel et al. 2024, Sec. 3.5: passage without wall contact, passage
  // with wall contact, clogging (at large size ratio and stiffness). A rod
  // as long as the pore is wide (L_Rod/d_pore = 1, alpha = 10 deg) passes
  // without touching; a stiff (15 MPa) rod three times the pore width across
  // the flow is trapped, as the paper's Fig. 10(c) shows for 15 MPa rods
  // already at L_Rod/d_pore = 2 (this case passed with contact with the
  // level-2 columns derived from level 3, whose load across a rod was ~45 %
  // above the resolved runs; the calibrated table traps it); the
  // same rod at 1.5 MPa bends against the cylinders and escapes: contact passage.
  EXPECT_EQ(pore_outcome(10, 10.0, 5e-3), 1.0);
  EXPECT_EQ(pore_outcome(30, 0.0, 7e-3), 3.0);
  EXPECT_EQ(pore_outcome(30, 0.0, 5e-3, "1.5e6"), 2.0);
}
