// Level 3 between rods solved rod by rod (hydro/cross_rod_disturbance.h)
// against the joint solve over all spheres (NonlocalRodModel::evaluate_rods),
// the reference it must reproduce: 2-5 rods of 10 spheres at several
// spacings, the resistance problem (sphere velocities given: forces) and
// the mobility problem (forces given: velocities, the step's problem without
// bonds). Iterated over the rods (block Gauss-Seidel on the obstruction forces) to
// a change of 1e-12, the rod-by-rod loads equal the joint ones to 1e-8 of
// the largest (the rest is the iteration's residual and round-off of two
// different factorisations, ~1e-12); one sweep from the rods' lone
// obstruction forces unknown (zero: the lagged coupling's first step) is off
// by the coupling between the rods, stated
// here; rods side by side within a sphere diameter converge slowly, and a
// capped iteration reports its residual change.
#include "hydro/cross_rod_disturbance.h"
#include "hydro/nonlocal_model.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using hsrod::NonlocalRodModel;
using hsrod::RodDrag;
using hsrod::RodGeometry;
using hsrod::RodObstructionForces;
using hsrod::UnitObstruction;

constexpr double kGap = 20e-6;      // H [m]
constexpr double kDiameter = 3e-6;  // d [m]: beta 0.15, the benchmark scene's

NonlocalRodModel model() {
  return NonlocalRodModel(hsrod::HydrodynamicParameters{1e-3, kGap, kDiameter},
                          hsrod::ConfinementTable::default_table());
}

// `count` rods of 10 spheres in a row across the stream, `spacing` [m]
// between their axes, each turned a little differently (no symmetry makes
// a coupling vanish), at mid-gap.
std::vector<RodGeometry> rods_in_a_row(int count, double spacing) {
  std::vector<RodGeometry> rods;
  for (int r = 0; r < count; ++r) {
    RodGeometry rod = hsrod_test::straight_rod(10, kDiameter, 0.15 * r - 0.1);
    for (auto& x : rod.positions) x += Eigen::Vector3d(0.3 * kDiameter * r, spacing * r, 0.5 * kGap);
    rod.id = r;
    rods.push_back(rod);
  }
  return rods;
}

std::vector<Eigen::Vector3d> slice(const std::vector<Eigen::Vector3d>& all, int from, int count) {
  return {all.begin() + from, all.begin() + from + count};
}

// The rods solved apart: per rod its lone load and obstruction, iterated
// `sweeps` times (block Jacobi), each sweep either at the given velocities
// (resistance problem) or solving each rod's velocities from the given
// external forces (mobility problem). Returns the last sweep's relative
// change of the obstruction forces; `forces`/`velocities` the result.
struct ApartResult {
  std::vector<Eigen::Vector3d> forces, velocities;  // hydrodynamic force [N], velocity [m/s] per sphere
  double last_change = 0.0;                         // [-]
  int sweeps = 0;
};

ApartResult solve_apart(const NonlocalRodModel& m, const std::vector<RodGeometry>& rods,
                        const std::vector<Eigen::Vector3d>* given_velocities,
                        const std::vector<Eigen::Vector3d>* external_forces, int max_sweeps, double tolerance) {
  hsrod_test::UniformStream flow(kGap);
  const int count = static_cast<int>(rods.size());
  std::vector<RodDrag> lone(count);
  std::vector<UnitObstruction> units(count);
  std::vector<RodObstructionForces> forces(count), previous;
  std::vector<int> first(count, 0);
  for (int r = 0; r < count; ++r) {
    m.evaluate_alone({rods[r]}, flow, lone[r], nullptr, units[r]);
    if (r > 0) first[r] = first[r - 1] + rods[r - 1].size();
    forces[r].start(rods[r].size());
  }
  ApartResult out;
  const int total = first.back() + rods.back().size();
  out.velocities.assign(total, Eigen::Vector3d::Zero());
  if (given_velocities) out.velocities = *given_velocities;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    previous = forces;
    for (int r = 0; r < count; ++r) {
      const int n = rods[r].size();
      // The disturbance of the others' latest obstruction (Gauss-Seidel:
      // rods before r in this sweep, the others from the last).
      forces[r].clear_disturbance();
      for (int s = 0; s < count; ++s)
        if (s != r) m.add_disturbance(rods[r], forces[r], rods[s], forces[s]);
      units[r].driving_disturbance = forces[r].driving_disturbance;
      units[r].velocity_disturbance = forces[r].velocity_disturbance;
      RodDrag drag = lone[r];
      hsrod::add_cross_rod_disturbance(units[r], drag);
      if (external_forces) {  // 0 = driving - R v + f
        Eigen::VectorXd rhs(3 * n);
        for (int i = 0; i < n; ++i) rhs.segment<3>(3 * i) = drag.driving_force[i] + (*external_forces)[first[r] + i];
        const Eigen::VectorXd v = drag.coupled_resistance.ldlt().solve(rhs);
        for (int i = 0; i < n; ++i) out.velocities[first[r] + i] = v.segment<3>(3 * i);
      }
      const std::vector<Eigen::Vector3d> v = slice(out.velocities, first[r], n);
      hsrod::unit_obstruction_forces(units[r], v, forces[r].driving, forces[r].velocity);
      Eigen::VectorXd scratch;
      std::vector<Eigen::Vector3d> f;
      drag.forces(v, f, scratch);
      if (r == 0) out.forces.clear();
      out.forces.insert(out.forces.end(), f.begin(), f.end());
    }
    out.sweeps = sweep + 1;
    out.last_change = hsrod::obstruction_change(previous, forces);
    if (out.last_change < tolerance) break;
  }
  return out;
}

// The joint solve: forces at given velocities, or velocities at given external forces.
ApartResult solve_joint(const NonlocalRodModel& m, const std::vector<RodGeometry>& rods,
                        const std::vector<Eigen::Vector3d>* given_velocities,
                        const std::vector<Eigen::Vector3d>* external_forces) {
  hsrod_test::UniformStream flow(kGap);
  RodDrag drag;
  m.evaluate_rods(rods, flow, drag, nullptr);
  const int n = static_cast<int>(drag.driving_force.size());
  ApartResult out;
  out.velocities.assign(n, Eigen::Vector3d::Zero());
  if (given_velocities) out.velocities = *given_velocities;
  if (external_forces) {
    Eigen::VectorXd rhs(3 * n);
    for (int i = 0; i < n; ++i) rhs.segment<3>(3 * i) = drag.driving_force[i] + (*external_forces)[i];
    const Eigen::VectorXd v = drag.coupled_resistance.ldlt().solve(rhs);
    for (int i = 0; i < n; ++i) out.velocities[i] = v.segment<3>(3 * i);
  }
  Eigen::VectorXd scratch;
  drag.forces(out.velocities, out.forces, scratch);
  return out;
}

double relative_difference(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    diff = std::max(diff, (a[i] - b[i]).norm());
    scale = std::max(scale, b[i].norm());
  }
  return diff / scale;
}

// Velocities of a sedimenting, spinning set: different per sphere, of the
// stream's order (1 m/s here: the loads are linear in them).
std::vector<Eigen::Vector3d> some_velocities(int n) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < n; ++i) v.emplace_back(0.6 + 0.02 * i, 0.1 * std::sin(0.7 * i), 0.0);
  return v;
}

// Per sphere a force of the order of its drag in the stream, varying along the rods.
std::vector<Eigen::Vector3d> some_forces(const NonlocalRodModel& m, int n) {
  const double zeta = m.film_friction() + m.obstruction_friction();  // [N s/m], times 1 m/s
  std::vector<Eigen::Vector3d> f;
  for (int i = 0; i < n; ++i) f.emplace_back(0.2 * zeta * std::cos(0.3 * i), -0.5 * zeta, 0.0);
  return f;
}

constexpr double kIterationTolerance = 1e-12;  // change of P between sweeps [-]
constexpr double kAgreement = 1e-8;             // rod by rod against joint [-]

TEST(CrossRodDisturbance, IteratedRodByRodEqualsTheJointSolve) {
  const NonlocalRodModel m = model();
  double last_one_sweep = 1.0;
  for (double spacing_d : {40.0, 15.0, 5.0, 2.5}) {
    double one_sweep_largest = 0.0;
    for (int count = 2; count <= 5; ++count) {
      const std::vector<RodGeometry> rods = rods_in_a_row(count, spacing_d * kDiameter);
      const int n = 10 * count;
      const std::vector<Eigen::Vector3d> v = some_velocities(n), f = some_forces(m, n);
      // Resistance problem: forces at given velocities.
      const ApartResult joint_f = solve_joint(m, rods, &v, nullptr);
      const ApartResult apart_f = solve_apart(m, rods, &v, nullptr, 200, kIterationTolerance);
      EXPECT_LT(apart_f.last_change, kIterationTolerance) << spacing_d << " d, " << count << " rods";
      EXPECT_LT(relative_difference(apart_f.forces, joint_f.forces), kAgreement) << spacing_d << " d, " << count;
      // Mobility problem: velocities at given forces.
      const ApartResult joint_v = solve_joint(m, rods, nullptr, &f);
      const ApartResult apart_v = solve_apart(m, rods, nullptr, &f, 200, kIterationTolerance);
      EXPECT_LT(apart_v.last_change, kIterationTolerance) << spacing_d << " d, " << count << " rods";
      EXPECT_LT(relative_difference(apart_v.velocities, joint_v.velocities), kAgreement) << spacing_d << " d, " << count;
      // One sweep from no disturbance (the lagged coupling's first step).
      const ApartResult once = solve_apart(m, rods, nullptr, &f, 1, 0.0);
      const double one_sweep = relative_difference(once.velocities, joint_v.velocities);
      one_sweep_largest = std::max(one_sweep_largest, one_sweep);
      std::printf("spacing %5.1f d, %d rods: iterated %2d/%2d sweeps, forces %.1e, velocities %.1e; one sweep %.1e\n",
                  spacing_d, count, apart_f.sweeps, apart_v.sweeps,
                  relative_difference(apart_f.forces, joint_f.forces),
                  relative_difference(apart_v.velocities, joint_v.velocities), one_sweep);
    }
    // The coupling between the rods grows as they come closer: so does what
    // one sweep leaves out.
    if (spacing_d < 40.0) {
      EXPECT_GT(one_sweep_largest, last_one_sweep) << spacing_d << " d";
    }
    last_one_sweep = one_sweep_largest;
  }
}

// Rods side by side nearly touching (1.1 d between axes: the near field at
// full strength) still converge (Gauss-Seidel on a symmetric positive
// definite system), but slowly: a few sweeps leave a change far above the
// tolerance, which the caller must see (fix rod/implicit refuses the step
// then), and the velocities' error is ~50x the change there (the close
// pair's mobility amplifies what the iteration leaves in P).
TEST(CrossRodDisturbance, RodsSideBySideConvergeSlowlyAndSaySo) {
  const NonlocalRodModel m = model();
  for (double spacing_d : {1.1, 1.5}) {
    const std::vector<RodGeometry> rods = rods_in_a_row(5, spacing_d * kDiameter);
    const std::vector<Eigen::Vector3d> f = some_forces(m, 50);
    const ApartResult joint = solve_joint(m, rods, nullptr, &f);
    const ApartResult few = solve_apart(m, rods, nullptr, &f, 4, 1e-8);
    EXPECT_EQ(few.sweeps, 4);
    EXPECT_GT(few.last_change, 100 * 1e-8) << spacing_d << " d";  // far above a 1e-8 tolerance, and reported
    const ApartResult apart = solve_apart(m, rods, nullptr, &f, 100, 1e-10);
    EXPECT_LT(apart.last_change, 1e-10) << spacing_d << " d";
    EXPECT_LT(relative_difference(apart.velocities, joint.velocities), 1e-7) << spacing_d << " d";
    std::printf("spacing %.1f d, 5 rods: 4 sweeps leave change %.1e (velocities %.1e); converged in %d sweeps, "
                "velocities %.1e\n", spacing_d, few.last_change, relative_difference(few.velocities, joint.velocities),
                apart.sweeps, relative_difference(apart.velocities, joint.velocities));
  }
}

TEST(CrossRodDisturbance, WallImagesAreRefusedRodByRod) {
  NonlocalRodModel m = model();
  m.set_wall_reflection(hsrod::WallReflection::images);
  hsrod_test::UniformStream flow(kGap);
  RodDrag drag;
  UnitObstruction unit;
  EXPECT_THROW(m.evaluate_alone(rods_in_a_row(1, 0.0), flow, drag, nullptr, unit), std::invalid_argument);
}

}  // namespace
