// Strict reading of coefficient tables: column names honoured,
// extra columns and trailing junk refused, unphysical values refused (they
// would give NaN or a rod moving upstream with exit code 0).
#include "hydro/confinement_coefficients.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

using namespace hsrod;

namespace {

const char* kHeader = "hsrod-confinement-coefficients 1\nsource test\n";
const char* kColumns =
    "columns beta sphere_friction sphere_driving parallel_friction perpendicular_friction "
    "parallel_driving perpendicular_driving\n";

std::string write_table(const std::string& name, const std::string& text) {
  const auto path = (std::filesystem::temp_directory_path() / ("hsrod_strict_" + name)).string();
  std::ofstream(path) << text;
  return path;
}

// Expects read() to fail with a message holding `fragment` (and the line).
void expect_refused(const std::string& name, const std::string& text, const std::string& fragment) {
  const std::string path = write_table(name, text);
  try {
    ConfinementTable::read(path);
    FAIL() << name << ": accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path + ":"), std::string::npos) << e.what();
  }
}

const std::string kRow1 = "0.1 1.11 1.49 0.52 0.86 1.49 1.49\n";
const std::string kRow2 = "0.3 1.41 1.46 0.49 1.36 1.41 1.47\n";

}  // namespace

TEST(ConfinementTableStrict, ReorderedColumnsAreHonoured) {
  // Same numbers, columns listed in another order: the same table.
  const ConfinementTable plain = ConfinementTable::read(
      write_table("plain", std::string(kHeader) + kColumns + kRow1 + kRow2));
  const ConfinementTable swapped = ConfinementTable::read(write_table(
      "swapped", std::string(kHeader) +
                     "columns beta perpendicular_driving sphere_driving parallel_friction "
                     "perpendicular_friction parallel_driving sphere_friction\n"
                     "0.1 1.49 1.49 0.52 0.86 1.49 1.11\n0.3 1.47 1.46 0.49 1.36 1.41 1.41\n"));
  for (double beta : {0.1, 0.2, 0.3}) {
    const ConfinementCoefficients a = plain.at(beta), b = swapped.at(beta);
    EXPECT_DOUBLE_EQ(a.sphere_friction, b.sphere_friction);
    EXPECT_DOUBLE_EQ(a.perpendicular_driving, b.perpendicular_driving);
    EXPECT_DOUBLE_EQ(a.parallel_driving, b.parallel_driving);
  }
  EXPECT_DOUBLE_EQ(swapped.at(0.1).sphere_friction, 1.11);
}

TEST(ConfinementTableStrict, MalformedTablesAreRefused) {
  const std::string head = std::string(kHeader) + kColumns;
  expect_refused("junk", head + "0.1 1.2junk 1.49 0.52 0.86 1.49 1.49\n" + kRow2,
                 "'1.2junk' in column sphere_friction is not a finite number");
  expect_refused("extra", head + "0.1 1.11 1.49 0.52 0.86 1.49 1.49 7\n" + kRow2,
                 "found 8 fields");
  expect_refused("short", head + "0.1 1.11 1.49 0.52 0.86 1.49\n" + kRow2, "found 6 fields");
  expect_refused("nan", head + "0.1 nan 1.49 0.52 0.86 1.49 1.49\n" + kRow2, "not a finite number");
  expect_refused("unknown_column",
                 std::string(kHeader) +
                     "columns beta sphere_friction sphere_driving parallel_friction "
                     "perpendicular_friction parallel_driving perp_driving\n" + kRow1 + kRow2,
                 "unknown column 'perp_driving'");
  expect_refused("extra_column",
                 std::string(kHeader) +
                     "columns beta sphere_friction sphere_driving parallel_friction "
                     "perpendicular_friction parallel_driving perpendicular_driving extra\n" +
                     kRow1 + kRow2,
                 "names 8 columns");
  expect_refused("twice",
                 std::string(kHeader) +
                     "columns beta beta sphere_driving parallel_friction "
                     "perpendicular_friction parallel_driving perpendicular_driving\n" + kRow1 + kRow2,
                 "named twice");
  expect_refused("no_header", std::string(kColumns) + kRow1 + kRow2, "missing header");
}

TEST(ConfinementTableStrict, UnphysicalValuesAreRefused) {
  const std::string head = std::string(kHeader) + kColumns;
  // Zero friction gave NaN velocities, negative friction a rod moving upstream.
  expect_refused("zero_friction", head + "0.1 1.11 1.49 0 0.86 1.49 1.49\n" + kRow2,
                 "parallel_friction = 0 outside its physical range (0, ");
  expect_refused("negative_friction", head + "0.1 -1.11 1.49 0.52 0.86 1.49 1.49\n" + kRow2,
                 "sphere_friction = -1.11 outside its physical range [1, ");
  expect_refused("negative_driving", head + "0.1 1.11 1.49 0.52 0.86 -1.49 1.49\n" + kRow2,
                 "parallel_driving = -1.49 outside its physical range (0, 3]");
  expect_refused("fast_driving", head + "0.1 1.11 3.5 0.52 0.86 1.49 1.49\n" + kRow2,
                 "sphere_driving = 3.5 outside its physical range (0, 3]");
  // The same checks guard tables built in code (calibration fits).
  std::vector<ConfinementTable::Row> rows(2);
  rows[0].beta = 0.1;
  rows[1].beta = 0.2;
  rows[1].c.perpendicular_friction = -0.5;
  EXPECT_THROW(ConfinementTable(rows, "code"), std::invalid_argument);
}

TEST(ConfinementTableStrict, ShippedTablesStillRead) {
  // The built-in defaults and the calibrated table in the repository pass
  // the physical checks.
  EXPECT_NO_THROW(ConfinementTable::default_table());
  EXPECT_NO_THROW(ConfinementTable::read(std::string(HSROD_SOURCE_DIR) +
                                         "/calibration/data/confinement_rodibfoam.txt"));
}
