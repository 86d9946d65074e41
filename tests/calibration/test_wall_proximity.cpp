// The near-wall correction of the reduced levels (drag-models/hydro/wall_proximity.h)
//  - its shapes are the single-wall results of 3-D Stokes flow (Brenner 1961's
//    exact wall-normal friction; Faxen's far field along the wall);
//  - the built-in law is the shipped fit (calibration/data/wall_proximity_fit.json);
//  - it keeps R symmetric positive definite down to contact and leaves spheres
//    far from walls untouched;
//  - accuracy against the resolved near-wall rows (campaign "geometry"): the
//    cases held out of the fit, and level 4's totals over all near-wall cases.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <fstream>
#include <string>

#include "flow/uniform_flow.h"
#include "hydro/local_models.h"
#include "hydro/model_registry.h"
#include "hydro/wall_proximity.h"
#include "level_crosscheck.h"
#include "resolved_campaign.h"
#include "scene_crosscheck.h"

namespace {

using hsrod::calib::SceneCase;

const std::string kRepo = std::string(HSROD_TEST_DATA_DIR) + "/../../";

TEST(calibration_WallProximity, NormalShapeIsBrennersExactWallFriction) {
  int n = 0;
  for (const auto& row : hsrod::calib::read_csv_rows(kRepo + "tests/calibration/data/brenner1961_wall_normal.csv")) {
    const double h = std::stod(row.at("h_over_a")), lambda = std::stod(row.at("lambda"));
    // Bevan & Prieve's Pade form is within 0.6 % of the exact series over h/a = 1.13-10
    EXPECT_NEAR(1.0 + hsrod::wall_normal_rise(h - 1.0), lambda, 0.01 * lambda) << "h/a = " << h;
    ++n;
  }
  EXPECT_EQ(n, 5);
  // lubrication at contact: lambda -> a / delta
  EXPECT_NEAR(hsrod::wall_normal_rise(1e-4) * 1e-4, 1.0, 1e-3);
  // along the wall, far away: Faxen's 9/16 a/h
  EXPECT_NEAR(hsrod::wall_along_rise(999.0) * 1000.0, 9.0 / 16.0, 1e-3);
}

TEST(calibration_WallProximity, BuiltInLawIsTheShippedFit) {
  std::ifstream in(kRepo + "calibration/data/wall_proximity_fit.json");
  ASSERT_TRUE(in) << "calibration/data/wall_proximity_fit.json";
  const nlohmann::json fit = nlohmann::json::parse(in);
  const auto& built = hsrod::WallProximityCalibration::built_in();
  for (const auto& [name, law] : {std::make_pair("local", built.local), std::make_pair("nonlocal", built.nonlocal),
                                  std::make_pair("twoway", built.twoway)}) {
    const auto& p = fit.at("levels").at(name).at("parameters");
    EXPECT_EQ(law.active, std::string(name) == "twoway") << name;  // applied at level 4 only (wall_proximity_fit.cpp)
    EXPECT_NEAR(law.normal, p.at("normal").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.along, p.at("along").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.screening, p.at("screening").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.normal_row_gain, p.at("normal_row_gain").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.along_row_gain, p.at("along_row_gain").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.normal_held, p.at("normal_held").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.along_held, p.at("along_held").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.squeeze, p.at("squeeze").get<double>(), 1e-8) << name;
    EXPECT_NEAR(law.squeeze_held, p.at("squeeze_held").get<double>(), 1e-8) << name;
  }
}

TEST(calibration_WallProximity, ResistanceStaysPositiveDefiniteAtContactAndUntouchedFarFromWalls) {
  const double d = 3e-6, H = 1e-5;
  const hsrod::HydrodynamicParameters p{1e-3, H, d};
  const auto table = hsrod::ConfinementTable::default_table();
  const hsrod::UniformFlow flow(hsrod::ChannelGeometry(40 * H, 20 * H, H), Eigen::Vector2d::Zero(), "fluid at rest");
  for (const char* level : {"twoway"}) {
    for (double gap : {0.0, 0.05 * d, 0.5 * d, 10 * H}) {
      for (double angle : {0.0, 0.3, 1.5707963}) {
        hsrod::RodGeometry rod;
        rod.sphere_diameter = d;
        for (int i = 0; i < 6; ++i)
          rod.positions.emplace_back(20 * H + i * d * std::cos(angle), gap + 0.5 * d + i * d * std::sin(angle), 0.5 * H);
        const auto model = hsrod::make_hydrodynamic_model(level, p, table);
        hsrod::RodDrag with, without;
        model->evaluate(rod, flow, with);
        auto bare = hsrod::make_hydrodynamic_model(level, p, table);
        dynamic_cast<hsrod::LocalDragBase&>(*bare).set_wall_proximity(hsrod::WallProximityLaw{});
        bare->evaluate(rod, flow, without);
        Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * rod.size(), 3 * rod.size()), R0 = R;
        for (int i = 0; i < rod.size(); ++i) {
          R.block<3, 3>(3 * i, 3 * i) = with.resistance[i];
          R0.block<3, 3>(3 * i, 3 * i) = without.resistance[i];
        }
        if (with.coupled()) R = with.coupled_resistance, R0 = without.coupled_resistance;
        EXPECT_LT((R - R.transpose()).norm(), 1e-12 * R.norm()) << level;
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(R);
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig0(R0);
        // the correction only adds resistance: no eigenvalue falls
        EXPECT_GE(eig.eigenvalues().minCoeff(), eig0.eigenvalues().minCoeff() * (1 - 1e-12)) << level << " gap " << gap;
        if (gap > 5 * H)  // 10 H from the wall: beyond the correction's reach (screening 0.39 H)
          EXPECT_EQ((R - R0).norm(), 0.0) << level;
        else
          EXPECT_GT((R - R0).norm(), 0.0) << level << " gap " << gap;
      }
    }
  }
}

// Largest |total error| (components carrying >= 20 % of |F|) and profile RMS.
std::pair<double, double> errors(const std::string& level, const SceneCase& c) {
  const auto m = hsrod::calib::scene_forces(level, c, hsrod::ConfinementTable::default_table());
  Eigen::Vector2d tm = Eigen::Vector2d::Zero(), tr = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < m.size(); ++i) {
    tm += m[i];
    tr += c.resolved[i];
  }
  double tot = 0.0;
  for (int k = 0; k < 2; ++k)
    if (std::abs(tr[k]) >= 0.2 * tr.norm()) tot = std::max(tot, std::abs(tm[k] / tr[k] - 1.0));
  return {tot, hsrod::calib::profile_rms(m, c.resolved)};
}

const std::vector<SceneCase>& near_wall_cases() {
  static const std::vector<SceneCase> cases = [] {
    std::vector<SceneCase> out;
    for (SceneCase& c : hsrod::calib::read_scene_cases(kRepo + "calibration/data/resolved_geometry_per_sphere.csv"))
      if (c.geometry != "bent") out.push_back(std::move(c));
    return out;
  }();
  return cases;
}

TEST(calibration_WallProximity, HeldOutNearWallRowsAtLevelFourWithinTenPercent) {
  // not in the fit (hsrod_fit_wall_proximity --hold-out, the report's held_out)
  std::ifstream in(kRepo + "calibration/data/wall_proximity_fit.json");
  const nlohmann::json fit = nlohmann::json::parse(in);
  int n = 0;
  for (const SceneCase& c : near_wall_cases()) {
    bool held = false;
    for (const auto& name : fit.at("held_out")) held = held || name.get<std::string>() == c.name;
    if (!held) continue;
    const auto [tot, rms] = errors("twoway", c);
    // measured: totals <= 7.4 %, profile RMS <= 7.4 % (row of 10 along the
    // wall at 0.5 d, row of 5 at 45 degrees at 1.5 d, row radial to the pore cylinder at 1.5 d)
    EXPECT_LT(tot, 0.10) << c.name << " " << c.load;
    EXPECT_LT(rms, 0.10) << c.name << " " << c.load;
    ++n;
  }
  EXPECT_GE(n, 6);
}

TEST(calibration_WallProximity, LevelFourTotalsWithinTenPercentNearWallsAndPores) {
  double worst = 0.0;
  for (const SceneCase& c : near_wall_cases()) {
    const double tot = errors("twoway", c).first;
    worst = std::max(worst, tot);
    EXPECT_LT(tot, 0.10) << c.name << " " << c.load;
  }
  // measured: 8.0 % (tangential friction of a row beside the pore cylinder at 0.5 d); before the correction 55.7 %
  EXPECT_GT(worst, 0.0);
}

}  // namespace
