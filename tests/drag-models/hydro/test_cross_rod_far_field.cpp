// The far field of rods beyond the interaction reach (hydro/cross_rod_far_field.h)
// against the direct sum over every distant sphere: of the untruncated
// Brinkman Green's function c G (brinkman_green.h, the independent
// reference: Bessel form, no cut-off), and of the pair mobilities the joint
// level-3 solve couples its spheres with (c G blended into the near
// field: NonlocalRodModel::add_disturbance). 300 rods of 10 spheres at
// random in the benchmark scene's density (tests/benchmarks/scripts/in.many_rods:
// ~5 % area fraction, d = 3 um, H = 20 um), random obstruction forces.
#include "common/math_constants.h"
#include "hydro/brinkman_green.h"
#include "hydro/cross_rod_far_field.h"
#include "hydro/nonlocal_model.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using hsrod::CrossRodFarField;
using hsrod::NonlocalRodModel;
using hsrod::RodGeometry;
using hsrod::RodObstructionForces;

constexpr double kGap = 20e-6;      // H [m]
constexpr double kDiameter = 3e-6;  // d [m]
constexpr double kViscosity = 1e-3;  // mu [Pa s]

NonlocalRodModel model() {
  return NonlocalRodModel(hsrod::HydrodynamicParameters{kViscosity, kGap, kDiameter},
                          hsrod::ConfinementTable::default_table());
}

struct Scene {
  std::vector<int> ids;
  std::vector<RodGeometry> rods;
  std::vector<RodObstructionForces> forces;  // P^D, P^v [N]: of the order of a sphere's drag at 1 m/s
};

// `count` rods placed at random in a planform of count x 1.8e-9 m^2 (the
// benchmark's area per rod), L = 2 W; forces in both channels along the
// stream (as a stream drives every rod) with a random part.
Scene random_scene(int count, double force_scale, unsigned seed) {
  std::mt19937 random(seed);
  const double width = std::sqrt(count * 1.8e-9 / 2.0), length = 2.0 * width;
  std::uniform_real_distribution<double> unit(0.0, 1.0), sign(-1.0, 1.0);
  Scene s;
  for (int r = 0; r < count; ++r) {
    RodGeometry rod = hsrod_test::straight_rod(10, kDiameter, 2.0 * M_PI * unit(random));
    const Eigen::Vector3d centre(length * unit(random), width * unit(random), 0.5 * kGap);
    for (auto& x : rod.positions) x += centre;
    rod.id = 3 * r + 1;  // ids need not be 0..N-1
    RodObstructionForces p;
    p.start(10);
    for (int k = 0; k < 20; ++k) {  // along the stream on every rod, plus a part of their own
      p.driving(k) = force_scale * ((k % 2 == 0 ? 1.0 : 0.0) + 0.5 * sign(random));
      p.velocity(k) = force_scale * ((k % 2 == 0 ? 0.6 : 0.0) + 0.5 * sign(random));
    }
    s.ids.push_back(rod.id);
    s.rods.push_back(rod);
    s.forces.push_back(p);
  }
  return s;
}

double nearest_sphere_distance(const RodGeometry& a, const RodGeometry& b) {
  double nearest = INFINITY;
  for (const auto& x : a.positions)
    for (const auto& y : b.positions) nearest = std::min(nearest, (x - y).head<2>().norm());
  return nearest;
}

// What the dipole leaves out of c G beyond r_c, relative to the dipole's
// size K / r^2 (the spectral norm of K (2 rhat rhat - I) / r^2): the
// Bessel terms (|dA| + |dB|) R^2, largest at r_c (they fall as e^-R, the
// dipole as R^-2).
double bessel_tail(double reach) {
  const double R = reach / (kGap / std::sqrt(12.0));
  const hsrod::BrinkmanKernels k = hsrod::brinkman_green_kernels_bessel(R);
  return (std::fabs(k.a + 1.0 / (R * R)) + std::fabs(k.b - 2.0 / (R * R))) * R * R;
}

struct Comparison {
  double largest_far = 0.0;        // max |q| of the far field [m/s]
  double largest_error = 0.0;      // max |far - direct| [m/s]
  double largest_allowed = 0.0;    // the tolerance at that sphere [m/s]
  double worst_ratio = 0.0;        // max |far - direct| / tolerance over all spheres [-]
  double largest_bound = 0.0;      // the truncation bound returned [m/s]
  double largest_near = 0.0;       // max |q| of the rods within reach [m/s]
};

// For every 15th rod: far field against the direct sum over the rods
// beyond reach, by `direct` (c G, or the model's pair mobilities), with
// the tolerance bound + pair_tail x sum_k K |f_k| / r^2 (+ rounding).
// With unit_every > 0, every rod r with r % unit_every == 0 is of the
// target's unit (stepped with it in one joint solve, however far: excluded
// from the far field like the rods within reach, and left out of the direct sum).
template <class Direct>
Comparison compare(const Scene& s, const NonlocalRodModel& m, double pair_tail, Direct direct, int unit_every = 0) {
  CrossRodFarField far;
  m.set_far_field_scene(far);
  std::vector<const RodGeometry*> rods;
  std::vector<const RodObstructionForces*> forces;
  for (std::size_t r = 0; r < s.rods.size(); ++r) {
    rods.push_back(&s.rods[r]);
    forces.push_back(&s.forces[r]);
  }
  far.build(s.ids, rods, forces);
  const double K = far.dipole_strength();
  Comparison c;
  for (std::size_t t = 0; t < s.rods.size(); t += 15) {
    std::vector<int> excluded{s.ids[t]};
    RodObstructionForces near = s.forces[t], reference = s.forces[t], summed = s.forces[t];
    near.clear_disturbance();
    reference.clear_disturbance();
    summed.clear_disturbance();
    std::vector<double> scale(20, 0.0);  // per target sphere and channel: sum_k K |f_k| / r^2 [m/s]
    for (std::size_t r = 0; r < s.rods.size(); ++r) {
      if (r == t) continue;
      if (unit_every > 0 && r % unit_every == 0) {
        excluded.push_back(s.ids[r]);
        continue;
      }
      if (nearest_sphere_distance(s.rods[t], s.rods[r]) <= far.reach()) {
        excluded.push_back(s.ids[r]);
        m.add_disturbance(s.rods[t], near, s.rods[r], s.forces[r]);
        continue;
      }
      direct(s.rods[t], reference, s.rods[r], s.forces[r]);
      for (int i = 0; i < 10; ++i)
        for (int k = 0; k < 10; ++k) {
          const double r2 = (s.rods[t].positions[i] - s.rods[r].positions[k]).head<2>().squaredNorm();
          scale[2 * i] += K * s.forces[r].driving.segment<2>(2 * k).norm() / r2;
          scale[2 * i + 1] += K * s.forces[r].velocity.segment<2>(2 * k).norm() / r2;
        }
    }
    std::sort(excluded.begin(), excluded.end());
    const double bound = far.add_disturbance(s.rods[t], excluded, summed);
    c.largest_bound = std::max(c.largest_bound, bound);
    for (int i = 0; i < 10; ++i) {
      for (int channel = 0; channel < 2; ++channel) {
        const auto& got = channel == 0 ? summed.driving_disturbance : summed.velocity_disturbance;
        const auto& want = channel == 0 ? reference.driving_disturbance : reference.velocity_disturbance;
        const auto& close = channel == 0 ? near.driving_disturbance : near.velocity_disturbance;
        const double error = (got.segment<2>(2 * i) - want.segment<2>(2 * i)).norm();
        // table of G (brinkman_kernel_table_error: 1e-10 of |A| + |B| = 3 K / r^2) and round-off
        const double allowed = bound + (pair_tail + 3e-10 + 1e-12) * scale[2 * i + channel];
        c.largest_far = std::max(c.largest_far, got.segment<2>(2 * i).norm());
        c.largest_near = std::max(c.largest_near, close.segment<2>(2 * i).norm());
        if (error / allowed > c.worst_ratio) {
          c.worst_ratio = error / allowed;
          c.largest_error = error;
          c.largest_allowed = allowed;
        }
      }
    }
  }
  return c;
}

// q of target t += the untruncated c G of rod src's obstruction forces p.
void add_green(const RodGeometry& t, RodObstructionForces& q, const RodGeometry& src, const RodObstructionForces& p) {
  for (int i = 0; i < t.size(); ++i)
    for (int k = 0; k < src.size(); ++k) {
      const Eigen::Matrix2d g = hsrod::kMidplaneFactor *
                                hsrod::brinkman_green_function((t.positions[i] - src.positions[k]).head<2>(),
                                                               kViscosity, kGap);
      q.driving_disturbance.segment<2>(2 * i) += g * p.driving.segment<2>(2 * k);
      q.velocity_disturbance.segment<2>(2 * i) += g * p.velocity.segment<2>(2 * k);
    }
}

constexpr double kForceScale = 1e-8;  // [N]: ~ a sphere's obstruction force in the benchmark's stream

TEST(CrossRodFarField, ReproducesTheUntruncatedGreensFunctionOverDistantRods) {
  const NonlocalRodModel m = model();
  const Scene s = random_scene(300, kForceScale, 7);
  const double tail = bessel_tail(m.interaction_reach());
  EXPECT_LT(tail, 1e-6);  // the dipole is G beyond r_c to this
  const Comparison c = compare(s, m, tail, add_green);
  std::printf("300 rods: far field %.3e m/s (rods within reach %.3e m/s), off the direct sum of c G by %.3e m/s "
              "(allowed %.3e: truncation bound %.3e, Bessel tail %.1e), worst error over tolerance %.2f\n",
              c.largest_far, c.largest_near, c.largest_error, c.largest_allowed, c.largest_bound, tail,
              c.worst_ratio);
  EXPECT_LE(c.worst_ratio, 1.0);
  // The expansion's order and opening keep the truncation far below the far field itself.
  EXPECT_LT(c.largest_bound, 1e-4 * c.largest_far);
  // The far field is not negligible beside the rods within reach (what this is for).
  EXPECT_GT(c.largest_far, 0.02 * c.largest_near);
}

// The joint solve couples the same pairs through the model's pair mobility,
// whose 3-D near-field blend has an exponential tail beyond r_c: measured
// here at r_c for one sphere pair (largest there: the blend falls as
// e^(-r / kappa H)), it bounds the relative difference of every far pair.
TEST(CrossRodFarField, ReproducesTheJointSolvesPairMobilitiesOverDistantRods) {
  const NonlocalRodModel m = model();
  CrossRodFarField far;
  m.set_far_field_scene(far);
  double blend_tail = 0.0;
  for (double over : {1.0, 1.5}) {
    double largest = 0.0;
    for (double angle = 0.0; angle < M_PI; angle += M_PI / 12) {
      RodGeometry a, b;
      a.positions = {Eigen::Vector3d::Zero()};
      b.positions = {over * far.reach() * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0)};
      for (int channel = 0; channel < 2; ++channel) {
        RodObstructionForces pa, pb;
        pa.start(1);
        pb.start(1);
        (channel == 0 ? pb.driving : pb.velocity) = Eigen::Vector2d(1.0, 0.3);
        m.add_disturbance(a, pa, b, pb);
        const Eigen::Vector2d q = channel == 0 ? pa.driving_disturbance : pa.velocity_disturbance;
        const Eigen::Vector2d rhat = -b.positions[0].head<2>().normalized();
        const double r = over * far.reach();
        const Eigen::Vector2d dipole = far.dipole_strength() / (r * r) *
                                       (2.0 * rhat * rhat.transpose() - Eigen::Matrix2d::Identity()) *
                                       Eigen::Vector2d(1.0, 0.3);
        largest = std::max(largest, (q - dipole).norm() / (far.dipole_strength() / (r * r) * std::hypot(1.0, 0.3)));
      }
    }
    std::printf("pair mobility beyond the dipole at %.1f r_c: %.2e of the dipole\n", over, largest);
    if (over == 1.0) blend_tail = largest;
    if (over > 1.0) {
      EXPECT_LT(largest, blend_tail);  // falling with distance, so r_c's bounds all
    }
  }
  const Scene s = random_scene(300, kForceScale, 11);
  const Comparison c = compare(s, m, blend_tail, [&m](const RodGeometry& t, RodObstructionForces& q,
                                                      const RodGeometry& src, const RodObstructionForces& p) {
    m.add_disturbance(t, q, src, p);
  });
  std::printf("300 rods: far field %.3e m/s, off the joint solve's pair mobilities by %.3e m/s (allowed %.3e), "
              "worst error over tolerance %.2f\n", c.largest_far, c.largest_error, c.largest_allowed, c.worst_ratio);
  EXPECT_LE(c.worst_ratio, 1.0);
  EXPECT_LT(blend_tail, 1e-2);  // what the far field leaves out of the joint coupling of a far pair
}

TEST(CrossRodFarField, RefusesABadSceneAndForcesThatDoNotFitTheRods) {
  CrossRodFarField far;
  EXPECT_THROW(far.set_scene(0.0, kGap, 1e-4), std::invalid_argument);
  far.set_scene(kViscosity, kGap, 1e-4);
  const Scene s = random_scene(3, kForceScale, 1);
  RodObstructionForces wrong;
  wrong.start(4);
  EXPECT_THROW(far.build(s.ids, {&s.rods[0], &s.rods[1], &s.rods[2]}, {&s.forces[0], &s.forces[1], &wrong}),
               std::invalid_argument);
  EXPECT_THROW(CrossRodFarField::truncation_factor(1.0), std::invalid_argument);
  const std::vector<int> twice{s.ids[0], s.ids[1], s.ids[0]};  // an id twice: the exclusion could not find both
  EXPECT_THROW(far.build(twice, {&s.rods[0], &s.rods[1], &s.rods[2]}, {&s.forces[0], &s.forces[1], &s.forces[2]}),
               std::invalid_argument);
}

// A unit stepped together (rods joined by contacts, transitively) can reach
// far beyond r_c; its members are coupled by its own joint solve, so the far
// field must leave them out wherever they sit, also inside a box it would
// otherwise sum whole.
TEST(CrossRodFarField, LeavesOutTheTargetsUnitBeyondTheReach) {
  const NonlocalRodModel m = model();
  const Scene s = random_scene(300, kForceScale, 13);
  const double tail = bessel_tail(m.interaction_reach());
  const Comparison c = compare(s, m, tail, add_green, 10);
  std::printf("300 rods, every 10th of the target's unit: far field %.3e m/s, off the direct sum by %.3e m/s "
              "(allowed %.3e), worst error over tolerance %.2f\n", c.largest_far, c.largest_error,
              c.largest_allowed, c.worst_ratio);
  EXPECT_LE(c.worst_ratio, 1.0);
}

}  // namespace
