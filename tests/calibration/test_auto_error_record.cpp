// The error model of `auto` (hydro/auto_model_choice.h) is the cross-check
// of the current levels against the resolved campaign: the built-in record
// (drag-models/hydro/auto_model_choice_record.cpp) equals the errors the
// levels make now against calibration/data/resolved_campaign_series.csv
// (fitted rigid rods) and the recorded file calibration/data/
// level_error_record.csv; regenerate both with the command in the .cpp when
// a level or the table changes. The record's interpolation predicts the
// errors at the held-out rod (7 spheres, beta 0.25, between the recorded
// lengths and betas) within 3 points or a fifth of the error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "flow/uniform_flow.h"
#include "hydro/auto_model_choice.h"
#include "hydro/model_registry.h"
#include "level_crosscheck.h"
#include "resolved_campaign.h"

using namespace hsrod::calib;

namespace {

const std::string kData = std::string(HSROD_TEST_DATA_DIR) + "/../../calibration/data/";

hsrod::LevelErrorRow measured(int level, const std::map<std::string, std::string>& s) {
  const double beta = std::stod(s.at("beta"));
  const int n = std::stoi(s.at("n"));
  const RowResponse m = row_response(hsrod::find_model_level(level)->name, beta, n, 1.0,
                                     hsrod::ConfinementTable::default_table());
  auto err = [&](double model, const char* q) { return std::abs(model / std::stod(s.at(q)) - 1.0); };
  return {level, beta, n,
          std::max({err(m.R_par(), "R_par"), err(m.R_perp(), "R_perp"), err(m.D_par(), "D_par"),
                    err(m.D_perp(), "D_perp")}),
          std::max(err(m.lambda_par(), "lambda_par"), err(m.lambda_perp(), "lambda_perp")), err(m.r(), "r")};
}

}  // namespace

TEST(calibration_AutoErrorModel, BuiltInRecordIsTheCurrentCrossCheck) {
  const auto& record = hsrod::level_error_record();
  std::map<std::tuple<int, double, int>, hsrod::LevelErrorRow> by_key;
  for (const auto& r : record) by_key[{r.level, r.beta, r.n}] = r;
  int rows = 0;
  for (const auto& s : read_csv_rows(kData + "resolved_campaign_series.csv")) {
    if (s.at("role") != "fit" || std::stod(s.at("spacing")) != 1.0) continue;
    for (int level = 1; level <= 4; ++level) {
      hsrod::LevelErrorRow now;
      try {
        now = measured(level, s);
      } catch (const std::exception& e) {  // a level that refuses the rod has no row (crosscheck_levels.cpp)
        EXPECT_EQ(by_key.count({level, std::stod(s.at("beta")), std::stoi(s.at("n"))}), 0u) << e.what();
        continue;
      }
      const auto it = by_key.find({level, now.beta, now.n});
      ASSERT_NE(it, by_key.end()) << "no record row for level " << level << " beta " << now.beta << " n " << now.n
                                  << ": regenerate the record (auto_model_choice_record.cpp)";
      const std::string where = "level " + std::to_string(level) + " beta " + s.at("beta") + " n " + s.at("n");
      EXPECT_NEAR(it->second.force_error, now.force_error, 1e-3 + 1e-4 * now.force_error) << where;
      EXPECT_NEAR(it->second.velocity_error, now.velocity_error, 1e-4) << where;
      EXPECT_NEAR(it->second.r_error, now.r_error, 1e-4) << where;
      ++rows;
    }
  }
  EXPECT_EQ(rows, static_cast<int>(record.size())) << "record rows without a resolved rod";
  EXPECT_GE(rows, 3 * 8);
}

TEST(calibration_AutoErrorModel, RecordedFileIsTheBuiltInRecord) {
  const auto file = read_csv_rows(kData + "level_error_record.csv");
  const auto& record = hsrod::level_error_record();
  ASSERT_EQ(file.size(), record.size());
  for (std::size_t k = 0; k < file.size(); ++k) {
    EXPECT_EQ(std::stoi(file[k].at("level")), record[k].level);
    EXPECT_NEAR(std::stod(file[k].at("beta")), record[k].beta, 1e-9);
    EXPECT_EQ(std::stoi(file[k].at("n")), record[k].n);
    EXPECT_NEAR(std::stod(file[k].at("force_error")), record[k].force_error, 1e-6 * (1 + record[k].force_error));
    EXPECT_NEAR(std::stod(file[k].at("velocity_error")), record[k].velocity_error, 1e-6);
  }
}

TEST(calibration_AutoErrorModel, InterpolatedRecordPredictsTheHeldOutRod) {
  int rods = 0;
  for (const auto& s : read_csv_rows(kData + "resolved_campaign_series.csv")) {
    if (s.at("role") != "heldout" || std::stod(s.at("spacing")) != 1.0) continue;
    ++rods;
    for (int level = 1; level <= 4; ++level) {
      hsrod::LevelErrorRow now;
      try {
        now = measured(level, s);
      } catch (const std::exception& e) {
        std::printf("held out beta %s n %s level %d refuses: %s\n", s.at("beta").c_str(), s.at("n").c_str(), level,
                    e.what());
        continue;
      }
      const auto predicted = hsrod::expected_level_error(hsrod::level_error_record(), level, now.beta, now.n);
      std::printf("held out beta %s n %s level %d: force error %.1f %% (record predicts %.1f %%), velocity %.2f %% "
                  "(%.2f %%)\n", s.at("beta").c_str(), s.at("n").c_str(), level, 100 * now.force_error,
                  100 * predicted.force, 100 * now.velocity_error, 100 * predicted.velocity);
      // auto relies on the record not UNDER-predicting a level's error (it would pick a level worse than it
      // thinks); an over-prediction only makes it pick a costlier level. With the near field of levels 3-4
      // the record over-predicts level 3 at beta 0.5 (linear between 0.45 and 0.6: 12.0 % against 8.9 %),
      // so the force check is one-sided, with the same tolerance.
      //
      // Beyond the record's longest rod (N = 10) the record is clamped and says so (extrapolated: auto prints
      // "scene outside the record"); there it is not a prediction and is not held to the bound. E.g.
      // the held-out N = 15 rod at beta 0.3 has force errors 5.3 % (level 3) and 4.6 % (level 4) against the
      // clamped ~2 % of N = 10 (the near field's across-flow load falls behind the pressure build-up
      // of rods longer than the fitted ones, calibration/data/near_field_coupling.txt).
      if (predicted.extrapolated) {
        EXPECT_GT(now.n, 10) << "only the longer held-out rod lies outside the record";
      } else {
        EXPECT_GE(predicted.force, now.force_error - std::max(0.03, 0.2 * now.force_error)) << "level " << level;
      }
      EXPECT_NEAR(predicted.velocity, now.velocity_error, std::max(0.01, 0.2 * now.velocity_error))
          << "level " << level;
    }
  }
  EXPECT_GE(rods, 1);
}

// The near-wall record (drag-models/hydro/auto_near_wall_record.cpp) is the
// recorded file calibration/data/level_error_near_walls.csv (both written by
// crosscheck_report.py --scenes-only from the same cross-check).
TEST(calibration_AutoErrorModel, BuiltInNearWallRecordIsTheRecordedFile) {
  const auto& record = hsrod::near_wall_error_record();
  int rows = 0;
  for (const auto& f : read_csv_rows(kData + "level_error_near_walls.csv")) {
    if (f.at("geometry") == "bent") continue;
    const int level = hsrod::find_model(f.at("level"))->level;
    const bool pore = f.at("geometry") == "pore";
    const double beta = std::stod(f.at("beta")), gap = std::stod(f.at("gap_over_d"));
    int found = 0;
    for (const auto& r : record)
      if (r.level == level && r.pore == pore && std::abs(r.beta - beta) < 1e-9 && std::abs(r.gap_over_d - gap) < 1e-9) {
        EXPECT_NEAR(r.force_error, std::stod(f.at("force_error")), 1e-3 * (1 + r.force_error));
        EXPECT_NEAR(r.profile_rms, std::stod(f.at("profile_rms")), 1e-3 * (1 + r.profile_rms));
        ++found;
      }
    EXPECT_EQ(found, 1) << f.at("level") << " " << f.at("geometry") << " beta " << beta << " gap " << gap;
    ++rows;
  }
  EXPECT_EQ(rows, static_cast<int>(record.size()));
  EXPECT_GE(rows, 4 * 6);
}

namespace {
// The stream of 1 mm/s over a channel's planform (zero inside its walls and
// pore cylinders).
hsrod::UniformFlow stream_over(hsrod::ChannelGeometry g) { return hsrod::UniformFlow(std::move(g), {1e-3, 0.0}); }
}  // namespace

// auto reads the near-wall record at the scene's gaps: a rigid row of 5
// spheres 0.5 d beside a pore cylinder at beta 0.3 (levels 2-3: 16-19 %,
// level 4: 8 % in the record) gets level 4 with the record's error; the same
// row in the middle of a wide channel (no wall within 2 x the record's
// largest gap) the slit record's cheapest level within 10 %.
TEST(calibration_AutoErrorModel, AutoUsesTheDistanceToWallsAndPores) {
  const double d = 3e-6, H = 1e-5, R = 1.5 * H;
  const hsrod::HydrodynamicParameters p{1e-3, H, d};
  const auto table = hsrod::ConfinementTable::default_table();
  const auto level3 = hsrod::make_hydrodynamic_model("nonlocal", p, table);
  const hsrod::UniformFlow pore = stream_over(hsrod::ChannelGeometry(12 * H, 6 * H, H, 0.0, 0.0, {{6 * H, 0.0, R}, {6 * H, 6 * H, R}}));
  hsrod::RodGeometry row;
  row.sphere_diameter = d;
  for (int i = 0; i < 5; ++i) row.positions.emplace_back(6 * H + (i - 2) * d, R + 0.5 * d + 0.5 * d + 0.01 * d, 0.5 * H);
  // the middle sphere is 0.51 d from the cylinder's top; the row's ends sit farther (the arc falls away)
  const auto near = hsrod::choose_auto_model({row}, pore, 0.3, *level3, 0.0, 0.01, 0.10);
  std::printf("%s\n", near.summary.c_str());
  EXPECT_NEAR(near.wall_gaps.pore, 0.51, 0.01);
  EXPECT_EQ(near.model, "twoway");
  bool extrapolated = false;
  const double level4_record = hsrod::expected_near_wall_error(hsrod::near_wall_error_record(), 4, true, 0.3, 0.51,
                                                               extrapolated);
  EXPECT_FALSE(extrapolated);
  EXPECT_NEAR(near.expected_error, level4_record, 1e-12);
  EXPECT_LT(near.expected_error, 0.10);
  EXPECT_GT(near.level_errors[1], 0.10);  // level 2 near the pore cylinder
  EXPECT_GT(near.level_errors[2], 0.10);  // level 3
  EXPECT_NE(near.summary.find("from a pore cylinder"), std::string::npos);

  const hsrod::UniformFlow wide = stream_over(hsrod::ChannelGeometry(40 * H, 40 * H, H));
  hsrod::RodGeometry middle = row;
  for (auto& x : middle.positions) x += Eigen::Vector3d(14 * H, 20 * H - x.y(), 0.0);
  const auto far = hsrod::choose_auto_model({middle}, wide, 0.3, *level3, 0.0, 0.01, 0.10);
  std::printf("%s\n", far.summary.c_str());
  for (double e : far.near_wall_errors) EXPECT_EQ(e, 0.0);
  EXPECT_NE(far.model, "twoway");
  EXPECT_LE(far.expected_error, 0.10);
}
