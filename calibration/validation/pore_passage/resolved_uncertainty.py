#!/usr/bin/python3
"""Numerical uncertainty of the resolved pore passage (resolved.csv) from its
recorded step and mesh series: the paper's three measures (passage time,
rotation in the pore, lateral displacement / W after the pore;
passage_measures.summary) of each recorded run, and per error source an
estimate of the reference's own error from the change over a refinement
(Richardson: a run at size h with error C h^p differs from the run at h / rho
by C h^p (1 - rho^-p)); the reference's uncertainty is the root sum of
squares of the two sources. Writes resolved_uncertainty.json (read by
tests/benchmarks/time_vs_error.py and tests/liggghts/pore_passage_vs_resolved.py).

    /usr/bin/python3 calibration/validation/pore_passage/resolved_uncertainty.py

Runs (raw rodMeasures.csv of each coupled run, beside this file):
  resolved_rodMeasures_raw.csv        the reference: 8 cells per d, CFD step 2.5 us
  coupled_h6_rodMeasures_raw.csv      6 cells per d, 2.5 us
  coupled_dt5_rodMeasures_raw.csv     6 cells per d, 5 us
  coupled_dt1.25_rodMeasures_raw.csv  6 cells per d, 1.25 us
Mesh: the change 6 -> 8 cells per d over (8/6)^p - 1 with p = 2 assumed (the
immersed boundary's convergence oscillates with d/h, no order is observable).
Step (on the 6-cells mesh): the error of the 2.5 us run, the change
2.5 -> 1.25 us times rho^p / (rho^p - 1), rho = 2, with p observed from the
changes 5 -> 2.5 and 2.5 -> 1.25 us (bounded to 1..2; 1 when they differ in
sign); without the 1.25 us run, the change 5 -> 2.5 us (p = 1).
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import passage_measures as pm  # noqa: E402

MEASURES = ("t_pass", "rotation", "lateral_after", "peak_angle_deg")
REFERENCE, MESH6 = "resolved_rodMeasures_raw.csv", "coupled_h6_rodMeasures_raw.csv"
STEP5, STEP125 = "coupled_dt5_rodMeasures_raw.csv", "coupled_dt1.25_rodMeasures_raw.csv"
MESH_RATIO, MESH_ORDER = 8.0 / 6.0, 2.0


def observed_order(coarse_change, fine_change):
    """Order p of a halving series from two successive changes, bounded to 1..2."""
    if coarse_change * fine_change <= 0 or abs(fine_change) >= abs(coarse_change):
        return 1.0
    return min(2.0, max(1.0, math.log(abs(coarse_change) / abs(fine_change), 2.0)))


def measures(path, sc):
    s = pm.summary(pm.read_run(path), sc)
    return {k: s[k] for k in MEASURES}


def main():
    sc = pm.scene()
    have = [f for f in (REFERENCE, MESH6, STEP5, STEP125) if os.path.exists(os.path.join(HERE, f))]
    runs = {f: measures(os.path.join(HERE, f), sc) for f in have}
    sources = {}
    if REFERENCE in runs and MESH6 in runs:
        factor = 1.0 / (MESH_RATIO ** MESH_ORDER - 1.0)
        sources["mesh 6 -> 8 cells per d (order %g assumed, change x %.3f)" % (MESH_ORDER, factor)] = {
            k: abs(runs[REFERENCE][k] - runs[MESH6][k]) * factor for k in MEASURES}
    if MESH6 in runs and STEP5 in runs:
        coarse = {k: runs[MESH6][k] - runs[STEP5][k] for k in MEASURES}
        if STEP125 in runs:
            fine = {k: runs[STEP125][k] - runs[MESH6][k] for k in MEASURES}
            order = {k: observed_order(coarse[k], fine[k]) for k in MEASURES}
            sources["CFD step 2.5 us (changes 5 -> 2.5 -> 1.25 us, observed order %s)" % ", ".join(
                "%s %.2f" % (k, order[k]) for k in MEASURES[:3])] = {
                k: abs(fine[k]) * 2 ** order[k] / (2 ** order[k] - 1) for k in MEASURES}
        else:
            sources["CFD step 2.5 us (change 5 -> 2.5 us, order 1)"] = {k: abs(coarse[k]) for k in MEASURES}
    rss = {k: sum(c[k] ** 2 for c in sources.values()) ** 0.5 for k in MEASURES}
    out = {"what": "root sum of squares of the estimated errors: " + "; ".join(sources), "runs": runs,
           "errors": sources, "uncertainty": rss}
    with open(os.path.join(HERE, "resolved_uncertainty.json"), "w") as f:
        json.dump(out, f, indent=1)
    for n, m in runs.items():
        print("%-34s t_pass %.4f ms, rotation %.2f deg, lateral after %+.4f W" % (
            n, m["t_pass"] * 1e3, m["rotation"], m["lateral_after"]))
    for what, c in sources.items():
        print("error from %s: t_pass %.4f ms, rotation %.2f deg, lateral %.4f W" % (
            what, c["t_pass"] * 1e3, c["rotation"], c["lateral_after"]))
    print("uncertainty: t_pass %.4f ms, rotation %.2f deg, lateral %.4f W" % (
        rss["t_pass"] * 1e3, rss["rotation"], rss["lateral_after"]))


if __name__ == "__main__":
    main()
