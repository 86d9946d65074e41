"""Measures of one rod passing the pore (Braesel et al. 2024, Sec. 2.3) and
their comparison between a run and the resolved reference; used by run.py
(table, plot) and by the ctest calibration.pore_passage_level (default
level against the recorded resolved run). Python 3 standard library.

A run is a list of rows {t, x_com, y_com, angle_deg, deflection,
lateral_over_W, vx_over_U} (SI, t in s, x in m), one per coupling interval
(resolved) or per 10 us (reduced).
"""
import csv
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
COLUMNS = ("t", "x_com", "y_com", "angle_deg", "deflection", "lateral_over_W", "vx_over_U")


def scene():
    with open(os.path.join(HERE, "scene.json")) as f:
        return json.load(f)


def read_run(path):
    """Rows of a run CSV (the columns above; extra columns ignored)."""
    with open(path) as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    return [{k: float(r[k]) for k in COLUMNS} for r in rows]


def write_run(path, rows):
    with open(path, "w") as f:
        f.write(",".join(COLUMNS) + "\n")
        for r in rows:
            f.write(",".join("%.9g" % r[k] for k in COLUMNS) + "\n")


def interp(xs, ys, x):
    """Linear interpolation in a monotone increasing xs; None outside."""
    if x < xs[0] or x > xs[-1]:
        return None
    lo, hi = 0, len(xs) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    if xs[hi] == xs[lo]:
        return ys[lo]
    w = (x - xs[lo]) / (xs[hi] - xs[lo])
    return ys[lo] + w * (ys[hi] - ys[lo])


def monotone_in_x(rows):
    """Rows with strictly increasing x_com (drops the rest-start samples)."""
    out = []
    for r in rows:
        if not out or r["x_com"] > out[-1]["x_com"]:
            out.append(r)
    return out


def time_at_x(rows, x):
    """First time the rod centre reaches x [s] (None if never)."""
    m = monotone_in_x(rows)
    return interp([r["x_com"] for r in m], [r["t"] for r in m], x)


def summary(rows, sc=None):
    """Scalar measures of a passage: the passage time t_pass from the pore
    entry x_in = pore centre - 1.5 R to the exit x_out = pore centre + 1.5 R
    (the rod's centre half a rod length before / past the cylinders; from
    station to station, so the resolved run's start-up from rest does not
    enter) [s], the time from the start to the pore centre [s], peak angle
    [deg] and where, peak v_x/U, peak deflection, and after the pore (rod
    centre at x_after = pore centre + 2 R, the rod clear of the cylinders)
    the lateral displacement/W and the angle."""
    sc = sc or scene()
    xc = sc["pore"]["x"]
    x_in, x_out = xc - 1.5 * sc["pore"]["R"], xc + 1.5 * sc["pore"]["R"]
    x_after = xc + 2.0 * sc["pore"]["R"]
    m = monotone_in_x(rows)
    upto = [r for r in m if r["x_com"] <= x_out]
    peak = max(upto, key=lambda r: r["angle_deg"])
    return {
        "t_pass": time_at_x(rows, x_out) - time_at_x(rows, x_in),
        "t_pore": time_at_x(rows, xc),
        "peak_angle_deg": peak["angle_deg"],
        "x_peak_angle": peak["x_com"],
        "peak_vx_over_U": max(r["vx_over_U"] for r in upto),
        "peak_deflection": max(r["deflection"] for r in upto),
        "lateral_after": interp([r["x_com"] for r in m], [r["lateral_over_W"] for r in m], x_after),
        "angle_after": interp([r["x_com"] for r in m], [r["angle_deg"] for r in m], x_after),
        "x_after": x_after,
        # rotation in the pore: peak angle minus the paper's initial angle
        # (create_rod's lab angle a is the paper's -(90 + a))
        "rotation": peak["angle_deg"] + (90.0 + sc["rod"]["angle_deg"]),
        "x_in": x_in,
        "x_out": x_out,
    }


def errors_along_x(run, ref, d, passage=None):
    """Errors of a run against the reference along the common x range
    (measures at equal rod-centre x) and of x(t) at equal time:
    max |dx|/d at equal t, rms and max |d(v_x/U)|, max |d angle| [deg],
    max |d lateral/W|, max |d deflection|; with passage = (x0, x1) also the
    rms and max |d(v_x/U)| over x0..x1 only (dvx_rms_passage, dvx_max_passage:
    the passage without the resolved run's start-up)."""
    a, b = monotone_in_x(run), monotone_in_x(ref)
    xa = [r["x_com"] for r in a]
    lo, hi = max(xa[0], b[0]["x_com"]), min(xa[-1], b[-1]["x_com"])
    out = {"dx_over_d_max": 0.0, "dvx_rms": 0.0, "dvx_max": 0.0, "dangle_max": 0.0,
           "dlateral_max": 0.0, "ddefl_max": 0.0}
    n, n_p, sq_p, max_p = 0, 0, 0.0, 0.0
    for r in b:
        if not (lo <= r["x_com"] <= hi):
            continue
        if passage and passage[0] <= r["x_com"] <= passage[1]:
            dv = interp(xa, [s["vx_over_U"] for s in a], r["x_com"]) - r["vx_over_U"]
            n_p, sq_p, max_p = n_p + 1, sq_p + dv * dv, max(max_p, abs(dv))
        for key, col in (("dvx_max", "vx_over_U"), ("dangle_max", "angle_deg"),
                         ("dlateral_max", "lateral_over_W"), ("ddefl_max", "deflection")):
            v = interp(xa, [s[col] for s in a], r["x_com"])
            out[key] = max(out[key], abs(v - r[col]))
            if col == "vx_over_U":
                out["dvx_rms"] += (v - r[col]) ** 2
                n += 1
    out["dvx_rms"] = math.sqrt(out["dvx_rms"] / max(1, n))
    if passage:
        out["dvx_rms_passage"], out["dvx_max_passage"] = math.sqrt(sq_p / max(1, n_p)), max_p
    ta = [r["t"] for r in run]
    for r in ref:
        x = interp(ta, [s["x_com"] for s in run], r["t"])
        if x is not None:
            out["dx_over_d_max"] = max(out["dx_over_d_max"], abs(x - r["x_com"]) / d)
    out["x_range"] = (lo, hi)
    return out
