#!/usr/bin/env bash
# Fig. 3d: rigid rod velocity over the mean flow against beta, perpendicular
# (alpha = 0) and parallel (alpha = 90) to the flow, levels 2 and 3, with
# hsrod-sweep (32 cases) -> velocity_beta.csv, velocity_beta.png.
# Usage: bash run_velocity_beta.sh [--fresh]   (WORKERS=2 default; BUILD=../../build)
# hsrod-sweep resumes an existing velocity_beta.csv of the same sweep (then
# only the plot is redrawn); --fresh (passed on to hsrod-sweep) re-runs all 32 cases.
set -euo pipefail
cd "$(dirname "$0")"
build="$(cd "${BUILD:-../../build}" && pwd)"
workers="${WORKERS:-2}"
sweep=("$build/hsrod-sweep")
[ "$workers" -gt 1 ] && sweep=(mpirun --allow-run-as-root --oversubscribe -np $((workers + 1)) "$build/hsrod-sweep")
"${sweep[@]}" --in in.velocity_beta --var model local,nonlocal --var alpha 0,90 --var beta 0.1:0.8:0.1 \
  --measure vx_over_U=c_shape[10] --measure vx_over_uc=v_vx_over_uc --measure angle=c_shape[7] --output velocity_beta.csv "$@" | tail -2
/usr/bin/python3 plot_velocity_beta.py velocity_beta.csv velocity_beta.png
