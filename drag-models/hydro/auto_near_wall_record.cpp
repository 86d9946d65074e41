// The near-wall record of `auto` (hydro/auto_model_choice.h), written by
//   /usr/bin/python3 calibration/validation/crosscheck_report.py build --scenes-only
// (hsrod_crosscheck_scenes ... --wall-record calibration/data/level_error_near_walls.csv
//  --wall-record-cpp drag-models/hydro/auto_near_wall_record.cpp).
// Do not edit: regenerate when a level changes (test
// calibration_AutoErrorModel.BuiltInNearWallRecordIsTheRecordedFile fails otherwise).
#include "hydro/auto_model_choice.h"

namespace hsrod {

const char* near_wall_error_record_provenance() {
  return "hsrod_crosscheck_scenes --wall-record on calibration/data/resolved_geometry_per_sphere.csv (levels with their built-in near-wall correction), table: built-in: hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json); rod columns (n = 10) fitted over beta 0.10-0.75, extrapolated outside";
}

const std::vector<NearWallErrorRow>& near_wall_error_record() {
  // level, pore, beta, gap_over_d, force_error, profile_rms
  static const std::vector<NearWallErrorRow> rows = {
      {1, true, 0.3, 0.5, 0.89156, 0.839352},
      {1, true, 0.3, 1.5, 0.905044, 0.827919},
      {1, false, 0.15, 0.5, 1.03801, 1.03731},
      {1, false, 0.3, 0.5, 1.25585, 1.25521},
      {1, false, 0.3, 1.5, 1.00577, 0.937305},
      {1, false, 0.3, 3, 0.942114, 0.933028},
      {2, true, 0.3, 0.5, 0.161718, 0.184794},
      {2, true, 0.3, 1.5, 0.219787, 0.243019},
      {2, false, 0.15, 0.5, 0.0954453, 0.136902},
      {2, false, 0.3, 0.5, 0.233879, 0.23169},
      {2, false, 0.3, 1.5, 0.176407, 0.242384},
      {2, false, 0.3, 3, 0.0965204, 0.255015},
      {3, true, 0.3, 0.5, 0.193907, 0.195101},
      {3, true, 0.3, 1.5, 0.218634, 0.221309},
      {3, false, 0.15, 0.5, 0.0644422, 0.136067},
      {3, false, 0.3, 0.5, 0.215601, 0.153283},
      {3, false, 0.3, 1.5, 0.159361, 0.182724},
      {3, false, 0.3, 3, 0.0822949, 0.0941726},
      {4, true, 0.3, 0.5, 0.0796514, 0.102416},
      {4, true, 0.3, 1.5, 0.072906, 0.0706073},
      {4, false, 0.15, 0.5, 0.0452211, 0.10889},
      {4, false, 0.3, 0.5, 0.0738931, 0.0938636},
      {4, false, 0.3, 1.5, 0.0416824, 0.0642912},
      {4, false, 0.3, 3, 0.0364587, 0.0368408},
  };
  return rows;
}

}  // namespace hsrod
