#!/usr/bin/env python3
"""sweep_aggregate.py and plot_sweep.py probability (ctest sweep_aggregate).

- wilson_interval against published values: 3 of 10 -> [0.1078, 0.6032],
  0 of 10 -> [0, 0.2775], 10 of 10 -> [0.7225, 1] (Newcombe, Stat. Med. 17,
  857 (1998), Table I, method 3, to 4 digits);
- probability() on a synthetic 2 x 2 x 5-seed sweep: the hits per cell,
  failed rows counted apart, not as misses;
- plot_sweep.py probability writes the PNG and a cell table with those
  numbers.
Usage: test_sweep_aggregate.py WORK_DIR
"""
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SWEEP = os.path.join(HERE, "..", "..", "liggghts-package", "sweep")
sys.path.insert(0, SWEEP)
import sweep_aggregate  # noqa: E402

work = sys.argv[1]
os.makedirs(work, exist_ok=True)
failures = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


for (k, n), (lo, hi) in {(3, 10): (0.1078, 0.6032), (0, 10): (0.0, 0.2775), (10, 10): (0.7225, 1.0)}.items():
    got = sweep_aggregate.wilson_interval(k, n)
    check(abs(got[0] - lo) < 6e-5 and abs(got[1] - hi) < 6e-5, f"Wilson {k}/{n} = [{got[0]:.4f}, {got[1]:.4f}], "
          f"published [{lo}, {hi}]")

# conc x ratio x seed; outcome 3 (clogged) in: (0.1, 1): 0 of 5; (0.1, 2): 2 of 5;
# (0.2, 1): 4 of 5 with one more failed; (0.2, 2): 5 of 5.
hits = {("0.1", "1"): 0, ("0.1", "2"): 2, ("0.2", "1"): 4, ("0.2", "2"): 5}
rows = []
case = 0
for (conc, ratio), h in hits.items():
    for seed in range(1, 6):
        rows.append({"case": case, "conc": conc, "ratio": ratio, "seed": seed, "status": "ok",
                     "outcome": 3 if seed <= h else 1})
        case += 1
rows.append({"case": case, "conc": "0.2", "ratio": "1", "seed": 6, "status": "failed", "outcome": ""})
path = os.path.join(work, "seeds.csv")
with open(path, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
cells = {(c["conc"], c["ratio"]): c for c in sweep_aggregate.probability(
    [{k: str(v) for k, v in r.items()} for r in rows], ["conc", "ratio"], "outcome", 3)}
for key, h in hits.items():
    c = cells[key]
    check(c["cases"] == 5 and c["hits"] == h and abs(c["probability"] - h / 5) < 1e-12,
          f"cell {key}: {c['hits']} of {c['cases']} clogged, expected {h} of 5")
check(cells[("0.2", "1")]["failed"] == 1, "the failed case is counted apart, not as a miss")

png, table = os.path.join(work, "p.png"), os.path.join(work, "cells.csv")
done = subprocess.run(["/usr/bin/python3", os.path.join(SWEEP, "plot_sweep.py"), "probability", path, "--x", "conc",
                       "--y", "ratio", "--table", table, "-o", png], capture_output=True, text=True)
print(done.stdout, done.stderr)
check(done.returncode == 0 and os.path.getsize(png) > 1000, "plot_sweep.py probability writes the PNG")
with open(table, newline="") as f:
    written = {(r["conc"], r["ratio"]): r for r in csv.DictReader(f)}
check(abs(float(written[("0.1", "2")]["ci_low"]) - sweep_aggregate.wilson_interval(2, 5)[0]) < 1e-12,
      "the cell table carries the Wilson interval")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("all checks passed")
