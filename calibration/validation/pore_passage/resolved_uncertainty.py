#!/usr/bin/python3
"""Numerical uncertainty of the resolved pore passage (resolved.csv) from its
recorded step and mesh series: the paper's three measures (passage time,
rotation in the pore, lateral displacement / W after the pore;
passage_measures.summary) of each recorded run, the change of each measure
over each refinement of the series (a halving of the CFD step, a finer mesh)
and, as the reference's uncertainty, the root sum of squares of those
changes (independent error sources). Writes resolved_uncertainty.json (read by
tests/benchmarks/time_vs_error.py and tests/liggghts/pore_passage_vs_resolved.py).

    /usr/bin/python3 calibration/validation/pore_passage/resolved_uncertainty.py

Runs of the series (raw rodMeasures.csv of each coupled run, beside this file;
a refinement is used when both of its runs are recorded):
  resolved_rodMeasures_raw.csv     the reference (resolved.csv)
  coupled_h6_rodMeasures_raw.csv   6 cells per d, CFD step 2.5 us
  coupled_dt5_rodMeasures_raw.csv  6 cells per d, CFD step 5 us
  coupled_dt1.25_rodMeasures_raw.csv  6 cells per d, CFD step 1.25 us (session 15)
The reference is the finest run: 8 cells per d at 2.5 us once recorded
(resolved_run.json names it), else the 6-cells run itself. One change per
error source: the step error of the reference's 2.5 us is the change from
2.5 to 1.25 us once that run is recorded (the error of a first-order step
is about the change over its own halving), else the change from 5 to 2.5 us.
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import passage_measures as pm  # noqa: E402

MEASURES = ("t_pass", "rotation", "lateral_after", "peak_angle_deg")
# (finer run, coarser run, what the refinement is, error source); the first
# pair of each source whose files exist is used; the first run of the first
# pair is the reference's own record.
REFINEMENTS = (("resolved_rodMeasures_raw.csv", "coupled_h6_rodMeasures_raw.csv", "mesh 6 -> 8 cells per d", "mesh"),
               ("coupled_dt1.25_rodMeasures_raw.csv", "coupled_h6_rodMeasures_raw.csv", "CFD step 2.5 -> 1.25 us",
                "step"),
               ("coupled_h6_rodMeasures_raw.csv", "coupled_dt5_rodMeasures_raw.csv", "CFD step 5 -> 2.5 us", "step"),
               ("resolved_rodMeasures_raw.csv", "coupled_dt5_rodMeasures_raw.csv", "CFD step 5 -> 2.5 us", "step"))


def measures(path, sc):
    s = pm.summary(pm.read_run(path), sc)
    return {k: s[k] for k in MEASURES}


def main():
    sc = pm.scene()
    runs, changes, used = {}, {}, set()
    for fine, coarse, what, source in REFINEMENTS:
        if source in used or not all(os.path.exists(os.path.join(HERE, f)) for f in (fine, coarse)):
            continue
        used.add(source)
        for f in (fine, coarse):
            runs.setdefault(f, measures(os.path.join(HERE, f), sc))
        changes[what] = {k: runs[fine][k] - runs[coarse][k] for k in MEASURES}
    rss = {k: sum(c[k] ** 2 for c in changes.values()) ** 0.5 for k in MEASURES}
    out = {"what": "root sum of squares of the changes over " + ", ".join(changes), "runs": runs,
           "changes": changes, "uncertainty": rss}
    with open(os.path.join(HERE, "resolved_uncertainty.json"), "w") as f:
        json.dump(out, f, indent=1)
    for n, m in runs.items():
        print("%-34s t_pass %.4f ms, rotation %.2f deg, lateral after %+.4f W" % (
            n, m["t_pass"] * 1e3, m["rotation"], m["lateral_after"]))
    for what, c in changes.items():
        print("change over %-24s t_pass %+.4f ms, rotation %+.2f deg, lateral %+.4f W" % (
            what + ":", c["t_pass"] * 1e3, c["rotation"], c["lateral_after"]))
    print("uncertainty (%s): t_pass %.4f ms, rotation %.2f deg, lateral %.4f W" % (
        out["what"], rss["t_pass"] * 1e3, rss["rotation"], rss["lateral_after"]))


if __name__ == "__main__":
    main()
