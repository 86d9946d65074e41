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
      {1, true, 0.3, 0.5, 0.860605, 0.824458},
      {1, true, 0.3, 1.5, 0.839749, 0.82585},
      {1, false, 0.15, 0.5, 0.903635, 0.944699},
      {1, false, 0.3, 0.5, 1.21621, 1.23926},
      {1, false, 0.3, 1.5, 1, 0.927235},
      {1, false, 0.3, 3, 0.930773, 0.931364},
      {2, true, 0.3, 0.5, 0.426232, 0.448996},
      {2, true, 0.3, 1.5, 0.238792, 0.272842},
      {2, false, 0.15, 0.5, 0.645592, 0.631312},
      {2, false, 0.3, 0.5, 0.541974, 0.540443},
      {2, false, 0.3, 1.5, 0.283252, 0.304758},
      {2, false, 0.3, 3, 0.120084, 0.260914},
      {3, true, 0.3, 0.5, 0.417129, 0.446685},
      {3, true, 0.3, 1.5, 0.226715, 0.227625},
      {3, false, 0.15, 0.5, 0.646035, 0.629339},
      {3, false, 0.3, 0.5, 0.534707, 0.53348},
      {3, false, 0.3, 1.5, 0.27188, 0.278456},
      {3, false, 0.3, 3, 0.106124, 0.112355},
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
