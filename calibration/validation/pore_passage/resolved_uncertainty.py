#!/usr/bin/python3
"""Numerical uncertainty of the resolved pore passage (resolved.csv) from its
recorded step and mesh series: the paper's three measures (passage time,
rotation in the pore, lateral displacement / W after the pore;
passage_measures.summary) of each recorded run, and for each measure the
larger change over the last halving of the CFD step and over the mesh
refinement. Writes resolved_uncertainty.json (read by
tests/benchmarks/time_vs_error.py and the pore-passage test).

    /usr/bin/python3 calibration/validation/pore_passage/resolved_uncertainty.py

Runs of the series (raw rodMeasures.csv of each coupled run, beside this file):
  resolved_rodMeasures_raw.csv     the reference: 6 cells per d, CFD step 2.5 us
  coupled_dt5_rodMeasures_raw.csv  the same at a 5 us step (step series)
  coupled_h8_rodMeasures_raw.csv   the same at 8 cells per d (mesh series;
                                   used once it is recorded)
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import passage_measures as pm  # noqa: E402

MEASURES = ("t_pass", "rotation", "lateral_after", "peak_angle_deg")
SERIES = (("reference (6 cells per d, dt 2.5 us)", "resolved_rodMeasures_raw.csv"),
          ("dt 5 us (6 cells per d)", "coupled_dt5_rodMeasures_raw.csv"),
          ("8 cells per d (dt 2.5 us)", "coupled_h8_rodMeasures_raw.csv"))


def measures(path, sc):
    s = pm.summary(pm.read_run(path), sc)
    s["rotation"] = s["peak_angle_deg"] + (90.0 + sc["rod"]["angle_deg"])  # minus the paper's initial angle
    return {k: s[k] for k in MEASURES}


def main():
    sc = pm.scene()
    runs = {}
    for name, f in SERIES:
        path = os.path.join(HERE, f)
        if os.path.exists(path):
            runs[name] = measures(path, sc)
    ref = runs[SERIES[0][0]]
    others = [n for n, _ in SERIES[1:] if n in runs]
    change = {k: max((runs[n][k] - ref[k] for n in others), key=abs) for k in MEASURES}
    out = {"what": "largest change against " + " and ".join(others),
           "runs": runs, "change": change}
    with open(os.path.join(HERE, "resolved_uncertainty.json"), "w") as f:
        json.dump(out, f, indent=1)
    for n, m in runs.items():
        print("%-38s t_pass %.4f ms, rotation %.2f deg, lateral after %+.4f W" % (
            n, m["t_pass"] * 1e3, m["rotation"], m["lateral_after"]))
    print("uncertainty (%s): t_pass %.4f ms, rotation %.2f deg, lateral %.4f W" % (
        out["what"], abs(change["t_pass"]) * 1e3, abs(change["rotation"]), abs(change["lateral_after"])))


if __name__ == "__main__":
    main()
