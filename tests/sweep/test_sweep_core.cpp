// hsrod-sweep's LIGGGHTS-free parts: value lists and ranges, the case grid,
// the script preparation and the resumable result file.
#include "sweep_csv.h"
#include "sweep_grid.h"
#include "sweep_script.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace hsrod::sweep;
using Strings = std::vector<std::string>;

TEST(SweepValues, ListsRangesAndGeometricRanges) {
  EXPECT_EQ(parse_values("E", "15e3,150e3,1.5e6"), (Strings{"15e3", "150e3", "1.5e6"}));
  // Inclusive of stop although 0.1 steps do not add up exactly in binary.
  EXPECT_EQ(parse_values("ratio", "1:5:0.5"), (Strings{"1", "1.5", "2", "2.5", "3", "3.5", "4", "4.5", "5"}));
  EXPECT_EQ(parse_values("b", "0.06:0.6:0.06").size(), 10u);
  EXPECT_EQ(parse_values("b", "0.06:0.6:0.06").back(), "0.6");
  EXPECT_EQ(parse_values("E", "15e3:15e6:*10"), (Strings{"15000", "150000", "1500000", "15000000"}));
  EXPECT_EQ(parse_values("a", "0,10:30:10,90"), (Strings{"0", "10", "20", "30", "90"}));
  EXPECT_EQ(parse_values("model", "local,nonlocal"), (Strings{"local", "nonlocal"}));
}

TEST(SweepValues, BadSpecificationsNameTheProblem) {
  const auto message = [](const std::string &name, const std::string &spec) {
    try {
      parse_values(name, spec);
    } catch (const GridError &e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("E", "1:x:2"), "--var E: 'x' in '1:x:2' is not a number (expected value, start:stop:step or start:stop:*factor)");
  EXPECT_EQ(message("E", "5:1:1"), "--var E: range '5:1:1' needs start <= stop and step > 0");
  EXPECT_EQ(message("E", "1:5:0"), "--var E: range '1:5:0' needs start <= stop and step > 0");
  EXPECT_EQ(message("E", "0:5:*10"), "--var E: geometric range '0:5:*10' needs 0 < start <= stop and factor > 1");
  EXPECT_EQ(message("E", "1:2:3:4"), "--var E: range '1:2:3:4' must be start:stop:step or start:stop:*factor");
  EXPECT_EQ(message("E", "1,,2"), "--var E: empty item in '1,,2'");
  EXPECT_EQ(message("E", "0:1:1e-9"), "--var E: range '0:1:1e-9' has more than 1000000 values");
  EXPECT_EQ(message("E-1", "1"), "--var 'E-1': a LIGGGHTS variable name has only letters, digits and '_'");
}

TEST(SweepGrid, CartesianProductLastVariableFastest) {
  CaseGrid grid({{"E", {"1", "2"}}, {"alpha", {"0", "45", "90"}}});
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid.values_of(0), (Strings{"1", "0"}));
  EXPECT_EQ(grid.values_of(2), (Strings{"1", "90"}));
  EXPECT_EQ(grid.values_of(3), (Strings{"2", "0"}));
  EXPECT_EQ(grid.values_of(5), (Strings{"2", "90"}));
  EXPECT_THROW(CaseGrid({{"E", {"1"}}, {"E", {"2"}}}), GridError);
}

TEST(SweepScript, SweptDefinitionsBecomeCommentsKeepingLineNumbers) {
  const std::string script =
      "variable E index 15e6\n"
      "variable U equal 0.03  # mean velocity\n"
      "variable L equal &\n"
      "  2*${U}\n"
      "  variable   U equal 0.05\n"
      "variable Ux equal 1\n"
      "run 10\n";
  const PreparedScript p = prepare_script(script, {"U", "L", "alpha"});
  std::istringstream lines(p.text);
  Strings out;
  for (std::string line; std::getline(lines, line);) out.push_back(line);
  ASSERT_EQ(out.size(), 7u);
  EXPECT_EQ(out[0], "variable E index 15e6");
  EXPECT_EQ(out[1].rfind("# (hsrod-sweep: U is set by the sweep)", 0), 0u);
  EXPECT_EQ(out[2].rfind("# (hsrod-sweep: L is set by the sweep)", 0), 0u);
  EXPECT_EQ(out[3].rfind("#", 0), 0u);  // the continuation line goes too
  EXPECT_EQ(out[4].rfind("# (hsrod-sweep: U", 0), 0u);
  EXPECT_EQ(out[5], "variable Ux equal 1");  // a longer name is another variable
  EXPECT_EQ(out[6], "run 10");
  EXPECT_EQ(p.defined, (Strings{"U", "L"}));
  EXPECT_EQ(p.not_defined, (Strings{"alpha"}));
}

namespace {
std::string slurp(const std::string &path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
CaseOutcome ok_outcome(const std::string &measure) {
  CaseOutcome o;
  o.ok = true;
  o.measures = {measure};
  return o;
}
}  // namespace

TEST(SweepResultFile, ResumesDropsATornLineAndRejectsAnotherSweep) {
  const std::string path = (std::filesystem::temp_directory_path() / "hsrod_sweep_test.csv").string();
  std::filesystem::remove(path);
  const CaseGrid grid({{"E", {"1", "2", "3"}}});
  {
    ResultFile file(path, grid, {"x"});
    EXPECT_TRUE(file.finished().empty());
    file.append(csv_row(grid, 2, ok_outcome("0.5")));
    CaseOutcome failed;
    failed.measures = {""};
    failed.error = "ERROR: bad \"value\", really";
    file.append(csv_row(grid, 0, failed));
  }
  EXPECT_EQ(slurp(path),
            "case,E,status,x,error,wall_s,cpu_s,rank\n"
            "2,3,ok,0.5,,0,0,0\n"
            "0,1,failed,,\"ERROR: bad \"\"value\"\", really\",0,0,0\n");
  { std::ofstream(path, std::ios::app) << "1,2,ok,0.7"; }  // torn by a kill
  {
    ResultFile file(path, grid, {"x"});
    EXPECT_EQ(file.finished(), (std::set<std::size_t>{0, 2}));
  }
  EXPECT_EQ(slurp(path).find("1,2,ok"), std::string::npos);
  EXPECT_THROW(ResultFile(path, grid, {"y"}), std::runtime_error);  // other measures
  const CaseGrid other({{"E", {"1", "2", "4"}}});                   // case 2 has another value
  EXPECT_THROW(ResultFile(path, other, {"x"}), std::runtime_error);
  std::filesystem::remove(path);
}

// A row whose status is neither ok nor failed (an edited file, a foreign
// tool's) was taken as a finished case on resume and never run.
TEST(SweepResultFile, RefusesARowWithAnotherStatus) {
  const std::string path = (std::filesystem::temp_directory_path() / "hsrod_sweep_status_test.csv").string();
  std::filesystem::remove(path);
  const CaseGrid grid({{"E", {"1", "2"}}});
  { ResultFile file(path, grid, {"x"}); }
  { std::ofstream(path, std::ios::app) << "1,2,running,0.7,,0,0,0\n"; }
  try {
    ResultFile file(path, grid, {"x"});
    ADD_FAILURE() << "a row of status 'running' was accepted as finished";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find("line 2: case 1 has status 'running' (expected ok or failed)"),
              std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}
