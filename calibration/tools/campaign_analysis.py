#!/usr/bin/env python3
"""campaign_analysis: the finished cases of a resolved campaign
(hsrod_campaign.py) as dimensionless per-sphere coefficients and
mesh-extrapolated rod columns.

Per case (row of n spheres along x, load at angle a to the row, speed U,
zeta0 = 3 pi mu d), per sphere i:
    par_i  = F_x,i / (zeta0 U cos a)      perp_i = F_y,i / (zeta0 U sin a)
(a lone sphere: a = 0, perp = par by isotropy). For load "friction" these are
the sphere's share of the rod's resistance along / across its axis (the row
translates at -U e), for "driving" its share of the held-in-flow load in
plane Poiseuille flow of gap-mean velocity U e. Totals: the sums over the
spheres. Derived rod columns (hsrod's table, drag-models/hydro/
confinement_coefficients.h): friction per sphere over the lone sphere's,
driving = force-free velocity over the gap-mean velocity = D / R.

Mesh series: each quantity at every mesh of the series; the estimate is the
finest mesh's value, its uncertainty the change from the next coarser mesh.
Richardson's p = 2 extrapolation is recorded but not used: the IBM's force
error is not monotone in d/h (sphere surfaces cut the cells differently as
d/h changes; measured: lone sphere at beta 0.3, friction 1.4205 / 1.4084 /
1.4147 at d/h 6 / 8 / 10), while ratios (force-free velocities, r) converge
smoothly (1.4496 / 1.4520 / 1.4533). Python 3 + numpy.
"""
import csv
import glob
import json
import math
import os
import sys

import numpy as np

import campaign_plan  # same directory: the plan's cases and their ids


ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def repo_path(path):
    """`path` relative to the repository when inside it (provenance that
    does not name this machine's checkout)."""
    p = os.path.abspath(path)
    return os.path.relpath(p, ROOT) if p.startswith(ROOT + os.sep) else p


RECORD_CSV, RECORD_PLAN, RECORD_PROVENANCE = "per_sphere_record.csv", "plan.json", "provenance.json"


def load_results(out):
    """The finished cases of campaign directory `out`: its per-case JSON
    files (results/*.json), plus the cases it holds only as a per-sphere
    record (load_recorded) that have no JSON file."""
    res = []
    for f in sorted(glob.glob(os.path.join(out, "results", "*.json"))):
        with open(f) as fh:
            r = json.load(fh)
        # straight rows in the wide slit only: bent rods and rows near walls
        # and pores (spec "geometry") are read by geometry_cases.py; box-size
        # studies (role "box": one row in several boxes) are not fit data
        spec = r.get("spec", {})
        if r.get("schema") == "hsrod-campaign-case 1" and "geometry" not in spec and spec.get("role") != "box":
            r["source"] = repo_path(f)
            res.append(r)
    if os.path.exists(os.path.join(out, RECORD_CSV)):
        have = {r["id"] for r in res}
        res += [r for r in load_recorded(out) if r["id"] not in have]
    return res


def load_recorded(out):
    """Cases recorded only as per-sphere coefficients (OUT/per_sphere_record.csv,
    the per-sphere CSV this module writes), with the plan that made them
    (OUT/plan.json) and their provenance (OUT/provenance.json). Each case id
    must be the plan's id of the same case: the id holds a hash of every case
    parameter, so a match proves the spec (d, U, mu, mesh, control) that the
    record itself does not store. Returned in the form of load_results, with
    the coefficients instead of the forces."""
    with open(os.path.join(out, RECORD_PLAN)) as f:
        specs = {c["id"]: c for c in campaign_plan.expand(json.load(f))}
    with open(os.path.join(out, RECORD_PROVENANCE)) as f:
        prov = json.load(f)
    source = repo_path(os.path.join(out, RECORD_CSV))
    cases = {}
    with open(os.path.join(out, RECORD_CSV)) as f:
        for row in csv.DictReader(l for l in f if not l.startswith("#")):
            cid = row["case"]
            if cid not in specs:
                sys.exit("campaign_analysis: recorded case %s is not a case of %s" % (cid, os.path.join(out, RECORD_PLAN)))
            spec = specs[cid]
            if (abs(float(row["beta"]) - spec["beta"]) > 1e-9 or int(row["n"]) != spec["n"] or row["load"] != spec["load"]
                    or int(row["cells_per_diameter"]) != spec["cells_per_diameter"]):
                sys.exit("campaign_analysis: recorded case %s disagrees with its plan" % cid)
            r = cases.setdefault(cid, {
                "schema": "hsrod-campaign-case 1", "id": cid, "spec": spec, "recorded": True, "source": source,
                "mesh": {"cells": int(row["cells"]), "cells_per_diameter": spec["cells_per_diameter"]},
                "run": {"iterations": int(row["iterations"]), "cpu_s": float(row["cpu_s"])},
                "spheres": [], "coefficients": ([], [], []),
                "provenance": {k: prov[k] for k in ("solver_sha256", "git_commits", "host")}})
            r["spheres"].append({"id": int(row["sphere"]), "x": [float(row["x_over_d"]) * spec["d"], 0.0, 0.0]})
            for k, col in enumerate(("par", "perp", "torque_z")):
                r["coefficients"][k].append(float(row[col]))
    for r in cases.values():
        if len(r["spheres"]) != r["spec"]["n"]:
            sys.exit("campaign_analysis: recorded case %s has %d of %d spheres" % (r["id"], len(r["spheres"]), r["spec"]["n"]))
    return list(cases.values())


def per_sphere(r):
    if "coefficients" in r:  # a recorded case (load_recorded)
        return tuple(np.array(c) for c in r["coefficients"])
    s = r["spec"]
    z0 = 3 * math.pi * s["mu"] * s["d"]
    a = math.radians(s["flow_angle_deg"])
    par, perp, tz = [], [], []
    for sp in r["spheres"]:
        fpar = sp["F"][0] / (z0 * s["U"] * math.cos(a))
        par.append(fpar)
        perp.append(sp["F"][1] / (z0 * s["U"] * math.sin(a)) if s["n"] > 1 else fpar)
        tz.append(sp["T"][2] / (z0 * s["U"] * s["d"]))
    return np.array(par), np.array(perp), np.array(tz)


def mesh_estimate(hs, vals):
    """(estimate, uncertainty, richardson) from values on meshes of spacing
    hs: the finest mesh's value, the change from the next coarser mesh as
    its uncertainty, and Richardson's p = 2 extrapolation from the two finest
    meshes for the record (not used: the IBM's error oscillates with d/h)."""
    order = np.argsort(hs)
    hs, vals = np.asarray(hs)[order], np.asarray(vals, dtype=float)[order]
    if len(hs) == 1:
        return float(vals[0]), float("nan"), float("nan")
    h1, h2, v1, v2 = hs[0], hs[1], vals[0], vals[1]
    rich = v1 + (v1 - v2) * h1 ** 2 / (h2 ** 2 - h1 ** 2)
    return float(v1), float(abs(v1 - v2)), float(rich)


def series_table(results):
    """{(beta, n, spacing): {load: {n_d: (par, perp, tz, result)}}}"""
    tab = {}
    for r in results:
        s = r["spec"]
        key = (round(s["beta"], 6), s["n"], s["spacing"])
        tab.setdefault(key, {}).setdefault(s["load"], {})[s["cells_per_diameter"]] = per_sphere(r) + (r,)
    return tab


def summarise(tab):
    """Rod/pair summaries with mesh-extrapolated quantities."""
    out = []
    lone = {}
    for (beta, n, sp), loads in sorted(tab.items()):
        if "friction" not in loads or "driving" not in loads:
            continue
        meshes = sorted(set(loads["friction"]) & set(loads["driving"]))
        if not meshes:
            continue
        hs = [1.0 / m for m in meshes]
        q = {}
        for name, fn in (
            ("R_par", lambda f, d: f[0].sum()), ("R_perp", lambda f, d: f[1].sum()),
            ("D_par", lambda f, d: d[0].sum()), ("D_perp", lambda f, d: d[1].sum()),
            ("lambda_par", lambda f, d: d[0].sum() / f[0].sum()),
            ("lambda_perp", lambda f, d: d[1].sum() / f[1].sum()),
            ("r", lambda f, d: (d[1].sum() / f[1].sum()) / (d[0].sum() / f[0].sum()))):
            vals = [fn(loads["friction"][m], loads["driving"][m]) for m in meshes]
            est, unc, rich = mesh_estimate(hs, vals)
            q[name] = {"by_mesh": dict(zip(meshes, [float(v) for v in vals])), "estimate": est,
                       "uncertainty": unc, "richardson_p2": rich}
        prof = {}
        for load in ("friction", "driving"):
            for comp, k in (("par", 0), ("perp", 1)):
                arr = np.array([loads[load][m][k] for m in meshes])
                est = [mesh_estimate(hs, arr[:, i])[0] for i in range(n)]
                prof["%s_%s" % (load, comp)] = [float(x) for x in est]
        rec = {"beta": beta, "n": n, "spacing": sp, "meshes": meshes,
               "role": loads["friction"][meshes[-1]][3]["spec"]["role"],
               "cells": {m: loads["friction"][m][3]["mesh"]["cells"] for m in meshes},
               "cpu_s": sum(loads[l][m][3]["run"]["cpu_s"] for l in loads for m in loads[l]),
               "quantities": q, "profiles": prof}
        if n == 1:
            lone[beta] = rec
        out.append(rec)
    for rec in out:
        lo = lone.get(rec["beta"])
        if lo and rec["n"] > 1:
            zs = lo["quantities"]["R_par"]["estimate"]
            rec["parallel_friction"] = rec["quantities"]["R_par"]["estimate"] / (rec["n"] * zs)
            rec["perpendicular_friction"] = rec["quantities"]["R_perp"]["estimate"] / (rec["n"] * zs)
    return out


# relative uncertainty floor of every resolved load coefficient: the lateral
# faces 4 H away (results.md sec. 2: Faxen ratio +0.43 % at 4 H, +0.12 % at 6 H)
DOMAIN_FLOOR = 0.003
# floor of the force-free velocities (ratios of two loads on one mesh and one
# domain): the lone sphere's velocity at beta 0.3 is within 0.12 % of Faxen's
# law on the finest mesh (1.4533 vs 1.4550; README "Mesh series"), its
# change from d/h 8 to 10 0.09 %
VELOCITY_FLOOR = 0.001
# absolute floor of r = lambda_perp / lambda_par (both from one run on one
# mesh: their mesh changes cancel to 1e-5 - 7e-5, mesh_convergence.md)
RATIO_FLOOR = 1e-4


def fit_points(summ):
    """Points for hsrod_fit_campaign: (quantity, beta, n, value, sigma, role).
    Loads over the lone sphere's friction (per sphere), force-free velocities
    over the gap-mean velocity (par_velocity, perp_velocity) and their ratio
    r (velocity_ratio)."""
    lone = {rec["beta"]: rec for rec in summ if rec["n"] == 1}
    pts = []

    def rel(q):
        u = q["uncertainty"]
        return (u / abs(q["estimate"])) if math.isfinite(u) else 0.0

    for rec in summ:
        q, beta, n = rec["quantities"], rec["beta"], rec["n"]
        if rec["spacing"] != 1:
            continue
        if n > 1:  # velocities need no lone sphere at this beta (held-out beta 0.5)
            for name, key in (("par_velocity", "lambda_par"), ("perp_velocity", "lambda_perp")):
                v = q[key]["estimate"]
                pts.append((name, beta, n, v, abs(v) * math.hypot(rel(q[key]), VELOCITY_FLOOR), rec["role"]))
            u = q["r"]["uncertainty"]
            pts.append(("velocity_ratio", beta, n, q["r"]["estimate"],
                        math.hypot(u if math.isfinite(u) else 0.0, RATIO_FLOOR), rec["role"]))
        if beta not in lone:
            continue
        K = lone[beta]["quantities"]["R_par"]
        if n == 1:
            for name, key, floor in (("sphere_friction", "R_par", DOMAIN_FLOOR),
                                     ("sphere_driving", "lambda_par", VELOCITY_FLOOR)):
                v = q[key]["estimate"]
                pts.append((name, beta, 1, v, abs(v) * math.hypot(rel(q[key]), floor), rec["role"]))
            continue
        for name, key in (("par_friction", "R_par"), ("perp_friction", "R_perp"),
                          ("par_held", "D_par"), ("perp_held", "D_perp")):
            v = q[key]["estimate"] / (n * K["estimate"])
            sig = abs(v) * math.sqrt(rel(q[key]) ** 2 + rel(K) ** 2 + DOMAIN_FLOOR ** 2)
            pts.append((name, beta, n, v, sig, rec["role"]))
    return pts


SERIES_QUANTITIES = ("R_par", "R_perp", "D_par", "D_perp", "lambda_par", "lambda_perp", "r")


def write_series(summ, path):
    """One row per (beta, n, spacing): the rod's totals over 3 pi mu d (R)
    and 3 pi mu d U (D), force-free velocities over U, r, with uncertainties."""
    with open(path, "w") as f:
        f.write("# resolved rodIbFoam campaign: rigid rows of spheres in a slit (campaign_analysis.py); "
                "R = friction / (3 pi mu d), D = held-in-flow load / (3 pi mu d U_mean), "
                "lambda = D / R (force-free velocity / U_mean), r = lambda_perp / lambda_par; "
                "finest mesh, *_u = change from the next coarser mesh\n")
        f.write("beta,n,spacing,role,meshes,%s,cells_finest,cpu_s\n" % ",".join(
            "%s,%s_u" % (q, q) for q in SERIES_QUANTITIES))
        for rec in summ:
            q = rec["quantities"]
            f.write("%g,%d,%g,%s,%s,%s,%d,%.1f\n" % (
                rec["beta"], rec["n"], rec["spacing"], rec["role"], "/".join(map(str, rec["meshes"])),
                ",".join("%.8g,%.3g" % (q[k]["estimate"], q[k]["uncertainty"] if math.isfinite(
                    q[k]["uncertainty"]) else -1) for k in SERIES_QUANTITIES),
                rec["cells"][rec["meshes"][-1]], rec["cpu_s"]))


def write_profiles(summ, path):
    with open(path, "w") as f:
        f.write("# per-sphere resolved coefficients (finest mesh): sphere i's share of R / D "
                "(campaign_analysis.py); spheres along x at x_over_d\n")
        f.write("beta,n,spacing,load,component,sphere,x_over_d,value\n")
        for rec in summ:
            n, sp = rec["n"], rec["spacing"]
            for key, vals in sorted(rec["profiles"].items()):
                load, comp = key.split("_")
                for i, v in enumerate(vals):
                    f.write("%g,%d,%g,%s,%s,%d,%g,%.8g\n" % (rec["beta"], n, sp, load, comp, i + 1,
                                                              (i - 0.5 * (n - 1)) * sp, v))


def write_mesh_convergence(summ, path):
    """Mesh convergence of every series (markdown): each quantity on every
    mesh, the change from the next coarser mesh and Richardson's p = 2 value."""
    with open(path, "w") as f:
        f.write("# Mesh convergence of the resolved campaign (campaign_analysis.py)\n\n"
                "Per series (beta, N, spacing / d): each quantity at d/h = 6, 8 (10), the relative change "
                "between the two finest meshes (the uncertainty the fit uses) and the p = 2 Richardson value's "
                "distance from the finest mesh. R: friction / (3 pi mu d), D: held load / (3 pi mu d U), "
                "lambda = D / R, r = lambda_perp / lambda_par.\n\n")
        f.write("| beta | N | s/d | quantity | by mesh | change | Richardson - finest |\n|---|---|---|---|---|---|---|\n")
        for rec in summ:
            for name in ("R_par", "R_perp", "lambda_par", "lambda_perp", "r"):
                if rec["n"] == 1 and name in ("R_perp", "lambda_perp", "r"):
                    continue
                q = rec["quantities"][name]
                if len(q["by_mesh"]) < 2:
                    continue
                est = q["estimate"]
                f.write("| %g | %d | %g | %s | %s | %+.3f %% | %+.3f %% |\n" % (
                    rec["beta"], rec["n"], rec["spacing"], name,
                    " / ".join("%d: %.5f" % (m, v) for m, v in sorted(q["by_mesh"].items())),
                    100 * q["uncertainty"] / abs(est), 100 * (q["richardson_p2"] - est) / abs(est)))


def collect(outs, csv_path, json_path=None, points_path=None, series_path=None, profiles_path=None,
            mesh_path=None):
    """Every finished case of the campaign directories `outs` (a case in two
    directories counts once, the first one's) into the per-sphere CSV and the
    optional summaries."""
    if isinstance(outs, str):
        outs = [outs]
    results, seen = [], set()
    for out in outs:
        for r in load_results(out):
            if r["id"] not in seen:
                seen.add(r["id"])
                results.append(r)
    if not results:
        sys.exit("campaign_analysis: no finished cases in %s" % ", ".join(outs))
    rows = []
    for r in results:
        s = r["spec"]
        par, perp, tz = per_sphere(r)
        for i, sp in enumerate(r["spheres"]):
            rows.append([s["beta"], s["n"], s["spacing"], s["load"], s["cells_per_diameter"], i + 1,
                         "%.6g" % (sp["x"][0] / s["d"]), "%.8g" % par[i], "%.8g" % perp[i], "%.8g" % tz[i],
                         r["mesh"]["cells"], r["run"]["iterations"], r["run"]["cpu_s"], s["role"], r["id"],
                         r["source"]])
    os.makedirs(os.path.dirname(os.path.abspath(csv_path)), exist_ok=True)
    with open(csv_path, "w", newline="") as f:
        f.write("# resolved rodIbFoam campaign (calibration/tools/hsrod_campaign.py), per sphere; "
                "coefficients over 3 pi mu d U (torque over 3 pi mu d^2 U); see campaign_analysis.py; "
                "source: the case's result JSON or the per-sphere record it was kept in (calibration/campaign/README.md)\n")
        w = csv.writer(f)
        w.writerow(["beta", "n", "spacing_over_d", "load", "cells_per_diameter", "sphere", "x_over_d",
                    "par", "perp", "torque_z", "cells", "iterations", "cpu_s", "role", "case", "source"])
        w.writerows(rows)
    summ = summarise(series_table(results))
    if json_path:
        sources = {}
        for r in results:
            src = sources.setdefault(os.path.dirname(r["source"]) if not r.get("recorded") else r["source"], {
                "cases": 0, "cpu_s": 0.0, "solver_sha256": set(), "git_commits": set(), "hosts": set(),
                "recorded_only": bool(r.get("recorded"))})
            src["cases"] += 1
            src["cpu_s"] += r["run"]["cpu_s"]
            pv = r["provenance"]
            src["solver_sha256"] |= set([pv["solver_sha256"]] if isinstance(pv["solver_sha256"], str) else pv["solver_sha256"])
            src["git_commits"] |= set([pv["git_commit"]] if "git_commit" in pv else pv["git_commits"])
            src["hosts"].add(pv["host"])
        for v in sources.values():
            for k in ("solver_sha256", "git_commits", "hosts"):
                v[k] = sorted(v[k])
            v["cpu_s"] = round(v["cpu_s"], 1)
        with open(json_path, "w") as f:
            json.dump({"schema": "hsrod-campaign-summary 2", "cases": len(results), "sources": sources,
                       "total_cpu_s": round(sum(r["run"]["cpu_s"] for r in results), 1),
                       "series": summ}, f, indent=1)
    if series_path:
        write_series(summ, series_path)
    if profiles_path:
        write_profiles(summ, profiles_path)
    if mesh_path:
        write_mesh_convergence(summ, mesh_path)
    if points_path:
        with open(points_path, "w") as f:
            f.write("# points for hsrod_fit_campaign (campaign_analysis.py from %d resolved cases)\n" % len(results))
            f.write("quantity,beta,n,value,sigma,role\n")
            for p_ in fit_points(summ):
                f.write("%s,%.6g,%d,%.8g,%.3g,%s\n" % p_)
    print("%-6s %-3s %-4s %-7s %-22s %-22s %-18s %-18s %s" % (
        "beta", "n", "s/d", "meshes", "R_par (sum)", "R_perp (sum)", "lambda_par", "lambda_perp", "r"))
    for rec in summ:
        q = rec["quantities"]
        print("%-6g %-3d %-4g %-7s %-22s %-22s %-18s %-18s %s" % (
            rec["beta"], rec["n"], rec["spacing"], ",".join(map(str, rec["meshes"])),
            "%.4f +- %.4f" % (q["R_par"]["estimate"], q["R_par"]["uncertainty"]),
            "%.4f +- %.4f" % (q["R_perp"]["estimate"], q["R_perp"]["uncertainty"]),
            "%.4f +- %.4f" % (q["lambda_par"]["estimate"], q["lambda_par"]["uncertainty"]),
            "%.4f +- %.4f" % (q["lambda_perp"]["estimate"], q["lambda_perp"]["uncertainty"]),
            "%.4f +- %.4f" % (q["r"]["estimate"], q["r"]["uncertainty"])))
    print("%d cases, %d series, %.0f s CPU" % (len(results), len(summ), sum(r["run"]["cpu_s"] for r in results)))
    return 0


if __name__ == "__main__":
    import argparse
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", nargs="+", help="campaign directories (hsrod_campaign.py run OUT; a directory may hold "
                    "recorded cases: per_sphere_record.csv, plan.json, provenance.json)")
    ap.add_argument("--csv", required=True, help="per-sphere table of every case")
    ap.add_argument("--json", help="series summary (JSON)")
    ap.add_argument("--points", help="points for hsrod_fit_campaign")
    ap.add_argument("--series", help="series totals CSV (cross-check, tests)")
    ap.add_argument("--profiles", help="per-sphere profiles CSV, finest mesh")
    ap.add_argument("--mesh", help="mesh convergence of every series (markdown)")
    a = ap.parse_args()
    sys.exit(collect(a.out, a.csv, a.json, a.points, a.series, a.profiles, a.mesh))
