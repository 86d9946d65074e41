// The friction correction of a step's rubbing points
// (dynamics/contact_friction_problem.h) against closed forms: one point of
// mobility m (M = m I) loaded by the step to slip w0, friction F = mu F_n,
// regularised below v_s. The solved slip v satisfies v = w0 + m f(v) with
// f(v) = -F v / max(|v|, v_s) (no secant, nothing applied yet):
//   sliding (|w0| > v_s + m F): v = w0 (1 - m F / |w0|), |v| = |w0| - m F;
//   sticking (|w0| < v_s + m F): v = w0 / (1 + m F / v_s).
#include <gtest/gtest.h>

#include "dynamics/contact_friction_problem.h"

#include <Eigen/Dense>

#include <cmath>

using namespace hsrod;

namespace {
constexpr double kMobility = 2.0;     // m [m/(N s)]
constexpr double kSliding = 1e-6;     // F [N]
constexpr double kSlipSpeed = 1e-6;   // v_s [m/s]

Eigen::VectorXd solve(const Eigen::Vector2d& w0, double secant, const Eigen::Vector2d& applied,
                      Eigen::VectorXd* slips) {
  return contact_friction_correction(kMobility * Eigen::Matrix2d::Identity(), w0, applied,
                                     {FrictionPointLaw{kSliding, secant}}, kSlipSpeed, 1e-9 * kSliding, slips);
}
}  // namespace

TEST(ContactFrictionProblem, ASlidingPointLosesMobilityTimesFriction) {
  const Eigen::Vector2d w0(3e-6, 4e-6);  // |w0| = 5e-6 > v_s + m F = 3e-6
  Eigen::VectorXd v;
  const Eigen::VectorXd g = solve(w0, 0.0, Eigen::Vector2d::Zero(), &v);
  const Eigen::Vector2d expected = w0 * (1.0 - kMobility * kSliding / w0.norm());
  EXPECT_LT((v - expected).norm(), 1e-6 * expected.norm());
  // The correction is the law at the solved slip: |g| = F against the slip.
  EXPECT_NEAR(g.norm(), kSliding, 1e-9 * kSliding);
  EXPECT_LT(g.dot(v), 0.0);
}

TEST(ContactFrictionProblem, AStickingPointSlipsOnlyInTheRegularisation) {
  const Eigen::Vector2d w0(-1e-6, 0.5e-6);  // |w0| = 1.1e-6 < v_s + m F = 3e-6
  Eigen::VectorXd v;
  const Eigen::VectorXd g = solve(w0, 0.0, Eigen::Vector2d::Zero(), &v);
  const Eigen::Vector2d expected = w0 / (1.0 + kMobility * kSliding / kSlipSpeed);
  EXPECT_LT((v - expected).norm(), 1e-6 * expected.norm());
  EXPECT_LT((g + kSliding / kSlipSpeed * expected).norm(), 1e-6 * g.norm());
}

// The step already applied a secant -c s and a correction g0: the slips
// then solve v = w0 + m (f(v) + c v - g0), and the correction returned is
// the law plus the secant at the solved slip.
TEST(ContactFrictionProblem, TheStepsSecantAndEarlierCorrectionAreAccountedFor) {
  const Eigen::Vector2d w0(3e-6, 4e-6);
  Eigen::VectorXd v_plain;
  solve(w0, 0.0, Eigen::Vector2d::Zero(), &v_plain);
  const double secant = 0.2;  // [N s/m], c m = 0.4 < 1 (convex)
  const Eigen::Vector2d applied(1e-7, -2e-7);
  // The step's slips w0' for which v_plain solves the problem with that
  // secant and g0: w0' = v - m (f(v) + c v - g0).
  const Eigen::Vector2d f = -kSliding * v_plain / v_plain.norm();
  const Eigen::Vector2d shifted = v_plain - kMobility * (f + secant * v_plain - applied);
  Eigen::VectorXd v;
  const Eigen::VectorXd g = solve(shifted, secant, applied, &v);
  EXPECT_LT((v - v_plain).norm(), 1e-6 * v_plain.norm());
  EXPECT_LT((g - (f + secant * v_plain)).norm(), 1e-6 * kSliding);
}

// Two coupled points (a sphere pressed on two walls): M with off-diagonal
// coupling; the solution satisfies the fixed-point equation at each point.
TEST(ContactFrictionProblem, CoupledPointsSatisfyTheLawAtEach) {
  Eigen::Matrix4d m;
  m << 2.0, 0.3, 0.5, 0.0,  //
      0.3, 1.5, 0.0, 0.2,   //
      0.5, 0.0, 2.5, 0.1,   //
      0.0, 0.2, 0.1, 1.0;
  const Eigen::Vector4d w0(4e-6, -1e-6, 0.5e-6, 0.2e-6);  // the first point slides, the second sticks
  const std::vector<FrictionPointLaw> laws{{kSliding, 0.0}, {kSliding, 0.0}};
  Eigen::VectorXd v;
  const Eigen::VectorXd g =
      contact_friction_correction(m, w0, Eigen::Vector4d::Zero(), laws, kSlipSpeed, 1e-12 * kSliding, &v);
  EXPECT_LT((v - (w0 + m * g)).norm(), 1e-6 * w0.norm());
  for (int p = 0; p < 2; ++p) {
    const Eigen::Vector2d s = v.segment<2>(2 * p);
    const Eigen::Vector2d law = -kSliding * s / std::max(s.norm(), kSlipSpeed);
    EXPECT_LT((g.segment<2>(2 * p) - law).norm(), 1e-6 * kSliding) << p;
  }
  EXPECT_GT(v.segment<2>(0).norm(), kSlipSpeed);  // sliding
  EXPECT_LT(v.segment<2>(2).norm(), kSlipSpeed);  // sticking
}
