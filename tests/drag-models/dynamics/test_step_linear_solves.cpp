// The step's linear solves (dynamics/step_linear_solves.cpp).
#include <gtest/gtest.h>

#include "dynamics/overdamped_rod_step.h"
#include "hydro/hydrodynamic_model.h"
#include "hydro/model_registry.h"
#include "rod_fixtures.h"

using namespace hsrod;

// A step matrix the sparse LU cannot factorise (a sphere with no drag, no
// bond and no contact: a zero column) gives a non-finite update for the step
// guard to refuse, not a solve through the failed factors (Eigen read sizes
// from them: std::bad_alloc, or a use after free, in a crowded rod cluster).
TEST(OverdampedStep, SparseSolveOfASingularMatrixGivesANonFiniteUpdate) {
  const double d = 3e-6;
  RodSpec spec;
  spec.number_of_sections = 3;
  spec.sphere_diameter = d;
  OverdampedRod rod = make_overdamped_rod(make_rod_layout(spec), BeamBondMaterial{15e3, 0.3, d, 0.0}, d);
  rod.bonds.clear();  // three free spheres
  const auto model = make_hydrodynamic_model("local", {1e-3, 20e-6, d}, ConfinementTable::default_table());
  const hsrod_test::UniformStream stream;
  RodGeometry geometry;
  geometry.sphere_diameter = d;
  geometry.positions = rod.positions;
  RodDrag drag;
  model->evaluate(geometry, stream, drag);
  drag.resistance[1].setZero();  // sphere 1: nothing resists its motion
  drag.rotational_resistance[1] = 0.0;
  OverdampedRodSolver solver;
  solver.set_linear_solver(OverdampedRodSolver::LinearSolver::sparse_lu);
  OverdampedStepResult result;
  ASSERT_NO_THROW(solver.step(rod, drag, 1e-6, nullptr, nullptr, result));
  bool finite = true;
  for (const Eigen::Vector3d& x : rod.positions) finite = finite && x.allFinite();
  EXPECT_FALSE(finite);
}
