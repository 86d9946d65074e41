// The neighbour-pair squeeze term of the near-wall law (hydro/wall_proximity.h,
// WallProximityLaw::pair_squeeze) on a row along a plane side wall: R stays
// symmetric, a rigid translation gets no net force and no along-wall force
// from it, and a rigid rotation gets the along-wall push the term's formula
// gives, F_t = k_p 3 pi mu d s(delta) Omega d per pair and sphere.
#include "hydro/wall_proximity.h"

#include "common/math_constants.h"
#include "flow/uniform_flow.h"
#include "hydro/hydrodynamic_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hsrod;

namespace {
constexpr double kMu = 1e-3, kH = 10e-6, kD = 3e-6;  // Pa s, m (beta 0.3), m
constexpr int kN = 10;
constexpr double kGap = 0.5 * kD;  // surface gap to the wall y = 0 [m]

WallProximityLaw pair_only(double k) {
  WallProximityLaw w;
  w.active = true;
  w.screening = 0.37;  // as the fitted laws [-]
  w.pair_squeeze = k;
  return w;
}

RodGeometry row_along_the_wall() {
  RodGeometry rod;
  rod.sphere_diameter = kD;
  for (int i = 0; i < kN; ++i) rod.positions.emplace_back(20.0 * kH + i * kD, 0.5 * kD + kGap, 0.5 * kH);
  return rod;
}

RodDrag coupled_zero(int n) {
  RodDrag drag;
  drag.resize(n);
  drag.coupled_resistance = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  return drag;
}

const UniformFlow& still_channel() {
  static const UniformFlow flow(ChannelGeometry(200.0 * kH, 5.0 * kH, kH), Eigen::Vector2d::Zero());
  return flow;
}
}  // namespace

TEST(WallPairSqueeze, ResistanceStaysSymmetric) {
  RodDrag drag = coupled_zero(kN);
  RodGeometry rod = row_along_the_wall();
  rod.positions[3].y() += 0.2 * kD;  // a bent row: pairs at different gaps and tilts
  rod.positions[7].x() += 0.1 * kD;
  add_wall_proximity(pair_only(0.14), rod, still_channel(), kMu, kH, drag);
  const Eigen::MatrixXd& R = drag.coupled_resistance;
  ASSERT_GT(R.norm(), 0.0);
  EXPECT_LT((R - R.transpose()).norm(), 1e-14 * R.norm());
}

TEST(WallPairSqueeze, RigidTranslationGetsNoNetForceAndNoAlongWallForce) {
  RodDrag drag = coupled_zero(kN);
  add_wall_proximity(pair_only(0.14), row_along_the_wall(), still_channel(), kMu, kH, drag);
  const double unit = 3.0 * kPi * kMu * kD * 0.01;  // 3 pi mu d U at U = 0.01 m/s [N]
  for (const Eigen::Vector2d& v : {Eigen::Vector2d(0.01, 0.0), Eigen::Vector2d(0.0, 0.01), Eigen::Vector2d(0.007, -0.007)}) {
    Eigen::VectorXd vel = Eigen::VectorXd::Zero(3 * kN);
    for (int i = 0; i < kN; ++i) vel.segment<2>(3 * i) = v;
    const Eigen::VectorXd f = drag.forces(vel);
    Eigen::Vector2d total = Eigen::Vector2d::Zero();
    for (int i = 0; i < kN; ++i) {
      total += f.segment<2>(3 * i);
      EXPECT_LT(std::abs(f(3 * i)), 1e-12 * unit) << "sphere " << i;  // along the wall (x)
    }
    EXPECT_LT(total.norm(), 1e-12 * unit);
  }
}

TEST(WallPairSqueeze, TurningRowIsPushedAlongTheWallAsTheFormulaGives) {
  const double k = 0.14, omega = 0.01 / kD;  // Omega d = U = 0.01 m/s
  RodDrag drag = coupled_zero(kN);
  const RodGeometry rod = row_along_the_wall();
  add_wall_proximity(pair_only(k), rod, still_channel(), kMu, kH, drag);
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& x : rod.positions) centre += x.head<2>() / kN;
  Eigen::VectorXd vel = Eigen::VectorXd::Zero(3 * kN);
  for (int i = 0; i < kN; ++i) {
    const Eigen::Vector2d r = rod.positions[i].head<2>() - centre;
    vel.segment<2>(3 * i) = omega * Eigen::Vector2d(-r.y(), r.x());
  }
  const Eigen::VectorXd f = drag.forces(vel);
  double along = 0.0, normal = 0.0;
  for (int i = 0; i < kN; ++i) {
    along += f(3 * i);
    normal += f(3 * i + 1);
  }
  // each of the 9 pairs pushes both its spheres by k 3 pi mu d s(delta) Omega d, towards
  // the receding end (+x for a counter-clockwise turn above the wall y = 0)
  const double screen = std::exp(-kGap / (0.37 * kH));
  const double expected = 2.0 * (kN - 1) * k * 3.0 * kPi * kMu * kD * screen * omega * kD;
  EXPECT_NEAR(along, expected, 1e-12 * expected);
  EXPECT_LT(std::abs(normal), 1e-12 * expected);  // no translation along the wall: no normal force
}
