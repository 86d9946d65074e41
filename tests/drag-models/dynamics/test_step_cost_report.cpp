// The cost model fix rod/implicit prints at the end of a run
// (dynamics/step_cost_report.h): per-step and per-sphere-step times from
// the totals, the split of the total into drag model, bonds, contacts,
// solve and the rest, and statistics of one run from totals before and
// after it.
#include "dynamics/step_cost_report.h"

#include <gtest/gtest.h>

#include <string>

using namespace hsrod;

TEST(StepCostReport, SplitsTheTotalAndScalesPerStepAndPerSphereStep) {
  StepCost cost;
  cost.steps = 1000;
  cost.sphere_steps = 10000;     // 10 spheres
  cost.total_seconds = 0.02;     // 20 us per step, 2 us per sphere-step
  cost.drag_seconds = 0.005;     // 25 %
  cost.solver.bond_seconds = 0.004;     // 20 %
  cost.solver.contact_seconds = 0.001;  // 5 %
  cost.solver.solve_seconds = 0.006;    // 30 %
  cost.solver.steps = 1200;
  cost.solver.banded_steps = 1200;
  EXPECT_NEAR(cost.other_seconds(), 0.004, 1e-15);  // 20 %
  const std::string line = cost.report();
  EXPECT_NE(line.find("1000 steps, 20 us per step, 2 us per sphere-step"), std::string::npos) << line;
  EXPECT_NE(line.find("drag model 25 %, bonds 20 %, contacts 5 %, solve 30 %, other (gather, guard, scatter) 20 %"),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("1200 solves (1200 block-tridiagonal, 0 sparse, 0 dense)"), std::string::npos) << line;
  // Timer jitter can make the parts exceed the total: the rest is then 0, not negative.
  cost.solver.solve_seconds = 0.02;
  EXPECT_EQ(cost.other_seconds(), 0.0);
}

TEST(StepCostReport, RunStatisticsAreTheDifferenceOfTotals) {
  OverdampedSolverStatistics before, during;
  before.steps = 5;
  before.bond_seconds = 1.0;
  during.steps = 7;
  during.sphere_steps = 70;
  during.bond_seconds = 0.5;
  during.sparse_steps = 2;
  OverdampedSolverStatistics after = before;
  accumulate(after, during);
  EXPECT_EQ(after.steps, 12);
  const OverdampedSolverStatistics run = difference(after, before);
  EXPECT_EQ(run.steps, 7);
  EXPECT_EQ(run.sphere_steps, 70);
  EXPECT_DOUBLE_EQ(run.bond_seconds, 0.5);
  EXPECT_EQ(run.sparse_steps, 2);
}
