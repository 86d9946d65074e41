// hsrod calibration: the one reader of the resolved campaign's CSV records
// (calibration/data/resolved_campaign_{series,profiles,per_sphere}.csv,
// written by calibration/tools/campaign_analysis.py). Plain C++17, no
// OpenFOAM: the calibration tools and the tests of every part read the
// records through it.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace hsrod::calib {

// One data row of a CSV file: column name -> text.
using CsvRow = std::map<std::string, std::string>;

// The data rows of a comma-separated file whose first non-comment line is
// the header; lines starting with '#' and empty lines are skipped. Throws
// std::runtime_error naming the file for a missing file and naming the line
// for a row with a different number of fields than the header.
std::vector<CsvRow> read_csv_rows(const std::string& path);

// One rigid row of spheres of the resolved series (resolved_campaign_series.csv):
// R = friction / (3 pi mu d), D = held-in-flow load / (3 pi mu d U_mean),
// lambda = D / R, r = lambda_perp / lambda_par, with their mesh changes *_u.
struct ResolvedRod {
  double beta = 0.0;     // d / H [-]
  int n = 1;             // spheres in the row
  double spacing = 1.0;  // centre spacing over d [-]
  std::string role;      // "fit" (used by the fits) or "heldout" (only predicted)
  std::map<std::string, double> q;  // every numeric column (R_par, R_perp, D_par, ..., r, cpu_s)
  double at(const std::string& quantity) const { return q.at(quantity); }
};

// The rows of resolved_campaign_series.csv (throws as read_csv_rows, and
// std::runtime_error naming the line for a non-numeric value).
std::vector<ResolvedRod> read_resolved_series(const std::string& path);

// Per-sphere resolved profiles (resolved_campaign_profiles.csv): the values
// along the row by (beta, n, spacing, "<load>_<component>") with load
// friction|driving and component par|perp, keys as written in the file.
struct ProfileKey {
  std::string beta, n, spacing, quantity;
  bool operator<(const ProfileKey& o) const;
};
std::map<ProfileKey, std::vector<double>> read_resolved_profiles(const std::string& path);

}  // namespace hsrod::calib
