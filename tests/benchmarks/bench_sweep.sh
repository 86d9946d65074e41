#!/usr/bin/env bash
# Benchmark (not a ctest test): hsrod-sweep on the paper's clogging maps
# (Figs. 10-11; examples/clogging/in.clogging, the cases of
# examples/regime-map/run_maps.sh, at its default level MODEL=local).
# Three parts (PARTS, default "100 maps ar5"):
#   100   100 cases (aspect ratio 10, alpha 0: E 20 values 15 kPa-15 MPa x
#         L_rod/d_pore 1-5) on 1 worker (one process) and on 2 workers
#         (mpirun -np 3: scheduler + 2 workers): wall times, and the
#         parallel efficiency measured two ways:
#           wall:  T1 / (2 T2)                          (needs a quiet machine)
#           load-independent: (C1 / C2) x (b2 / b1)     (C = summed case CPU,
#             b = busy fraction printed by hsrod-sweep: summed case wall /
#             (workers x makespan); load slows cases and makespan alike, so
#             b measures the farm's idle time and C1/C2 any slow-down of the
#             cases themselves by running two at once)
#   maps  the Figs. 10a + 11a grids at aspect ratio 10 (13 x 9 + 13 x 9 =
#         234 cases) on 2 workers: wall time, summed case CPU, and the time
#         on two free cores, C / (2 b)
#   ar5   a sample of aspect-ratio-5 cases (2x2 spheres per section, Figs.
#         10b/11b: E 15 kPa, 1.5 MPa, 15 MPa x L_rod/d_pore 1, 3, 5) on 2
#         workers: their CPU per case, to project the full ~500-case grid
#         (Figs. 10a, 10b, 11a, 11b at 13 x 9 each = 468 cases)
# and the per-case cost model projecting a 1e5-case sweep on a cluster.
# The pore's flow field is solved once (cached) before timing.
# Usage: tests/benchmarks/bench_sweep.sh [work-dir]   (after scripts/build.sh)
# Environment: MODEL (default local), PARTS, HSROD_BUILD (default build/).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HSROD_BUILD:-$root/build}"
work="$(mkdir -p "${1:-$build/bench-sweep}" && cd "${1:-$build/bench-sweep}" && pwd)"
model="${MODEL:-local}"
parts="${PARTS:-100 maps ar5}"
clogging="$root/examples/clogging"
sweep="$build/hsrod-sweep"
E20=$(/usr/bin/python3 -c "print(','.join('%.4g' % (15e3 * 10 ** (3 * i / 19)) for i in range(20)))")
E13=15e3,26.67e3,47.43e3,84.35e3,150e3,266.7e3,474.3e3,843.5e3,1.5e6,2.667e6,4.743e6,8.435e6,15e6
common=(--in "$clogging/in.clogging" --workdir "$clogging" --var model "$model" --measure outcome=f_out[2]
        --measure t=time)

echo "== hsrod-sweep benchmark, model $model, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(git -C "$root" rev-parse --short HEAD)"
echo "== warming the flow cache"
"$sweep" "${common[@]}" --var section 1,2 --var ratio 1 --output "$work/warm.csv" --fresh | tail -1

sweep_run() {  # sweep_run <label> <workers> <sweep arguments...>: writes <label>.csv/.out, appends to runs.txt
  local label=$1 workers=$2
  shift 2
  local cmd=("$sweep")
  [ "$workers" -gt 1 ] && cmd=(mpirun --allow-run-as-root --oversubscribe -np $((workers + 1)) "$sweep")
  local load_before start end
  load_before=$(cut -d' ' -f1 /proc/loadavg)
  start=$(date +%s.%N)
  "${cmd[@]}" "${common[@]}" "$@" --output "$work/$label.csv" --fresh > "$work/$label.out"
  end=$(date +%s.%N)
  grep -E "busy fraction|finished" "$work/$label.out" | sed "s/^/  $label: /"
  echo "$label $workers $(/usr/bin/python3 -c "print($end - $start)") $load_before $(cut -d' ' -f1 /proc/loadavg)" >> "$work/runs.txt"
}
rm -f "$work/runs.txt"
for part in $parts; do
  case $part in
    100) sweep_run one100 1 --var section 1 --var alpha 0 --var E "$E20" --var ratio 1:5:1
         sweep_run two100 2 --var section 1 --var alpha 0 --var E "$E20" --var ratio 1:5:1 ;;
    maps) sweep_run fig10a 2 --var section 1 --var alpha 0 --var E "$E13" --var ratio 1:5:0.5
          sweep_run fig11a 2 --var section 1 --var E 15e6 --var alpha 0:90:7.5 --var ratio 1:5:0.5 ;;
    ar5) sweep_run ar5 2 --var section 2 --var alpha 0 --var E 15e3,1.5e6,15e6 --var ratio 1,3,5 ;;
    *) echo "bench_sweep.sh: unknown part '$part' (100, maps, ar5)" >&2; exit 1 ;;
  esac
done

/usr/bin/python3 - "$work" <<'PY'
import csv, os, re, statistics, sys
work = sys.argv[1]
runs = {}
for line in open(os.path.join(work, "runs.txt")):
    label, workers, wall, load0, load1 = line.split()
    out = open(os.path.join(work, label + ".out")).read()
    busy = re.search(r"busy fraction ([0-9.]+) %.*summed case CPU ([0-9.e+-]+) s", out)
    sched = re.search(r"scheduler: ([0-9.e+-]+) ms per finished case", out)
    rows = list(csv.DictReader(open(os.path.join(work, label + ".csv"))))
    runs[label] = dict(workers=int(workers), wall=float(wall), load=(float(load0), float(load1)),
                       busy=float(busy.group(1)) / 100, cpu=float(busy.group(2)), sched_ms=float(sched.group(1)),
                       rows=rows, cases=len(rows), failed=sum(r["status"] != "ok" for r in rows),
                       case_cpu=[float(r["cpu_s"]) for r in rows])
print("\n| run | workers | cases (failed) | wall | summed case CPU | busy fraction | on 2 free cores, C/(W b) | load before/after |")
print("| --- | --- | --- | --- | --- | --- | --- | --- |")
for k, r in runs.items():
    print(f"| {k} | {r['workers']} | {r['cases']} ({r['failed']}) | {r['wall']:.1f} s | {r['cpu']:.1f} s | "
          f"{r['busy']:.1%} | {r['cpu'] / (r['workers'] * r['busy']):.1f} s | {r['load'][0]:.1f} / {r['load'][1]:.1f} |")
def stable(rows):
    return sorted(tuple(v for k, v in r.items() if k not in ("wall_s", "cpu_s", "rank", "error")) for r in rows)
if "one100" in runs and "two100" in runs:
    one, two = runs["one100"], runs["two100"]
    e_wall = one["wall"] / (2 * two["wall"])
    e_load = (one["cpu"] / two["cpu"]) * (two["busy"] / one["busy"])
    print(f"\n100 cases: 1 worker {one['wall']:.1f} s, 2 workers {two['wall']:.1f} s wall; same rows: {stable(one['rows']) == stable(two['rows'])}")
    print(f"parallel efficiency 2 workers vs 1: wall T1/(2 T2) = {e_wall:.1%} (load {one['load'][0]:.1f} -> {two['load'][1]:.1f}); "
          f"load-independent (C1/C2)(b2/b1) = {one['cpu'] / two['cpu']:.3f} x {two['busy'] / one['busy']:.3f} = {e_load:.1%}")
    print(f"100 cases on 2 free cores (CPU-bound): C2/(2 b2) = {two['cpu'] / (2 * two['busy']):.1f} s")
    c = statistics.mean(one["case_cpu"])
    s = two["sched_ms"] / 1e3
    print(f"cost model: T(N, P) = N c / (P e) + one start-up, c = {c:.3f} s CPU per case (mean; median "
          f"{statistics.median(one['case_cpu']):.3f}, max {max(one['case_cpu']):.2f}), e = {e_load:.2f}; "
          f"the scheduler serialises N s, s = {s * 1e3:.2f} ms per row")
    for P in (64, 256, 1024):
        N = 1e5
        print(f"  1e5 cases on {P} workers: {N * c / (P * e_load) / 60:.1f} min of case work; scheduler floor N s = {N * s / 60:.1f} min")
maps = [runs[k] for k in ("fig10a", "fig11a") if k in runs]
if maps:
    cpu = sum(r["cpu"] for r in maps); n = sum(r["cases"] for r in maps)
    busy = sum(r["busy"] * r["wall"] for r in maps) / sum(r["wall"] for r in maps)
    print(f"\nFigs. 10a + 11a (aspect ratio 10): {n} cases, {sum(r['wall'] for r in maps):.0f} s wall here, "
          f"{cpu:.1f} s summed case CPU ({cpu / n:.3f} s per case), on 2 free cores {cpu / (2 * busy):.0f} s")
    if "ar5" in runs:
        a = runs["ar5"]
        c5 = a["cpu"] / a["cases"]
        total = cpu + 234 * c5
        print(f"aspect ratio 5 sample: {a['cases']} cases, {c5:.1f} s CPU per case (median "
              f"{statistics.median(a['case_cpu']):.1f}, max {max(a['case_cpu']):.1f}); the full grid (Figs. 10a, 10b, 11a, 11b "
              f"at 13 x 9 = 468 cases) projected at {total:.0f} s CPU = {total / (2 * busy) / 60:.1f} min on 2 free cores, "
              f"{cpu / (2 * busy) / 60:.1f} min of it for the 234 aspect-ratio-10 cases")
PY
