// Level 3's kept coupling (NonlocalState, hydro/nonlocal_model.h): a rod
// that moved as a rigid body in the plane gets the stored inverses turned
// with it, equal to a fresh solve to round-off; a rod that bent beyond
// kShapeTolerance is solved afresh; below it the loads stay within the
// tolerance's bound of a fresh solve; restart data gives the same loads.
#include "hydro/nonlocal_model.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using hsrod::NonlocalRodModel;
using hsrod::NonlocalState;
using hsrod::RodDrag;
using hsrod::RodGeometry;

constexpr double kGap = 20e-6;      // H [m]
constexpr double kDiameter = 3e-6;  // d [m]: beta 0.15, the main example's

NonlocalRodModel model() {
  return NonlocalRodModel(hsrod::HydrodynamicParameters{1e-3, kGap, kDiameter},
                          hsrod::ConfinementTable::default_table());
}

// A gently bent 10-sphere rod (an arc of 6 d radius), not symmetric about any axis.
RodGeometry bent_rod() {
  RodGeometry rod;
  rod.sphere_diameter = kDiameter;
  const double radius = 6.0 * kDiameter;
  for (int k = 0; k < 10; ++k) {
    const double phi = 0.3 + (k - 4.5) * kDiameter / radius;
    rod.positions.emplace_back(radius * std::cos(phi), radius * std::sin(phi), 0.5 * kGap + 0.02 * kDiameter * k);
  }
  return rod;
}

// The rod turned by `angle` [rad] about the z axis through `pivot` and shifted by `shift` [m].
RodGeometry moved(const RodGeometry& rod, double angle, const Eigen::Vector3d& pivot, const Eigen::Vector3d& shift) {
  RodGeometry out = rod;
  const Eigen::Matrix3d q = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (auto& x : out.positions) x = pivot + q * (x - pivot) + shift;
  return out;
}

// Largest difference of the loads' entries over the largest entry (resistance and driving apart).
double relative_difference(const RodDrag& a, const RodDrag& b) {
  const double r = (a.coupled_resistance - b.coupled_resistance).cwiseAbs().maxCoeff() /
                   b.coupled_resistance.cwiseAbs().maxCoeff();
  double f = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.driving_force.size(); ++i) {
    f = std::max(f, (a.driving_force[i] - b.driving_force[i]).cwiseAbs().maxCoeff());
    scale = std::max(scale, b.driving_force[i].cwiseAbs().maxCoeff());
  }
  return std::max(r, f / scale);
}

TEST(NonlocalReuse, RigidlyMovedRodGetsTheTurnedCouplingOfAFreshSolve) {
  const NonlocalRodModel m = model();
  const hsrod_test::UniformStream stream(kGap);
  auto state = m.make_state();
  auto& kept = dynamic_cast<NonlocalState&>(*state);
  RodDrag first, again, fresh;
  m.evaluate(bent_rod(), stream, first, state.get());
  const RodGeometry later = moved(bent_rod(), 0.7, Eigen::Vector3d(1e-6, 2e-6, 0), Eigen::Vector3d(5e-6, -3e-6, 0));
  m.evaluate(later, stream, again, state.get());
  m.evaluate(later, stream, fresh);
  EXPECT_EQ(kept.evaluations, 2);
  EXPECT_EQ(kept.solves, 1);  // the second call reused the first's coupling
  EXPECT_LT(relative_difference(again, fresh), 1e-12);
  // and the turn is not trivial: the loads at the two places differ
  EXPECT_GT(relative_difference(first, fresh), 0.05);
}

// The rod evaluated with a state, then again with its last sphere moved
// across by `shift` kShapeTolerance diameters; beside it a fresh solve of
// the moved rod and the state's count of solves.
struct BentEndEvaluation {
  RodDrag kept, fresh;
  long solves = 0;
};

BentEndEvaluation evaluate_with_bent_end(double shift) {
  const NonlocalRodModel m = model();
  const hsrod_test::UniformStream stream(kGap);
  auto state = m.make_state();
  BentEndEvaluation out;
  m.evaluate(bent_rod(), stream, out.kept, state.get());
  RodGeometry bent = bent_rod();
  bent.positions[9].y() += shift * NonlocalRodModel::kShapeTolerance * kDiameter;
  m.evaluate(bent, stream, out.kept, state.get());
  m.evaluate(bent, stream, out.fresh);
  out.solves = dynamic_cast<NonlocalState&>(*state).solves;
  return out;
}

TEST(NonlocalReuse, RodBentBeyondTheToleranceIsSolvedAfresh) {
  const BentEndEvaluation e = evaluate_with_bent_end(3.0);
  EXPECT_EQ(e.solves, 2);
  EXPECT_LT(relative_difference(e.kept, e.fresh), 1e-12);
}

// Below the tolerance the stored coupling is reused: the loads differ from
// a fresh solve by about the centres' misfit over their spacing, ~1e-4 here.
TEST(NonlocalReuse, RodBentWithinTheToleranceKeepsTheLoadsWithinIt) {
  const BentEndEvaluation e = evaluate_with_bent_end(0.8);
  EXPECT_EQ(e.solves, 1);
  const double difference = relative_difference(e.kept, e.fresh);
  EXPECT_GT(difference, 1e-9);  // reused, not solved: not equal
  EXPECT_LT(difference, NonlocalRodModel::kShapeTolerance);
}

TEST(NonlocalReuse, RestartDataGivesTheSameLoads) {
  const NonlocalRodModel m = model();
  const hsrod_test::UniformStream stream(kGap);
  auto state = m.make_state();
  RodDrag drag, restored_drag;
  RodGeometry rod = bent_rod();
  rod.id = 3;
  m.evaluate(rod, stream, drag, state.get());
  const std::vector<double> data = m.save_state(*state);
  auto restored = m.make_state();
  m.restore_state(*restored, data, stream);
  RodGeometry later = moved(rod, -0.2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1e-6, 0, 0));
  later.positions[0].x() += 0.5 * NonlocalRodModel::kShapeTolerance * kDiameter;  // reused, not re-solved
  m.evaluate(later, stream, drag, state.get());
  m.evaluate(later, stream, restored_drag, restored.get());
  EXPECT_EQ(dynamic_cast<NonlocalState&>(*restored).solves, 1);
  EXPECT_EQ((drag.coupled_resistance - restored_drag.coupled_resistance).cwiseAbs().maxCoeff(), 0.0);
  for (std::size_t i = 0; i < drag.driving_force.size(); ++i)
    EXPECT_EQ((drag.driving_force[i] - restored_drag.driving_force[i]).cwiseAbs().maxCoeff(), 0.0);
  std::vector<double> foreign = data;
  foreign[0] = 4.0;
  EXPECT_THROW(m.restore_state(*restored, foreign, stream), std::invalid_argument);
  foreign = data;
  foreign.pop_back();
  EXPECT_THROW(m.restore_state(*restored, foreign, stream), std::invalid_argument);
}

}  // namespace
