#!/usr/bin/env python3
"""throat.py: the pore-passage rod held rigid at throat configurations of the
resolved run, rodIbFoam (campaign geometry "throat") against levels 1-4.

    /usr/bin/python3 calibration/validation/pore_passage/throat.py BUILD_DIR [--levels-bin PATH]

Reads the resolved cases of calibration/campaign/throat/results/ (plan
calibration/campaign/plan_throat.json: per configuration the rod held in the
channel flow, translating along x and along y, rotating about its centroid),
runs BUILD_DIR/hsrod_throat_loads on the same configurations, and writes
beside this file
  throat_per_sphere.csv   per configuration, source (resolved mesh 6 / 8, level),
                          load and sphere: centre, force over 3 pi mu d U, z-torque
                          over 3 pi mu d^2 U (provenance in the header)
  throat_rigid.csv        per configuration and source: rigid reduction (below)
  throat_tables.md        the tables of the README section
Rigid reduction, the same code for both sides (hydro/rigid_rod_load.h's
form): rigid motion q = (V_x, V_y, Omega) about the centroid c, sphere i moving
with (V_x - Omega (y_i - c_y), V_y + Omega (x_i - c_x)) and spinning at Omega;
the rod's load Q = (sum F_x, sum F_y, sum (x_i - c) x F_i + T_z,i); R = -Q of
the unit motions (columns), D = Q held; free motion (force- and torque-free)
q = R^-1 D; rotation locked: (V_x, V_y) = R_tt^-1 D_t. Units: d, U, U/d.
numpy (Debian).
"""
import argparse
import csv
import glob
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
CAMPAIGN = os.path.join(ROOT, "calibration", "campaign", "throat")
PLAN = os.path.join(ROOT, "calibration", "campaign", "plan_throat.json")
LOADS = ("driving", "friction_x", "friction_y", "rotation")
LEVELS = ("isotropic", "local", "nonlocal", "twoway")
LEVEL_NAME = {"isotropic": "L1", "local": "L2", "nonlocal": "L3", "twoway": "L4"}


def config_key(x_um, y_um, ang):
    return "%.2f,%.2f,%.1f" % (x_um, y_um, ang)


def resolved_cases():
    """{(config, mesh): {load: {"F": 4x2, "T": 4, "pos": 4x2, "cpu", "cells", "iterations", "id"}}}"""
    out = {}
    for f in sorted(glob.glob(os.path.join(CAMPAIGN, "results", "*.json"))):
        r = json.load(open(f))
        s = r["spec"]
        if s.get("geometry", {}).get("kind") != "throat":
            continue
        g = s["geometry"]
        key = config_key(g["centre"][0] * 1e6, g["centre"][1] * 1e6, g["row_angle_deg"])
        z0 = 3 * np.pi * s["mu"] * s["d"] * s["U"]
        sp = sorted(r["spheres"], key=lambda q: q["id"])
        mesh = s["cells_per_diameter"]
        if "refine_margin" in s.get("mesh", {}):       # a refinement-box variant: its own source
            mesh = "%d box %gd" % (mesh, s["mesh"]["refine_margin"])
        out.setdefault((key, mesh), {})[s["motion"]] = {
            "F": np.array([[q["F"][0], q["F"][1]] for q in sp]) / z0,
            "T": np.array([q["T"][2] for q in sp]) / (z0 * s["d"]),
            "pos": np.array([[q["x"][0], q["x"][1]] for q in sp]) / s["d"],
            "cpu": r["run"]["cpu_s"], "wall": r["run"]["wall_s"], "cells": r["mesh"]["cells"],
            "iterations": r["run"]["iterations"], "id": r["id"],
            "commit": r["provenance"]["git_commit"], "solver_sha256": r["provenance"]["solver_sha256"]}
    return out


def level_cases(binary, plan, csv_path):
    args = [binary, csv_path]
    for s in plan["series"]:
        c = "%.6g,%.6g,%.6g" % (s["centre"][0] * 1e6, s["centre"][1] * 1e6, s["row_angle_deg"])
        if c not in args:                      # a configuration on several meshes: once
            args += ["--config", c]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    out = {}
    d = plan["d"]
    for row in csv.DictReader(open(csv_path)):
        key = config_key(float(row["x_um"]), float(row["y_um"]), float(row["row_angle_deg"]))
        e = out.setdefault((key, row["level"]), {}).setdefault(row["load"], {"F": [], "T": [], "pos": []})
        e["F"].append([float(row["fx"]), float(row["fy"])])
        e["T"].append(float(row["tz"]))
        e["pos"].append([float(row["x"]) / d, float(row["y"]) / d])
    for case in out.values():
        for e in case.values():
            for k in ("F", "T", "pos"):
                e[k] = np.array(e[k])
    return out, " ".join(args[2:])


def rigid(case):
    """R (3x3), D (3), free q, locked (Vx, Vy) of one source's four loads."""
    pos = case["driving"]["pos"]
    c = pos.mean(axis=0)

    def q_of(e):
        r = e["pos"] - c
        return np.array([e["F"][:, 0].sum(), e["F"][:, 1].sum(),
                         (r[:, 0] * e["F"][:, 1] - r[:, 1] * e["F"][:, 0]).sum() + e["T"].sum()])

    R = -np.column_stack([q_of(case[k]) for k in ("friction_x", "friction_y", "rotation")])
    D = q_of(case["driving"])
    free = np.linalg.solve(R, D)
    locked = np.linalg.solve(R[:2, :2], D[:2])
    return R, D, free, locked


def trajectory_rates(plan):
    """The converged record's (resolved.csv, CFD step 2.5 us) own rates where its
    centre passes each configuration's x: central differences over +-10 us.
    (The first four configurations were taken from the 10 us record; at the same
    x the converged rod is turned by up to 0.9 deg more.)"""
    rows = list(csv.DictReader(open(os.path.join(HERE, "resolved.csv"))))
    t = [float(r["t"]) for r in rows]
    out = {}
    for s in plan["series"]:
        k = min(range(len(t)), key=lambda i: abs(float(rows[i]["x_com"]) - s["centre"][0]))
        a = min(range(len(t)), key=lambda i: abs(t[i] - (t[k] - 1e-5)))
        b = min(range(len(t)), key=lambda i: abs(t[i] - (t[k] + 1e-5)))
        dt = t[b] - t[a]
        vy = (float(rows[b]["y_com"]) - float(rows[a]["y_com"])) / dt / 0.01
        vx = (float(rows[b]["x_com"]) - float(rows[a]["x_com"])) / dt / 0.01
        da = (float(rows[b]["angle_deg"]) - float(rows[a]["angle_deg"])) / dt
        # paper angle alpha = -(90 + lab angle): Omega = -d alpha/dt [rad/s], over U/d
        om = -np.radians(da) * plan["d"] / 0.01
        out[config_key(s["centre"][0] * 1e6, s["centre"][1] * 1e6, s["row_angle_deg"])] = (
            s, np.array([vx, vy, om]))
    return out


def pct(m, r, scale):
    return 100.0 * (m - r) / scale


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--levels-bin", help="hsrod_throat_loads (default BUILD/hsrod_throat_loads)")
    a = ap.parse_args(argv)
    plan = json.load(open(PLAN))
    res = resolved_cases()
    binary = a.levels_bin or os.path.join(a.build, "hsrod_throat_loads")
    lev_csv = os.path.join(HERE, ".throat_levels.csv")
    lev, lev_args = level_cases(binary, plan, lev_csv)
    os.unlink(lev_csv)
    traj = trajectory_rates(plan)
    keys = list(traj)
    meshes = sorted({m for (_, m) in res if isinstance(m, int)})
    variants = sorted({m for (_, m) in res if not isinstance(m, int)})
    sources = load_sources(res, lev, keys, meshes, variants)
    write_per_sphere(res, sources, keys, traj, binary, lev_args)
    rig = {ks: rigid(c) for ks, c in sources.items()}
    write_rigid(rig, traj)
    md = (per_sphere_tables(sources, keys, traj, meshes) + rigid_table(rig, keys, traj)
          + lateral_velocity_table(rig, keys, traj) + displacement_table(rig, keys, traj)
          + cost_table(res, keys, traj, meshes, variants))
    with open(os.path.join(HERE, "throat_tables.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))
    return 0


def load_sources(res, lev, keys, meshes, variants):
    """{(config, source): {load: ...}}: per configuration the resolved cases
    with all four loads on each mesh and variant, then levels 1-4."""
    sources = {}
    for k in keys:
        for m in meshes:
            if (k, m) in res and all(l in res[(k, m)] for l in LOADS):
                sources[(k, "resolved m%d" % m)] = res[(k, m)]
        for m in variants:
            if (k, m) in res and all(l in res[(k, m)] for l in LOADS):
                sources[(k, "resolved m%s" % m)] = res[(k, m)]
        for lv in LEVELS:
            sources[(k, LEVEL_NAME[lv])] = lev[(k, lv)]
    return sources


def write_per_sphere(res, sources, keys, traj, binary, lev_args):
    """throat_per_sphere.csv: every source's per-sphere loads, provenance in the header."""
    commits = sorted({e["commit"] for c in res.values() for e in c.values()})
    shas = sorted({e["solver_sha256"] for c in res.values() for e in c.values()})
    with open(os.path.join(HERE, "throat_per_sphere.csv"), "w") as f:
        f.write("# pore passage, rod held rigid at throat configurations of resolved.csv (plan "
                "calibration/campaign/plan_throat.json): per sphere, force / (3 pi mu d U), z-torque / "
                "(3 pi mu d^2 U), positions in d = 3 um; loads: driving = held in the channel flow (mean U), "
                "friction_x / friction_y = translating at +U along x / y in fluid at rest, rotation = turning at "
                "U/d about +z about the centroid (spheres spinning with it)\n")
        f.write("# resolved: rodIbFoam steady Stokes (hsrod_campaign.py run calibration/campaign/throat --plan "
                "calibration/campaign/plan_throat.json --solver build/calibration/rodIbFoam), results "
                "calibration/campaign/throat/results/*.json, git commit(s) %s, solver sha256 %s; mesh m6 = 6 cells "
                "per d around the rod (0.5 um, the coupled run's), m8 = 8\n" % (" ".join(commits), " ".join(shas)))
        f.write("# levels: %s (hsrod_throat_loads %s); written by calibration/validation/pore_passage/throat.py\n"
                % (os.path.basename(binary), lev_args))
        f.write("config_x_um,config_y_um,row_angle_deg,paper_alpha_deg,source,load,sphere,x_over_d,y_over_d,fx,fy,tz,"
                "cells,cpu_s\n")
        for k in keys:
            s = traj[k][0]
            for (kk, src), case in sources.items():
                if kk != k:
                    continue
                for ld in LOADS:
                    e = case[ld]
                    for i in range(4):
                        f.write("%s,%g,%s,%s,%d,%.6f,%.6f,%.7g,%.7g,%.7g,%s,%s\n" % (
                            k, s["paper_angle_deg"], src, ld, i + 1, e["pos"][i, 0], e["pos"][i, 1],
                            e["F"][i, 0], e["F"][i, 1], e["T"][i], e.get("cells", ""), e.get("cpu", "")))


def write_rigid(rig, traj):
    """throat_rigid.csv: the rigid reduction of every source, with the trajectory's own rates."""
    with open(os.path.join(HERE, "throat_rigid.csv"), "w") as f:
        f.write("# rigid reduction of throat_per_sphere.csv (throat.py): R (resistance, units 3 pi mu d^k), "
                "D (held load: Fx, Fy over 3 pi mu d U, Tz over 3 pi mu d^2 U), free motion q = R^-1 D "
                "(Vx/U, Vy/U, Omega d/U), locked: rotation suppressed\n")
        f.write("config,source,Dx,Dy,Dt,Rxx,Rxy,Rxt,Ryx,Ryy,Ryt,Rtx,Rty,Rtt,Vx_free,Vy_free,Om_free,Vx_locked,Vy_locked,"
                "traj_Vx,traj_Vy,traj_Om\n")
        for (k, src), (R, D, q, lk) in rig.items():
            f.write("\"%s\",%s,%s,%s,%s,%s,%s\n" % (k, src, ",".join("%.6g" % v for v in D),
                                                    ",".join("%.6g" % v for v in R.ravel()),
                                                    ",".join("%.6g" % v for v in q), ",".join("%.6g" % v for v in lk),
                                                    ",".join("%.5g" % v for v in traj[k][1])))


def per_sphere_tables(sources, keys, traj, meshes):
    """Per-sphere loads held, dragged across and along, resolved (finest mesh) against the levels."""
    md = []
    def finest(k):
        return max((m for m in meshes if (k, "resolved m%d" % m) in sources), default=None)
    md.append("Per-sphere load of the rod held in the channel flow (F / 3 pi mu d U; sphere 1 the upper, "
              "downstream end, sphere 4 the lower, upstream end; in brackets: resolved, the change from mesh 6 "
              "to 8; levels, the error (level - resolved) over the mean |F_i| of the resolved case, %; resolved "
              "on the finest mesh of the configuration, 8 (6 at x = 48.7 um)):\n")
    md.append("| config (x µm, α) | sphere | resolved F_x | F_y | L1 F_x | F_y | L2 F_x | F_y | L3 F_x | F_y | L4 F_x | F_y |")
    md.append("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for load, title in (("driving", None), ("friction_y", "Per-sphere load of the rod translating at +U along y "
                                          "in fluid at rest (lateral friction; F / 3 pi mu d U):"),
                        ("friction_x", "Per-sphere load of the rod translating at +U along x in fluid at rest:")):
        if title:
            md.append("\n" + title + "\n")
            md.append("| config (x µm, α) | sphere | resolved F_x | F_y | L1 F_x | F_y | L2 F_x | F_y | L3 F_x | F_y | L4 F_x | F_y |")
            md.append("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
        for k in keys:
            s = traj[k][0]
            ref_mesh = finest(k)
            if ref_mesh is None:
                continue
            rsrc = "resolved m%d" % ref_mesh
            r = sources[(k, rsrc)][load]["F"]
            r6 = sources.get((k, "resolved m6"), {}).get(load, {}).get("F")
            scale = np.linalg.norm(r, axis=1).mean()
            for i in range(4):
                cells = ["%.1f, %.1f°" % (s["centre"][0] * 1e6, s["paper_angle_deg"]) if i == 0 else "", "%d" % (i + 1)]
                for c in (0, 1):
                    t = "%+.3f" % r[i, c]
                    if r6 is not None and ref_mesh != 6:
                        t += " (%+.3f)" % (r[i, c] - r6[i, c])
                    cells.append(t)
                for lv in LEVELS:
                    m = sources[(k, LEVEL_NAME[lv])][load]["F"]
                    for c in (0, 1):
                        cells.append("%+.3f (%+.0f)" % (m[i, c], pct(m[i, c], r[i, c], scale)))
                md.append("| " + " | ".join(cells) + " |")
    return md


def rigid_table(rig, keys, traj):
    """Held load, resistance and free motion of the rigid rod per configuration and source."""
    md = []
    md.append("\nRigid rod (same reduction on both sides): held load D = (F_x, F_y, T_z) on the rod, resistance "
              "diagonal R_xx, R_yy, R_tt and coupling R_yt, R_xy; free motion (force- and torque-free) V_x/U, "
              "V_y/U, Ω d/U; V_y/U with the rotation locked; the resolved trajectory's own rates where "
              "its centre passes the configuration's x (resolved.csv, central difference, ±10 µs):\n")
    md.append("| config | source | D_x | D_y | D_t | R_xx | R_yy | R_tt | R_xy | R_yt | V_x/U free | V_y/U free | Ω d/U free | V_y/U locked |")
    md.append("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for k in keys:
        s, tr = traj[k]
        first = True
        for (kk, src), (R, D, q, lk) in rig.items():
            if kk != k:
                continue
            md.append("| %s | %s | %+.3f | %+.3f | %+.3f | %.3f | %.3f | %.3f | %+.3f | %+.3f | %+.4f | %+.4f | %+.4f | %+.4f |" % (
                ("%.1f, %.1f°" % (s["centre"][0] * 1e6, s["paper_angle_deg"])) if first else "", src,
                D[0], D[1], D[2], R[0, 0], R[1, 1], R[2, 2], R[0, 1], R[1, 2], q[0], q[1], q[2], lk[1]))
            first = False
        md.append("| | resolved trajectory | | | | | | | | | %+.4f | %+.4f | %+.4f | |" % tuple(tr))
    return md


def lateral_velocity_table(rig, keys, traj):
    """The free lateral velocity V_y = (D_y - R_yx V_x - R_yt Omega) / R_yy split into
    the push of the held load, the x-y coupling at the free V_x and the rotation term."""
    md = []
    md.append("\nWhat the free lateral velocity is made of, V_y = (D_y - R_yx V_x - R_yt Ω) / R_yy (velocities "
              "over U): the held lateral load D_y / R_yy (\"push\"), the x-y coupling of the resistance at the "
              "free V_x, -R_yx V_x / R_yy, and the rotation term; the levels' error of V_y split into the two:\n")
    md.append("| config | source | push D_y / R_yy | coupling -R_yx V_x / R_yy | rotation -R_yt Ω / R_yy | V_y / U |")
    md.append("| --- | --- | ---: | ---: | ---: | ---: |")
    for k in keys:
        s = traj[k][0]
        first = True
        for (kk, src), (R, D, q, lk) in rig.items():
            if kk != k or src.startswith("resolved m6") and (k, "resolved m8") in rig:
                continue
            md.append("| %s | %s | %+.3f | %+.3f | %+.4f | %+.4f |" % (
                ("%.1f, %.1f°" % (s["centre"][0] * 1e6, s["paper_angle_deg"])) if first else "", src,
                D[1] / R[1, 1], -R[1, 0] * q[0] / R[1, 1], -R[1, 2] * q[2] / R[1, 1], q[1]))
            first = False
    return md


def displacement_table(rig, keys, traj):
    """Lateral displacement across the throat, free rigid rod against the trajectory."""
    md = []
    # lateral displacement across the throat from the quasi-steady free motion (trapezoid of V_y / V_x over
    # the configurations' x; angles and lateral positions held at the trajectory's)
    xs = [traj[k][0]["centre"][0] * 1e6 for k in keys]
    W = 36.0
    md.append("\nLateral displacement / W from x = %.1f to %.1f µm: integral of V_y / V_x of the free rigid rod "
              "along x (trapezoid over the configurations; the angle and y of the trajectory), against the "
              "trajectory's own Δy:\n" % (xs[0], xs[-1]))
    md.append("| source | Δy / W |")
    md.append("| --- | ---: |")
    for src in ["resolved m6"] + [LEVEL_NAME[lv] for lv in LEVELS]:
        if not all((k, src) in rig for k in keys):
            continue
        slope = [rig[(k, src)][2][1] / rig[(k, src)][2][0] for k in keys]
        dy = sum(0.5 * (slope[i] + slope[i + 1]) * (xs[i + 1] - xs[i]) for i in range(len(keys) - 1))
        md.append("| %s | %+.4f |" % (src, dy / W))
    conv = [r for r in csv.DictReader(open(os.path.join(HERE, "resolved.csv")))]
    cx, cy = [float(r["x_com"]) * 1e6 for r in conv], [float(r["y_com"]) * 1e6 for r in conv]
    keep = [i for i in range(len(cx)) if i == 0 or cx[i] > max(cx[:i])]  # monotone in x
    y_at = lambda x: float(np.interp(x, [cx[i] for i in keep], [cy[i] for i in keep]))
    md.append("| resolved trajectory (resolved.csv) | %+.4f |" % ((y_at(xs[-1]) - y_at(xs[0])) / W))
    return md


def cost_table(res, keys, traj, meshes, variants):
    """Cells, iterations and CPU time of every resolved case."""
    md = []
    md.append("\nrodIbFoam cases (one core, `nice -n 10`, shared machine):\n")
    md.append("| config | mesh | load | cells | iterations | CPU [s] | wall [s] |")
    md.append("| --- | ---: | --- | ---: | ---: | ---: | ---: |")
    total = 0.0
    for k in keys:
        s = traj[k][0]
        for m in meshes + variants:
            for ld in LOADS:
                e = res.get((k, m), {}).get(ld)
                if e:
                    total += e["cpu"]
                    md.append("| %.1f, %.1f° | %s | %s | %d | %d | %.1f | %.1f |" % (
                        s["centre"][0] * 1e6, s["paper_angle_deg"], m, ld, e["cells"], e["iterations"], e["cpu"],
                        e["wall"]))
    md.append("\n%d cases, %.0f s CPU in all." % (sum(len(c) for c in res.values()), total))
    return md



if __name__ == "__main__":
    sys.exit(main())
