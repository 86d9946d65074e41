// Adaptive substeps (steps where the motion is) on the
// paper's pore passage (pore_passage_driver.h), level 2, stiff rod
// (15 MPa): with a timestep 10x the fixed default (4e-5 s) and adaptive
// substeps at tolerance 1e-2, the passage agrees with a fixed fine step
// (4e-7 s, 11 000 plain steps: the benchmark's error reference step) within
// what the tolerance promises, and costs fewer solves than the fixed
// default (4e-6 s, 1 100 guarded steps). Counted, not timed.
//
// What the tolerance promises: each accepted substep's local error is at
// most `tolerance` of its displacement, so (for a passage that does not
// amplify errors) the accumulated error is at most `tolerance` times the
// distance the rod travels: 124 d here, 1.24 d at 1e-2.
// Measured (2026-12-01): fixed 4e-6 s 1 341 solves (guard substeps
// included), 0.173 d / 0.83 deg / 1.9e-4 W against the fine step; adaptive
// 1e-2: 1 044 solves, 0.219 d / 0.95 deg / 1.4e-4 W; adaptive 3e-3: 1 909
// solves, 0.135 d. So the gain in solves is modest at equal error on this
// scene (the guard's 0.25 d displacement limit sets most substeps); the
// larger gain is in LIGGGHTS steps (110 instead of 1 100: gather, scatter,
// neighbour work), measured in tests/benchmarks.
#include "pore_passage_driver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

constexpr double kD = 3e-6;  // [m]

struct Difference {
  double x = 0.0, angle = 0.0, lateral = 0.0;  // [d], [deg], [W]
};

// Largest difference over the samples both runs share (same physical times).
Difference compare(const std::vector<hsrod_test::PassageSample>& a, double dt_a,
                   const std::vector<hsrod_test::PassageSample>& b, double dt_b) {
  Difference d;
  for (const auto& sa : a)
    for (const auto& sb : b)
      if (std::fabs(sa.step * dt_a - sb.step * dt_b) < 1e-3 * dt_a) {
        d.x = std::max(d.x, std::fabs(sa.x_centre - sb.x_centre) / kD);
        d.angle = std::max(d.angle, std::fabs(sa.angle_deg - sb.angle_deg));
        d.lateral = std::max(d.lateral, std::fabs(sa.lateral - sb.lateral));
      }
  return d;
}

}  // namespace

TEST(AdaptivePassage, AgreesWithAFineFixedStepWithinTheToleranceAndTakesFewerSolves) {
  hsrod_test::PassageCase fine;
  fine.model = "local";
  fine.dt = 4e-7;
  fine.steps = 11000;
  fine.sample_every = 1000;
  const auto reference = hsrod_test::run_pore_passage(fine, HSROD_TEST_CACHE_DIR);

  hsrod_test::PassageCase fixed = fine;
  fixed.dt = 4e-6;
  fixed.steps = 1100;
  fixed.sample_every = 100;
  hsrod_test::PassageWork fixed_work;
  const auto fixed_run =
      hsrod_test::run_guarded_pore_passage(fixed, hsrod::StepGuardLimits{}, HSROD_TEST_CACHE_DIR, fixed_work);

  hsrod_test::PassageCase large = fine;
  large.dt = 4e-5;
  large.steps = 110;
  large.sample_every = 10;
  hsrod::StepGuardLimits adaptive;
  adaptive.adaptive = true;
  adaptive.displacement_tolerance = 1e-2;
  hsrod_test::PassageWork adaptive_work;
  const auto adaptive_run =
      hsrod_test::run_guarded_pore_passage(large, adaptive, HSROD_TEST_CACHE_DIR, adaptive_work);

  const Difference e_fixed = compare(fixed_run, fixed.dt, reference, fine.dt);
  const Difference e_adaptive = compare(adaptive_run, large.dt, reference, fine.dt);
  const double travelled = (reference.back().x_centre - reference.front().x_centre) / kD;
  std::printf("passage %.1f d: fixed 4e-6 s: %ld solves, error %.3g d, %.3g deg, %.3g W; adaptive (dt 4e-5 s, "
              "tolerance 1e-2): %ld substeps + %ld rejected = %ld solves, error %.3g d, %.3g deg, %.3g W\n",
              travelled, fixed_work.solves(), e_fixed.x, e_fixed.angle, e_fixed.lateral, adaptive_work.substeps,
              adaptive_work.rejected_trials, adaptive_work.solves(), e_adaptive.x, e_adaptive.angle,
              e_adaptive.lateral);
  EXPECT_GT(reference.back().x_centre, 450e-6);  // the passage happened
  EXPECT_LT(e_adaptive.x, adaptive.displacement_tolerance * travelled);
  EXPECT_LT(e_adaptive.lateral * 200e-6 / kD, adaptive.displacement_tolerance * travelled);
  EXPECT_LT(adaptive_work.solves(), fixed_work.solves());
  // And not bought with error: comparable to the fixed default's (recorded 0.219 vs 0.173 d).
  EXPECT_LT(e_adaptive.x, 2.0 * e_fixed.x);
}
