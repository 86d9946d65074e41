#!/usr/bin/env bash
# Runs Fig. 9's cases (beta 0.06, 0.15, 0.3 for both moduli; BETAS="0.06 0.15 0.3 0.5 0.6"
# adds the thin gaps, whose background-flow grid takes minutes and GBs) and
# plots them (confinement.png).
set -euo pipefail
cd "$(dirname "$0")"
hsrod="${1:-../../build/hsrod}"
specs=()
for E in 15e3 15e6; do
  for b in ${BETAS:-0.06 0.15 0.3}; do
    "$hsrod" -in in.confinement -log none -var E "$E" -var beta "$b" | grep -a "model\|passed"
    label="beta = $b, $([ "$E" = 15e3 ] && echo '15 kPa' || echo '15 MPa')"
    specs+=("beta_E${E}_b${b}.csv:$label")
  done
done
/usr/bin/python3 ../pore-constriction/summarise_pore.py "${specs[@]}" --csv summary.csv
/usr/bin/python3 ../pore-constriction/plot_pore.py --title "Confinement (Fig. 9): L_rod/d_pore = 1, alpha = 10 deg, no offset" \
  confinement.png "${specs[@]}"
