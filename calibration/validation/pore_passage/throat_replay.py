#!/usr/bin/env python3
"""throat_replay.py: the resolved passage's own throat motion replayed with
prescribed motion in rodIbFoam's transient (PIMPLE) run, to tell whether the
coupled run's drift in the throat is quasi-steady Stokes (the rigid throat
cases, throat.py) or not.

    /usr/bin/python3 calibration/validation/pore_passage/throat_replay.py BUILD_DIR [--work DIR] [--keep]

The coupled run's trajectory (resolved.csv: centre, paper angle) is smoothed
(2-point average, which removes the exchange's interval-to-interval
alternation, then a local quadratic fit over +-40 us) and sampled every 1 us
from T0 = 0.95 ms to T1 = 1.42 ms; the 4 spheres follow it (`motion table`,
hsrod_case.py channel kind with scene.json's mesh: h = 1 um, the band x 10-72,
y 10-26 um refined once, 0.5 um = d/6; the same PIMPLE settings and CFD step
10 us as the coupled run; fluid and rod start from rest at T0, 150 us before
the first throat configuration). No spin is prescribed (table motion moves
the sphere centres only). The rod's load Q = (F_x, F_y, T_z about the
centroid) is read at the throat configurations' times (1.10, 1.20, 1.30, 1.40 ms), and its mean and
standard deviation over +-30 us around them (the loads of the moving spheres oscillate as they cross
cells), and
compared with the quasi-steady load of the same motion from the rigid steady
cases, Q_steady = D - R q (throat_rigid.csv, resolved mesh 6 and the finest
mesh), q = (V_x, V_y, Omega) of the smoothed path. A force-free rod gives
Q ~ 0: the coupled rod was force-free by construction, so Q_replay tells how
well the replay reproduces it, and Q_steady - Q_replay is the part that is
not quasi-steady Stokes (the unsteady term rho du/dt the transient run keeps,
Re = V H / nu ~ 0.34 with the rod's speed), both over 3 pi mu d U (U = 0.01 m/s).
Writes throat_replay.csv beside this file.
"""
import argparse
import copy
import csv
import json
import os
import resource
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(ROOT, "calibration", "tools"))
import hsrod_case  # noqa: E402

T0, T1, DT_PATH = 0.95e-3, 1.42e-3, 1e-6
T_CONFIGS = (1.10e-3, 1.20e-3, 1.30e-3, 1.40e-3)
D, U, MU, N = 3e-6, 0.01, 1e-3, 4


def smooth_path():
    rows = list(csv.DictReader(open(os.path.join(HERE, "resolved_dt10.csv"))))
    t = np.array([float(r["t"]) for r in rows])
    v = np.array([[float(r["x_com"]), float(r["y_com"]), float(r["angle_deg"])] for r in rows])
    tm, vm = 0.5 * (t[1:] + t[:-1]), 0.5 * (v[1:] + v[:-1])

    def at(tq):
        sel = np.abs(tm - tq) <= 40e-6 + 1e-12
        s = tm[sel] - tq
        A = np.column_stack([np.ones_like(s), s, s * s])
        c, *_ = np.linalg.lstsq(A, vm[sel], rcond=None)
        return c[0], c[1]                      # value (x, y, alpha), rate
    return at


def sphere_positions(x, y, alpha):
    phi = np.radians(-(90.0 + alpha))
    return [(x + (i - 1.5) * D * np.cos(phi), y + (i - 1.5) * D * np.sin(phi)) for i in range(N)]


def rod_load(rows, t, u_ref):
    """(Fx, Fy, Tz about the centroid) over 3 pi mu d U at the output time closest to t."""
    times = sorted({float(r["t"]) for r in rows})
    tt = min(times, key=lambda s: abs(s - t))
    sp = sorted([r for r in rows if float(r["t"]) == tt], key=lambda r: int(r["id"]))
    pos = np.array([[float(r["x"]), float(r["y"])] for r in sp])
    F = np.array([[float(r["Fx"]), float(r["Fy"])] for r in sp])
    T = np.array([float(r["Tz"]) for r in sp])
    c = pos.mean(axis=0)
    r = pos - c
    z0 = 3 * np.pi * MU * D * u_ref
    return tt, np.array([F[:, 0].sum() / z0, F[:, 1].sum() / z0,
                         ((r[:, 0] * F[:, 1] - r[:, 1] * F[:, 0]).sum() + T.sum()) / (z0 * D)])


def rod_load_window(rows, t, u_ref, half):
    """Mean and standard deviation of the rod load over the outputs within t +- half (the moving
    immersed boundary's loads oscillate as the spheres cross cells)."""
    times = sorted({float(r["t"]) for r in rows})
    qs = np.array([rod_load(rows, s, u_ref)[1] for s in times if abs(s - t) <= half + 1e-12])
    return qs.mean(axis=0), qs.std(axis=0)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--work", default="/tmp/hsrod_throat_replay")
    ap.add_argument("--collect-only", action="store_true", help="read a finished case in --work")
    ap.add_argument("--time-scale", type=float, default=1.0,
                    help="S: the same motion S times slower (times x S, inflow and rod speeds / S, CFD step x S: the "
                         "same displacement per step, Re / S): what is left of Q_replay - Q_steady at S = 10 is "
                         "not the unsteady term")
    ap.add_argument("--dt", type=float, default=1e-5, help="CFD step [s] at S = 1 (coupled run: 1e-5)")
    a = ap.parse_args(argv)
    S = a.time_scale
    tag = "" if (S == 1.0 and a.dt == 1e-5) else "_S%g_dt%g" % (S, a.dt)
    at = smooth_path()
    case = os.path.join(a.work, "replay" + tag)
    cpu = wall = None
    if not a.collect_only:
        scene = json.load(open(os.path.join(HERE, "scene.json")))
        scene = copy.deepcopy(scene)
        for k in ("dem", "rod"):
            scene.pop(k, None)
        (x0, y0, al0), _ = at(T0)
        scene["spheres"] = [{"id": i + 1, "x": [p[0], p[1], 0.5 * scene["channel"]["H"]], "d": D}
                            for i, p in enumerate(sphere_positions(x0, y0, al0))]
        scene["ib"] = dict(scene.get("ib", {}), motion="table", pathTable="path.csv")
        scene["control"] = dict(scene["control"], steady=False, creeping=True, end_time=(T1 - T0) * S,
                                dt=a.dt * S, write_interval=1e3)
        scene["inflow"] = dict(scene["inflow"], U=scene["inflow"]["U"] / S)
        if os.path.exists(case):
            shutil.rmtree(case)
        os.makedirs(case)
        hsrod_case.make_channel(scene, case)
        with open(os.path.join(case, "scene.json"), "w") as f:
            json.dump(scene, f, indent=1)
        with open(os.path.join(case, "constant", "path.csv"), "w") as f:
            f.write("t,id,x,y,z\n")
            for k in range(int(round((T1 - T0) / DT_PATH)) + 2):
                t = k * DT_PATH
                (x, y, al), _ = at(T0 + t)
                for i, p in enumerate(sphere_positions(x, y, al)):
                    f.write("%.9g,%d,%.12g,%.12g,%.12g\n" % (t * S, i + 1, p[0], p[1], 0.5 * scene["channel"]["H"]))
        env = dict(os.environ, RODIBFOAM=os.path.join(a.build, "calibration", "rodIbFoam"))
        env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
        r0, w0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.time()
        rc = subprocess.run(["nice", "-n", "10", os.path.join(case, "Allrun")], cwd=case, env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT).returncode
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu, wall = r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime, time.time() - w0
        if rc != 0:
            sys.exit("replay failed: see %s/log.rodIbFoam" % case)
    if cpu is None:                            # --collect-only: the solver's own last ExecutionTime / ClockTime
        import re
        log = open(os.path.join(case, "log.rodIbFoam")).read()
        cpu = float(re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", log)[-1])
        clock = re.findall(r"ClockTime = ([0-9.eE+-]+) s", log)
        wall = float(clock[-1]) if clock else None
    rows = list(csv.DictReader(l for l in open(os.path.join(case, "postProcessing", "rodIbFoam", "sphereForces.csv"))
                               if not l.startswith("#")))
    cells = None
    for l in open(os.path.join(case, "log.rodIbFoam")):
        if "cells" in l and cells is None and "nCells" in l:
            cells = l.split()[-1]
    rigid = {}
    for r in csv.DictReader(l for l in open(os.path.join(HERE, "throat_rigid.csv")) if not l.startswith("#")):
        rigid.setdefault(r["config"], {})[r["source"]] = r
    out = ["# throat_replay.py: the resolved passage's throat motion replayed (prescribed, smoothed) in rodIbFoam's "
           "transient run; rod load over 3 pi mu d U (U = 0.01 m/s), T_z over 3 pi mu d^2 U; Q_steady = D - R q of "
           "the rigid steady cases (throat_rigid.csv); case %s, CPU %s s, wall %s s" % (
               case, "%.0f" % cpu if cpu else "?", "%.0f" % wall if wall else "?"),
           "t_ms,x_um,y_um,alpha_deg,Vx_over_U,Vy_over_U,Om_d_over_U,source,Qx,Qy,Qt,"
           "Qx_mean_30us,Qy_mean_30us,Qt_mean_30us,Qx_std_30us,Qy_std_30us,Qt_std_30us"]
    keys = list(rigid)
    for k, t in enumerate(T_CONFIGS):
        (x, y, al), (vx, vy, da) = at(t)
        q = np.array([vx / U, vy / U, -np.radians(da) * D / U])
        tt, Q = rod_load(rows, (t - T0) * S, U / S)
        tt = tt / S
        head = "%.3f,%.3f,%.4f,%.3f,%.4f,%.4f,%.4f" % (t * 1e3, x * 1e6, y * 1e6, al, q[0], q[1], q[2])
        Qm, Qs = rod_load_window(rows, (t - T0) * S, U / S, 30e-6 * S)
        out.append(head + ",replay (transient%s) t=%.1f us,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f" % (
            "" if not tag else "; time scale %g; dt %g us" % (S, a.dt * 1e6), (tt + T0) * 1e6, *Q, *Qm, *Qs))
        cfg = keys[k]
        for src, r in rigid[cfg].items():
            if not src.startswith("resolved"):
                continue
            Dv = np.array([float(r["D" + c]) for c in "xyt"])
            R = np.array([float(r["R" + a + b]) for a in "xyt" for b in "xyt"]).reshape(3, 3)
            Qs = Dv - R @ q
            out.append(head + ",quasi-steady %s,%.4f,%.4f,%.4f,,,,,," % (src, *Qs))
    with open(os.path.join(HERE, "throat_replay%s.csv" % tag), "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
