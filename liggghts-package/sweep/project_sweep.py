#!/usr/bin/env python3
"""Projected wall time of a large hsrod-sweep from a small one's log.

Reads the summary lines hsrod-sweep prints at the end of a sweep (its
standard output, saved to LOG):
  "per case: C s wall and X s CPU in its process"   case cost
  "busy fraction B %"                               the farm's scheduling efficiency
  "scheduler: S ms per finished case"               rank 0's serial work per row
and prints, for N cases on P workers,

  T(N, P) = max(N c / (P e), N s) + t_start,

with c the case cost (CPU by default: on quiet cluster cores a case takes
its CPU time; --wall uses the measured wall time), e the busy fraction, s
the scheduler's time per row (the floor: rank 0 writes every row) and
t_start one MPI start-up (~0.45 s per process on the 2-core reference
machine, paid once per job: srun starts the ranks in parallel).

Usage: project_sweep.py LOG [--cases N] [--workers P,P,...] [--wall] [--start S]
"""
import argparse
import re
import sys

PATTERNS = {
    "case_wall": r"per case: ([0-9.eE+-]+) s wall",
    "case_cpu": r"s wall and ([0-9.eE+-]+) s CPU in its process",
    "busy": r"busy fraction ([0-9.eE+-]+) %",
    "scheduler_ms": r"scheduler: ([0-9.eE+-]+) ms per finished case",
}


def read_log(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    values = {}
    for key, pattern in PATTERNS.items():
        found = re.findall(pattern, text)
        if not found:
            sys.exit(f"project_sweep.py: ERROR: {path} has no '{pattern}' line: "
                     "give the standard output of a finished hsrod-sweep run")
        values[key] = float(found[-1])
    return values


def projected_seconds(cases, workers, cost, efficiency, scheduler_s, start_s):
    return max(cases * cost / (workers * efficiency), cases * scheduler_s) + start_s


def fmt(seconds):
    if seconds < 120:
        return f"{seconds:.1f} s"
    if seconds < 7200:
        return f"{seconds / 60:.1f} min"
    return f"{seconds / 3600:.1f} h"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("log")
    ap.add_argument("--cases", type=float, default=1e5, help="cases of the projected sweep (default 1e5)")
    ap.add_argument("--workers", default="16,64,256,1024", help="comma-separated worker counts")
    ap.add_argument("--wall", action="store_true", help="case cost = measured wall time, not CPU")
    ap.add_argument("--start", type=float, default=0.45, help="MPI start-up [s] (default 0.45)")
    a = ap.parse_args()
    m = read_log(a.log)
    try:
        workers = [int(w) for w in a.workers.split(",")]
    except ValueError:
        sys.exit(f"project_sweep.py: ERROR: --workers must be comma-separated integers >= 1, got '{a.workers}'")
    if a.cases < 1 or any(w < 1 for w in workers):
        sys.exit("project_sweep.py: ERROR: --cases and every --workers value must be >= 1")
    cost = m["case_wall"] if a.wall else m["case_cpu"]
    efficiency = max(m["busy"] / 100.0, 1e-3)
    s = m["scheduler_ms"] / 1e3
    print(f"measured: case {cost:.3g} s ({'wall' if a.wall else 'CPU'}), busy fraction {100 * efficiency:.1f} %, "
          f"scheduler {1e3 * s:.3g} ms per row")
    print(f"scheduler floor for {a.cases:.0f} cases: {fmt(a.cases * s)}; "
          f"it sets the pace above {cost / (efficiency * s):.0f} workers")
    print("workers  projected wall  (case work | scheduler floor)")
    for p in workers:
        work = a.cases * cost / (p * efficiency)
        total = projected_seconds(a.cases, p, cost, efficiency, s, a.start)
        print(f"{p:7d}  {fmt(total):>14}  ({fmt(work)} | {fmt(a.cases * s)})")


if __name__ == "__main__":
    main()
