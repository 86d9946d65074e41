// The shipped near-field fit (hydro/near_field_coupling.h), written by
//   build/hsrod_fit_near_field (calibration/tools/fit_near_field.cpp)
// Do not edit: equals calibration/data/near_field_coupling.txt (test
// NearFieldCoupling.BuiltInIsTheShippedFile).
#include "hydro/near_field_coupling.h"

namespace hsrod {

NearFieldCalibration NearFieldCalibration::built_in() {
  NearFieldCalibration c;
  c.nonlocal = {0.3316754246, 0.1673103434, -0.03896256246};
  c.twoway = {0.3466112416, 0.2526038509, -0.1411424773};
  c.source = "hsrod_fit_near_field on resolved_campaign_series.csv (resolved rodIbFoam rigid rods, per-sphere profiles, finest mesh), table: built-in: hsrod_fit_campaign on the resolved campaign of 2026-12-01 (calibration/data/campaign_summary.json); sphere columns Faxen's (not rejected by the runs); rod columns (n = 10) fitted over beta 0.15-0.30, extrapolated outside";
  return c;
}

}  // namespace hsrod
