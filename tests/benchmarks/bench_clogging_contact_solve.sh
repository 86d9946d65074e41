#!/usr/bin/env bash
# Benchmark (not a ctest test): the clogging run of
# examples/suspension-clogging/in.suspension (40 rods, lattice in front of
# the cylinders, jitter 0.5 um / 2 deg, seed 1: a plug forms) with fix
# rod/implicit's contact_solve capacitance and lu, REPEATS rounds
# interleaved: user and wall time of each run beside its outcome (rods
# clogged, passed with / without contact, the time it was decided), the
# medians per variant and the 1-minute load after each run (the machine may
# be shared: compare runs of one round).
# Usage: tests/benchmarks/bench_clogging_contact_solve.sh [work-dir]
# Environment: REPEATS (default 2), NRODS (40), SEED (1), HSROD_BUILD (build/),
#              VARIANTS (default "capacitance lu": contact_solve values, each
#              optionally LABEL=SOLVE@BINARY to time another build's hsrod).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HSROD_BUILD:-$root/build}"
work="$(mkdir -p "${1:-$build/bench-clogging}" && cd "${1:-$build/bench-clogging}" && pwd)"
repeats="${REPEATS:-2}"
variants="${VARIANTS:-capacitance lu}"
cd "$work"
# The example with the contact solve as a variable.
sed 's/^\(fix  *step  *all  *rod\/implicit .*\)$/\1 contact_solve ${contact_solve}/' \
  "$root/examples/suspension-clogging/in.suspension" > in.suspension
grep -q 'contact_solve ${contact_solve}' in.suspension
echo "== clogging run: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(git -C "$root" rev-parse --short HEAD), ${NRODS:-40} rods, seed ${SEED:-1}"
declare -A users walls
for round in $(seq "$repeats"); do
  for variant in $variants; do
    label="${variant%%=*}"; spec="${variant#*=}"
    solve="${spec%%@*}"; binary="$build/hsrod"
    [[ "$spec" == *@* ]] && binary="${spec#*@}"
    /usr/bin/time -f "%U %e" -o time.txt "$binary" -in in.suspension -var contact_solve "$solve" \
      -var spheres 10 -var layout lattice -var angle 0 -var x_min 120e-6 -var x_max 215e-6 \
      -var jitter_x 0.5e-6 -var jitter_angle 2 -var nrods "${NRODS:-40}" -var seed "${SEED:-1}" \
      -log none -echo none > "run_${label}_$round.txt"
    read -r user wall < time.txt
    users[$label]="${users[$label]:-} $user"; walls[$label]="${walls[$label]:-} $wall"
    outcome=$(grep '^SUSPENSION' "run_${label}_$round.txt" | awk '{print "clogged", $7, "passed", $9 "/" $11, "t", $13}')
    printf "round %d %-14s user %7.1f s wall %7.1f s  %s  load %s\n" "$round" "$label" "$user" "$wall" "$outcome" \
      "$(cut -d' ' -f1 /proc/loadavg)"
  done
done
median() { printf "%s\n" $1 | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
for variant in $variants; do
  label="${variant%%=*}"
  printf "median %-14s user %s s (runs:%s), wall %s s (runs:%s)\n" "$label" "$(median "${users[$label]}")" \
    "${users[$label]}" "$(median "${walls[$label]}")" "${walls[$label]}"
done
