#include "hydro/confinement_coefficients.h"
#include "hydro/hydrodynamic_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

using namespace hsrod;

TEST(ConfinementTable, FaxenSeriesValues) {
  // Happel & Brenner eq. 7-4.28 evaluated by hand at a/l = 0.3: 1/(1 - 0.3012 + 0.011286 + 0.001701 - 0.000411).
  EXPECT_NEAR(faxen_midplane_friction(0.3), 1.0 / 0.711376, 1e-5);
  EXPECT_DOUBLE_EQ(faxen_midplane_friction(0.0), 1.0);
}

TEST(ConfinementTable, WriteReadRoundTrip) {
  const auto table = ConfinementTable::default_table();
  const auto path = (std::filesystem::temp_directory_path() / "hsrod_coefficients_test.txt").string();
  table.write(path);
  const auto back = ConfinementTable::read(path);
  ASSERT_EQ(back.rows().size(), table.rows().size());
  const auto a = table.at(0.37), b = back.at(0.37);
  EXPECT_NEAR(a.perpendicular_friction, b.perpendicular_friction, 1e-9);
  EXPECT_NEAR(a.parallel_driving, b.parallel_driving, 1e-9);
}

TEST(ConfinementTable, BadInputIsRefused) {
  const auto table = ConfinementTable::default_table();
  EXPECT_THROW(table.at(0.95), std::invalid_argument);
  EXPECT_THROW(ConfinementTable::read("/nonexistent/coefficients.txt"), std::runtime_error);
  const auto path = (std::filesystem::temp_directory_path() / "hsrod_bad_coefficients.txt").string();
  std::ofstream(path) << "hsrod-confinement-coefficients 2\n";
  EXPECT_THROW(ConfinementTable::read(path), std::runtime_error);
  EXPECT_THROW(make_hydrodynamic_model("slender", {1e-3, 20e-6, 3e-6}, table), std::invalid_argument);
  EXPECT_THROW(make_hydrodynamic_model("local", {1e-3, 2e-6, 3e-6}, table), std::invalid_argument);  // beta > 1
}
