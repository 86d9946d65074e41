// Several rods in one scene through fix rod/implicit:
// rods pressed together by opposite forces stop at the Hertz overlap of
// the force (rod_contact hertz; Johnson 1985, eq. 4.22 for two equal
// spheres), rods far apart move bit for bit as each alone, a fast rod
// stops on a resting one it meets within a step, and rods that
// overlap without rod_contact are refused (bad-input test
// rods_overlap_no_pair).
#include "liggghts_session.h"

#include "fix_hele_shaw_drag.h"
#include "hydro/rod_hydrodynamics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr double kD = 3e-6, kLoad = 1e-9;  // sphere diameter [m], push per sphere [N]

// Two 10-sphere rods across the flow (along y) in a straight channel of the
// pore scene's size, 6.5 um apart in x, pushed towards each other by kLoad
// per sphere (fix addforce), level 2 (equal drag on both rods, so the
// contact carries exactly the push once they rest on each other).
std::vector<std::string> pressed_rods(const std::string &contact, const std::string &model,
                                      const std::string &processors = "1 1 1") {
  return {"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
          "newton off", "processors " + processors, "communicate single cutoff 1e-5 vel yes",
          "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
          "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 297e-6 100e-6 10e-6 angle 0",
          "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 303.5e-6 100e-6 10e-6 angle 0",
          "group a molecule 1", "group b molecule 2",
          "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3",
          "fix drag all hele_shaw/drag mean_velocity 0.03 model " + model,
          "fix push_a a addforce " + hsrod_test::num(kLoad) + " 0 0",
          "fix push_b b addforce " + hsrod_test::num(-kLoad) + " 0 0",
          "fix step all rod/implicit bonds bonds drag drag " + contact, "timestep 2e-6", "run 300"};
}

}  // namespace

TEST(SeveralRods, RodsPressedTogetherRestAtTheHertzOverlap) {
  hsrod_test::LiggghtsSession s;
  s.commands(pressed_rods("rod_contact hertz rod_friction 0.5", "local"));
  const auto x = s.gather("x");
  ASSERT_EQ(x.size(), 20u);
  // F = 4/3 E_p sqrt(r/2) delta^(3/2), E_p = E / (2 (1 - nu^2)).
  const double pair_modulus = 15e6 / (2.0 * (1.0 - 0.09));
  const double hertz = std::pow(3.0 * kLoad / (4.0 * pair_modulus * std::sqrt(0.25 * kD)), 2.0 / 3.0);
  for (int i = 0; i < 10; i++) {
    const double overlap = kD - (x[i] - x[10 + i]).norm();
    EXPECT_NEAR(overlap, hertz, 2e-3 * hertz) << "sphere pair " << i;
  }
  LAMMPS_NS::Fix *step = s.fix("step");
  std::printf("pressed rods: Hertz overlap %.4e m, pair 0 %.4e m; rods touching %g, contact force %.6e N\n", hertz,
              kD - (x[0] - x[10]).norm(), step->compute_vector(10), step->compute_vector(11));
  EXPECT_EQ(step->compute_vector(10), 2.0);
  EXPECT_NEAR(step->compute_vector(11), 10 * kLoad, 2e-3 * 10 * kLoad);
}

TEST(SeveralRods, RodsFarApartMoveBitForBitAsEachAlone) {
  // Level 3 couples rods only within its interaction reach (~0.1 mm here):
  // two rods 150 um apart across the channel, each also run alone.
  const auto scene = [](bool first, bool second) {
    std::vector<std::string> lines = {
        "units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
        "newton off", "communicate single cutoff 1e-5 vel yes",
        "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box"};
    if (first) lines.push_back("create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 150e-6 25e-6 10e-6 angle 30 mol 1");
    if (second) lines.push_back("create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 150e-6 175e-6 10e-6 angle 60 mol 2");
    for (const char *l : {"fix bonds all rod/bonds youngs_modulus 15e3 poisson_ratio 0.3",
                          "fix drag all hele_shaw/drag mean_velocity 0.03 model nonlocal",
                          "fix step all rod/implicit bonds bonds drag drag rod_contact hertz", "timestep 2e-6",
                          "run 200"})
      lines.push_back(l);
    return lines;
  };
  std::vector<Eigen::Vector3d> both, first, second;
  {
    hsrod_test::LiggghtsSession s;
    s.commands(scene(true, true));
    both = s.gather("x");
  }
  {
    hsrod_test::LiggghtsSession s;
    s.commands(scene(true, false));
    first = s.gather("x");
  }
  {
    hsrod_test::LiggghtsSession s;
    s.commands(scene(false, true));
    second = s.gather("x");
  }
  ASSERT_EQ(both.size(), 20u);
  for (int i = 0; i < 10; i++) {
    EXPECT_EQ(both[i], first[i]) << "rod 1 sphere " << i;
    EXPECT_EQ(both[10 + i], second[i]) << "rod 2 sphere " << i;
  }
  double centre_x = 0.0;
  for (int i = 0; i < 10; i++) centre_x += both[i].x() / 10;
  EXPECT_GT(centre_x, 155e-6) << "rod 1 was carried downstream";
}

namespace {
// Two 10-sphere rods across the flow (along y), the second `gap_x` behind
// the first, at rest in a straight channel of the pore scene's size, with
// fix hele_shaw/drag applied explicitly (no fix rod/implicit): `run 0`
// leaves each sphere's force = its drag at rest, the driving load.
std::vector<std::string> rods_at_rest(const std::string &model, bool second, double gap_x) {
  std::vector<std::string> lines = {
      "units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
      "newton off", "communicate single cutoff 1e-5 vel yes", "region box block 0 600e-6 0 200e-6 0 20e-6 units box",
      "create_box 1 box", "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 300e-6 100e-6 10e-6 angle 0"};
  if (second)
    lines.push_back("create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre " + hsrod_test::num(300e-6 - gap_x) +
                    " 100e-6 10e-6 angle 0");
  for (const std::string &l : std::vector<std::string>{"fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3",
                              "fix drag all hele_shaw/drag mean_velocity 0.03 model " + model, "timestep 1e-10",
                              "run 0"})
    lines.push_back(l);
  return lines;
}
}  // namespace

TEST(SeveralRods, ExplicitDragEvaluatesCoupledRodsTogether) {
  // Levels 3 and 4 couple rods hydrodynamically; the explicit path (fix
  // hele_shaw/drag alone) evaluated each rod by itself, so the leading
  // rod's load was that of the rod alone. Now the rods within the model's
  // interaction reach are evaluated together: each sphere's force is the
  // joint load of drag-models (RodHydrodynamics::loads over both rods), and
  // two rods 2 d apart shield each other (level 3 in a uniform stream:
  // 0.72 of the lone load, tests/drag-models/hydro/test_rigid_rod_transport.cpp).
  for (const std::string model : {"nonlocal", "twoway"}) {
    double alone = 0.0;
    {
      hsrod_test::LiggghtsSession s;
      s.commands(rods_at_rest(model, false, 0.0));
      for (const auto &f : s.gather("f")) alone += f.x();
    }
    hsrod_test::LiggghtsSession s;
    s.commands(rods_at_rest(model, true, 6e-6));
    const auto f = s.gather("f"), x = s.gather("x");
    ASSERT_EQ(f.size(), 20u);
    double leading = 0.0, trailing = 0.0;
    for (int i = 0; i < 10; i++) {
      leading += f[i].x();
      trailing += f[10 + i].x();
    }
    // The same load from drag-models directly, over both rods together.
    auto *drag = dynamic_cast<LAMMPS_NS::FixHeleShawDrag *>(s.fix("drag"));
    ASSERT_NE(drag, nullptr);
    std::vector<hsrod::RodGeometry> rods(2);
    for (int r = 0; r < 2; r++) {
      rods[r].id = r + 1;
      rods[r].sphere_diameter = 3e-6;
      rods[r].positions.assign(x.begin() + 10 * r, x.begin() + 10 * (r + 1));
    }
    hsrod::RodDrag joint;
    drag->hydrodynamics().loads(rods, joint);
    for (int i = 0; i < 20; i++)
      EXPECT_LT((f[i] - joint.driving_force[i]).norm(), 1e-9 * joint.driving_force[i].norm()) << model << " sphere " << i;
    std::printf("%s, explicit drag at rest, rods 2 d apart: load / rod alone: leading %.4f, trailing %.4f\n",
                model.c_str(), leading / alone, trailing / alone);
    EXPECT_LT(leading / alone, 0.85) << model;
    EXPECT_LT(trailing / alone, 0.85) << model;
    EXPECT_GT(leading / alone, 0.6) << model;
  }
}

// A fast rod driven at a resting one 4 d ahead, with a step in which the
// fast rod alone would travel ~11 d (push F = 1e-8 N per sphere against a
// drag ~3e-8 N s/m per sphere: ~0.3 m/s relative to the fluid, dt = 1e-4 s).
// The rods are not within each other's reach at the step's start (rest
// before it: reach 1.5 d), so the contact must be found within the step:
// the trial steps' paths meet, and the rods are stepped again together.
// Then (overdamped, equal local drag on both rods) the resting rod is
// carried by the contact alone: each sphere pair carries F / 2 once both
// move together, and never more than the push F on the driven sphere, so
// no pair overlaps more than the Hertz overlap of a load F (Johnson 1985,
// eq. 4.22), and the rods' summed contact force is 10 F / 2.
TEST(SeveralRods, AFastRodStopsOnARestingOneWithinTheStep) {
  constexpr double push = 1e-8;  // [N] per sphere of the driven rod
  hsrod_test::LiggghtsSession s;
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
              "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 290e-6 100e-6 10e-6 angle 0",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 302e-6 100e-6 10e-6 angle 0",
              "group a molecule 1", "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3",
              "fix drag all hele_shaw/drag mean_velocity 0.03 model local",
              "fix push_a a addforce " + hsrod_test::num(push) + " 0 0",
              "fix step all rod/implicit bonds bonds drag drag rod_contact hertz rod_friction 0.5", "timestep 1e-4"});
  const double pair_modulus = 15e6 / (2.0 * (1.0 - 0.09));
  const double hertz_at_push = std::pow(3.0 * push / (4.0 * pair_modulus * std::sqrt(0.25 * kD)), 2.0 / 3.0);
  LAMMPS_NS::Fix *step = s.fix("step");
  for (int n = 1; n <= 5; ++n) {
    s.command("run 1");
    const auto x = s.gather("x");
    ASSERT_EQ(x.size(), 20u);
    double smallest_gap = 1.0, centre_a = 0.0, centre_b = 0.0;
    for (int i = 0; i < 10; i++) {
      centre_a += x[i].x() / 10;
      centre_b += x[10 + i].x() / 10;
      for (int j = 10; j < 20; j++) smallest_gap = std::min(smallest_gap, (x[i] - x[j]).norm() - kD);
    }
    std::printf("step %d: rod centres %.4e %.4e m, smallest gap %.3e m (bound -%.3e m), contact force %.4e N\n", n,
                centre_a, centre_b, smallest_gap, hertz_at_push, step->compute_vector(11));
    EXPECT_GT(smallest_gap, -hertz_at_push) << "step " << n;
    EXPECT_LT(centre_a, centre_b) << "the driven rod passed through the resting one at step " << n;
    EXPECT_EQ(step->compute_vector(10), 2.0) << "step " << n;
    // From the second step on both move together: force balance on the
    // carried rod, its drag 10 zeta v = 10 F / 2 (the first step starts
    // both from rest and carries the approach).
    if (n >= 2) {
      EXPECT_NEAR(step->compute_vector(11), 10 * push / 2, 2e-3 * 10 * push / 2) << "step " << n;
    }
  }
}

namespace {

// Rods of 10 spheres (`create_rods`: their create_rod commands) in a
// 600 x 200 x 20 um slit, level 3, 20 steps of 2 us with `coupling` (fix
// rod/implicit rod_interaction); the final sphere centres and the start.
std::vector<Eigen::Vector3d> rods_run(const std::vector<std::string> &create_rods, const std::string &coupling,
                                      std::vector<Eigen::Vector3d> *start) {
  hsrod_test::LiggghtsSession s;
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
              "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box"});
  s.commands(create_rods);
  s.commands({"fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3",
              "fix drag all hele_shaw/drag mean_velocity 0.03 model nonlocal",
              "fix step all rod/implicit bonds bonds drag drag rod_interaction " + coupling, "timestep 2e-6",
              "run 0"});
  if (start) *start = s.gather("x");
  s.command("run 20");
  return s.gather("x");
}

// Three rods across the flow, 4-7 d apart (all within the interaction reach).
std::vector<Eigen::Vector3d> three_rods_run(const std::string &coupling, std::vector<Eigen::Vector3d> *start) {
  return rods_run({"create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 297e-6 100e-6 10e-6 angle 0",
                   "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 309e-6 104e-6 10e-6 angle 0.2",
                   "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 330e-6 98e-6 10e-6 angle -0.1"},
                  coupling, start);
}

}  // namespace

TEST(SeveralRods, RodsSolvedApartAndIteratedFollowTheJointStep) {
  // Rods within reach of each other solved apart with each other's
  // disturbance (hydro/cross_rod_disturbance.h), iterated to 1e-9, take
  // the joint solve's steps: the same equations split by rod, so the
  // centres agree to the iteration's residual times the motion (the
  // Newton and friction iterations of each rod's step are exact linear
  // solves here: no wall contact, no substeps). Lagged by a step, the
  // coupling is explicit: its error is stated, and must stay well below
  // that of no coupling at all (what the coupling moves).
  std::vector<Eigen::Vector3d> start;
  const auto joint = three_rods_run("yes", &start);
  const auto iterated = three_rods_run("iterated 200 1e-9", nullptr);
  const auto lagged = three_rods_run("lagged", nullptr);
  const auto none = three_rods_run("no", nullptr);
  ASSERT_EQ(joint.size(), 30u);
  double motion = 0.0, iterated_off = 0.0, lagged_off = 0.0, none_off = 0.0;
  for (std::size_t i = 0; i < joint.size(); ++i) {
    motion = std::max(motion, (joint[i] - start[i]).norm());
    iterated_off = std::max(iterated_off, (iterated[i] - joint[i]).norm());
    lagged_off = std::max(lagged_off, (lagged[i] - joint[i]).norm());
    none_off = std::max(none_off, (none[i] - joint[i]).norm());
  }
  std::printf("three rods, 20 steps, largest motion %.3g d: off the joint run by iterated %.2e, lagged %.2e, "
              "no coupling %.2e of the motion\n", motion / kD, iterated_off / motion, lagged_off / motion,
              none_off / motion);
  EXPECT_GT(none_off, 1e-3 * motion);  // the coupling matters here
  EXPECT_LT(iterated_off, 1e-6 * motion);  // the sweeps settle to ~1e-10 (the steps round-off), not below
  EXPECT_LT(lagged_off, 0.2 * none_off);
}

namespace {

// Six rods in a row along the stream, 80 um between centres: each within
// the interaction reach (115 um) of the next, so the joint solve chains all
// six into one cluster and couples every pair, the pairs 160-400 um apart
// too; solved apart, those pairs are the far field's (rod_far_field).
std::vector<Eigen::Vector3d> rods_in_a_row_run(const std::string &coupling, std::vector<Eigen::Vector3d> *start) {
  std::vector<std::string> rods;
  for (int r = 0; r < 6; ++r)
    rods.push_back("create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre " + hsrod_test::num(100e-6 + 80e-6 * r) +
                   " " + hsrod_test::num(100e-6 + 3e-6 * (r % 3)) + " 10e-6 angle " + hsrod_test::num(0.3 * r - 0.7));
  return rods_run(rods, coupling, start);
}

}  // namespace

TEST(SeveralRods, RodsApartBeyondTheReachFollowTheJointStepWithTheFarField) {
  // The joint solve couples rods beyond the reach through the chain; solved
  // apart they are coupled by the far field (hydro/cross_rod_far_field.h),
  // whose pairs differ from the joint solve's by the near-field blend's
  // tail, <= 1.6e-3 of a pair's coupling at the reach and falling
  // exponentially beyond (CrossRodFarField.*), which adds up where the
  // dipoles cancel: iterated, the centres agree with the joint run to a
  // fraction of a per cent of what the far pairs move them (measured
  // 3e-3; 0.4-0.7 % in the 30-rod suspension, tests/benchmarks/RESULTS.md),
  // which is what the run without the far field misses.
  std::vector<Eigen::Vector3d> start;
  const auto joint = rods_in_a_row_run("yes", &start);
  const auto far = rods_in_a_row_run("iterated 200 1e-9", nullptr);
  const auto near = rods_in_a_row_run("iterated 200 1e-9 rod_far_field no", nullptr);
  const auto lagged = rods_in_a_row_run("lagged", nullptr);
  const auto lagged_near = rods_in_a_row_run("lagged rod_far_field no", nullptr);
  const auto none = rods_in_a_row_run("no", nullptr);
  ASSERT_EQ(joint.size(), 60u);
  double motion = 0.0, far_off = 0.0, near_off = 0.0, lagged_off = 0.0, lagged_near_off = 0.0, none_off = 0.0;
  for (std::size_t i = 0; i < joint.size(); ++i) {
    motion = std::max(motion, (joint[i] - start[i]).norm());
    far_off = std::max(far_off, (far[i] - joint[i]).norm());
    near_off = std::max(near_off, (near[i] - joint[i]).norm());
    lagged_off = std::max(lagged_off, (lagged[i] - joint[i]).norm());
    lagged_near_off = std::max(lagged_near_off, (lagged_near[i] - joint[i]).norm());
    none_off = std::max(none_off, (none[i] - joint[i]).norm());
  }
  std::printf("six rods in a row, 20 steps, largest motion %.3g d: off the joint run by iterated with the far field "
              "%.2e, without %.2e, lagged with %.2e, without %.2e, no coupling %.2e of the motion\n",
              motion / kD, far_off / motion, near_off / motion, lagged_off / motion, lagged_near_off / motion,
              none_off / motion);
  EXPECT_GT(near_off, 1e-2 * none_off);  // the pairs beyond the reach matter here
  EXPECT_LT(far_off, 1e-2 * near_off);   // the far field carries them (to the blend's tail)
  EXPECT_LT(lagged_off, lagged_near_off);
}

