#!/usr/bin/env bash
# Benchmark (not a ctest test): cost per rod-step of a suspension of rods of
# 10 spheres (tests/benchmarks/scripts/in.many_rods: create_rods at area
# fraction ~5 %, rod-rod Hertz contact with friction, straight channel,
# beta 0.15) against the number of rods, at the levels in MODELS, median of
# REPEATS runs, on one core, with the 1-minute load after each count (the
# machine may be shared: compare ratios within one run); and the same 100-rod run on 1 and 2 MPI ranks
# (largest difference of the final sphere positions, relative to d); with
# PORE_RODS set, that many rods through the paper's pore scene lengthened
# upstream (tests/benchmarks/scripts/in.pore_many_rods), level 2, one core:
# wall time (set-up and loop) beside the rods clogged and passed.
# Usage: tests/benchmarks/bench_many_rods.sh [work-dir]   (after scripts/build.sh)
# Environment: COUNTS (default "10 100 1000"), MODELS (default "local"),
#              COUPLING (fix rod/implicit rod_interaction: yes = one joint solve,
#              lagged, or iterated with SWEEPS > 0 sweeps to SWEEP_TOLERANCE;
#              FAR_FIELD yes|no: rod_far_field of the rods apart, default yes),
#              RANKS_MODEL (level of the 1 vs 2 ranks run, default local),
#              STEPS (default 100), REPEATS (default 3), HSROD_BUILD (build/),
#              PORE_RODS (default: none, skip), PORE_UPSTREAM (default 1800e-6 m),
#              PORE_TMAX (default 0.1 s: the run stops there if rods are left),
#              PORE_COMPARE (set: the pore scene REPEATS times with each of fix
#              rod/implicit's contact_solve capacitance and lu, interleaved:
#              median loop time of each, their ratio, and the largest
#              difference of the final sphere positions between the two),
#              FAR_FIELD_COMPARE (set: level 3 rods apart at each count with
#              rod_far_field no and yes, interleaved: loop time and CPU time).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HSROD_BUILD:-$root/build}"
work="$(mkdir -p "${1:-$build/bench-many-rods}" && cd "${1:-$build/bench-many-rods}" && pwd)"
script="$root/tests/benchmarks/scripts/in.many_rods"
counts="${COUNTS:-10 100 1000}"
models="${MODELS:-local}"
steps="${STEPS:-100}"
repeats="${REPEATS:-3}"
coupling=(-var coupling "${COUPLING:-yes}" -var sweeps "${SWEEPS:-0}" -var sweep_tolerance "${SWEEP_TOLERANCE:-1e-6}"
          -var far_field "${FAR_FIELD:-yes}")
cd "$work"
echo "== many rods: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(git -C "$root" rev-parse --short HEAD), $steps steps, rod_interaction ${COUPLING:-yes} (sweeps ${SWEEPS:-0}, rod_far_field ${FAR_FIELD:-yes})"
printf "%-8s %7s %12s %14s %16s %8s\n" model rods "loop [s]" "per rod-step" "vs 100 rods" "load"
for model in $models; do
  ref=""
  for n in $counts; do
    times=()
    for _ in $(seq "$repeats"); do
      t=$("$build/hsrod" -in "$script" -var nrods "$n" -var model "$model" -var steps "$steps" "${coupling[@]}" -log none -echo none |
          awk '/^Loop time of/ {t = $4} END {print t}')
      times+=("$t")
    done
    median=$(printf "%s\n" "${times[@]}" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')
    per=$(awk -v t="$median" -v n="$n" -v s="$steps" 'BEGIN {printf "%.3g", t / (n * s)}')
    [ "$n" = 100 ] && ref=$per
    growth=$([ -n "$ref" ] && awk -v a="$per" -v b="$ref" 'BEGIN {printf "%.2fx", a / b}' || echo "-")
    printf "%-8s %7s %12s %12s s %16s %8s\n" "$model" "$n" "$median" "$per" "$growth" "$(cut -d' ' -f1 /proc/loadavg)"
  done
done
# 1 vs 2 ranks: the same rods and the same trajectory (to round-off).
for ranks in 1 2; do
  cp "$script" "ranks$ranks.in"
  echo "write_dump all custom final$ranks.txt id x y z modify sort id format \"%d %.16e %.16e %.16e\"" >> "ranks$ranks.in"
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/hsrod" -in "ranks$ranks.in" -var nrods 100 \
    -var model "${RANKS_MODEL:-local}" -var steps "$steps" "${coupling[@]}" -log none -echo none > /dev/null
done
/usr/bin/python3 - <<'PY'
import numpy as np
a, b = (np.loadtxt(f"final{r}.txt", skiprows=9) for r in (1, 2))
print(f"1 vs 2 ranks, 100 rods, {len(a)} spheres: largest position difference {np.abs(a[:, 1:] - b[:, 1:]).max() / 3e-6:.2e} d")
PY
# Many rods through the pore scene: wall time beside the outcome counts.
if [ -n "${PORE_RODS:-}" ] && [ -z "${PORE_COMPARE:-}" ]; then
  start=$(date +%s.%N)
  out=$("$build/hsrod" -in "$root/tests/benchmarks/scripts/in.pore_many_rods" -var nrods "$PORE_RODS" \
        -var upstream "${PORE_UPSTREAM:-1800e-6}" -var t_max "${PORE_TMAX:-0.1}" -log none -echo none)
  wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}')
  loop=$(printf "%s\n" "$out" | awk '/^Loop time of/ {t += $4; s += $9} END {printf "%.1f s over %d steps", t, s}')
  printf "pore scene, %s rods, level 2, 1 core: wall %s s (loop %s), load %s\n" "$PORE_RODS" "$wall" "$loop" \
    "$(cut -d' ' -f1 /proc/loadavg)"
  printf "%s\n" "$out" | grep '^PORE'
fi
# The pore scene's contact clusters by the capacitance solve and by the
# general LU: time beside the trajectories' difference.
if [ -n "${PORE_RODS:-}" ] && [ -n "${PORE_COMPARE:-}" ]; then
  declare -A loops
  for solve in capacitance lu; do
    cp "$root/tests/benchmarks/scripts/in.pore_many_rods" "pore_$solve.in"
    echo "write_dump all custom pore_final_$solve.txt id x y z modify sort id format \"%d %.17g %.17g %.17g\"" >> "pore_$solve.in"
  done
  for _ in $(seq "$repeats"); do
    for solve in capacitance lu; do
      t=$("$build/hsrod" -in "pore_$solve.in" -var nrods "$PORE_RODS" -var upstream "${PORE_UPSTREAM:-1800e-6}" \
          -var t_max "${PORE_TMAX:-0.1}" -var contact_solve "$solve" -log none -echo none |
          awk '/^Loop time of/ {t += $4; s += $9} END {printf "%.2f", t}')
      loops[$solve]="${loops[$solve]:-} $t"
    done
  done
  median() { printf "%s\n" $1 | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
  mc=$(median "${loops[capacitance]}"); ml=$(median "${loops[lu]}")
  diff=$(/usr/bin/python3 - <<'PY'
import numpy as np
a, b = (np.loadtxt(f"pore_final_{s}.txt", skiprows=9) for s in ("capacitance", "lu"))
print(f"{np.abs(a[:, 1:] - b[:, 1:]).max() / 3e-6:.2e} d")
PY
)
  printf "pore scene, %s rods, t_max %s: loop capacitance %s s (runs:%s), lu %s s (runs:%s), lu / capacitance %s; largest final position difference %s; load %s\n" \
    "$PORE_RODS" "${PORE_TMAX:-0.1}" "$mc" "${loops[capacitance]}" "$ml" "${loops[lu]}" \
    "$(awk -v a="$ml" -v b="$mc" 'BEGIN {printf "%.2f", a / b}')" "$diff" "$(cut -d' ' -f1 /proc/loadavg)"
fi
# With FAR_FIELD_COMPARE set: rods apart (COUPLING lagged or iterated) at
# each count, REPEATS runs each of rod_far_field no and yes, interleaved:
# median loop time and user CPU per rod-step of each (the CPU time is less
# disturbed by a shared machine's load than the loop's wall time).
if [ -n "${FAR_FIELD_COMPARE:-}" ]; then
  median() { printf "%s\n" $1 | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
  for n in $counts; do
    declare -A loop cpu
    for _ in $(seq "$repeats"); do
      for far in no yes; do
        out=$( { /usr/bin/time -f "CPU %U" "$build/hsrod" -in "$script" -var nrods "$n" -var model nonlocal \
                 -var steps "$steps" "${coupling[@]}" -var far_field "$far" -log none -echo none; } 2>&1)
        loop[$far]="${loop[$far]:-} $(printf "%s\n" "$out" | awk '/^Loop time of/ {t = $4} END {print t}')"
        cpu[$far]="${cpu[$far]:-} $(printf "%s\n" "$out" | awk '/^CPU/ {print $2}')"
      done
    done
    printf "rods apart %s, %s rods, %s steps: rod_far_field no: loop %s s, CPU %s s (runs:%s); yes: loop %s s, CPU %s s (runs:%s); CPU per rod-step no %s ms, yes %s ms, yes / no %s; load %s\n" \
      "${COUPLING:-yes}" "$n" "$steps" "$(median "${loop[no]}")" "$(median "${cpu[no]}")" "${cpu[no]}" \
      "$(median "${loop[yes]}")" "$(median "${cpu[yes]}")" "${cpu[yes]}" \
      "$(awk -v t="$(median "${cpu[no]}")" -v n="$n" -v s="$steps" 'BEGIN {printf "%.3g", 1e3 * t / (n * s)}')" \
      "$(awk -v t="$(median "${cpu[yes]}")" -v n="$n" -v s="$steps" 'BEGIN {printf "%.3g", 1e3 * t / (n * s)}')" \
      "$(awk -v a="$(median "${cpu[yes]}")" -v b="$(median "${cpu[no]}")" 'BEGIN {printf "%.3f", a / b}')" \
      "$(cut -d' ' -f1 /proc/loadavg)"
    unset loop cpu
  done
fi
