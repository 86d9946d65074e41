#!/usr/bin/python3
"""The validation scene's channel without the rod, resolved (rodIbFoam, steady
creeping flow, 3-D): its gap-averaged velocity at planform points of the rod's
band, the reference of hsrod's background flow (test
pore_flow_vs_resolved, tests/liggghts/pore_flow_vs_resolved.py).

    /usr/bin/python3 calibration/validation/pore_passage/empty_channel_flow.py BUILD_DIR WORK_DIR [--h 1e-6]

Steps: the scene of scene.json without rod, DEM and IB settings, control
steady (hsrod_case.py) -> WORK_DIR/case, its Allrun (blockMesh, topoSet,
refineMesh, rodIbFoam until the steady tolerance), cell centres and volumes
(postProcess writeCellCentres / writeCellVolumes), and the gap average of
the velocity over the column of cells within h_probe/2 of each point in x
and y (volume weighted), at the points x = 20.5 .. 71.5 um, y = 11 .. 25 um
(1 um apart; the refined band, 2 H behind the inlet plug, where the rod
travels). Written to WORK_DIR/empty_channel_h<h>.csv; the test's data file
is that of the finest mesh with the change from the coarser one (du_mesh):

    empty_channel_flow.py --combine FINE.csv COARSE.csv tests/liggghts/data/pore_passage_empty_channel_resolved.csv

(the recorded file: base meshes 0.75 and 1 um). numpy (Debian).
"""
import argparse
import json
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
PROBE_HALF = 0.5e-6  # half the probe column's width [m]


def read_internal(path, n_comp):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(", text)
    n = int(m.group(1))
    body = text[m.end():]
    if n_comp == 3:
        vals = re.findall(r"\(([^()]*)\)", body)[:n]
        return np.array([[float(v) for v in s.split()] for s in vals])
    return np.array([float(v) for v in body.split(")")[0].split()[:n]])


def points():
    return [(x * 1e-6 + 0.5e-6, y * 1e-6) for x in range(20, 72) for y in range(11, 26)]


def read_csv(path):
    with open(path) as f:
        lines = f.readlines()
    head = [l for l in lines if l.startswith("#")]
    rows = [l.strip().split(",") for l in lines if not l.startswith("#")]
    return head, [dict(zip(rows[0], map(float, r))) for r in rows[1:]]


def combine(fine_path, coarse_path, out_path):
    """The fine mesh's points with du_mesh = |u_fine - u_coarse| / |u_fine|."""
    head, fine = read_csv(fine_path)
    coarse_head, coarse = read_csv(coarse_path)
    with open(out_path, "w") as f:
        f.writelines(head)
        f.write("# du_mesh: |u(fine) - u(coarse)| / |u(fine)|, the change of the gap average from the coarser\n"
                "# base mesh (%s) to this one: the resolved flow's mesh uncertainty.\n" % os.path.basename(coarse_path))
        f.writelines("# coarser mesh:" + l[1:] for l in coarse_head if "base mesh" in l or "cells" in l)
        f.write("x_m,y_m,ux_m_s,uy_m_s,du_mesh\n")
        for a, b in zip(fine, coarse):
            if a["x_m"] != b["x_m"] or a["y_m"] != b["y_m"]:
                sys.exit("empty_channel_flow: the two files' points differ")
            du = np.hypot(a["ux_m_s"] - b["ux_m_s"], a["uy_m_s"] - b["uy_m_s"]) / np.hypot(a["ux_m_s"], a["uy_m_s"])
            f.write("%.9g,%.9g,%.9g,%.9g,%.3g\n" % (a["x_m"], a["y_m"], a["ux_m_s"], a["uy_m_s"], du))
    print("wrote", out_path)


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "--combine":
        return combine(*sys.argv[2:])
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("work")
    ap.add_argument("--h", type=float, default=1e-6, help="base cell size [m] (one refinement level in the band)")
    a = ap.parse_args()
    with open(os.path.join(HERE, "scene.json")) as f:
        scene = json.load(f)
    for k in ("rod", "dem", "ib"):
        scene.pop(k, None)
    scene["control"] = {"steady": True, "creeping": True}
    scene["mesh"]["h"] = a.h
    os.makedirs(a.work, exist_ok=True)
    sj, case = os.path.join(a.work, "scene.json"), os.path.join(a.work, "case")
    with open(sj, "w") as f:
        json.dump(scene, f, indent=1)
    env = dict(os.environ, RODIBFOAM=os.path.join(os.path.abspath(a.build), "calibration", "rodIbFoam"))
    env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    if not os.path.exists(os.path.join(case, "log.rodIbFoam")) or "steady state reached" not in open(
            os.path.join(case, "log.rodIbFoam")).read():
        subprocess.run([sys.executable, os.path.join(ROOT, "calibration", "tools", "hsrod_case.py"), sj, case],
                       check=True)
        subprocess.run(["sh", os.path.join(case, "Allrun")], env=env, check=True)
    last = max((d for d in os.listdir(case) if re.match(r"^[0-9.]+$", d) and d != "0"), key=float)
    for func in ("writeCellCentres", "writeCellVolumes"):
        if not os.path.exists(os.path.join(case, last, "V" if "Vol" in func else "C")):
            subprocess.run(["postProcess", "-func", func, "-time", last, "-case", case], env=env, check=True,
                           stdout=subprocess.DEVNULL)
    U = read_internal(os.path.join(case, last, "U"), 3)
    C = read_internal(os.path.join(case, last, "C"), 3)
    V = read_internal(os.path.join(case, last, "V"), 1)
    log = open(os.path.join(case, "log.rodIbFoam")).read()
    cells = re.search(r"rodIbFoam: (\d+) iterations, (\d+) cells, ([0-9.eE+-]+) s CPU", log)
    out = os.path.join(a.work, "empty_channel_h%g.csv" % a.h)
    with open(out, "w") as f:
        f.write("# Resolved (rodIbFoam, steady creeping 3-D Stokes) gap-averaged velocity of the channel of\n"
                "# calibration/validation/pore_passage/scene.json without the rod: L 84 um, W 36 um, H 10 um,\n"
                "# pore cylinders R 9 um at x = 42 um on both side walls, mean inflow 0.01 m/s (uniform plug at\n"
                "# x = 0); base mesh h = %g m, one refinement level in x 10-72 um, y 10-26 um; %s iterations,\n"
                "# %s cells, %s s CPU. Gap average: volume-weighted mean of the cells within %g m of the point\n"
                "# in x and y. Generated by calibration/validation/pore_passage/empty_channel_flow.py.\n"
                % (a.h, cells.group(1) if cells else "?", cells.group(2) if cells else "?",
                   cells.group(3) if cells else "?", PROBE_HALF))
        f.write("x_m,y_m,ux_m_s,uy_m_s\n")
        for x, y in points():
            sel = (np.abs(C[:, 0] - x) <= PROBE_HALF) & (np.abs(C[:, 1] - y) <= PROBE_HALF)
            w = V[sel]
            f.write("%.9g,%.9g,%.9g,%.9g\n" % (x, y, (U[sel, 0] * w).sum() / w.sum(), (U[sel, 1] * w).sum() / w.sum()))
    print("wrote", out)


if __name__ == "__main__":
    main()
