// The cross-check record of `auto` (hydro/auto_model_choice.h), written by (one command)
//   build/hsrod_crosscheck_levels calibration/data/resolved_campaign_series.csv
//     calibration/data/resolved_campaign_profiles.csv build/crosscheck/record.csv
//     --error-record calibration/data/level_error_record.csv
//     --error-record-cpp drag-models/hydro/auto_model_choice_record.cpp
// Do not edit: regenerate when a level or the table changes (test
// calibration_AutoErrorModel.BuiltInRecordIsTheCurrentCrossCheck fails otherwise).
#include "hydro/auto_model_choice.h"

namespace hsrod {

const char* level_error_record_provenance() {
  return "hsrod_crosscheck_levels --error-record: levels against the resolved campaign (resolved_campaign_series.csv, rigid rods, role fit), table: built-in: hsrod_fit_campaign on the resolved campaign of 2026-12-01 (calibration/data/campaign_summary.json); sphere columns Faxen's (not rejected by the runs); rod columns (n = 10) fitted over beta 0.15-0.30, extrapolated outside";
}

const std::vector<LevelErrorRow>& level_error_record() {
  // level, beta, n, force_error, velocity_error, r_error
  static const std::vector<LevelErrorRow> rows = {
      {1, 0.15, 1, 0.00574105, 0.00193428, 0},
      {1, 0.15, 2, 0.487996, 0.00253632, 6.02964e-05},
      {1, 0.15, 5, 1.19838, 0.00317566, 0.000230147},
      {1, 0.15, 10, 1.7004, 0.00354143, 0.000394245},
      {1, 0.3, 1, 0.00633524, 0.00113889, 0},
      {1, 0.3, 2, 0.426256, 0.00469888, 0.000323995},
      {1, 0.3, 5, 1.01336, 0.00735257, 0.00119138},
      {1, 0.3, 10, 1.38669, 0.00878531, 0.00218282},
      {2, 0.15, 1, 0.00574105, 0.00193428, 0},
      {2, 0.15, 2, 0.0265972, 0.00153351, 0.000671261},
      {2, 0.15, 5, 0.0153348, 0.00083226, 0.000901423},
      {2, 0.15, 10, 0.024294, 0.000427037, 0.000697033},
      {2, 0.3, 1, 0.00633524, 0.00113889, 0},
      {2, 0.3, 2, 0.0330812, 0.00178093, 0.00145439},
      {2, 0.3, 5, 0.021047, 0.000843034, 0.00120455},
      {2, 0.3, 10, 0.00830168, 0.000353856, 0.000148829},
      {3, 0.15, 1, 0.00574105, 0.00193428, 0},
      {3, 0.15, 2, 0.177668, 0.00181672, 0.00125852},
      {3, 0.15, 5, 0.352361, 0.00206424, 0.00409428},
      {3, 0.15, 10, 0.455447, 0.00401373, 0.00691202},
      {3, 0.3, 1, 0.00633524, 0.00113889, 0},
      {3, 0.3, 2, 0.146731, 0.00583585, 0.00986735},
      {3, 0.3, 5, 0.305321, 0.0165171, 0.0266192},
      {3, 0.3, 10, 0.392331, 0.0232867, 0.039091},
      {4, 0.15, 1, 0.00483588, 0.00192751, 0},
      {4, 0.15, 2, 0.209167, 0.00187921, 0.00107285},
      {4, 0.15, 5, 0.403925, 0.00237243, 0.00357858},
      {4, 0.15, 10, 0.565013, 0.00341654, 0.00589391},
      {4, 0.3, 1, 0.00636557, 0.00113794, 0},
      {4, 0.3, 2, 0.154761, 0.00418609, 0.00817538},
      {4, 0.3, 5, 0.362055, 0.010981, 0.0220057},
      {4, 0.3, 10, 0.403224, 0.0173776, 0.0330187},
  };
  return rows;
}

}  // namespace hsrod
