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
      {1, true, 0.3, 0.5, 0.860149, 0.82405},
      {1, true, 0.3, 1.5, 0.839752, 0.825433},
      {1, false, 0.15, 0.5, 0.903424, 0.944498},
      {1, false, 0.15, 1.5, 1.10659, 1.14058},
      {1, false, 0.3, 0.5, 1.21566, 1.23874},
      {1, false, 0.3, 1.5, 1, 0.926789},
      {1, false, 0.3, 3, 0.930777, 0.930917},
      {2, true, 0.3, 0.5, 0.426805, 0.448982},
      {2, true, 0.3, 1.5, 0.239551, 0.272621},
      {2, false, 0.15, 0.5, 0.643913, 0.629397},
      {2, false, 0.15, 1.5, 0.331521, 0.34825},
      {2, false, 0.3, 0.5, 0.542431, 0.540506},
      {2, false, 0.3, 1.5, 0.283967, 0.304572},
      {2, false, 0.3, 3, 0.120962, 0.257539},
      {3, true, 0.3, 0.5, 0.411659, 0.442034},
      {3, true, 0.3, 1.5, 0.219457, 0.221483},
      {3, false, 0.15, 0.5, 0.642735, 0.626268},
      {3, false, 0.15, 1.5, 0.32931, 0.313052},
      {3, false, 0.3, 0.5, 0.53034, 0.529481},
      {3, false, 0.3, 1.5, 0.265046, 0.27288},
      {3, false, 0.3, 3, 0.0977339, 0.106304},
      {4, true, 0.3, 0.5, 0.0822335, 0.0999284},
      {4, true, 0.3, 1.5, 0.0630319, 0.0650014},
      {4, false, 0.15, 0.5, 0.050769, 0.109189},
      {4, false, 0.15, 1.5, 0.0309695, 0.0596971},
      {4, false, 0.3, 0.5, 0.0779736, 0.0926249},
      {4, false, 0.3, 1.5, 0.0419863, 0.0620848},
      {4, false, 0.3, 3, 0.0378242, 0.0415911},
  };
  return rows;
}

}  // namespace hsrod
