#!/usr/bin/env python3
"""throat_coupled_step.py: the coupled passage (scene.json) at half the CFD
step against the recorded one, in the throat.

    # the case: scene.json with dem.coupling_interval 500 (CFD step 5 us) and control.end_time 2e-3
    python3 calibration/tools/hsrod_case.py SCENE_DT5.json CASE && RODIBFOAM=... nice -n 10 CASE/Allrun
    /usr/bin/python3 calibration/validation/pore_passage/throat_coupled_step.py CASE [CASE_2.5US]

Copies CASE/postProcessing/rodIbFoam/rodMeasures.csv to
coupled_dt5_rodMeasures_raw.csv (beside this file; a second case, the same at
2.5 us to 1.5 ms: coupled_dt2.5_rodMeasures_raw.csv) and prints, at equal
rod-centre x, lateral / W and the paper angle of the recorded run
(resolved_dt10.csv, step 10 us: the earlier record) and of the 5 us run, and both runs' smoothed V_y / U
(2-point average, local quadratic fit over +-40 us in time) at the throat
configurations of throat.py; the rigid steady value (throat_rigid.csv, finest
resolved mesh) beside them.
"""
import csv
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
W, U = 36e-6, 0.01


def read(path):
    rows = [r for r in csv.DictReader(l for l in open(path) if not l.startswith("#"))]
    t = np.array([float(r["t"]) for r in rows])
    x = np.array([float(r["x_com"]) for r in rows])
    y = np.array([float(r["y_com"]) for r in rows])
    a = np.array([float(r["angle_deg"]) for r in rows])
    return t, x, y, a


def smooth_rate(t, y, tq):
    tm, ym = 0.5 * (t[1:] + t[:-1]), 0.5 * (y[1:] + y[:-1])
    sel = np.abs(tm - tq) <= 40e-6 + 1e-12
    s = tm[sel] - tq
    c = np.polyfit(s, ym[sel], 2)
    return c[1]


def at_x(t, x, v, xq):
    k = np.searchsorted(x, xq)
    w = (xq - x[k - 1]) / (x[k] - x[k - 1])
    return v[k - 1] + w * (v[k] - v[k - 1]), t[k - 1] + w * (t[k] - t[k - 1])


def main(argv):
    case = argv[1]
    raw = os.path.join(case, "postProcessing", "rodIbFoam", "rodMeasures.csv")
    shutil.copy(raw, os.path.join(HERE, "coupled_dt5_rodMeasures_raw.csv"))
    ref = read(os.path.join(HERE, "resolved_dt10.csv"))
    new = read(raw)
    fine = None
    if len(argv) > 2:
        raw2 = os.path.join(argv[2], "postProcessing", "rodIbFoam", "rodMeasures.csv")
        shutil.copy(raw2, os.path.join(HERE, "coupled_dt2.5_rodMeasures_raw.csv"))
        fine = read(raw2)
    rigid = {}
    for r in csv.DictReader(l for l in open(os.path.join(HERE, "throat_rigid.csv")) if not l.startswith("#")):
        if r["source"] in ("resolved m8", "resolved m6"):
            rigid.setdefault(r["config"], {})[r["source"]] = float(r["Vy_free"])
    levels = [(n, read(os.path.join(HERE, f))) for n, f in (("L1", "level1_isotropic.csv"), ("L2", "level2_local.csv"),
                                                            ("L3", "level3_nonlocal.csv"), ("L4", "level4_twoway.csv"))]
    print("| x [µm] | lateral/W, step 10 µs (recorded) | step 5 µs | step 2.5 µs | %s | angle [deg] 10 µs / 5 µs | "
          "t [ms] 10 µs / 5 µs |" % " | ".join(n for n, _ in levels))
    print("| ---: | ---: | ---: | ---: | %s | ---: | ---: |" % " | ".join("---:" for _ in levels))
    for xq in (30.0, 35.0, 38.7, 42.0, 45.5, 48.7, 51.0, 55.5, 60.0, 64.0):
        if xq * 1e-6 > new[1].max() or xq * 1e-6 > ref[1].max():
            continue
        l10, t10 = at_x(ref[0], ref[1], ref[2], xq * 1e-6)
        l5, t5 = at_x(new[0], new[1], new[2], xq * 1e-6)
        a10, _ = at_x(ref[0], ref[1], ref[3], xq * 1e-6)
        a5, _ = at_x(new[0], new[1], new[3], xq * 1e-6)
        lv = [(at_x(r[0], r[1], r[2], xq * 1e-6)[0] - 18e-6) / W for _, r in levels]
        l25 = "%+.4f" % ((at_x(fine[0], fine[1], fine[2], xq * 1e-6)[0] - 18e-6) / W) \
            if fine is not None and xq * 1e-6 < fine[1].max() else "-"
        print("| %.1f | %+.4f | %+.4f | %s | %s | %.2f / %.2f | %.3f / %.3f |" % (
            xq, (l10 - 18e-6) / W, (l5 - 18e-6) / W, l25, " | ".join("%+.4f" % v for v in lv), a10, a5, t10 * 1e3,
            t5 * 1e3))
    print("V_y / U at equal x (smoothed): config | dt 10 us | dt 5 us | dt 2.5 us | rigid steady")
    for cfg, vals in rigid.items():
        xq = float(cfg.split(",")[0]) * 1e-6
        if xq > new[1].max() - 2e-6:
            continue
        _, t10 = at_x(ref[0], ref[1], ref[2], xq)
        _, t5 = at_x(new[0], new[1], new[2], xq)
        v10 = smooth_rate(ref[0], ref[2], t10) / U
        v5 = smooth_rate(new[0], new[2], t5) / U
        v25 = float("nan")
        if fine is not None and xq < fine[1].max() - 2e-6:
            v25 = smooth_rate(fine[0], fine[2], at_x(fine[0], fine[1], fine[2], xq)[1]) / U
        print("%s | %+.4f | %+.4f | %+.4f | %+.4f (%s)" % (cfg, v10, v5, v25, vals.get("resolved m8", vals.get("resolved m6")),
                                                  "m8" if "resolved m8" in vals else "m6"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
