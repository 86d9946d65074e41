#!/usr/bin/env bash
# Runs the six cases of Figs. 7-8 and plots them (initial_offset.png).
set -euo pipefail
cd "$(dirname "$0")"
hsrod="${1:-../../build/hsrod}"
specs=()
snaps_15e3=()
snaps_15e6=()
for E in 15e3 15e6; do
  for dy in 0 15e-6 30e-6; do
    "$hsrod" -in in.initial_offset -log none -var E "$E" -var offset "$dy" | grep -a "model\|passed"
    label="dy = $dy m, $([ "$E" = 15e3 ] && echo '15 kPa' || echo '15 MPa')"
    if [ "$E" = 15e3 ]; then snaps_15e3+=("rod_snap_E${E}_dy${dy}.txt:$label"); else snaps_15e6+=("rod_snap_E${E}_dy${dy}.txt:$label"); fi
    specs+=("offset_E${E}_dy${dy}.csv:$label")
  done
done
/usr/bin/python3 ../pore-constriction/summarise_pore.py "${specs[@]}" --csv summary.csv
/usr/bin/python3 ../pore-constriction/plot_pore.py --title "Initial offset (Figs. 7-8): L_rod/d_pore = 1, alpha = 0.1 deg, beta = 0.15" \
  initial_offset.png "${specs[@]}"
# Fig. 7: snapshots of the rods over the pore flow (speed and streamlines;
# fix hele_shaw/field's flow_0.vti and flow_walls.vtp from these runs), (a) 15 kPa, (b) 15 MPa.
/usr/bin/python3 ../pore-constriction/plot_flow.py initial_offset_snapshots_15kPa.png flow_0.vti flow_walls.vtp "${snaps_15e3[@]}"
/usr/bin/python3 ../pore-constriction/plot_flow.py initial_offset_snapshots_15MPa.png flow_0.vti flow_walls.vtp "${snaps_15e6[@]}"
