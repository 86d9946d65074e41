#!/usr/bin/env bash
# Runs the six cases of Figs. 5-6 and plots them (initial_angle.png).
set -euo pipefail
cd "$(dirname "$0")"
hsrod="${1:-../../build/hsrod}"
specs=()
snaps_15e3=()
snaps_15e6=()
for E in 15e3 15e6; do
  for a in 0.1 10 45; do
    "$hsrod" -in in.initial_angle -log none -var E "$E" -var alpha "$a" | grep -a "model\|passed"
    label="alpha = $a deg, $([ "$E" = 15e3 ] && echo '15 kPa' || echo '15 MPa')"
    if [ "$E" = 15e3 ]; then snaps_15e3+=("rod_snap_E${E}_a${a}.txt:$label"); else snaps_15e6+=("rod_snap_E${E}_a${a}.txt:$label"); fi
    specs+=("angle_E${E}_a${a}.csv:$label")
  done
done
/usr/bin/python3 ../pore-constriction/summarise_pore.py "${specs[@]}" --csv summary.csv
/usr/bin/python3 ../pore-constriction/plot_pore.py --title "Initial angle (Figs. 5-6): L_rod/d_pore = 1, no offset, beta = 0.15" \
  initial_angle.png "${specs[@]}"
# Fig. 5: snapshots of the rods over the pore flow (speed and streamlines;
# fix hele_shaw/field's flow_0.vti and flow_walls.vtp from these runs), (a) 15 kPa, (b) 15 MPa.
/usr/bin/python3 ../pore-constriction/plot_flow.py initial_angle_snapshots_15kPa.png flow_0.vti flow_walls.vtp "${snaps_15e3[@]}"
/usr/bin/python3 ../pore-constriction/plot_flow.py initial_angle_snapshots_15MPa.png flow_0.vti flow_walls.vtp "${snaps_15e6[@]}"
