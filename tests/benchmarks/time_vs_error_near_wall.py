"""The near-wall scene of time_vs_error: each level's static loads on rigid
rows of 5 spheres 1 d from a side wall and from a pore cylinder against the
resolved near-wall campaign (rodIbFoam, calibration/data/
resolved_near_wall_per_sphere.csv; the 1 d cases are left out of every fit).

Error: the largest total-vector error |F_model - F_resolved| / |F_resolved|
over the held-out 1 d cases (along, across, 45 deg; dragged and held), side
wall and pore cylinder; the per-sphere profile RMS and the 0.5 d pore case
(in the fits) beside it. Run time: CPU time of hsrod_crosscheck_scenes for
the level over all 40 configurations of the campaign (rows x loads) (process start-up
included), per configuration. Resolved: the measured CPU time of the
held-out cases' runs (mesh 6 cells per d, one steady run per configuration),
per configuration; its error is the mesh change 6 -> 8 cells per d of the
0.25 d cases (the 1 d cases ran on one mesh).
"""
import csv
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CASES = os.path.join(ROOT, "calibration", "data", "resolved_near_wall_per_sphere.csv")
RESULTS = os.path.join(ROOT, "calibration", "campaign", "near-wall", "results")
# (crosscheck level name, level shown in the table)
NEAR_WALL_LEVELS = (("local", 2), ("nonlocal", 3), ("nonlocal+images", "3 + images"),
                    ("nonlocal+reflections", "3 + reflections"), ("twoway", 4))


def _rows(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def _child_cpu():
    import resource
    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def _worst(rows, geometry, gap, key):
    vals = [float(r[key]) for r in rows if r["geometry"] == geometry and float(r["gap_over_d"]) == gap]
    return max(vals) if vals else float("nan")


def near_wall(build, runs, skip_twoway=False):
    tool = os.path.join(build, "hsrod_crosscheck_scenes")
    rows = []
    mesh_change = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, level in NEAR_WALL_LEVELS:
            if skip_twoway and name == "twoway":
                continue
            table = os.path.join(tmp, "%s.csv" % name)
            times = []
            for _ in range(runs):
                c0 = _child_cpu()
                r = subprocess.run([tool, CASES, os.path.join(tmp, "out.csv"), "--levels", name, "--case-table", table],
                                   capture_output=True, text=True)
                if r.returncode != 0:
                    sys.exit("time_vs_error: hsrod_crosscheck_scenes %s failed:\n%s" % (name, r.stdout[-2000:] + r.stderr[-2000:]))
                times.append(_child_cpu() - c0)
            case_rows = _rows(table)
            held = [r for r in case_rows if r["role"].endswith("_heldout")]
            mesh_change += [float(r["resolved_mesh_change"]) for r in case_rows if r["resolved_mesh_change"] != "nan"]
            wall_e, pore_e = _worst(held, "wall", 1, "total_error"), _worst(held, "pore", 1, "total_error")
            rows.append({"scene": "near wall", "level": level, "model": name,
                         "cpu_s": statistics.median(times) / len(case_rows), "error": max(wall_e, pore_e),
                         "detail": "held out, 1 d: side wall %.1f %% (profile RMS %.1f %%), pore cylinder %.1f %% "
                                   "(RMS %.1f %%); 0.5 d pore (not held out) %.1f %%; %d configurations per run" % (
                                       100 * wall_e, 100 * _worst(held, "wall", 1, "profile_rms"), 100 * pore_e,
                                       100 * _worst(held, "pore", 1, "profile_rms"),
                                       100 * _worst(case_rows, "pore", 0.5, "total_error"), len(case_rows))})
    cpu = []
    for path in glob.glob(os.path.join(RESULTS, "*_g1_*.json")):
        with open(path) as f:
            cpu.append(float(json.load(f)["run"]["cpu_s"]))
    if cpu:
        rows.append({"scene": "near wall", "level": "resolved", "model": "rodIbFoam",
                     "cpu_s": statistics.median(cpu), "error": max(mesh_change) if mesh_change else float("nan"),
                     "detail": "median measured CPU of the %d held-out 1 d runs (6 cells per d), per configuration; "
                               "error = largest total change from 6 to 8 cells per d (0.25 d cases)" % len(cpu)})
    return rows
