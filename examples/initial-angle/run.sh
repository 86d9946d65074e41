#!/usr/bin/env bash
# Runs the six cases of Figs. 5-6 and plots them (initial_angle.png).
set -euo pipefail
cd "$(dirname "$0")"
hsrod="${1:-../../build/hsrod}"
specs=()
for E in 15e3 15e6; do
  for a in 0.1 10 45; do
    "$hsrod" -in in.initial_angle -log none -var E "$E" -var alpha "$a" | grep -a "model\|passed"
    label="alpha = $a deg, $([ "$E" = 15e3 ] && echo '15 kPa' || echo '15 MPa')"
    specs+=("angle_E${E}_a${a}.csv:$label")
  done
done
/usr/bin/python3 ../pore-constriction/summarise_pore.py "${specs[@]}" --csv summary.csv
/usr/bin/python3 ../pore-constriction/plot_pore.py --title "Initial angle (Figs. 5-6): L_rod/d_pore = 1, no offset, beta = 0.15" \
  initial_angle.png "${specs[@]}"
