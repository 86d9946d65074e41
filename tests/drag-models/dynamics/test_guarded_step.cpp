// The accuracy guard of the implicit rod step against closed forms: a step
// whose linearisation error, displacement or wall crossing is too large is
// taken as substeps or refused, never silently accepted, and lands where
// the exact motion does (rigid rotation of a stiff rod under a couple;
// Hertz equilibrium at a wall; the spring strain of a pulled rod; a sphere
// sliding off a cylinder). Refusals in a fast stream and quiet steps at a
// wall: test_guarded_step_decisions.cpp.
#include "common/math_constants.h"
#include "dynamics/guarded_step.h"
#include "flow/uniform_flow.h"
#include "hydro/hydrodynamic_model.h"
#include "rod/rod_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace hsrod;

namespace {

// Fluid at rest (the rod is driven by external forces only).
UniformFlow still_fluid() { return UniformFlow::wide_slit(1.0, Eigen::Vector2d::Zero()); }

struct CoupleScene {
  int n = 10;
  double d = 3e-6, youngs_modulus = 1.5e12, couple_force = 4.6e-9, duration = 2e-4;
};

double rod_angle(const OverdampedRod& rod) {
  const Eigen::Vector3d t = rod.positions.front() - rod.positions.back();
  return std::atan2(t.y(), t.x());
}

// A straight stiff rod along x; forces +F y on the first sphere and -F y on
// the last (fixed in the lab frame), isotropic drag in still fluid. A rigid
// rod turns as d theta/dt = a cos(theta), a = F (n-1) d / zeta_rot, so
// theta(t) = 2 atan(tanh(a t / 2)) (the Gudermannian of a t).
struct CoupleRun {
  double angle, exact, worst_strain;
  int substeps;
};
CoupleRun run_couple(const CoupleScene& s, double dt, bool guarded) {
  RodSpec spec;
  spec.number_of_sections = s.n;
  spec.sphere_diameter = s.d;
  spec.angle = 0.5 * kPi;  // along x
  const BeamBondMaterial material{s.youngs_modulus, 0.3, s.d, 0.0};
  OverdampedRod rod = make_overdamped_rod(make_rod_layout(spec), material, s.d);
  const auto model = make_hydrodynamic_model("isotropic", {1e-3, s.d / 0.15, s.d}, ConfinementTable::default_table());
  const UniformFlow fluid = still_fluid();
  RodGeometry geometry;
  geometry.sphere_diameter = s.d;
  RodDrag drag;
  auto drag_at = [&](const OverdampedRod& r, RodDrag& out) {
    geometry.positions = r.positions;
    model->evaluate(geometry, fluid, out);
  };
  rod.external_forces.front() = Eigen::Vector3d(0, s.couple_force, 0);
  rod.external_forces.back() = Eigen::Vector3d(0, -s.couple_force, 0);
  const double theta0 = rod_angle(rod);
  drag_at(rod, drag);
  // Rotational friction of the rigid rod about its centre.
  const Eigen::Vector3d centre = 0.5 * (rod.positions.front() + rod.positions.back());
  double zeta_rot = 0.0;
  for (int i = 0; i < s.n; ++i)
    zeta_rot += drag.resistance[i](1, 1) * (rod.positions[i] - centre).squaredNorm() + drag.rotational_resistance[i];
  const double a = s.couple_force * (s.n - 1) * s.d / zeta_rot;
  OverdampedRodSolver solver;
  CoupleRun out{0, 2.0 * std::atan(std::tanh(0.5 * a * s.duration)), 0, 0};
  const int steps = static_cast<int>(std::lround(s.duration / dt));
  for (int k = 0; k < steps; ++k) {
    drag_at(rod, drag);
    if (guarded) {
      const GuardedStepReport r = guarded_rod_step(solver, rod, drag, drag_at, dt, nullptr, nullptr);
      out.substeps += r.substeps;
      out.worst_strain = std::max(out.worst_strain, r.largest_bond_strain);
    } else {
      solver.step(rod, drag, dt, nullptr, nullptr);
      out.substeps += 1;
      out.worst_strain = std::max(out.worst_strain, bond_strain_and_energy(rod).first);
    }
  }
  out.angle = rod_angle(rod) - theta0;
  return out;
}

}  // namespace

TEST(GuardedStep, StiffRodTurnsAsTheRigidRodInPlainSteps) {
  // A very stiff rod (E = 1.5e12 Pa and 1.5e13 Pa) must turn as much at a
  // large step as at a small one. A tangent position update would stretch
  // each turning bond by phi^2 / 2, and the next step's geometric stiffness
  // of that spurious tension would block the rotation on every other step
  // (45 % behind the closed form at dt = 4e-6 s, and still at 4e-7 s).
  // With finite bond rotations (dynamics/finite_rotation_update.h) the plain
  // step follows the rigid rotation to backward Euler's first-order error
  // (a dt / 2 = 1 % at a dt = 0.0195 rad per step; 50 steps of 4e-6 s), and
  // the guard accepts every step whole (its co-rotated Newton estimate does
  // not mistake the turned stiff axis for an error).
  for (double youngs_modulus : {1.5e12, 1.5e13}) {
    CoupleScene s;
    s.youngs_modulus = youngs_modulus;
    const CoupleRun plain = run_couple(s, 4e-6, false);
    const CoupleRun guarded = run_couple(s, 4e-6, true);
    std::printf("E %.2g Pa: rigid rotation %.4f rad: plain step %.4f rad (%+.2f %%, %d steps, strain %.2e), guarded "
                "%.4f rad (%+.2f %%, %d substeps, strain %.2e)\n",
                youngs_modulus, plain.exact, plain.angle, 100 * (plain.angle / plain.exact - 1), plain.substeps,
                plain.worst_strain, guarded.angle, 100 * (guarded.angle / guarded.exact - 1), guarded.substeps,
                guarded.worst_strain);
    EXPECT_NEAR(plain.angle / plain.exact, 1.0, 0.01);
    EXPECT_NEAR(guarded.angle / guarded.exact, 1.0, 0.01);
    EXPECT_EQ(guarded.substeps, 50);
    // The rigid rotation leaves the bonds at the couple's own strain
    // (F / (E A) ~ 1e-10 at 1.5e12 Pa), not the phi^2 / 2 = 1.9e-4 of the
    // tangent update.
    EXPECT_LT(plain.worst_strain, 1e-8);
  }
}

TEST(GuardedStep, StepIntoAWallIsSubdividedAndEndsAtTheHertzEquilibrium) {
  // A sphere 10 um from the side wall pushed towards it so fast that one step
  // of 1e-3 s would carry it 20 um through the wall (what the plain step
  // does); the guard subdivides and the sphere stops at the Hertz overlap.
  ChannelGeometry channel(1e-3, 1e-4, 20e-6);
  WallContactParameters walls;
  walls.youngs_modulus = 15e6;
  OverdampedRod rod;
  rod.positions = {Eigen::Vector3d(5e-4, 10e-6, 10e-6)};
  rod.orientations = {Eigen::Quaterniond::Identity()};
  rod.radii = {1.5e-6};
  const double zeta = 3 * kPi * 1e-3 * 3e-6, push = 1e-9;
  rod.external_forces = {Eigen::Vector3d(0, -push, 0)};
  rod.external_torques = {Eigen::Vector3d::Zero()};
  RodDrag drag;
  drag.resize(1);
  drag.resistance[0] = zeta * Eigen::Matrix3d::Identity();
  drag.rotational_resistance[0] = kPi * 1e-3 * 27e-18;
  const double dt = 20e-6 * zeta / push;  // free travel 20 um in one step
  OverdampedRod plain = rod;
  OverdampedRodSolver solver;
  solver.step(plain, drag, dt, &channel, &walls);
  EXPECT_LT(plain.positions[0].y(), 0.0);  // the plain step leaves the channel
  OverdampedRodSolver guarded_solver;
  for (int k = 0; k < 5; ++k) guarded_rod_step(guarded_solver, rod, drag, {}, dt, &channel, &walls);
  const double e_star = 15e6 / (1 - 0.09);
  const double delta = std::pow(push / (4.0 / 3.0 * e_star * std::sqrt(1.5e-6)), 2.0 / 3.0);
  EXPECT_NEAR(rod.positions[0].y(), 1.5e-6 - delta, 0.01 * delta);
}

TEST(GuardedStep, StiffSphereReachingAWallInTheStepStopsAtTheBackwardEulerContactForce) {
  // The "pop" off a pore wall: a step that carries a sphere onto a wall it
  // did not touch at the step's start has no contact stiffness in its
  // linearisation, so the sphere ends inside the wall by its free travel
  // minus the gap. With E = 1.5e12 Pa a 100 nm overlap of a 3 um sphere is a
  // Hertz force of ~0.08 N (here 9e7 times the push), within the overlap
  // limit (0.1 r = 150 nm); released in the next step it flings a stiff rod
  // wedged in the pore ~1 um per substep at any substep. Backward
  // Euler's own end state has the Hertz force that balances the push less
  // the drag of crossing the gap: zeta (g + delta) / h = F - F_H(delta),
  // solved here by bisection; the guard's Newton iterations on the contact
  // set must land on it.
  ChannelGeometry channel(1e-3, 1e-4, 20e-6);
  WallContactParameters walls;
  walls.youngs_modulus = 1.5e12;
  const double r = 1.5e-6, gap = 0.2e-6, free_travel = 0.3e-6;
  OverdampedRod rod;
  rod.positions = {Eigen::Vector3d(5e-4, r + gap, 10e-6)};
  rod.orientations = {Eigen::Quaterniond::Identity()};
  rod.radii = {r};
  const double zeta = 3 * kPi * 1e-3 * 3e-6, push = 1e-9;
  rod.external_forces = {Eigen::Vector3d(0, -push, 0)};
  rod.external_torques = {Eigen::Vector3d::Zero()};
  RodDrag drag;
  drag.resize(1);
  drag.resistance[0] = zeta * Eigen::Matrix3d::Identity();
  drag.rotational_resistance[0] = kPi * 1e-3 * 27e-18;
  const double h = free_travel * zeta / push;  // 0.3 um of free travel: within the displacement limit
  const double e_star = 1.5e12 / (1 - 0.09);
  const auto hertz = [&](double delta) { return 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(delta, 1.5); };
  double low = 0.0, high = 1e-6;  // the root of zeta (g + delta) / h + F_H(delta) - F
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (low + high);
    (zeta * (gap + mid) / h + hertz(mid) - push > 0.0 ? high : low) = mid;
  }
  const double exact_force = hertz(0.5 * (low + high));
  EXPECT_NEAR(exact_force, push * (1.0 - gap / free_travel), 1e-3 * push);  // the overlap itself is ~1e-13 m
  OverdampedRodSolver solver;
  const GuardedStepReport report = guarded_rod_step(solver, rod, drag, {}, h, &channel, &walls);
  const double overlap = r - rod.positions[0].y();
  const double force = overlap > 0.0 ? hertz(overlap) : 0.0;
  std::printf("end overlap %.3g m, Hertz force %.4g N (backward Euler %.4g N), %d substeps, %d contact iterations\n",
              overlap, force, exact_force, report.substeps, report.contact_iterations);
  EXPECT_NEAR(force, exact_force, 0.01 * exact_force);
  EXPECT_GT(report.contact_iterations, 0);
}

namespace {

// A straight soft rod (E = 15 kPa, the stress matrix's soft rod) along x,
// pulled apart by forces +-F along its axis on the end spheres, isotropic
// drag in still fluid, guarded steps of 1e-4 s (the stress matrix's dt).
// Each bond then settles at the strain F / (E A) (linear axial spring
// k_n = E A / L0; relaxation time zeta / k_n ~ 1 us << dt). The force is
// ramped up over 200 steps, so that each step stretches the rod a little
// (as a flow loads a rod gradually) and the strain builds up over many.
struct PullRun {
  double strain = 0.0;  // largest |axial strain| after the last accepted step
  bool refused = false;
  std::string message;
};
PullRun run_pull(double target_strain, int steps) {
  const double d = 3e-6, e = 15e3;
  RodSpec spec;
  spec.number_of_sections = 10;
  spec.sphere_diameter = d;
  spec.angle = 0.5 * kPi;  // along x
  const BeamBondMaterial material{e, 0.3, d, 0.0};
  OverdampedRod rod = make_overdamped_rod(make_rod_layout(spec), material, d);
  const Eigen::Vector3d axis = (rod.positions.back() - rod.positions.front()).normalized();
  const double force = target_strain * e * material.area();
  const auto model = make_hydrodynamic_model("isotropic", {1e-3, d / 0.6, d}, ConfinementTable::default_table());
  const UniformFlow fluid = still_fluid();
  RodGeometry geometry;
  geometry.sphere_diameter = d;
  RodDrag drag;
  auto drag_at = [&](const OverdampedRod& r, RodDrag& out) {
    geometry.positions = r.positions;
    model->evaluate(geometry, fluid, out);
  };
  OverdampedRodSolver solver;
  PullRun out;
  for (int k = 0; k < steps; ++k) {
    const double ramp = std::min(1.0, (k + 1) / 200.0);
    rod.external_forces.front() = -ramp * force * axis;
    rod.external_forces.back() = ramp * force * axis;
    drag_at(rod, drag);
    try {
      out.strain = guarded_rod_step(solver, rod, drag, drag_at, 1e-4, nullptr, nullptr).largest_bond_strain;
    } catch (const StepRefused& refused) {
      out.refused = true;
      out.message = refused.what();
      out.strain = bond_strain_and_energy(rod).first;  // the rod as before the refused step
      break;
    }
  }
  return out;
}

}  // namespace

TEST(GuardedStep, RodPulledToAModerateStrainSettlesAtTheSpringStrain) {
  // F / (E A) = 0.3, below the default bound 0.5: run to equilibrium.
  const PullRun r = run_pull(0.3, 400);
  std::printf("pull to strain 0.3: %s, strain %.4f\n", r.refused ? r.message.c_str() : "accepted", r.strain);
  EXPECT_FALSE(r.refused) << r.message;
  EXPECT_NEAR(r.strain, 0.3, 0.003);
}

TEST(GuardedStep, OverStrainedRodIsRefusedWithTheFigures) {
  // A limit on the strain change per step alone lets soft rods at
  // dt = 1e-4 s end with bond strains of 0.70-1.18 and exit code 0. Pulled
  // to F / (E A) = 0.8, the run stops, naming the strain and the bound,
  // before any bond exceeds it.
  const PullRun r = run_pull(0.8, 400);
  std::printf("pull to strain 0.8: %s, strain before %.4f\n", r.refused ? r.message.c_str() : "accepted", r.strain);
  ASSERT_TRUE(r.refused) << "accepted at strain " << r.strain;
  EXPECT_NE(r.message.find("axial strain reaches"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("max_bond_strain 0.5"), std::string::npos) << r.message;
  EXPECT_LE(r.strain, 0.5);
  EXPECT_GT(r.strain, 0.45);  // refused where the bound is reached, not earlier
}

TEST(GuardedStep, DragIsEvaluatedOnlyAtAcceptedSubstepStarts) {
  // A stateful model (level 4's windows) must advance only along the
  // accepted path. The stiff rod under a couple needs substeps and
  // Newton checks at every one (kAlways): each drag evaluation must be at the
  // start of an accepted substep (substeps - 1 per step), none at rejected
  // attempts or at trial midpoints.
  const CoupleScene s;
  RodSpec spec;
  spec.number_of_sections = s.n;
  spec.sphere_diameter = s.d;
  spec.angle = 0.5 * kPi;
  OverdampedRod rod = make_overdamped_rod(make_rod_layout(spec), {s.youngs_modulus, 0.3, s.d, 0.0}, s.d);
  rod.external_forces.front() = Eigen::Vector3d(0, s.couple_force, 0);
  rod.external_forces.back() = Eigen::Vector3d(0, -s.couple_force, 0);
  const auto model = make_hydrodynamic_model("isotropic", {1e-3, s.d / 0.15, s.d}, ConfinementTable::default_table());
  const UniformFlow fluid = still_fluid();
  RodGeometry geometry;
  geometry.sphere_diameter = s.d;
  int evaluations = 0;
  auto drag_at = [&](const OverdampedRod& r, RodDrag& out) {
    ++evaluations;
    geometry.positions = r.positions;
    model->evaluate(geometry, fluid, out);
  };
  StepGuardLimits limits;
  limits.newton_check = StepGuardLimits::NewtonCheck::kAlways;
  OverdampedRodSolver solver;
  GuardWorkspace workspace;
  RodDrag drag;
  int substeps = 0, steps_with_substeps = 0;
  for (int k = 0; k < 10; ++k) {
    geometry.positions = rod.positions;
    model->evaluate(geometry, fluid, drag);
    evaluations = 0;
    const GuardedStepReport r = guarded_rod_step(solver, rod, drag, drag_at, 2e-5, nullptr, nullptr, limits, workspace);
    EXPECT_EQ(evaluations, r.substeps - 1) << "step " << k;
    substeps += r.substeps;
    steps_with_substeps += r.substeps > 1;
  }
  std::printf("couple, dt 2e-5 s: %d substeps in 10 steps\n", substeps);
  EXPECT_GT(steps_with_substeps, 5);  // the case exercises rejections
}

namespace {

// A sphere pushed by a constant force F along x onto the upstream side of a
// z-cylinder of radius R, a little off the cylinder's centre line, slides
// round it: on the circle rho = R + r (the Hertz overlap, ~1e-9 m here, is
// negligible) the tangential force F sin(theta) against the drag zeta
// rho dtheta/dt gives tan(theta/2) = tan(theta0/2) exp(lambda t),
// lambda = F / (zeta rho): an unstable state left at the rate lambda, the
// release of a rod pinned across a pore.
struct SlidingOffACylinder {
  static constexpr double r = 1.5e-6, cylinder_radius = 20e-6, rho = cylinder_radius + r;
  static constexpr double push = 1e-9, theta0 = 0.01;  // [N], [rad]
  const double zeta = 3 * kPi * 1e-3 * 2 * r;         // [N s/m]
  const double lambda = push / (zeta * rho);          // [1/s]
  ChannelGeometry channel{1e-3, 1e-3, 20e-6, 0.0, 0.0, {ZCylinder{5e-4, 5e-4, cylinder_radius}}};
  WallContactParameters walls;
  OverdampedRod rod;
  RodDrag drag;
  SlidingOffACylinder() {
    walls.youngs_modulus = 15e6;
    rod.positions = {position(theta0)};
    rod.orientations = {Eigen::Quaterniond::Identity()};
    rod.radii = {r};
    rod.external_forces = {Eigen::Vector3d(push, 0, 0)};
    rod.external_torques = {Eigen::Vector3d::Zero()};
    // As fix rod/implicit gives them after any earlier step: the sphere's velocity.
    rod.velocities = {push * std::sin(theta0) / zeta * Eigen::Vector3d(std::sin(theta0), std::cos(theta0), 0)};
    rod.angular_velocities = {Eigen::Vector3d::Zero()};
    drag.resize(1);
    drag.resistance[0] = zeta * Eigen::Matrix3d::Identity();
    drag.rotational_resistance[0] = kPi * 1e-3 * 8 * r * r * r;
  }
  Eigen::Vector3d position(double theta) const {
    return Eigen::Vector3d(5e-4 - rho * std::cos(theta), 5e-4 + rho * std::sin(theta), 10e-6);
  }
  double exact_theta(double t) const { return 2.0 * std::atan(std::tan(0.5 * theta0) * std::exp(lambda * t)); }
  double theta_of(const OverdampedRod& state) const {
    return std::atan2(state.positions[0].y() - 5e-4, 5e-4 - state.positions[0].x());
  }
  // theta after `steps` guarded steps of dt, with `limits`.
  double run(double dt, int steps, const StepGuardLimits& limits, long* substeps = nullptr) {
    OverdampedRod moved = rod;
    OverdampedRodSolver solver;
    GuardWorkspace workspace;
    for (int k = 0; k < steps; ++k) {
      const std::vector<Eigen::Vector3d> before = moved.positions;
      const GuardedStepReport report = guarded_rod_step(solver, moved, drag, {}, dt, &channel, &walls, limits, workspace);
      if (substeps) *substeps += report.substeps;
      moved.velocities[0] = (moved.positions[0] - before[0]) / dt;
    }
    return theta_of(moved);
  }
};

}  // namespace

TEST(GuardedStep, GrowingMotionIsSubsteppedAndLeavesTheUnstableStateInTime) {
  // Steps of 0.4 ms (lambda dt = 0.66) for 2.4 ms: the sphere slides from
  // 0.57 to ~29 deg. Each step sees the contact normal at its start, so the
  // growth is followed once per (sub)step, not continuously: the unguarded
  // steps (max_growth 0; each within the displacement limit) leave the
  // stagnation line at the wrong rate (here early; the stress matrix's rod,
  // late). The guard keeps lambda h <= max_growth = 0.1, a per-step error
  // of order (lambda h)^2 / 2 in the log of tan(theta/2) (exactly lambda t),
  // so at most ~ (max_growth / 2) lambda t in all: 0.05 lambda t.
  SlidingOffACylinder scene;
  const double dt = 4e-4, t = 2.4e-3;
  const int steps = 6;
  StepGuardLimits off, on;
  off.max_growth = 0.0;
  ASSERT_DOUBLE_EQ(on.max_growth, 0.1);  // the default
  long substeps = 0;
  const double exact = scene.exact_theta(t), lagging = scene.run(dt, steps, off);
  const double guarded = scene.run(dt, steps, on, &substeps);
  const auto log_tan = [](double theta) { return std::log(std::tan(0.5 * theta)); };
  const double growth = scene.lambda * t;  // log tan(theta/2) - log tan(theta0/2), exact
  std::printf("lambda %.4g 1/s, lambda dt %.3g: theta at %.3g s: exact %.3f deg, max_growth 0: %.3f deg, 0.1: %.3f "
              "deg (%ld substeps); growth of log tan(theta/2): exact %.3f, %.3f, %.3f\n",
              scene.lambda, scene.lambda * dt, t, exact * 180 / kPi, lagging * 180 / kPi, guarded * 180 / kPi,
              substeps, growth, log_tan(lagging) - log_tan(SlidingOffACylinder::theta0),
              log_tan(guarded) - log_tan(SlidingOffACylinder::theta0));
  EXPECT_GT(exact * 180 / kPi, 20.0);  // the sphere did leave the stagnation line
  // Unguarded: the error this guard exists for (more than 3x the guarded bound).
  EXPECT_GT(std::fabs(log_tan(lagging) - log_tan(SlidingOffACylinder::theta0) - growth), 0.15 * growth);
  // Guarded: within 0.05 lambda t of the exact growth.
  EXPECT_NEAR(log_tan(guarded) - log_tan(SlidingOffACylinder::theta0), growth, 0.05 * growth);
}
