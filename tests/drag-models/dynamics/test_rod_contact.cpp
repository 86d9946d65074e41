// Rod-rod contact inside the implicit step: two rods
// pressed together stop at the Hertz overlap of their load (Johnson 1985,
// eq. 4.22 for two equal elastic spheres) and never press in further than
// the guard's stated bound; friction between two rods is capped at mu F_n
// (sliding at exactly mu F_n, sticking below it); rods beyond reach are
// separate clusters and a merged step of rods that do not touch equals the
// rods' own steps bit for bit.
#include "common/math_constants.h"
#include "dynamics/guarded_step.h"
#include "dynamics/overdamped_rod_step.h"
#include "dynamics/rod_cluster.h"
#include "hydro/hydrodynamic_model.h"
#include "rod/rod_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace hsrod;

namespace {
using hsrod::kPi;
constexpr double d = 3e-6, r = 0.5 * d;             // sphere [m]
constexpr double viscosity = 1e-3;                  // [Pa s]
const double zeta = 3 * kPi * viscosity * d;        // translational resistance [N s/m]
const double zeta_r = kPi * viscosity * d * d * d;  // rotational resistance [N m s]
constexpr double E = 15e6, nu = 0.3;                // the paper's stiff rod [Pa], [-]

// A straight rod of n spheres along x centred at `centre`.
OverdampedRod rod_along_x(int n, const Eigen::Vector3d& centre) {
  RodSpec spec;
  spec.number_of_sections = n;
  spec.sphere_diameter = d;
  spec.centre = centre;
  spec.angle = kPi / 2;  // from the y axis: along x
  return make_overdamped_rod(make_rod_layout(spec), {E, nu, d, 0.0}, d);
}

OverdampedRod lone_sphere(const Eigen::Vector3d& x) {
  OverdampedRod rod;
  rod.positions = {x};
  rod.orientations = {Eigen::Quaterniond::Identity()};
  rod.radii = {r};
  rod.external_forces = {Eigen::Vector3d::Zero()};
  rod.external_torques = {Eigen::Vector3d::Zero()};
  return rod;
}

// Isotropic drag without a stream; `scale` per sphere (a held rod: 1e6).
RodDrag still_fluid(const std::vector<double>& scale) {
  RodDrag drag;
  drag.resize(static_cast<int>(scale.size()));
  for (std::size_t i = 0; i < scale.size(); ++i) {
    drag.resistance[i] = scale[i] * zeta * Eigen::Matrix3d::Identity();
    drag.rotational_resistance[i] = scale[i] * zeta_r;
  }
  return drag;
}

WallContactParameters rod_contact(double friction) {
  WallContactParameters p;
  p.youngs_modulus = E;
  p.poisson_ratio = nu;
  p.rod_contact = true;
  p.rod_friction_coefficient = friction;
  p.slip_velocity = 1e-6;
  return p;
}

// Hertz overlap of two equal spheres under a load F: F = 4/3 E_p sqrt(R*) delta^(3/2)
// with E_p = E / (2 (1 - nu^2)), R* = r / 2 (Johnson 1985, eq. 4.22).
double hertz_overlap(double load) {
  const double pair_modulus = E / (2.0 * (1.0 - nu * nu));
  return std::pow(3.0 * load / (4.0 * pair_modulus * std::sqrt(0.5 * r)), 2.0 / 3.0);
}

// Largest overlap between spheres of different rods [m].
double largest_overlap(const OverdampedRod& rod) {
  double largest = 0.0;
  for (int i = 0; i < rod.size(); ++i)
    for (int j = i + 1; j < rod.size(); ++j)
      if (!rod.same_rod(i, j))
        largest = std::max(largest, rod.radii[i] + rod.radii[j] - (rod.positions[i] - rod.positions[j]).norm());
  return largest;
}
}  // namespace

TEST(RodContact, RodsPressedTogetherStopAtTheHertzOverlap) {
  // Two parallel 5-sphere rods 0.1 d apart in a gap of 1.05 d (the gap
  // walls keep them from riding over each other: head-on pressing is
  // unstable to that, as for real rods in a wider gap), each sphere pushed
  // towards the other rod by F; guarded steps of 1e-5 s (the Hertz
  // relaxation time zeta / k is ~4e-8 s at 1e-9 N: 250x below the step).
  const ChannelGeometry channel(200e-6, 200e-6, 1.05 * d);
  for (double load : {1e-9, 1e-7}) {
    const int n = 5;
    const Eigen::Vector3d centre(100e-6, 100e-6, 0.525 * d);
    OverdampedRod rod = merge_rods({rod_along_x(n, centre), rod_along_x(n, centre + Eigen::Vector3d(0, 1.1 * d, 0))});
    for (int i = 0; i < 2 * n; ++i) rod.external_forces[i] = Eigen::Vector3d(0, i < n ? load : -load, 0);
    const RodDrag drag = still_fluid(std::vector<double>(2 * n, 1.0));
    const WallContactParameters contact = rod_contact(0.0);
    StepGuardLimits limits;
    OverdampedRodSolver solver;
    double deepest = 0.0;
    bool touched = false;
    for (int step = 0; step < 200; ++step) {
      const GuardedStepReport report = guarded_rod_step(solver, rod, drag, {}, 1e-5, &channel, &contact, limits);
      touched = touched || report.result.rod_contact;
      deepest = std::max(deepest, largest_overlap(rod));
    }
    const double expected = hertz_overlap(load);
    const double final_overlap = largest_overlap(rod);
    std::printf("load %.0e N: Hertz overlap %.4e m (%.4f r), final %.4e m, deepest during approach %.4e m (%.4f r)\n",
                load, expected, expected / r, final_overlap, deepest, deepest / r);
    EXPECT_TRUE(touched);
    // Equilibrium: every pair carries F (the rods are straight and parallel).
    for (int i = 0; i < n; ++i) {
      const double overlap = d - (rod.positions[i] - rod.positions[n + i]).norm();
      EXPECT_NEAR(overlap, expected, 1e-3 * expected) << "pair " << i;
    }
    // Stated bound while approaching: the load's Hertz overlap plus the
    // guard's max_overlap radii of new overlap in one step.
    EXPECT_LT(deepest, expected + limits.max_overlap * r);
    EXPECT_NEAR(rod.positions[0].y() + rod.positions[n].y(), 2 * centre.y() + 1.1 * d, 1e-12)
        << "the pair's centre stays put";
  }
}

TEST(RodContact, WithoutRodContactTheRodsPassThroughEachOther) {
  // The same rods with rod_contact off: the only thing keeping them apart is the contact.
  const int n = 3;
  OverdampedRod rod = merge_rods({rod_along_x(n, {0, 0, 0}), rod_along_x(n, {0, 1.1 * d, 0})});
  for (int i = 0; i < 2 * n; ++i) rod.external_forces[i] = Eigen::Vector3d(0, i < n ? 1e-9 : -1e-9, 0);
  WallContactParameters contact = rod_contact(0.0);
  contact.rod_contact = false;
  OverdampedRodSolver solver;
  for (int step = 0; step < 20; ++step) solver.step(rod, still_fluid(std::vector<double>(2 * n, 1.0)), 1e-5, nullptr, &contact);
  EXPECT_LT(rod.positions[n].y(), rod.positions[0].y()) << "crossed";
}

namespace {
// Sphere A (a rod of one sphere that cannot spin) pressed onto sphere B (a
// held rod) by P along -y and pushed along z by T; small steps, so that the
// contact's geometry stays that of the start (A moves < 0.01 d).
struct SlidingPair {
  static constexpr double held = 1e9;  // resistance scale of what cannot move
  OverdampedRod rod = merge_rods({lone_sphere({0, 0, 0}), lone_sphere({0, d - hertz_overlap(1e-9), 0})});
  RodDrag drag = still_fluid({held, 1.0});
  WallContactParameters contact = rod_contact(0.5);
  OverdampedRodSolver solver;
  SlidingPair() { drag.rotational_resistance[1] = held * zeta_r; }
  struct Loads {
    double normal, friction, slip;  // on A [N], [N], [m/s]
  };
  // One step of dt; the contact force on A from its force balance
  // (contact = zeta v - external), split along the normal at the step's start.
  Loads step(double tangential, double dt) {
    rod.external_forces[1] = Eigen::Vector3d(0.0, -1e-9, tangential);
    const Eigen::Vector3d n = (rod.positions[1] - rod.positions[0]).normalized();
    const OverdampedStepResult result = solver.step(rod, drag, dt, nullptr, &contact);
    const Eigen::Vector3d on_a = zeta * result.velocities[1] - rod.external_forces[1];
    const Eigen::Vector3d tangential_part = on_a - on_a.dot(n) * n;
    return {on_a.dot(n), tangential_part.norm(), result.velocities[1].z() - result.velocities[0].z()};
  }
};
}  // namespace

TEST(RodContact, SlidingFrictionBetweenRodsIsMuTimesTheNormalForce) {
  constexpr double mu = 0.5, press = 1e-9;
  SlidingPair s;
  for (int k = 0; k < 20; ++k) s.step(0.0, 1e-8);  // the normal contact settles (Hertz relaxation ~4e-8 s)
  const double load = 2.0 * mu * press;
  SlidingPair::Loads loads{};
  int breakaway = -1;
  for (int k = 0; k < 60; ++k) {
    loads = s.step(load, 1e-8);
    EXPECT_LE(loads.friction, load * (1 + 1e-9)) << "friction never exceeds the load it resists";
    if (breakaway < 0 && loads.friction <= mu * loads.normal * (1 + 1e-3)) breakaway = k;
  }
  std::printf("sliding: T = %.3e N, friction %.6e N, mu F_n %.6e N, slip %.3e m/s (expected %.3e), "
              "breakaway after %d steps\n", load, loads.friction, mu * loads.normal, loads.slip,
              (load - mu * press) / zeta, breakaway);
  EXPECT_NEAR(loads.normal, press, 1e-2 * press);  // the load's normal part (A has moved 0.004 d along z)
  EXPECT_NEAR(loads.friction, mu * loads.normal, 1e-3 * mu * press);
  // The lagged secant law (dynamics/wall_contact.h) starts from the stick:
  // its slip grows by the factor T / (mu F_n) = 2 per step while far below
  // the sliding speed v (log2(v / v_s) ~ 14 steps) and then converges
  // linearly with ratio mu F_n / T = 1/2 (~10 steps to 1e-3): until then
  // the friction exceeds mu F_n (a breakaway of ~24 steps, of any length).
  EXPECT_GE(breakaway, 0);
  EXPECT_LE(breakaway, 30);
  EXPECT_GT(loads.slip, s.contact.slip_velocity);
  EXPECT_LT(std::fabs(s.rod.positions[1].z()), 0.01 * d);
}

TEST(RodContact, BelowMuTimesTheNormalForceARodSticks) {
  constexpr double mu = 0.5, press = 1e-9;
  SlidingPair s;
  for (int k = 0; k < 20; ++k) s.step(0.0, 1e-8);
  const double load = 0.3 * mu * press;
  SlidingPair::Loads loads{};
  for (int k = 0; k < 10; ++k) loads = s.step(load, 1e-8);
  std::printf("sticking: T = %.3e N, friction %.6e N, mu F_n %.6e N, slip %.3e m/s\n", load, loads.friction,
              mu * loads.normal, loads.slip);
  // The regularised law's stick: a creep below the slip velocity,
  // v = T / (zeta + mu F_n / v_s), and the friction carries the load.
  EXPECT_LT(loads.slip, s.contact.slip_velocity);
  EXPECT_NEAR(loads.slip, load / (zeta + mu * press / s.contact.slip_velocity), 2e-3 * loads.slip);
  EXPECT_LE(loads.friction, mu * loads.normal);
  EXPECT_NEAR(loads.friction, load, 1e-3 * load);
}

TEST(RodContact, ClustersJoinRodsWithinReachTransitively) {
  const auto positions = [](const OverdampedRod& rod) { return rod.positions; };
  const OverdampedRod a = rod_along_x(5, {0, 0, 0}), b = rod_along_x(5, {0, 1.05 * d, 0}),
                      c = rod_along_x(5, {0, 2.1 * d, 0}), far = rod_along_x(5, {0, 100 * d, 0});
  const auto clusters = rod_clusters({positions(far), positions(c), positions(a), positions(b)}, 1.1 * d);
  ASSERT_EQ(clusters.size(), 2u);
  EXPECT_EQ(clusters[0], std::vector<int>({0}));
  EXPECT_EQ(clusters[1], std::vector<int>({1, 2, 3}));  // c - b - a: a and c are 2.1 d apart
}

TEST(RodContact, RodsThatDoNotTouchStepExactlyAsAlone) {
  // Merged (one solve) and alone: bit-identical while no contact couples them.
  OverdampedRod a = rod_along_x(6, {0, 0, 0}), b = rod_along_x(4, {2 * d, 3 * d, 0});
  for (int i = 0; i < a.size(); ++i) a.external_forces[i] = Eigen::Vector3d(1e-9, 2e-10 * i, 0);
  for (int i = 0; i < b.size(); ++i) b.external_forces[i] = Eigen::Vector3d(-1e-9, 3e-10 * i, 1e-10);
  OverdampedRod both = merge_rods({a, b});
  const WallContactParameters contact = rod_contact(0.5);
  OverdampedRodSolver solve_a, solve_b, solve_both;
  for (int step = 0; step < 5; ++step) {
    solve_a.step(a, still_fluid(std::vector<double>(6, 1.0)), 1e-5, nullptr, &contact);
    solve_b.step(b, still_fluid(std::vector<double>(4, 1.0)), 1e-5, nullptr, &contact);
    const auto result = solve_both.step(both, still_fluid(std::vector<double>(10, 1.0)), 1e-5, nullptr, &contact);
    EXPECT_FALSE(result.rod_contact);
  }
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector3d alone = i < 6 ? a.positions[i] : b.positions[i - 6];
    EXPECT_EQ(both.positions[i], alone) << "sphere " << i;
  }
}

// Contact within a step: two spheres of radius d/2 whose straight paths
// cross come within contact although neither end touches (a sphere carried
// through another in one step); paths that pass 1.05 d apart, or groups
// that touch only within themselves, do not meet. The closest approach of
// the segments is exact geometry: d0 = (-3d, 0.9d) to (3d, 0.9d) against a
// sphere at rest at the origin passes at 0.9 d < d, at 1.05 d > d.
TEST(RodContact, GroupsMeetWhereTheirPathsComeWithinContactInTheStep) {
  const std::vector<double> r1{0.5 * d}, r2{0.5 * d, 0.5 * d};
  const std::vector<Eigen::Vector3d> at_rest{{0, 0, 0}}, pair{{20 * d, 0, 0}, {20.9 * d, 0, 0}};
  for (const double offset : {0.9, 1.05}) {
    const std::vector<Eigen::Vector3d> start{{-3 * d, offset * d, 0}}, end{{3 * d, offset * d, 0}};
    const auto meeting = groups_meeting_in_step({&at_rest, &start, &pair}, {&at_rest, &end, &pair}, {&r1, &r1, &r2});
    if (offset < 1.0) {
      ASSERT_EQ(meeting.size(), 1u) << "paths " << offset << " d apart";
      EXPECT_EQ(meeting[0], std::make_pair(0, 1));
    } else {
      EXPECT_TRUE(meeting.empty()) << "paths " << offset << " d apart";
    }
  }
}
