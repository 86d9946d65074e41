#!/usr/bin/env bash
# Benchmark (not a ctest test): hsrod-sweep on 100 cases of the regime-map
# scene (examples/regime-map/in.regime at L_rod/L_pore = 2: E 20 values
# 15 kPa-15 MPa x initial angle alpha 0-90 deg, model auto, dt 4 us) with
# 1 worker (one process), 1 worker + scheduler (mpirun -np 2) and 2 workers
# (-np 3). Prints wall times, parallel efficiency, the per-case cost and the
# projection of a 1e5-case sweep on a cluster. The pore's flow field is
# solved once (cached in ~/.cache/hsrod) before timing: a new pore width
# costs a one-off grid solve of 0.5-several min, not part of a case.
# Usage: tests/benchmarks/bench_sweep.sh [work-dir]   (after scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HSROD_BUILD:-$root/build}"
work="${1:-$build/bench-sweep}"
mkdir -p "$work"
cd "$root/examples/regime-map"
sweep="$build/hsrod-sweep"
E_values=$(/usr/bin/python3 -c "print(','.join('%.4g' % (15e3 * 10 ** (3 * i / 19)) for i in range(20)))")
args=(--in in.regime --var E "$E_values" --var alpha 0:90:22.5
      --measure outcome=f_out[2] --measure x=c_shape[2] --measure angle=c_shape[7] --measure t=time)

echo "== warming the flow cache"
"$sweep" --in in.regime --var E 15e6 --measure outcome=f_out[2] \
  --output "$work/warm.csv" --fresh | tail -2

run() {  # run <label> <ranks>
  local label=$1 ranks=$2 cmd=("$sweep")
  [ "$ranks" -gt 1 ] && cmd=(mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$sweep")
  echo "== $label: ${cmd[*]} ${args[*]:0:4} ... (load $(cut -d' ' -f1-3 /proc/loadavg))"
  local start end
  start=$(date +%s.%N)
  "${cmd[@]}" "${args[@]}" --output "$work/$label.csv" --fresh > "$work/$label.out"
  end=$(date +%s.%N)
  tail -2 "$work/$label.out"
  echo "$label $(/usr/bin/python3 -c "print($end - $start)")" >> "$work/times.txt"
}
rm -f "$work/times.txt"
run serial 1
run np2 2
run np3 3

/usr/bin/python3 - "$work" <<'PY'
import csv, statistics, sys, os
work = sys.argv[1]
times = dict(line.split() for line in open(os.path.join(work, "times.txt")))
times = {k: float(v) for k, v in times.items()}
def table(label):
    return list(csv.DictReader(open(os.path.join(work, label + ".csv"))))
rows = {k: table(k) for k in times}
def stable(t):
    return sorted(tuple(v for k, v in r.items() if k not in ("wall_s", "cpu_s", "rank", "error")) for r in t)
same = stable(rows["serial"]) == stable(rows["np2"]) == stable(rows["np3"])
serial = rows["serial"]
wall = [float(r["wall_s"]) for r in serial]
cpu = [float(r["cpu_s"]) for r in serial]
outcomes = {}
for r in serial:
    outcomes[r["outcome"]] = outcomes.get(r["outcome"], 0) + 1
T1, T2, T3 = times["serial"], times["np2"], times["np3"]
eff2 = T1 / (2 * T3)
print(f"cases: {len(serial)}, failed: {sum(r['status'] != 'ok' for r in serial)}, outcome counts {outcomes}")
print(f"same rows (all but timing) in the three runs: {same}")
print(f"| run | workers | wall time, 100 cases | speed-up vs 1 worker | parallel efficiency |")
print(f"| --- | --- | --- | --- | --- |")
print(f"| serial (1 process) | 1 | {T1:.1f} s | 1 | - |")
print(f"| mpirun -np 2 | 1 | {T2:.1f} s | {T1 / T2:.2f} | {T1 / T2:.0%} (1 worker) |")
print(f"| mpirun -np 3 | 2 | {T3:.1f} s | {T1 / T3:.2f} | {eff2:.0%} |")
print(f"per case (serial run): median wall {statistics.median(wall):.3f} s, median CPU {statistics.median(cpu):.3f} s, "
      f"max wall {max(wall):.2f} s, mean wall {statistics.mean(wall):.3f} s; sweep wall per case {T1 / len(serial):.3f} s")
# Projection: N cases on P workers at the measured 2-worker efficiency,
# bounded below by the scheduler's serial work per case.
sched_ms = float([l for l in open(os.path.join(work, "np3.out")) if "scheduler:" in l][0].split(":")[2].split()[0])
for P in (64, 256, 1024):
    N = 1e5
    t_work = N * (T1 / len(serial)) / (P * eff2)
    t_sched = N * sched_ms / 1e3
    print(f"projection: 1e5 cases on {P} workers: {t_work / 3600:.2f} h of case work "
          f"(mean {T1 / len(serial):.3f} s per case, efficiency {eff2:.0%}); the scheduler's serial share "
          f"({sched_ms:.2g} ms per row) bounds it at >= {t_sched / 60:.1f} min")
PY
