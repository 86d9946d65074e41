// The linearly implicit overdamped rod step: exact transport of free
// spheres, stability far beyond the explicit limit with convergence in dt,
// the C-shape of a flexible rod across the flow (level 3 only), and wall
// contact keeping spheres out of the walls.
#include "common/math_constants.h"
#include "dynamics/overdamped_rod_step.h"
#include "hydro/hydrodynamic_model.h"
#include "rod/rod_linearisation.h"
#include "rod/rod_measures.h"
#include "rod/stability_limits.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

using namespace hsrod;

namespace {
using hsrod::kPi;

struct Scene {
  double d, beta, youngs_modulus;
  int n;
};

// Runs a rod perpendicular to a uniform stream for `duration` with step dt;
// returns the final rod.
OverdampedRod run_across_stream(const Scene& s, const std::string& model_name, double dt, double duration) {
  RodSpec spec;
  spec.number_of_sections = s.n;
  spec.sphere_diameter = s.d;
  spec.angle = 0.0;  // along y: across the flow
  BeamBondMaterial material{s.youngs_modulus, 0.3, s.d, 0.0};
  OverdampedRod rod = make_overdamped_rod(make_rod_layout(spec), material, s.d);
  const auto model =
      make_hydrodynamic_model(model_name, {1e-3, s.d / s.beta, s.d}, ConfinementTable::default_table());
  const hsrod_test::UniformStream stream;
  const int steps = static_cast<int>(std::lround(duration / dt));
  RodGeometry geometry;
  geometry.sphere_diameter = s.d;
  RodDrag drag;
  for (int k = 0; k < steps; ++k) {
    geometry.positions = rod.positions;
    model->evaluate(geometry, stream, drag);
    overdamped_rod_step(rod, drag, dt, nullptr, nullptr);
  }
  return rod;
}

double deflection(const OverdampedRod& rod, double rod_length) {
  std::vector<Eigen::Vector2d> centres;
  for (const auto& p : rod.positions) centres.push_back(p.head<2>());
  return relative_deflection_eq2(centres.front(), centres.back(), centres, rod_length);
}
}  // namespace

TEST(OverdampedStep, FreeSphereMovesWithTheDrivingVelocity) {
  // Two unbonded spheres far apart, isotropic model: v = lambda(beta) u exactly.
  OverdampedRod rod;
  rod.positions = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1e-3, 0)};
  rod.orientations.assign(2, Eigen::Quaterniond::Identity());
  rod.radii.assign(2, 1.5e-6);
  rod.external_forces.assign(2, Eigen::Vector3d::Zero());
  rod.external_torques.assign(2, Eigen::Vector3d::Zero());
  const auto table = ConfinementTable::default_table();
  const auto model = make_hydrodynamic_model("isotropic", {1e-3, 20e-6, 3e-6}, table);
  RodGeometry g;
  g.sphere_diameter = 3e-6;
  g.positions = rod.positions;
  RodDrag drag;
  model->evaluate(g, hsrod_test::UniformStream(), drag);
  const auto result = overdamped_rod_step(rod, drag, 1e-3, nullptr, nullptr);
  EXPECT_NEAR(result.velocities[0].x(), table.at(0.15).sphere_driving, 1e-12);
  EXPECT_NEAR(rod.positions[1].x(), 1e-3 * table.at(0.15).sphere_driving, 1e-15);
}

TEST(OverdampedStep, StiffRodStableFarBeyondExplicitLimitAndConvergesInDt) {
  // The pore scene's stiff rod: d = 3 um, E = 15 MPa, beta = 0.15, N = 10,
  // across the flow with level 3 (which bends it). Explicit limit ~2.2e-8 s.
  const Scene s{3e-6, 0.15, 15e6, 10};
  RodSpec spec;
  spec.number_of_sections = s.n;
  spec.sphere_diameter = s.d;
  const double explicit_limit =
      compute_stability_limits(make_rod_layout(spec), {s.d, 1170, s.youngs_modulus, 0.3},
                               {s.youngs_modulus, 0.3, s.d, 0.0}, 1e-3)
          .explicit_bond_limit;
  const double duration = 2e-4;
  const double coarse_dt = 1e-5, fine_dt = 1e-6;
  const OverdampedRod coarse = run_across_stream(s, "nonlocal", coarse_dt, duration);
  const OverdampedRod fine = run_across_stream(s, "nonlocal", fine_dt, duration);
  double worst = 0.0;
  for (int i = 0; i < s.n; ++i) worst = std::max(worst, (coarse.positions[i] - fine.positions[i]).norm());
  const double travelled = fine.positions[0].x();
  std::printf("dt %.0e s = %.0f x explicit limit %.3g s: rod travelled %.4g m, differs from dt %.0e by %.3g m (%.2e of d)\n",
              coarse_dt, coarse_dt / explicit_limit, explicit_limit, travelled, fine_dt, worst, worst / s.d);
  EXPECT_GT(coarse_dt / explicit_limit, 100.0);
  EXPECT_TRUE(std::isfinite(worst));
  // Transport is exact for any dt; what differs is the transient of the
  // small bending (time scale zeta L^4 / EI): within 1e-3 d.
  EXPECT_LT(worst, 1e-3 * s.d);
}

TEST(OverdampedStep, FlexibleRodAcrossTheFlowBendsIntoCShapeOnlyWithLevel3) {
  // The paper's Hele-Shaw scene (Table 1): 15 spheres of 54 um, E = 2 kPa,
  // H = 65 um (beta = 0.83), perpendicular to the flow (Cappello et al. 2019).
  const Scene s{54e-6, 54.0 / 65.0, 2e3, 15};
  const double rod_length = s.n * s.d;
  const double duration = 2e-3, dt = 2e-5;
  const OverdampedRod nonlocal = run_across_stream(s, "nonlocal", dt, duration);
  const OverdampedRod local = run_across_stream(s, "local", dt, duration);
  const double bent = deflection(nonlocal, rod_length);
  const double straight = deflection(local, rod_length);
  const double middle_lead = nonlocal.positions[s.n / 2].x() - 0.5 * (nonlocal.positions[0].x() + nonlocal.positions[s.n - 1].x());
  std::printf("C-shape: level 3 deflection %.4g (middle leads the ends by %.3g d); level 2 deflection %.2g\n", bent,
              middle_lead / s.d, straight);
  EXPECT_GT(bent, 1e-3);
  EXPECT_GT(middle_lead, 0.0);  // the middle is ahead: the ends lag
  EXPECT_LT(straight, 1e-9);    // uniform local drag cannot bend a straight rod
}

TEST(OverdampedStep, WallContactStopsASphereAtTheWall) {
  // A sphere pushed against the side wall y = 0 by a force: it settles where
  // the Hertz force balances the push, never deep in the wall.
  ChannelGeometry channel(1e-3, 1e-4, 20e-6);
  WallContactParameters walls;
  walls.youngs_modulus = 15e6;
  walls.gap_bottom = 0.0;
  OverdampedRod rod;
  rod.positions = {Eigen::Vector3d(5e-4, 3e-6, 10e-6)};
  rod.orientations = {Eigen::Quaterniond::Identity()};
  rod.radii = {1.5e-6};
  rod.external_forces = {Eigen::Vector3d(0, -1e-9, 0)};
  rod.external_torques = {Eigen::Vector3d::Zero()};
  RodDrag drag;
  drag.resize(1);
  drag.resistance[0] = 3 * kPi * 1e-3 * 3e-6 * Eigen::Matrix3d::Identity();
  drag.rotational_resistance[0] = kPi * 1e-3 * 27e-18;
  for (int k = 0; k < 2000; ++k) overdamped_rod_step(rod, drag, 1e-5, &channel, &walls);
  // Hertz: 1e-9 N = 4/3 E* sqrt(r) delta^1.5.
  const double e_star = 15e6 / (1 - 0.09);
  const double delta = std::pow(1e-9 / (4.0 / 3.0 * e_star * std::sqrt(1.5e-6)), 2.0 / 3.0);
  EXPECT_NEAR(rod.positions[0].y(), 1.5e-6 - delta, 1e-3 * delta);
}

TEST(OverdampedStep, NonBondedSpheresOfOneRodTouchWithHertz) {
  // A rod folded back on itself: spheres 0 and 2 of a 3-sphere "rod" bonded
  // 0-1 and 1-2 only are pressed together; they settle at the Hertz overlap
  // for the push, while a bonded pair feels no contact.
  WallContactParameters contact;
  contact.youngs_modulus = 15e6;
  contact.planform_walls = contact.gap_walls = false;
  OverdampedRod rod;
  rod.positions = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3e-6, 0, 0), Eigen::Vector3d(0, 3.2e-6, 0)};
  rod.orientations.assign(3, Eigen::Quaterniond::Identity());
  rod.radii.assign(3, 1.5e-6);
  const double push = 1e-9;  // [N]
  rod.external_forces = {Eigen::Vector3d(0, push, 0), Eigen::Vector3d::Zero(), Eigen::Vector3d(0, -push, 0)};
  rod.external_torques.assign(3, Eigen::Vector3d::Zero());
  RodDrag drag;
  drag.resize(3);
  for (int i = 0; i < 3; ++i) {
    drag.resistance[i] = 3 * kPi * 1e-3 * 3e-6 * Eigen::Matrix3d::Identity();
    drag.rotational_resistance[i] = kPi * 1e-3 * 27e-18;
  }
  // Only sphere 0 and 2 interact (no bonds at all here: 1 is far from both after this).
  rod.positions[1] = Eigen::Vector3d(1e-4, 0, 0);
  OverdampedStepResult last;
  for (int k = 0; k < 3000; ++k) last = overdamped_rod_step(rod, drag, 1e-5, nullptr, &contact);
  EXPECT_TRUE(last.self_contact);
  const double e_pair = 0.5 * 15e6 / (1 - 0.09);
  const double r_star = 0.75e-6;
  const double delta = std::pow(push / (4.0 / 3.0 * e_pair * std::sqrt(r_star)), 2.0 / 3.0);
  const double gap = (rod.positions[2] - rod.positions[0]).norm();
  EXPECT_NEAR(gap, 3e-6 - delta, 1e-3 * delta);

  // Bonded spheres closer than a diameter feel no contact.
  OverdampedRod bonded = rod;
  bonded.bonds.push_back({0, 2, BeamBondRest::from_current(rod.positions[0], rod.orientations[0], rod.positions[2],
                                                           rod.orientations[2]),
                          BeamBondStiffness{}});
  bonded.external_forces.assign(3, Eigen::Vector3d::Zero());
  const auto r = overdamped_rod_step(bonded, drag, 1e-5, nullptr, &contact);
  EXPECT_FALSE(r.self_contact);
}

TEST(OverdampedStep, CellListFindsExactlyThePairsOfTheAllPairsSearch) {
  // A rod folded into a tight zig-zag (many near pairs, also pairs exactly
  // one reach apart in x) plus a few spheres stacked across the gap: the
  // cell list must return the same pairs as the O(n^2) search, in order.
  std::vector<Eigen::Vector3d> positions;
  const double d = 3e-6;
  for (int k = 0; k < 300; ++k) {
    const int lane = (k / 20) % 2 ? 19 - k % 20 : k % 20;
    positions.emplace_back(lane * 0.9 * d + 1e-7 * std::sin(7.0 * k), (k / 20) * 0.95 * d, 1e-6 * std::cos(3.0 * k));
  }
  positions.emplace_back(0.0, 0.0, 0.0);
  positions.emplace_back(d, 0.0, 2.0 * d);  // exactly one reach away in x
  const double reach = d;
  std::vector<std::pair<int, int>> all_pairs;
  for (int i = 0; i < static_cast<int>(positions.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(positions.size()); ++j) {
      const Eigen::Vector3d offset = positions[i] - positions[j];
      if (std::fabs(offset.x()) <= reach && std::fabs(offset.y()) <= reach) all_pairs.emplace_back(i, j);
    }
  const auto cell_pairs = nearby_sphere_pairs(positions, reach);
  std::printf("zig-zag of %zu spheres: %zu candidate pairs\n", positions.size(), all_pairs.size());
  EXPECT_GT(all_pairs.size(), positions.size());  // the test has near pairs to find
  EXPECT_EQ(cell_pairs, all_pairs);
}

TEST(OverdampedStep, CellListOrderIsTheSameBucketedSortedOrKept) {
  // The cells are bucketed by a counting sort where the grid is compact, sorted
  // by comparison where it is not, and re-sorted from the last call's order
  // when kept: the pairs in cell order (unsorted) must be the same, in the
  // same order, on all three paths (the implicit step's contact sums follow it).
  const double d = 3e-6, reach = d;
  std::vector<Eigen::Vector3d> positions;
  for (int k = 0; k < 400; ++k)
    positions.emplace_back(0.8 * d * (k % 25) + 1e-7 * std::sin(5.0 * k), 0.85 * d * (k / 25), 1e-6 * std::cos(k));
  const auto bucketed = nearby_sphere_pairs(positions, reach, false);
  // One sphere far out in +x: the grid spans 10^5 cells, > 4 n: comparison sort;
  // x_min, y_min are unchanged, so are the others' cells, and it has no pairs.
  std::vector<Eigen::Vector3d> sparse = positions;
  sparse.emplace_back(1.0, 0.0, 0.0);
  const auto sorted = nearby_sphere_pairs(sparse, reach, false);
  // Kept: a first call on shuffled-in-place positions, then the real ones.
  PairSearchCells cells;
  std::vector<std::pair<int, int>> kept;
  std::vector<Eigen::Vector3d> moved = positions;
  for (auto& x : moved) x.x() = -x.x();
  find_nearby_pairs(moved, reach, cells, kept, false);
  find_nearby_pairs(positions, reach, cells, kept, false);
  EXPECT_GT(bucketed.size(), positions.size());  // there are near pairs to find
  EXPECT_EQ(sorted, bucketed);
  EXPECT_EQ(kept, bucketed);
  auto lexicographic = bucketed;
  std::sort(lexicographic.begin(), lexicographic.end());
  EXPECT_EQ(nearby_sphere_pairs(positions, reach, true), lexicographic);
}

TEST(OverdampedStep, KeptSolverAnalysesThePatternOnceAndMatchesFreshSteps) {
  // A 40-sphere stiff rod (block-tridiagonal path) across a uniform stream for 30
  // steps: the solver kept between steps analyses its LU pattern once and
  // moves the rod as a fresh solver per step does, to round-off.
  const double d = 3e-6;
  RodSpec spec;
  spec.number_of_sections = 40;
  spec.sphere_diameter = d;
  const BeamBondMaterial material{15e6, 0.3, d, 0.0};
  OverdampedRod kept_rod = make_overdamped_rod(make_rod_layout(spec), material, d);
  OverdampedRod fresh_rod = kept_rod;
  const auto model = make_hydrodynamic_model("local", {1e-3, 20e-6, d}, ConfinementTable::default_table());
  const hsrod_test::UniformStream stream;
  WallContactParameters contact;
  contact.youngs_modulus = 15e6;
  OverdampedRodSolver solver;
  RodGeometry geometry;
  geometry.sphere_diameter = d;
  RodDrag drag;
  double worst = 0.0;
  for (int k = 0; k < 30; ++k) {
    geometry.positions = kept_rod.positions;
    model->evaluate(geometry, stream, drag);
    solver.step(kept_rod, drag, 1e-5, nullptr, &contact);
    geometry.positions = fresh_rod.positions;
    model->evaluate(geometry, stream, drag);
    overdamped_rod_step(fresh_rod, drag, 1e-5, nullptr, &contact);
    for (int i = 0; i < kept_rod.size(); ++i)
      worst = std::max(worst, (kept_rod.positions[i] - fresh_rod.positions[i]).norm());
  }
  const double travelled = kept_rod.positions[0].x();
  std::printf("kept vs fresh solver: travelled %.3g m, largest difference %.3g m\n", travelled, worst);
  EXPECT_EQ(solver.pattern_analyses(), 1);
  EXPECT_GT(travelled, 50.0 * d);  // the rod moved: the comparison means something
  EXPECT_LT(worst, 1e-12 * travelled);
}

namespace {
// Moves `rod` 40 steps of 1 us (40 um) across a uniform stream of 1 m/s with `method`, each sphere
// also pushed by a small force along z and wall contacts on (gap walls,
// friction), so that bonds bend, twist and stretch. Returns the solver's
// statistics.
OverdampedSolverStatistics run_with(OverdampedRod& rod, OverdampedRodSolver::LinearSolver method, double d) {
  const auto model = make_hydrodynamic_model("local", {1e-3, 20e-6, d}, ConfinementTable::default_table());
  const hsrod_test::UniformStream stream;
  const ChannelGeometry channel(1e-3, 1e-3, 20e-6, -5e-4, -5e-4, {});
  WallContactParameters contact;
  contact.youngs_modulus = 15e3;
  // The bottom wall 0.2 um above the lowest point of the 2x2 rod's lower
  // layer (centres at z = -3 um): those spheres touch it and rub.
  contact.gap_bottom = -4.5e-6 + 0.2e-6;
  contact.friction_coefficient = 0.5;
  OverdampedRodSolver solver;
  solver.set_linear_solver(method);
  RodGeometry geometry;
  geometry.sphere_diameter = d;
  RodDrag drag;
  for (int i = 0; i < rod.size(); ++i) rod.external_forces[i] = Eigen::Vector3d(0.0, 0.0, 1e-12 * (i % 3 - 1));
  for (int k = 0; k < 40; ++k) {
    geometry.positions = rod.positions;
    model->evaluate(geometry, stream, drag);
    solver.step(rod, drag, 1e-6, &channel, &contact);
  }
  return solver.statistics();
}
}  // namespace

TEST(OverdampedStep, GroupedBandOfMultiSphereSectionsMatchesTheGeneralSolvers) {
  // Rods whose bonds join spheres up to g apart (2x2 sections: g = 4; 3x1:
  // g = 3; a chain with extra bonds to the next-but-one sphere, 11 spheres:
  // g = 2 with a smaller last group) are solved block-tridiagonally in
  // groups of g spheres; the rod must move as with the sparse and the dense
  // LU of the whole system, to round-off: 1e-8 of the distance travelled,
  // 1e-7 rad. (The sparse and the dense LU disagree with each other by up to
  // 1.5e-9 of the distance and 1e-7 rad here: the 2x2 rod rubs on the wall,
  // and the secant friction law near stick amplifies round-off. A wrong
  // block moves the rod by a sizeable fraction of d.)
  const double d = 3e-6;
  const BeamBondMaterial material{15e3, 0.3, d, 0.0};
  std::vector<OverdampedRod> rods;
  for (const auto& section : {std::make_pair(2, 2), std::make_pair(3, 1)}) {
    RodSpec spec;
    spec.number_of_sections = 8;
    spec.sphere_diameter = d;
    spec.angle = 0.4;
    spec.centre = Eigen::Vector3d(0.0, 0.0, section.second == 2 ? -0.5 * d : 0.0);
    spec.section_rows = section.first;
    spec.section_layers = section.second;
    rods.push_back(make_overdamped_rod(make_rod_layout(spec), material, d));
  }
  {
    RodSpec spec;
    spec.number_of_sections = 11;
    spec.sphere_diameter = d;
    spec.angle = 0.4;
    const RodLayout layout = make_rod_layout(spec);
    OverdampedRod chain = make_overdamped_rod(layout, material, d);
    for (int i = 0; i + 2 < 11; ++i) {
      RodBond bond;
      bond.i = i;
      bond.j = i + 2;
      bond.rest = layout_rest_state(layout, {i, i + 2});
      bond.stiffness = BeamBondStiffness::from_material(material, bond.rest.rest_length());
      chain.bonds.push_back(bond);
    }
    rods.push_back(chain);
  }
  for (const OverdampedRod& start : rods) {
    OverdampedRod grouped = start, sparse = start, dense = start;
    const auto stats = run_with(grouped, OverdampedRodSolver::LinearSolver::automatic, d);
    run_with(sparse, OverdampedRodSolver::LinearSolver::sparse_lu, d);
    run_with(dense, OverdampedRodSolver::LinearSolver::dense_lu, d);
    double travelled = 0.0, worst_sparse = 0.0, worst_dense = 0.0, worst_turn = 0.0, general_turn = 0.0;
    for (int i = 0; i < start.size(); ++i) {
      travelled = std::max(travelled, (grouped.positions[i] - start.positions[i]).norm());
      worst_sparse = std::max(worst_sparse, (grouped.positions[i] - sparse.positions[i]).norm());
      worst_dense = std::max(worst_dense, (grouped.positions[i] - dense.positions[i]).norm());
      worst_turn = std::max(worst_turn, grouped.orientations[i].angularDistance(sparse.orientations[i]));
      general_turn = std::max(general_turn, dense.orientations[i].angularDistance(sparse.orientations[i]));
    }
    std::printf("%d spheres, %zu bonds: travelled %.3g m; grouped vs sparse %.3g m, vs dense %.3g m, turn %.3g rad "
                "(sparse vs dense %.3g rad)\n",
                start.size(), start.bonds.size(), travelled, worst_sparse, worst_dense, worst_turn, general_turn);
    // The grouped path was taken by every step and every repeat that put wall
    // friction at the end velocities (each after one sparse solve that
    // keeps its factors for the contacts' Delassus operator).
    EXPECT_EQ(stats.banded_steps, 40 + stats.friction_repeats);
    EXPECT_GT(travelled, 5.0 * d);
    EXPECT_LT(worst_sparse, 1e-8 * travelled);
    EXPECT_LT(worst_dense, 1e-8 * travelled);
    EXPECT_LT(worst_turn, 1e-7);
  }
}

namespace {
struct LockstepDifference {
  double travelled = 0.0;   // largest displacement of a sphere over the run [m]
  double z_spread = 0.0;    // largest z difference between spheres at the end [m]
  double position = 0.0;    // largest |x_automatic - x_dense| after one step from the same state, relative to the step
  double turn = 0.0;        // largest rotation between the two solvers' orientations after one step [rad]
  double correction = 0.0;  // largest |delta_automatic - delta_dense| of newton_correction's dx, relative to the last step's
  double correction_turn = 0.0;  // the same for its rotations [rad]
  OverdampedSolverStatistics automatic, dense;
};

// A 12-sphere chain at 0.4 rad to a uniform stream with level 3's non-local
// drag, pushed along z and rubbing on the bottom wall (gap walls, friction),
// 40 steps of 1 us. Each step is taken from the same state by the
// automatic solver and by the dense LU of the whole system, friction
// linearised about the same velocities (the automatic step's, given in the
// rod), then the rod goes on with the automatic one. `z_coupling` [N s/m] adds a
// symmetric coupling of neighbouring spheres' z velocities to the drag (as
// a model coupling z would).
LockstepDifference run_lockstep(const OverdampedRod& start, double z_coupling, double friction_coefficient) {
  const double d = 3e-6;
  const auto model = make_hydrodynamic_model("nonlocal", {1e-3, 20e-6, d}, ConfinementTable::default_table());
  const hsrod_test::UniformStream stream;
  const ChannelGeometry channel(1e-3, 1e-3, 20e-6, -5e-4, -5e-4, {});
  WallContactParameters contact;
  contact.youngs_modulus = 15e3;
  contact.gap_bottom = -1.5e-6 + 0.2e-6;  // 0.2 um into the spheres (centres at z = 0)
  contact.friction_coefficient = friction_coefficient;
  OverdampedRodSolver automatic, dense;
  dense.set_linear_solver(OverdampedRodSolver::LinearSolver::dense_lu);
  RodGeometry geometry;
  geometry.sphere_diameter = d;
  RodDrag drag;
  OverdampedRod rod = start;
  for (int i = 0; i < rod.size(); ++i) rod.external_forces[i] = Eigen::Vector3d(0.0, 0.0, 1e-12 * (i % 3 - 1));
  LockstepDifference diff;
  double largest_step = 0.0;  // of the last step [m]
  for (int k = 0; k < 40; ++k) {
    geometry.positions = rod.positions;
    model->evaluate(geometry, stream, drag);
    for (int i = 0; i + 1 < rod.size(); ++i) {
      drag.coupled_resistance(3 * i + 2, 3 * i + 5) += z_coupling;
      drag.coupled_resistance(3 * i + 5, 3 * i + 2) += z_coupling;
    }
    OverdampedRod other = rod;
    const OverdampedStepResult result = automatic.step(rod, drag, 1e-6, &channel, &contact);
    dense.step(other, drag, 1e-6, &channel, &contact);
    // Friction linearised about the same velocities in both (a solver's own
    // last step differs from the other's by round-off, which the secant
    // friction law near stick amplifies).
    rod.velocities = result.velocities;
    rod.angular_velocities = result.angular_velocities;
    largest_step = result.largest_displacement;
    for (int i = 0; i < rod.size(); ++i) {
      diff.position = std::max(diff.position, (rod.positions[i] - other.positions[i]).norm() / largest_step);
      diff.turn = std::max(diff.turn, rod.orientations[i].angularDistance(other.orientations[i]));
    }
    if (k == 39) {
      Eigen::VectorXd delta, dense_delta;
      EXPECT_TRUE(automatic.newton_correction(rod, drag, &channel, &contact, delta));
      EXPECT_TRUE(dense.newton_correction(rod, drag, &channel, &contact, dense_delta));
      for (int i = 0; i < rod.size(); ++i) {
        diff.correction = std::max(diff.correction, (delta - dense_delta).segment<3>(6 * i).norm() / largest_step);
        diff.correction_turn = std::max(diff.correction_turn, (delta - dense_delta).segment<3>(6 * i + 3).norm());
      }
    }
  }
  for (int i = 0; i < rod.size(); ++i) {
    diff.travelled = std::max(diff.travelled, (rod.positions[i] - start.positions[i]).norm());
    diff.z_spread = std::max(diff.z_spread, std::fabs(rod.positions[i].z() - rod.positions[0].z()));
  }
  diff.automatic = automatic.statistics();
  diff.dense = dense.statistics();
  return diff;
}
}  // namespace

TEST(OverdampedStep, ChainWithNonlocalDragSolvedThroughTheSchurComplementMatchesTheDenseLu) {
  // A chain with non-local drag is solved by eliminating z and the rotations
  // (block-tridiagonal) onto the coupled in-plane translations (dynamics/
  // coupled_chain_solve.h); with a z coupling z stays among the coupled
  // unknowns. Each step must equal the dense LU of the whole 6n x 6n
  // system's from the same state to round-off, and so must the Newton
  // correction (a re-solve with the kept factors): without wall friction
  // 1e-9 of the step and 1e-8 rad (measured 1e-10, 4e-10 rad); with wall
  // friction, whose secant law near stick makes the system ill-conditioned,
  // 1e-5 of the step and 1e-5 rad (measured 1e-6, 1e-6 rad; the sparse LU
  // differs from the dense one by as much here: 6.7e-13 m, 1.3e-6 rad). A wrong
  // or missing block moves a step by a sizeable fraction of itself.
  const double d = 3e-6;
  const BeamBondMaterial material{15e3, 0.3, d, 0.0};
  RodSpec spec;
  spec.number_of_sections = 12;
  spec.sphere_diameter = d;
  spec.angle = 0.4;
  const OverdampedRod start = make_overdamped_rod(make_rod_layout(spec), material, d);
  for (const auto& scene : {std::make_pair(0.0, 0.0), std::make_pair(5e-9, 0.0), std::make_pair(0.0, 0.5)}) {
    const double z_coupling = scene.first, friction = scene.second;
    const LockstepDifference diff = run_lockstep(start, z_coupling, friction);
    std::printf("z coupling %.3g N s/m, wall friction %.2g: travelled %.3g m, z spread %.3g m; Schur vs dense LU per "
                "step %.3g of the step, turn %.3g rad; Newton correction %.3g of the step, turn %.3g rad\n",
                z_coupling, friction, diff.travelled, diff.z_spread, diff.position, diff.turn, diff.correction,
                diff.correction_turn);
    const double tolerance = friction > 0.0 ? 1e-5 : 1e-9;
    const double turn_tolerance = friction > 0.0 ? 1e-5 : 1e-8;
    // 40 steps, plus the repeats that put wall friction at the end velocities.
    EXPECT_EQ(diff.automatic.dense_steps, 40 + diff.automatic.friction_repeats);
    EXPECT_EQ(diff.automatic.banded_steps + diff.automatic.sparse_steps, 0);
    EXPECT_EQ(diff.dense.dense_steps, 40 + diff.dense.friction_repeats);
    EXPECT_GT(diff.travelled, 5.0 * d);
    EXPECT_GT(diff.z_spread, 1e-4 * d);  // z moved unevenly: the z forces, couplings and the wall act
    EXPECT_LT(diff.position, tolerance);
    EXPECT_LT(diff.turn, turn_tolerance);
    EXPECT_LT(diff.correction, 1e-9);
    EXPECT_LT(diff.correction_turn, turn_tolerance);
  }
}
