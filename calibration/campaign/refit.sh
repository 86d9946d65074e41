#!/bin/sh
# Levels 1-2 refitted to every resolved case of the campaign, in one command
# (calibration/campaign/README.md):
#   calibration/campaign/refit.sh BUILD_DIR
# 1. collect: calibration/campaign/session4 record + beta-range results + the straight rows of the
#    geometry campaign (N = 20; its wall, pore and bent cases are skipped) -> calibration/data/*.csv,
#    campaign_summary.json, calibration/campaign/mesh_convergence.md
# 2. hsrod_fit_campaign -> calibration/data/confinement_campaign.txt, its fit
#    report, and the built-in table's parameters
#    (drag-models/hydro/default_coefficients_fit.h)
# 3. rebuild, then hsrod_fit_near_field -> the near field of levels 3-4
#    (calibration/data/near_field_coupling.txt, drag-models/hydro/
#    near_field_coupling_fit.cpp) on the new table's sphere columns
# 4. rebuild, then hsrod_crosscheck_levels -> the error record of `auto`
#    (calibration/data/level_error_record.csv, drag-models/hydro/
#    auto_model_choice_record.cpp) with the new built-in table and near
#    field; rebuild.
# (The pore-passage references move with these: re-record them as
# calibration/campaign/README.md says.)
set -e
build=${1:?usage: refit.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
data=calibration/data
/usr/bin/python3 calibration/tools/hsrod_campaign.py collect calibration/campaign/session4 calibration/campaign/beta-range calibration/campaign/geometry \
  --csv $data/resolved_campaign_per_sphere.csv --json $data/campaign_summary.json \
  --points $data/campaign_fit_points.csv --series $data/resolved_campaign_series.csv \
  --profiles $data/resolved_campaign_profiles.csv --mesh calibration/campaign/mesh_convergence.md
"$build"/hsrod_fit_campaign $data/campaign_fit_points.csv $data/confinement_campaign.txt \
  --report $data/confinement_campaign_fit.json --cpp drag-models/hydro/default_coefficients_fit.h \
  --source "hsrod_fit_campaign on the resolved campaign (calibration/data/campaign_summary.json)"
nice cmake --build "$build" -j2 --target hsrod_fit_near_field
"$build"/hsrod_fit_near_field $data/resolved_campaign_series.csv $data/resolved_campaign_profiles.csv \
  $data/near_field_coupling.txt --write-cpp drag-models/hydro/near_field_coupling_fit.cpp
nice cmake --build "$build" -j2 --target hsrod_crosscheck_levels
mkdir -p "$build"/crosscheck
"$build"/hsrod_crosscheck_levels $data/resolved_campaign_series.csv $data/resolved_campaign_profiles.csv \
  "$build"/crosscheck/record.csv --error-record $data/level_error_record.csv \
  --error-record-cpp drag-models/hydro/auto_model_choice_record.cpp
nice cmake --build "$build" -j2 --target hsrod_crosscheck_levels
