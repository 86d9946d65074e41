#!/usr/bin/env bash
# The paper's clogging regime maps (Braesel et al. 2024, Figs. 10-11) with
# hsrod-sweep on an MPI task farm, each case one run of
# ../clogging/in.clogging (rod lengthened at a fixed pore, d_pore = 30 um,
# beta = 0.15, Re = 2, mu_fr = 0.5) that stops once fix rod/outcome has
# decided: 1 passed without wall contact, 2 passed with contact, 3 clogged.
#   fig10a: aspect ratio 10 (1 sphere per section), alpha = 0,
#           E 15 kPa - 15 MPa (13 values, 4 per decade) x L_rod/d_pore 1 - 5 (step 0.5)
#   fig11a: aspect ratio 10, E = 15 MPa, alpha 0 - 90 deg (step 7.5) x L_rod/d_pore 1 - 5
#   fig10b: aspect ratio 5 (2x2 spheres per section, d_rod = 6 um, H = 40 um),
#           E 15 kPa - 15 MPa (7 values, 2 per decade) x L_rod/d_pore 1 - 5 (step 1)   [coarse: see README]
#   fig11b: aspect ratio 5, E = 15 MPa, alpha 0 - 45 deg (step 15) x L_rod/d_pore 2 - 4 (step 1)   [coarse]
#   fig10b_full, fig11b_full: the aspect-ratio-5 maps on fig10a's / fig11a's 13 x 9 grid
#           (with fig10a and fig11a: the full 468-case grid)
# Usage: bash run_maps.sh [fig10a fig11a fig10b fig11b fig10b_full fig11b_full]   (default: the first four)
# Environment: WORKERS (default 2; the farm runs WORKERS + 1 MPI ranks),
# MODEL (drag model, default local = level 2), BUILD (default ../../build),
# CASE_TIMEOUT (seconds of wall time per case, default 0 = none),
# RETRY_FAILED=1 (drop the failed rows of an existing <map>.csv first, so the
# resumed sweep runs only those cases again, e.g. after a code fix).
# Each map goes to <name>.csv (resumable: run the same command again after an
# interruption) and <name>.png; the time of each sweep to times.txt.
set -euo pipefail
cd "$(dirname "$0")"
here="$PWD"
build="$(cd "${BUILD:-../../build}" && pwd)"
workers="${WORKERS:-2}"
model="${MODEL:-local}"
sweep=("$build/hsrod-sweep")
[ "$workers" -gt 1 ] && sweep=(mpirun --allow-run-as-root --oversubscribe -np $((workers + 1)) "$build/hsrod-sweep")
E13=15e3,26.67e3,47.43e3,84.35e3,150e3,266.7e3,474.3e3,843.5e3,1.5e6,2.667e6,4.743e6,8.435e6,15e6
measures=(--measure outcome=f_out[2] --measure t_decided=time --measure x_centre=c_shape[2]
          --measure y_centre=c_shape[3] --measure angle=c_shape[7] --measure deflection=c_shape[8]
          --measure first_contact_t=f_out[3] --measure first_contact_x=f_out[4])
run() {  # run <name> <sweep arguments...>
  local name=$1
  shift
  local start
  if [ "${RETRY_FAILED:-0}" = 1 ] && [ -f "$name.csv" ]; then
    /usr/bin/python3 - "$name.csv" <<'PY'
import csv, os, sys
path = sys.argv[1]
with open(path, newline="") as f:
    rows = list(csv.reader(f))
status = rows[0].index("status")
kept = [rows[0]] + [r for r in rows[1:] if len(r) == len(rows[0]) and r[status] == "ok"]
with open(path + ".tmp", "w", newline="") as f:
    csv.writer(f, lineterminator="\n").writerows(kept)
os.replace(path + ".tmp", path)
print(f"{path}: {len(rows) - len(kept)} failed row(s) dropped, {len(kept) - 1} kept")
PY
  fi
  start=$(date +%s.%N)
  "${sweep[@]}" --in "$here/../clogging/in.clogging" --workdir "$here/../clogging" --var model "$model" "$@" "${measures[@]}" \
    --case-timeout "${CASE_TIMEOUT:-0}" --output "$here/$name.csv" | tail -2
  echo "$name $(/usr/bin/python3 -c "print(round($(date +%s.%N) - $start, 1))") s wall, $workers workers, load $(cut -d' ' -f1-3 /proc/loadavg)" \
    | tee -a times.txt
}
plot() {  # plot <name> <x> <title> [--logx]
  /usr/bin/python3 ../../liggghts-package/sweep/plot_sweep.py map "$1.csv" --x "$2" --y ratio --class outcome \
    --ylabel "L_rod / d_pore" --title "$3" "${@:4}" -o "$1.png"
}
maps=("$@")
[ ${#maps[@]} -eq 0 ] && maps=(fig10a fig11a fig10b fig11b)
for map in "${maps[@]}"; do
  case $map in
    fig10a) run fig10a --var section 1 --var alpha 0 --var E "$E13" --var ratio 1:5:0.5
            plot fig10a E "Fig. 10a: aspect ratio 10, alpha = 0 (hsrod, $model)" --logx --xlabel "E [Pa]" ;;
    fig11a) run fig11a --var section 1 --var E 15e6 --var alpha 0:90:7.5 --var ratio 1:5:0.5
            plot fig11a alpha "Fig. 11a: aspect ratio 10, E = 15 MPa (hsrod, $model)" --xlabel "initial angle alpha [deg]" ;;
    fig10b) run fig10b --var section 2 --var alpha 0 --var E 15e3,47.43e3,150e3,474.3e3,1.5e6,4.743e6,15e6 --var ratio 1:5:1
            plot fig10b E "Fig. 10b: aspect ratio 5, alpha = 0 (hsrod, $model)" --logx --xlabel "E [Pa]" ;;
    fig11b) run fig11b --var section 2 --var E 15e6 --var alpha 0:45:15 --var ratio 2:4:1
            plot fig11b alpha "Fig. 11b: aspect ratio 5, E = 15 MPa (hsrod, $model)" --xlabel "initial angle alpha [deg]" ;;
    # The aspect-ratio-5 maps on the full 13 x 9 grid of fig10a / fig11a
    # (with fig10a and fig11a: the 468-case grid of tests/benchmarks/project_grid_cost.py).
    fig10b_full) run fig10b_full --var section 2 --var alpha 0 --var E "$E13" --var ratio 1:5:0.5
            plot fig10b_full E "Fig. 10b: aspect ratio 5, alpha = 0 (hsrod, $model)" --logx --xlabel "E [Pa]" ;;
    fig11b_full) run fig11b_full --var section 2 --var E 15e6 --var alpha 0:90:7.5 --var ratio 1:5:0.5
            plot fig11b_full alpha "Fig. 11b: aspect ratio 5, E = 15 MPa (hsrod, $model)" --xlabel "initial angle alpha [deg]" ;;
    *) echo "run_maps.sh: unknown map '$map' (fig10a, fig11a, fig10b, fig11b, fig10b_full, fig11b_full)" >&2; exit 1 ;;
  esac
done
