#!/usr/bin/env bash
# The regime map of Fig. 10: outcome of in.clogging over E x L_rod/d_pore for
# aspect ratio 10 (section 1) and 5 (section 2), alpha = 0, one hsrod run per
# case (helper-free; the sweep tool does the same on an MPI task farm).
# Writes map.csv (one row per case: section, E, ratio, outcome code (-1: the
# run failed, 0: undecided after 40 ms), time and x of the decision, first
# contact time and x, wall time) and the per-case CSVs.
# Usage: bash run_map.sh [hsrod binary] ; then /usr/bin/python3 plot_clogging.py
set -euo pipefail
cd "$(dirname "$0")"
hsrod="${1:-../../build/hsrod}"
moduli="${MODULI:-15e3 150e3 1.5e6 15e6}"
ratios="${RATIOS:-1 2 3 4 5}"
sections="${SECTIONS:-1 2}"
echo "section,E_Pa,ratio,outcome,t_decided_s,x_decided_m,first_contact_t_s,first_contact_x_m,wall_s" > map.csv
for s in $sections; do
  for E in $moduli; do
    for r in $ratios; do
      start=$(date +%s%N)
      line=$("$hsrod" -in in.clogging -log none -var E "$E" -var ratio "$r" -var section "$s" -var vtk 0 \
               -var out "clog_E${E}_r${r}_s${s}_a0.csv" 2>&1 | grep "^OUTCOME" || echo "OUTCOME -1")
      wall=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN { printf "%.2f", (b - a) / 1e9 }')
      # OUTCOME code E .. ratio .. section .. alpha .. t T x X first_contact_t TC first_contact_x XC
      read -r _ code _ _ _ _ _ _ _ _ _ t _ x _ tc _ xc <<< "$line"
      echo "$s,$E,$r,$code,${t:-},${x:-},${tc:-},${xc:-},$wall" >> map.csv
      echo "section $s E $E ratio $r -> outcome $code (${wall} s)"
    done
  done
done
