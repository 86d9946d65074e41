#!/usr/bin/env python3
"""fig3_bent: what decides the states of the paper's Fig. 3 scene (a flexible
rod of 15 spheres across the flow of a Hele-Shaw slit, beta 0.83), resolved
against levels 2-4: the loads on the straight and the C-shaped (bent) rod
held rigid in the wide slit (campaigns fig3-bent and beta-high).

    fig3_bent.py --crosscheck build/hsrod_crosscheck_scenes \
        [--campaign calibration/campaign/fig3-bent] [--straight calibration/campaign/beta-high] \
        [--per-sphere calibration/data/resolved_fig3_bent_per_sphere.csv] \
        [--states calibration/data/fig3_bent_states.csv] [--plot FILE.png] [--levels local,nonlocal,twoway]

Every case is a rigid arc of n spheres (bend 0 = the straight row), chord
along x, apex towards -y, symmetric under the mirror x -> -x, dragged and
held with the load at 45 degrees to the chord. The mirror separates the
response to a stream across the chord (e_y: the rod perpendicular to the
flow, Fig. 3's C-shape state) from the one along it (e_x: the rod aligned):
sphere m(i) = n + 1 - i under e maps to sphere i under M e, so with
G_i = F_i(e45) sqrt 2:
    F_i,x(e_x) = (G_i,x + G_m,x) / 2,  F_i,x(e_y) = (G_i,x - G_m,x) / 2,
    F_i,y(e_y) = (G_i,y + G_m,y) / 2,  F_i,y(e_x) = (G_i,y - G_m,y) / 2,
and the sphere torques T_i(e_y) = (g_i - g_m) / 2, T_i(e_x) = (g_i + g_m) / 2.
By the same mirror the total force under e_y is along y, under e_x along x,
and the rod's torque under e_y vanishes.
Quantities (forces over 3 pi mu d U, moments over 3 pi mu d^2 U, U the
gap-mean velocity of the stream):
  lam_perp, lam_par  force-free velocity of the rigid rod across / along the
                     chord over U (held total over friction total);
  r                  lam_perp / lam_par (the anisotropy that drifts a tilted rod);
  q_i                net load on sphere i of the rod translating force-free
                     across the stream: F_held,i(e_y) - lam_perp F_fric,i(e_y)
                     (what its elasticity carries; zero for a uniform rod);
  B                  moment of the q_i (and sphere torques) of the half x > 0
                     (with half the middle sphere) about the middle sphere's
                     centre, sign such that B > 0 pushes the middle ahead of the
                     ends along the stream: the flexural load that bends a
                     straight rod middle-leading, and for a rod bent
                     middle-leading (apex downstream) the moment that bends it
                     further (B > 0) or straightens it (B < 0);
  tau                torque on the rod tilted by phi from perpendicular, held
                     at its orientation and translating force-free, over
                     sin(phi): T_held(e_x) - lam_par T_fric(e_x) (the sign of its
                     angular velocity when free, since the rotational
                     resistance is positive definite). For the middle-leading
                     C (flow -e_y) tau > 0 turns it back to perpendicular,
                     tau < 0 turns it further (towards reorientation); a
                     straight row has tau = 0 by its second mirror y -> -y.
The per-sphere CSV is geometry_cases.py's format (the straight row as geometry
"bent", bend 0); the levels come from hsrod_crosscheck_scenes on it, so this
reruns unchanged after a refit of the levels. Python 3 standard library
(matplotlib for --plot)."""
import argparse
import csv
import glob
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import geometry_cases  # noqa: E402

LEVEL_NAMES = {"local": "level 2", "nonlocal": "level 3", "twoway": "level 4"}


def straight_cases(out, n, beta):
    """The straight row of n at beta from a straight-row campaign, keyed as a bent rod of bend 0."""
    cases = {}
    for f in sorted(glob.glob(os.path.join(out, "results", "*.json"))):
        with open(f) as fh:
            r = json.load(fh)
        s = r["spec"]
        if r.get("schema") != "hsrod-campaign-case 1" or "geometry" in s or s["n"] != n \
                or abs(s["beta"] - beta) > 1e-9 or s["spacing"] != 1.0:
            continue
        s["geometry"] = {"kind": "bent", "bend_deg": 0.0}
        r["source"] = os.path.relpath(os.path.abspath(f), ROOT)
        cases.setdefault((geometry_cases.case_key(s), s["load"]), {})[s["cells_per_diameter"]] = r
    return cases


def read_per_sphere(path):
    """{(case, load, mesh): {"bend", "finest", "x": [...], "F": [(fx, fy)], "T": [tz]}} in sphere order."""
    out = {}
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            k = (row["case"], row["load"], int(row["cells_per_diameter"]))
            c = out.setdefault(k, {"bend": float(row["bend_deg"]), "finest": row["finest"] == "1", "beta":
                                   float(row["beta"]), "x": [], "F": [], "T": []})
            c["x"].append((float(row["x"]) / float(row["d"]), float(row["y"]) / float(row["d"])))
            c["F"].append((float(row["fx"]), float(row["fy"])))
            c["T"].append(float(row["tz"]))
    return out


def split_mirror(F45, T45):
    """Per-sphere responses to unit streams e_x and e_y from the 45-degree load (module docstring)."""
    n = len(F45)
    s = math.sqrt(2.0)
    G = [(fx * s, fy * s) for fx, fy in F45]
    g = [t * s for t in T45]
    Fx, Fy, Tx, Ty = [], [], [], []
    for i in range(n):
        m = n - 1 - i
        Fx.append((0.5 * (G[i][0] + G[m][0]), 0.5 * (G[i][1] - G[m][1])))
        Fy.append((0.5 * (G[i][0] - G[m][0]), 0.5 * (G[i][1] + G[m][1])))
        Tx.append(0.5 * (g[i] + g[m]))
        Ty.append(0.5 * (g[i] - g[m]))
    return Fx, Fy, Tx, Ty


def rod_torque(x, F, T):
    n = len(x)
    cx, cy = sum(p[0] for p in x) / n, sum(p[1] for p in x) / n
    return sum((p[0] - cx) * f[1] - (p[1] - cy) * f[0] for p, f in zip(x, F)) + sum(T)


def states(x, fric45, held45, fric_t45, held_t45):
    """The module docstring's quantities of one rigid arc from its friction and held 45-degree loads."""
    n = len(x)
    fx_f, fy_f, tx_f, ty_f = split_mirror(fric45, fric_t45)
    fx_h, fy_h, tx_h, ty_h = split_mirror(held45, held_t45)
    lam_perp = sum(f[1] for f in fy_h) / sum(f[1] for f in fy_f)
    lam_par = sum(f[0] for f in fx_h) / sum(f[0] for f in fx_f)
    q = [(h[0] - lam_perp * f[0], h[1] - lam_perp * f[1]) for h, f in zip(fy_h, fy_f)]
    qt = [h - lam_perp * f for h, f in zip(ty_h, ty_f)]
    mid = (n - 1) // 2
    xm, ym = x[mid]
    # right half about the middle sphere's centre; an odd n splits the middle sphere's load in two
    w = [0.0 if x[i][0] < xm - 1e-9 else (0.5 if i == mid and n % 2 else 1.0) for i in range(n)]
    if n % 2 == 0:
        xm, ym = 0.5 * (x[mid][0] + x[mid + 1][0]), 0.5 * (x[mid][1] + x[mid + 1][1])
    Mz = sum(wi * ((p[0] - xm) * qi[1] - (p[1] - ym) * qi[0] + ti) for wi, p, qi, ti in zip(w, x, q, qt))
    T_h = rod_torque(x, fx_h, tx_h)
    T_f = rod_torque(x, fx_f, tx_f)
    return {"lam_perp": lam_perp, "lam_par": lam_par, "r": lam_perp / lam_par,
            "R_perp": sum(f[1] for f in fy_f), "R_par": sum(f[0] for f in fx_f),
            "B": -Mz, "tau": T_h - lam_par * T_f, "q_y": [qi[1] for qi in q],
            "held_y": [h[1] for h in fy_h], "fric_y": [f[1] for f in fy_f]}


def resolved_states(per_sphere):
    """{case: {mesh: states}} of every case with both loads on a mesh."""
    out = {}
    for (case, load, mesh), c in per_sphere.items():
        if load != "friction" or (case, "driving", mesh) not in per_sphere:
            continue
        h = per_sphere[(case, "driving", mesh)]
        st = states(c["x"], c["F"], h["F"], c["T"], h["T"])
        st.update(bend=c["bend"], beta=c["beta"], finest=c["finest"], x=c["x"])
        out.setdefault(case, {})[mesh] = st
    return out


def level_states(per_sphere, path, crosscheck, levels):
    """{level: {case: states}} from hsrod_crosscheck_scenes's per-sphere model forces and torques
    (finest-mesh cases)."""
    with tempfile.TemporaryDirectory() as tmp:
        cc = os.path.join(tmp, "cc.csv")
        subprocess.run([crosscheck, path, cc, "--levels",
                        ",".join(levels)], check=True, stdout=subprocess.DEVNULL)
        rows = list(csv.DictReader(open(cc)))
    model = {}
    for r in rows:
        m = model.setdefault((r["level"], r["case"], r["load"]), {"f": {}, "t": {}})
        qn = r["quantity"]
        if qn[:3] in ("fx_", "fy_"):
            m["f"].setdefault(int(qn[3:]), [0.0, 0.0])["xy".index(qn[1])] = float(r["model"])
        elif qn[:3] == "tz_":
            m["t"][int(qn[3:])] = float(r["model"])
    out = {}
    for (level, case, load), m in model.items():
        if load != "friction" or (level, case, "driving") not in model:
            continue
        h = model[(level, case, "driving")]
        fin = [c for (cs, ld, _), c in per_sphere.items() if cs == case and ld == "friction" and c["finest"]][0]
        n = len(fin["x"])
        fric = [tuple(m["f"][i + 1]) for i in range(n)]
        held = [tuple(h["f"][i + 1]) for i in range(n)]
        st = states(fin["x"], fric, held, [m["t"][i + 1] for i in range(n)], [h["t"][i + 1] for i in range(n)])
        out.setdefault(level, {})[case] = st
    return out


def bend_stiffness(E, d, U, mu, n):
    """Elastic moment of a uniformly bent rod of n spheres (bonds: circular beams of the sphere
    diameter, fix rod/bonds) per radian of total bend, over 3 pi mu d^2 U: E I / L / (3 pi mu d^2 U),
    I = pi d^4 / 64, L = (n - 1) d [-]."""
    return E * math.pi * d ** 4 / 64.0 / ((n - 1) * d) / (3.0 * math.pi * mu * d * d * U)


def predicted_state(by_bend, stiffness):
    """From {bend_deg: states} (0 = straight): the sense the straight rod bends in (B(0) > 0:
    middle leading), the bend where the flow's moment in that sense meets the elastic one
    (stiffness x bend; piecewise linear in the bends; None beyond the largest), and whether the
    C-shape turns away from perpendicular (the sign of tau in that sense: middle leading, tau < 0)."""
    bends = sorted(by_bend)
    straight = by_bend[bends[0]]
    if abs(straight["B"]) < 1e-9 * abs(straight["R_perp"]):  # a local drag: uniform along the rod, no bending load
        return {"sense": "stays straight", "bend_deg": 0.0, "reorients": None}
    sense = 1.0 if straight["B"] > 0 else -1.0
    excess = [sense * by_bend[b]["B"] - stiffness * math.radians(b) for b in bends]
    eq = None
    for k in range(len(bends) - 1):
        if excess[k] > 0 >= excess[k + 1]:
            eq = bends[k] + (bends[k + 1] - bends[k]) * excess[k] / (excess[k] - excess[k + 1])
            break
    taus = [by_bend[b]["tau"] for b in bends if b > 0]
    turns = all(sense * t < 0 for t in taus) if taus else None
    return {"sense": "bends middle leading" if sense > 0 else "bends ends leading", "bend_deg": eq, "reorients": turns}


def write_states(path, res, lev, levels):
    cols = ("lam_perp", "lam_par", "r", "R_perp", "R_par", "B", "tau")
    lines = ["# fig3_bent.py (calibration/tools): rigid 15-sphere rods of bend 0 (straight), 20, 60, 100 deg at "
             "beta 0.83 in the wide slit, resolved (rodIbFoam, campaigns fig3-bent and beta-high, finest mesh; "
             "mesh_change = finest - next coarser) and levels 2-4 (hsrod_crosscheck_scenes); forces over 3 pi mu d U, "
             "moments over 3 pi mu d^2 U; definitions in the tool's docstring",
             "source,case,bend_deg,meshes," + ",".join(cols)]
    for case in sorted(res, key=lambda c: res[c][max(res[c])]["bend"]):
        meshes = sorted(res[case])
        fin = res[case][meshes[-1]]
        b = fin["bend"]
        lines.append("resolved,%s,%g,%s," % (case, b, "/".join(map(str, meshes))) +
                     ",".join("%.6g" % fin[k] for k in cols))
        if len(meshes) > 1:
            co = res[case][meshes[-2]]
            lines.append("mesh_change,%s,%g,%s," % (case, b, "/".join(map(str, meshes))) +
                         ",".join("%.3g" % (fin[k] - co[k]) for k in cols))
        for lv in levels:
            if case in lev.get(lv, {}):
                lines.append("%s,%s,%g,%d," % (lv, case, b, meshes[-1]) +
                             ",".join("%.6g" % lev[lv][case][k] for k in cols))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def print_table(res, lev, levels):
    print("| bend (delta_r) | quantity | resolved (mesh change) | " + " | ".join(LEVEL_NAMES.get(lv, lv) for lv in levels)
          + " |")
    print("| --- | --- | --- | " + " | ".join("---" for _ in levels) + " |")
    for case in sorted(res, key=lambda c: res[c][max(res[c])]["bend"]):
        meshes = sorted(res[case])
        fin = res[case][meshes[-1]]
        co = res[case][meshes[-2]] if len(meshes) > 1 else None
        xs = fin["x"]
        chord = math.hypot(xs[-1][0] - xs[0][0], xs[-1][1] - xs[0][1])
        sag = max(abs((xs[-1][0] - xs[0][0]) * (xs[0][1] - p[1]) - (xs[0][0] - p[0]) * (xs[-1][1] - xs[0][1]))
                  / chord for p in xs)
        length = sum(math.hypot(xs[i + 1][0] - xs[i][0], xs[i + 1][1] - xs[i][1]) for i in range(len(xs) - 1))
        tag = "%g deg (%.3f)" % (fin["bend"], sag / (length * len(xs) / (len(xs) - 1)))
        for k in ("R_perp", "r", "B", "tau"):
            if k == "tau" and fin["bend"] == 0:
                continue
            ch = " (%+.2g %%)" % (100 * (fin[k] - co[k]) / abs(fin[k])) if co else " (one mesh)"
            cells = []
            for lv in levels:
                m = lev.get(lv, {}).get(case)
                cells.append("%.4g (%+.1f %%)" % (m[k], 100 * (m[k] / fin[k] - 1)) if m else "-")
            print("| %s | %s | %.4g%s | %s |" % (tag, k, fin[k], ch, " | ".join(cells)))


def plot(path, res, lev, levels):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = sorted(res, key=lambda c: res[c][max(res[c])]["bend"])
    fig, axes = plt.subplots(1, len(cases), figsize=(3.6 * len(cases), 3.4), sharey=True)
    for ax, case in zip(axes, cases):
        fin = res[case][max(res[case])]
        i = list(range(1, len(fin["q_y"]) + 1))
        ax.plot(i, fin["q_y"], "ko-", label="resolved (mesh %d)" % max(res[case]))
        for lv, st in zip(levels, ("s--", "^-", "v-")):
            if case in lev.get(lv, {}):
                ax.plot(i, lev[lv][case]["q_y"], st, label=LEVEL_NAMES.get(lv, lv), ms=4)
        ax.axhline(0, color="grey", lw=0.5)
        ax.set_title("bend %g deg" % fin["bend"])
        ax.set_xlabel("sphere")
    axes[0].set_ylabel("net load along the stream, $q_y$ / ($3\\pi\\mu d U$)")
    axes[0].legend(fontsize=7)
    fig.suptitle("Fig. 3 rod (15 spheres, $\\beta$ 0.83) across the stream, translating force-free", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--crosscheck", required=True, help="hsrod_crosscheck_scenes")
    ap.add_argument("--campaign", default=os.path.join(ROOT, "calibration", "campaign", "fig3-bent"))
    ap.add_argument("--straight", default=os.path.join(ROOT, "calibration", "campaign", "beta-high"))
    ap.add_argument("--per-sphere", default=os.path.join(ROOT, "calibration", "data",
                                                         "resolved_fig3_bent_per_sphere.csv"))
    ap.add_argument("--states", default=os.path.join(ROOT, "calibration", "data", "fig3_bent_states.csv"))
    ap.add_argument("--plot", default="")
    ap.add_argument("--levels", default="local,nonlocal,twoway")
    ap.add_argument("--elastic", default="2e3:54e-6:0.0465069:1e-3",
                    help="E:d:U:mu of the flexible rod for the equilibrium bend (default: examples/hele-shaw; "
                         "U its gap-mean velocity as fix hele_shaw/drag reports it)")
    ap.add_argument("--no-write", action="store_true", help="read --per-sphere as it is (do not rewrite it)")
    a = ap.parse_args(argv)
    if not a.no_write:
        cases = geometry_cases.load_cases([a.campaign])
        cases.update(straight_cases(a.straight, 15, 0.83))
        geometry_cases.write_csv(cases, a.per_sphere, [
            "'%s'" % os.path.basename(os.path.normpath(a.campaign)),
            "'%s' (its straight row of 15 at beta 0.83, as a bent rod of bend 0)"
            % os.path.basename(os.path.normpath(a.straight))])
    ps = read_per_sphere(a.per_sphere)
    res = resolved_states(ps)
    levels = a.levels.split(",")
    lev = level_states(ps, a.per_sphere, a.crosscheck, levels)
    write_states(a.states, res, lev, levels)
    print_table(res, lev, levels)
    if a.plot:
        plot(a.plot, res, lev, levels)
    E, d, U, mu = (float(v) for v in a.elastic.split(":"))
    k = bend_stiffness(E, d, U, mu, 15)
    print("\nelastic moment per radian of bend (E %g Pa, d %g m, U %g m/s, mu %g Pa s): %.4g" % (E, d, U, mu, k))
    sources = [("resolved", {res[c][max(res[c])]["bend"]: res[c][max(res[c])] for c in res})]
    sources += [(LEVEL_NAMES.get(lv, lv), {res[c][max(res[c])]["bend"]: lev[lv][c] for c in lev.get(lv, {})})
                for lv in levels]
    for name, by_bend in sources:
        p = predicted_state(by_bend, k)
        eq = "beyond %g deg" % max(by_bend) if p["bend_deg"] is None else "%.0f deg" % p["bend_deg"]
        print("%-9s %s, equilibrium bend %s, C-shape %s" % (
            name, p["sense"], eq, {True: "turns away from perpendicular (reorientation)",
                                  False: "turns back to perpendicular", None: "-"}[p["reorients"]]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
