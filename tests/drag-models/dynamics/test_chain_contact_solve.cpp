// The capacitance (Woodbury) solve of chains with pair contacts off the band
// (dynamics/chain_contact_solve.cpp) against the general sparse LU of the
// same step: clusters of 2, 5, 20 and 40 touching rods (the capacitance
// matrix factorised densely and sparsely), and matrices where it must hand
// over to the sparse LU (a singular band, nearly every sphere coupled).
#include "common/math_constants.h"
#include "dynamics/overdamped_rod_step.h"
#include "dynamics/rod_cluster.h"
#include "rod/rod_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <utility>
#include <vector>

using namespace hsrod;

namespace {
constexpr double d = 3e-6;                          // sphere diameter [m]
constexpr double viscosity = 1e-3;                  // [Pa s]
const double zeta = 3 * kPi * viscosity * d;        // translational resistance [N s/m]
const double zeta_r = kPi * viscosity * d * d * d;  // rotational resistance [N m s]
constexpr double E = 15e6, nu = 0.3;                // the paper's rod [Pa], [-]
constexpr double dt = 2e-6;                         // the pore scene's step [s]

OverdampedRod rod_along_x(int n, const Eigen::Vector3d& centre) {
  RodSpec spec;
  spec.number_of_sections = n;
  spec.sphere_diameter = d;
  spec.centre = centre;
  spec.angle = kPi / 2;  // from the y axis: along x
  return make_overdamped_rod(make_rod_layout(spec), {E, nu, d, 0.0}, d);
}

// `chains` rods of `spheres` spheres in a staircase near the origin (small
// coordinates: the position round-off stays far below the displacements'
// 1e-12): rod k+1 shifted by (spheres - 2) d along x and 0.95 d along y,
// so its first two spheres overlap the last two of rod k (two contacts
// per neighbouring pair, off the band: their indices differ by ~spheres),
// and, with `bundle`, every third rod also laid alongside rod k-2 so that
// rods touch more than one other.
OverdampedRod staircase(int chains, int spheres, bool bundle) {
  std::vector<OverdampedRod> rods;
  for (int k = 0; k < chains; ++k) {
    Eigen::Vector3d centre((spheres - 2) * d * k, 0.95 * d * k, 0.0);
    if (bundle && k % 3 == 2) centre = Eigen::Vector3d((spheres - 2) * d * (k - 2), 0.95 * d * (k - 2) - 0.95 * d, 0.0);
    centre -= Eigen::Vector3d((spheres - 2) * d * chains / 2, 0.95 * d * chains / 2, 0.0);
    rods.push_back(rod_along_x(spheres, centre));
  }
  OverdampedRod rod = merge_rods(rods);
  // Loads of ~1e-9 N that differ from sphere to sphere (displacements ~0.05 d
  // per step), previous velocities for the friction secants.
  rod.velocities.resize(rod.size());
  rod.angular_velocities.resize(rod.size());
  for (int i = 0; i < rod.size(); ++i) {
    const double a = 0.7 * i;
    rod.external_forces[i] = 1e-9 * Eigen::Vector3d(std::sin(a), std::cos(1.3 * a), 0.2 * std::sin(2.1 * a));
    rod.external_torques[i] = 1e-15 * Eigen::Vector3d(std::cos(a), 0.5, std::sin(0.4 * a));
    rod.velocities[i] = 1e-3 * Eigen::Vector3d(std::cos(0.9 * a), std::sin(a), 0.0);
    rod.angular_velocities[i] = 1e2 * Eigen::Vector3d(0.0, 0.0, std::sin(1.7 * a));
  }
  return rod;
}

RodDrag local_drag(int n) {
  RodDrag drag;
  drag.resize(n);
  for (int i = 0; i < n; ++i) {
    drag.resistance[i] = zeta * Eigen::Vector3d(1.0, 1.6, 1.2).asDiagonal();
    drag.rotational_resistance[i] = zeta_r;
  }
  return drag;
}

WallContactParameters rod_contact() {
  WallContactParameters p;
  p.youngs_modulus = E;
  p.poisson_ratio = nu;
  p.rod_contact = true;
  p.rod_friction_coefficient = 0.5;  // Table 1
  p.slip_velocity = 1e-6;
  return p;
}

// Largest differences of two steps from `start`: displacements and rotations,
// each relative to the largest of `reference`'s [-].
struct Difference {
  double translation, rotation;
};
Difference difference(const OverdampedRod& start, const OverdampedRod& a, const OverdampedStepResult& ra,
                      const OverdampedRod& reference, const OverdampedStepResult& rr) {
  double dx = 0.0, ddx = 0.0, dphi = 0.0, ddphi = 0.0;
  for (int i = 0; i < start.size(); ++i) {
    dx = std::max(dx, (reference.positions[i] - start.positions[i]).norm());
    ddx = std::max(ddx, (a.positions[i] - reference.positions[i]).norm());
    dphi = std::max(dphi, rr.angular_velocities[i].norm());
    ddphi = std::max(ddphi, (ra.angular_velocities[i] - rr.angular_velocities[i]).norm());
  }
  return {ddx / dx, ddphi / dphi};
}

struct Compared {
  Difference automatic, dense;  // the automatic path's and the dense LU's from the sparse LU
  OverdampedSolverStatistics statistics;  // of the automatic path
};

// One step (no walls, friction about the given velocities, no repeats) by
// the automatic path, the sparse LU and the dense LU.
Compared compare_with_sparse_lu(const OverdampedRod& start, const RodDrag& drag) {
  const WallContactParameters contact = rod_contact();
  OverdampedRod a = start, b = start, c = start;
  OverdampedRodSolver automatic, sparse, dense;
  sparse.set_linear_solver(OverdampedRodSolver::LinearSolver::sparse_lu);
  dense.set_linear_solver(OverdampedRodSolver::LinearSolver::dense_lu);
  const OverdampedStepResult ra = automatic.step(a, drag, dt, nullptr, &contact);
  const OverdampedStepResult rb = sparse.step(b, drag, dt, nullptr, &contact);
  const OverdampedStepResult rc = dense.step(c, drag, dt, nullptr, &contact);
  EXPECT_TRUE(ra.rod_contact);
  return {difference(start, a, ra, b, rb), difference(start, c, rc, b, rb), automatic.statistics()};
}

OverdampedRod lone_sphere(const Eigen::Vector3d& x) {
  OverdampedRod rod;
  rod.positions = {x};
  rod.orientations = {Eigen::Quaterniond::Identity()};
  rod.radii = {0.5 * d};
  rod.external_forces = {Eigen::Vector3d::Zero()};
  rod.external_torques = {Eigen::Vector3d::Zero()};
  return rod;
}
}  // namespace

// 2, 5 and 20 rods touching in a staircase (and across it):
// the capacitance solve is the same linear algebra as the sparse LU, so the
// two agree to round-off amplified by the step matrix's condition. That
// amplification is large here (a Hertz contact of ~5 N/m and bonds of
// ~30 N/m against drag / dt of ~0.03 N/m, rotations and displacements in
// one system): the sparse and the dense LU of the same matrix, both
// backward stable, differ by up to ~2e-10 in the rotations of the 20-rod
// cluster. So the bound is 1e-12 or, where the two general LUs differ by
// more, four times their difference: their difference only estimates the
// size of their forward errors (cond x round-off, of unknown sign), the
// capacitance solve's own error being of that size too (its componentwise
// backward error is brought to ~2e-16 by the refinement).
// The translations are compared through the positions (x + dx at
// |x| <= 60 d: position round-off ~1e-20 m against displacements ~1e-7 m).
TEST(ChainContactSolve, ClustersOfTouchingRodsMatchTheSparseLu) {
  // (rods, spheres per rod, bundled): the 20-rod cluster has 76 of its 160
  // spheres coupled (the sparse capacitance LU).
  const std::vector<std::tuple<int, int, bool>> clusters = {{2, 8, false}, {5, 8, false}, {5, 8, true}, {20, 8, false}};
  for (const auto& [chains, spheres, bundle] : clusters) {
    const OverdampedRod rod = staircase(chains, spheres, bundle);
    const Compared c = compare_with_sparse_lu(rod, local_drag(rod.size()));
    std::printf("%d rods%s: capacitance steps %ld (sparse %ld), fallbacks %ld; from the sparse LU: translations %.2e, rotations "
                "%.2e (dense LU: %.2e, %.2e)\n",
                chains, bundle ? " (bundled)" : "", c.statistics.capacitance_steps, c.statistics.sparse_capacitance_steps,
                c.statistics.capacitance_fallbacks,
                c.automatic.translation, c.automatic.rotation, c.dense.translation, c.dense.rotation);
    EXPECT_EQ(c.statistics.capacitance_steps, 1) << chains << " rods: the capacitance path";
    EXPECT_EQ(c.statistics.capacitance_fallbacks, 0);
    EXPECT_LT(c.automatic.translation, std::max(1e-12, 4.0 * c.dense.translation)) << chains << " rods";
    EXPECT_LT(c.automatic.rotation, std::max(1e-12, 4.0 * c.dense.rotation)) << chains << " rods";
  }
}

// A cluster of 40 rods of 20 spheres in a staircase (156 of its 800 spheres
// coupled by contacts off the band, a capacitance matrix of 936 unknowns)
// takes the capacitance path with the sparse LU of I + G M, and agrees
// with the sparse LU of the whole matrix to the bound of the clusters
// above (1e-12, or four times the sparse and dense LUs' own difference).
TEST(ChainContactSolve, ALargeClusterTakesTheSparseCapacitanceSolve) {
  const OverdampedRod rod = staircase(40, 20, false);
  const Compared c = compare_with_sparse_lu(rod, local_drag(rod.size()));
  std::printf("40 rods of 20 in a staircase: sparse capacitance steps %ld, fallbacks %ld; from the sparse LU: "
              "translations %.2e, rotations %.2e (dense LU: %.2e, %.2e)\n",
              c.statistics.sparse_capacitance_steps, c.statistics.capacitance_fallbacks, c.automatic.translation,
              c.automatic.rotation, c.dense.translation, c.dense.rotation);
  EXPECT_EQ(c.statistics.capacitance_steps, 1);
  EXPECT_EQ(c.statistics.sparse_capacitance_steps, 1);
  EXPECT_EQ(c.statistics.capacitance_fallbacks, 0);
  EXPECT_LT(c.automatic.translation, std::max(1e-12, 4.0 * c.dense.translation));
  EXPECT_LT(c.automatic.rotation, std::max(1e-12, 4.0 * c.dense.rotation));
}

// A cluster where every sphere is coupled (40 rods laid side by side, each
// sphere touching its neighbours: 320 of 320), whose capacitance matrix
// would be as large as the step's matrix and denser: the sparse LU solves
// the same matrix (its entries summed in the same order as the general
// path's), the same result to round-off.
TEST(ChainContactSolve, AClusterCoupledThroughoutGoesToTheSparseLu) {
  std::vector<OverdampedRod> rods;
  for (int k = 0; k < 40; ++k) rods.push_back(rod_along_x(8, Eigen::Vector3d(0.3 * d * (k % 2), 0.95 * d * (k - 20), 0.0)));
  OverdampedRod rod = merge_rods(rods);
  const OverdampedRod loaded = staircase(40, 8, false);  // its loads and velocities
  rod.external_forces = loaded.external_forces;
  rod.external_torques = loaded.external_torques;
  rod.velocities = loaded.velocities;
  rod.angular_velocities = loaded.angular_velocities;
  const Compared c = compare_with_sparse_lu(rod, local_drag(rod.size()));
  std::printf("40 rods side by side: hand-overs %ld, fallbacks %ld; from the sparse LU: translations %.2e, rotations %.2e\n",
              c.statistics.capacitance_handovers, c.statistics.capacitance_fallbacks, c.automatic.translation,
              c.automatic.rotation);
  EXPECT_EQ(c.statistics.capacitance_handovers, 1);  // sent on by design, not refused
  EXPECT_EQ(c.statistics.capacitance_fallbacks, 0);
  EXPECT_EQ(c.statistics.capacitance_steps, 0);
  EXPECT_LT(c.automatic.translation, 1e-12);  // the same matrix to the last bit: only the pattern's explicit zeros differ
  EXPECT_LT(c.automatic.rotation, 1e-12);
}

// A sphere nothing holds in some direction (no drag, frictionless contact
// with one partner: its diagonal block has rank 1) makes the band's block
// elimination singular: the step goes to the sparse LU, which reports the
// singular matrix as a non-finite update for the step guard, as the sparse
// path does (test_step_linear_solves.cpp), not a solve through infinite pivots.
TEST(ChainContactSolve, ASingularBandTakesTheSparseFallback) {
  // Rods 0 and 2 of three spheres apart; rod 1 a lone sphere touching rod 0's sphere 3.
  std::vector<OverdampedRod> rods = {rod_along_x(5, {0, 0, 0}), lone_sphere({0, 0.97 * d, 0}),
                                     rod_along_x(5, {0, 5 * d, 0})};
  OverdampedRod rod = merge_rods(rods);
  rod.external_forces.assign(rod.size(), Eigen::Vector3d(1e-9, 0, 0));
  RodDrag drag = local_drag(rod.size());
  drag.resistance[5].setZero();  // the lone sphere: no drag
  drag.rotational_resistance[5] = 0.0;
  WallContactParameters contact = rod_contact();
  contact.rod_friction_coefficient = 0.0;
  OverdampedRodSolver solver;
  OverdampedStepResult result;
  ASSERT_NO_THROW(solver.step(rod, drag, dt, nullptr, &contact, result));
  EXPECT_TRUE(result.rod_contact);
  EXPECT_EQ(solver.statistics().capacitance_fallbacks, 1);
  bool finite = true;
  for (const Eigen::Vector3d& x : rod.positions) finite = finite && x.allFinite();
  EXPECT_FALSE(finite);
}
