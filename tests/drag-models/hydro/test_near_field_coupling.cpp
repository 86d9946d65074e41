// The near-field coupling of levels 3-4 (hydro/near_field_coupling.h):
//  - the Rotne-Prager(-Yamakawa) tensor against its closed forms (Rotne &
//    Prager 1969 at contact; continuity with Yamakawa's overlapping form;
//    the self mobility 1/(3 pi mu d) at zero distance);
//  - the blend keeps the sums right: a lone sphere is untouched, and a pair
//    farther apart than a few blend lengths gets exactly the depth-averaged
//    coupling at level 3 and level 4;
//  - the level-4 path (add_near_field on a load) applied to level 3 without
//    near field is level 3 with it;
//  - the resistance stays symmetric positive definite over beta 0.05-0.75
//    for touching and overlapping (0.75 d) spheres;
//  - the file is read strictly.
#include "common/math_constants.h"
#include "flow/uniform_flow.h"
#include "hydro/near_field_coupling.h"
#include "hydro/nonlocal_model.h"
#include "hydro/twoway_near_field.h"
#include "rod_fixtures.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

using namespace hsrod;

namespace {
using hsrod::kPi;
constexpr double kD = 3e-6, kMu = 1e-3;

// A stream of 1 mm/s along x in a wide slit of gap H [m].
UniformFlow stream_in_slit(double gap) { return UniformFlow::wide_slit(gap, {1e-3, 0.0}); }

RodGeometry pair(double distance) {
  RodGeometry rod;
  rod.sphere_diameter = kD;
  rod.positions = {Eigen::Vector3d(-0.5 * distance, 0.0, 0.0), Eigen::Vector3d(0.5 * distance, 0.0, 0.0)};
  return rod;
}

double max_relative_difference(const RodDrag& a, const RodDrag& b) {
  const double r = (a.coupled_resistance - b.coupled_resistance).cwiseAbs().maxCoeff() /
                   a.coupled_resistance.cwiseAbs().maxCoeff();
  double f = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.driving_force.size(); ++i) {
    f = std::max(f, (a.driving_force[i] - b.driving_force[i]).norm());
    scale = std::max(scale, a.driving_force[i].norm());
  }
  return std::max(r, f / scale);
}
}  // namespace

TEST(NearFieldCoupling, RotnePragerAgainstItsClosedForms) {
  const double mu = kMu, d = kD, unit = 8 * kPi * mu * d;
  // At contact r = d (a = d/2): (1 + 1/6) I + (1 - 1/2) e e over 8 pi mu r.
  const Eigen::Matrix2d contact = rotne_prager_mobility({d, 0.0}, mu, d);
  EXPECT_NEAR(contact(0, 0) * unit, 7.0 / 6.0 + 0.5, 1e-12);
  EXPECT_NEAR(contact(1, 1) * unit, 7.0 / 6.0, 1e-12);
  EXPECT_NEAR(contact(0, 1) * unit, 0.0, 1e-12);
  // Yamakawa's overlapping form is continuous at contact and gives the self mobility at r -> 0.
  const Eigen::Matrix2d inside = rotne_prager_mobility({d * (1 - 1e-9), 0.0}, mu, d);
  EXPECT_NEAR((inside - contact).norm() / contact.norm(), 0.0, 1e-8);
  const Eigen::Matrix2d close = rotne_prager_mobility({0.0, 1e-9 * d}, mu, d);
  EXPECT_NEAR(close(0, 0) * 3 * kPi * mu * d, 1.0, 1e-8);
  // Far: the Oseen tensor (I + e e) / (8 pi mu r).
  const Eigen::Matrix2d far = rotne_prager_mobility({0.0, 1e3 * d}, mu, d);
  EXPECT_NEAR(far(1, 1) * 8 * kPi * mu * 1e3 * d, 2.0, 1e-6);
  EXPECT_NEAR(far(0, 0) * 8 * kPi * mu * 1e3 * d, 1.0, 1e-6);
}

TEST(NearFieldCoupling, DistantPairsKeepTheDepthAveragedCoupling) {
  const NearFieldCalibration built_in = NearFieldCalibration::built_in();
  ASSERT_TRUE(built_in.nonlocal.active);
  ASSERT_TRUE(built_in.twoway.active);
  for (double beta : {0.15, 0.3, 0.6}) {
    struct {
      NearFieldAtBeta nonlocal, twoway;
    } fit{built_in.nonlocal.at(beta), built_in.twoway.at(beta)};
    ASSERT_TRUE(fit.nonlocal.friction.active() && fit.nonlocal.driving.active());
    const double gap = kD / beta;
    const HydrodynamicParameters p{kMu, gap, kD};
    const UniformFlow stream = stream_in_slit(gap);
    const ConfinementTable& table = ConfinementTable::default_table();
    const NonlocalRodModel near3(p, table), plain3(p, table, NearFieldAtBeta{});
    // Beyond 23 blend lengths the weight is below 1e-10 and dropped: the coupling is exactly the level's own.
    const double far = 23.5 *
                       std::max({fit.nonlocal.friction.blend_length, fit.nonlocal.driving.blend_length,
                                 fit.twoway.friction.blend_length, fit.twoway.driving.blend_length,
                                 fit.nonlocal.friction.along(), fit.nonlocal.driving.along(), fit.twoway.friction.along(),
                                 fit.twoway.driving.along()}) *
                       gap;
    RodDrag a, b;
    near3.evaluate(pair(far), stream, a);
    plain3.evaluate(pair(far), stream, b);
    // (Round-off only: the held load's own coupling is solved, not multiplied by an inverse.)
    EXPECT_LT(max_relative_difference(a, b), 1e-14) << "level 3, beta " << beta;
    // Level 4's path (add_near_field on a load) with level 4's fit, on a load
    // without near field (level 3's: a window this wide would take minutes).
    plain3.evaluate(pair(far), stream, a);
    b = a;
    add_near_field(pair(far), p, plain3.film_friction(), plain3.obstruction_friction(), fit.twoway, a);
    EXPECT_EQ(max_relative_difference(a, b), 0.0) << "level 4's near field, beta " << beta;
    // Close pairs do change (the near field is on): touching spheres are shielded more.
    near3.evaluate(pair(kD), stream, a);
    plain3.evaluate(pair(kD), stream, b);
    auto pair_friction_along = [](const RodDrag& drag) {  // x-force on sphere 0 when both move along x
      return drag.coupled_resistance(0, 0) + drag.coupled_resistance(0, 3);
    };
    EXPECT_LT(pair_friction_along(a), pair_friction_along(b)) << "beta " << beta;
  }
}

TEST(NearFieldCoupling, LevelFourPathOnLevelThreeIsLevelThree) {
  const double beta = 0.2, gap = kD / beta;
  const HydrodynamicParameters p{kMu, gap, kD};
  // Friction and held load each with its own near field (NearFieldAtBeta).
  const NearFieldAtBeta c{NearFieldCoupling{0.3, 0.6, 0.2, 0.8}, NearFieldCoupling{0.45, -0.3, 0.4, 0.2}};
  const NonlocalRodModel with(p, ConfinementTable::default_table(), c);
  const NonlocalRodModel without(p, ConfinementTable::default_table(), NearFieldAtBeta{});
  const UniformFlow stream = stream_in_slit(gap);
  RodGeometry rod = hsrod_test::straight_rod(8, kD, 0.4);
  rod.positions[3].y() += 0.3 * kD;  // bent
  RodDrag a, b;
  with.evaluate(rod, stream, a);
  without.evaluate(rod, stream, b);
  add_near_field(rod, p, without.film_friction(), without.obstruction_friction(), c, b);
  EXPECT_LT(max_relative_difference(a, b), 1e-10);
}

TEST(NearFieldCoupling, ResistanceStaysSymmetricPositiveDefinite) {
  for (double beta : {0.05, 0.1, 0.15, 0.3, 0.45, 0.6, 0.75}) {
    const double gap = kD / beta;
    const HydrodynamicParameters p{kMu, gap, kD};
    const UniformFlow stream = stream_in_slit(gap);
    const NonlocalRodModel level3(p, ConfinementTable::default_table());
    // Touching and overlapping (0.75 d) spheres. Closer still (0.5 d) the
    // depth-averaged coupling alone is already indefinite at beta >= 0.45
    // (its logarithmic 2-D Stokeslet exceeds the self mobility), with or
    // without the near field: not a configuration of the rods of hsrod.
    for (double spacing : {0.75, 1.0}) {
      RodGeometry rod = hsrod_test::straight_rod(10, kD, 0.0);
      for (auto& x : rod.positions) x *= spacing;
      rod.positions[9].y() += 0.5 * kD;  // a bent end
      RodDrag drag;
      level3.evaluate(rod, stream, drag);
      const Eigen::MatrixXd& R = drag.coupled_resistance;
      EXPECT_LT((R - R.transpose()).norm(), 1e-12 * R.norm());
      const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(R).eigenvalues().minCoeff();
      EXPECT_GT(smallest, 0.0) << "level 3, beta " << beta << " spacing " << spacing;
      if (beta == 0.15 || beta == 0.3) {
        const NearFieldTwoWayModel level4(p, ConfinementTable::default_table());
        level4.evaluate(rod, stream, drag);
        const double smallest4 = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(drag.coupled_resistance).eigenvalues().minCoeff();
        EXPECT_GT(smallest4, 0.0) << "level 4, beta " << beta << " spacing " << spacing;
      }
    }
  }
}

TEST(NearFieldCoupling, FileIsReadStrictly) {
  const std::string path = ::testing::TempDir() + "near_field_test.txt";
  auto refused = [&](const std::string& text, const std::string& what) {
    std::ofstream(path) << text;
    try {
      NearFieldCalibration::read(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused("nonlocal 0.3 0.5\n", "header");
  refused("hsrod-near-field-coupling 3\n", "header");
  refused("hsrod-near-field-coupling 1\nnonlocal 0.3 0.5\ntwoway 0.3 0.5 0\n", "three numbers");
  refused("hsrod-near-field-coupling 1\nnonlocal 0.3 0.5 0 7\ntwoway 0.3 0.5 0\n", "three numbers");
  refused("hsrod-near-field-coupling 1\nnonlocal -0.3 0.5 0\ntwoway 0.3 0.5 0\n", "blend_length");
  refused("hsrod-near-field-coupling 1\nnonlocal 0.3 0.5 20\ntwoway 0.3 0.5 0\n", "reflection_along");
  refused("hsrod-near-field-coupling 1\nnonlocal 0.3 nan 0\ntwoway 0.3 0.5 0\n", "three numbers");
  refused("hsrod-near-field-coupling 1\nnonlocal 0.3 0.5 0\n", "twoway");
  refused("hsrod-near-field-coupling 1\nnonlocal 0.3 0.5 0\nnonlocal 0.3 0.5 0\ntwoway 0.3 0.5 0\n", "twice");
  refused("hsrod-near-field-coupling 1\nlocal 0.3 0.5 0\n", "unknown entry");
  std::ofstream(path) << "hsrod-near-field-coupling 1 # comment\nsource test\ntwoway 0.2 -0.1 0.05\nnonlocal 0.3 0.5 0\n";
  const NearFieldCalibration c = NearFieldCalibration::read(path);
  EXPECT_EQ(c.source, "test");
  EXPECT_DOUBLE_EQ(c.nonlocal.at(0.3).friction.blend_length, 0.3);
  EXPECT_DOUBLE_EQ(c.twoway.at(0.3).driving.reflection, -0.1);
  EXPECT_DOUBLE_EQ(c.twoway.at(0.3).friction.reflection_along, 0.05);
  // Version 2: the law in beta (friction and driving, polynomials in beta - 0.3, ln of the blend length).
  const std::string law_lines =
      "nonlocal friction ln_blend_length -1.1 0.5\nnonlocal friction reflection 0.1\nnonlocal friction reflection_along 0 1\n"
      "nonlocal driving ln_blend_length -1.2\nnonlocal driving reflection 0.2\nnonlocal driving reflection_along 0\n"
      "twoway friction ln_blend_length -1.1\ntwoway friction reflection 0.1\ntwoway friction reflection_along 0\n"
      "twoway driving ln_blend_length -1.2\ntwoway driving reflection 0.2\ntwoway driving reflection_along 0\n";
  refused("hsrod-near-field-coupling 2\n" + law_lines, "beta_range");
  refused("hsrod-near-field-coupling 2\nbeta_range 0.1 0.75\n" + law_lines.substr(law_lines.find('\n') + 1), "missing line");
  refused("hsrod-near-field-coupling 2\nbeta_range 0.75 0.1\n" + law_lines, "beta_range");
  refused("hsrod-near-field-coupling 2\nbeta_range 0.1 0.75\n" + law_lines + "twoway driving reflection 0\n", "twice");
  refused("hsrod-near-field-coupling 2\nbeta_range 0.1 0.75\nnonlocal drive reflection 0\n", "friction|driving");
  refused("hsrod-near-field-coupling 2\nbeta_range 0.1 0.75\nnonlocal driving reflection 1x\n", "not a finite number");
  refused("hsrod-near-field-coupling 2\nbeta_range 0.1 0.75\n" + law_lines + "nonlocal 0.3 0.5 0\n", "friction|driving");
  // A law that leaves the accepted range inside beta_range (reflection 0.1 + 30 (beta - 0.3) > 10 at 0.75).
  std::string bad = law_lines;
  bad.replace(bad.find("nonlocal friction reflection 0.1"), 32, "nonlocal friction reflection 0.1 30");
  refused("hsrod-near-field-coupling 2\nbeta_range 0.1 0.75\n" + bad, "reflection");
  std::ofstream(path) << "hsrod-near-field-coupling 2\nsource law\nbeta_range 0.1 0.75\n" << law_lines;
  const NearFieldCalibration law = NearFieldCalibration::read(path);
  const NearFieldAtBeta at = law.nonlocal.at(0.5);
  EXPECT_NEAR(at.friction.blend_length, std::exp(-1.1 + 0.5 * 0.2), 1e-12);
  EXPECT_NEAR(at.friction.reflection_along, 0.2, 1e-12);
  EXPECT_NEAR(at.driving.blend_length, std::exp(-1.2), 1e-12);
  EXPECT_NEAR(law.nonlocal.at(0.9).friction.reflection_along, 0.45, 1e-12) << "beta clamped to beta_max";
  EXPECT_NEAR(law.nonlocal.at(0.01).friction.reflection_along, -0.2, 1e-12) << "beta clamped to beta_min";
  // Below beta_min the driving tends to the friction as (beta / beta_min)^2.
  EXPECT_NEAR(law.nonlocal.at(0.05).driving.reflection, 0.1 + 0.25 * (0.2 - 0.1), 1e-12);
  EXPECT_NEAR(law.nonlocal.at(1e-9).driving.blend_length, law.nonlocal.at(1e-9).friction.blend_length, 1e-12);
  // Version 1: one coupling for both loads at every beta.
  EXPECT_NEAR(c.nonlocal.at(0.2).friction.blend_length, 0.3, 1e-12);
  EXPECT_NEAR(c.twoway.at(0.7).driving.reflection, -0.1, 1e-12);
}
