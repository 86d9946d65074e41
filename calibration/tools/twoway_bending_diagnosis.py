#!/usr/bin/env python3
"""twoway_bending_diagnosis: what sets the sign of the flexural load B of level 4
(and level 3) on the straight rows of the resolved campaigns, at the paper's
Fig. 3 scene (15 spheres, beta 0.83) and along beta (fig3_bent.py defines B).

    twoway_bending_diagnosis.py --parts build/hsrod_twoway_load_parts [--plot FILE.png]

Prints four tables (forces over 3 pi mu d U, moments over 3 pi mu d^2 U):
  1. the straight 15-sphere row at beta 0.83 with level 4 taken apart (near
     field off, one coupling for friction and held load) and with its window
     options changed (finer lattice, one scale, gentler grading);
  2. B of the straight rows of n >= 5 of the resolved campaigns (beta 0.1-0.83,
     finest mesh, sphere forces only: the per-sphere table of the straight rows
     has no e_y sphere torques) against levels 3 and 4;
  3. the 45-degree mirror split (fig3_bent.py) against streams along and
     across the chord directly, for B and tau of the four Fig. 3 rods;
  4. the change of R_perp, lambda_perp and B of the straight 15-sphere row for
     a change of one near-field parameter of level 4 at a time;
  5. B against lambda_perp of the straight rows of 10 and 15 at beta 0.83 over
     all variants of levels 3 and 4 (near field on, off, one coupling, one
     parameter changed, finer window): the least-squares line B = a lambda_perp
     + b, each variant's distance from it, and the resolved rod's; then the
     same with every variant's film friction shielded along the rod like its
     obstruction friction (zeta_f S_i / zeta_o in place of zeta_f, S_i the
     sphere's coupled obstruction friction, zeta_o a lone sphere's);
  6. the q profile of the straight 15-sphere row with that film and the held
     load's reflection alpha raised by 0.08 (by hand, not a fit: whether a
     level of that form can have the resolved profile at the resolved
     lambda_perp), and the same construction on the Fig. 3 arcs (R_perp,
     lambda_perp, B, tau from the 45-degree split).
The levels come from hsrod_twoway_load_parts; Python 3 standard library
(matplotlib for --plot)."""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import fig3_bent  # noqa: E402

DATA = os.path.join(ROOT, "calibration", "data")
FIG3 = os.path.join(DATA, "resolved_fig3_bent_per_sphere.csv")
STRAIGHT = "bent_c0_b0.830_n15"
BENT = [STRAIGHT, "bent_c20_b0.830_n15", "bent_c60_b0.830_n15", "bent_c100_b0.830_n15"]


def run_parts(tool, tmp, args, variants):
    """{(variant, load): {quantity: value}} of one hsrod_twoway_load_parts call."""
    out = os.path.join(tmp, "parts_%d.csv" % len(os.listdir(tmp)))
    subprocess.run([tool, args[0], out] + args[1:] + ["--variants", ",".join(variants)], check=True,
                   stdout=subprocess.DEVNULL)
    m = {}
    for r in csv.DictReader(open(out)):
        m.setdefault((r["variant"], r["load"]), {})[r["quantity"]] = float(r["model"])
    return m


def split_states(m, variant, x):
    """fig3_bent.states of one variant's 45-degree friction and driving loads."""
    n = len(x)
    f, h = m[(variant, "friction")], m[(variant, "driving")]
    F = lambda d: [(d["fx_%d" % (i + 1)], d["fy_%d" % (i + 1)]) for i in range(n)]  # noqa: E731
    T = lambda d: [d["tz_%d" % (i + 1)] for i in range(n)]  # noqa: E731
    return fig3_bent.states(x, F(f), F(h), T(f), T(h))


def direct_states(m0, m90, variant, x):
    """B from the stream across the chord (90 deg) and tau from the stream along it (0 deg), directly."""
    n = len(x)
    g = lambda d, c, i: d["f%s_%d" % (c, i + 1)]  # noqa: E731
    h, f = m90[(variant, "driving")], m90[(variant, "friction")]
    lam = sum(g(h, "y", i) for i in range(n)) / sum(g(f, "y", i) for i in range(n))
    mid = (n - 1) // 2
    xm, ym = x[mid]
    w = [0.0 if x[i][0] < xm - 1e-9 else (0.5 if i == mid else 1.0) for i in range(n)]
    B = -sum(w[i] * ((x[i][0] - xm) * (g(h, "y", i) - lam * g(f, "y", i)) - (x[i][1] - ym) *
                     (g(h, "x", i) - lam * g(f, "x", i)) + h["tz_%d" % (i + 1)] - lam * f["tz_%d" % (i + 1)])
             for i in range(n))
    h, f = m0[(variant, "driving")], m0[(variant, "friction")]
    lam_par = sum(g(h, "x", i) for i in range(n)) / sum(g(f, "x", i) for i in range(n))
    cx, cy = sum(p[0] for p in x) / n, sum(p[1] for p in x) / n
    T = lambda d: sum((p[0] - cx) * g(d, "y", i) - (p[1] - cy) * g(d, "x", i) + d["tz_%d" % (i + 1)]  # noqa: E731
                      for i, p in enumerate(x))
    return B, T(h) - lam_par * T(f)


def forces_B(x, held, fric):
    """B of sphere forces across a straight row (x in d): moment of held - lambda friction, right half."""
    n = len(x)
    mid = (n - 1) // 2
    xm = x[mid] if n % 2 else 0.5 * (x[mid] + x[mid + 1])
    w = [0.0 if xi < xm - 1e-9 else (0.5 if n % 2 and i == mid else 1.0) for i, xi in enumerate(x)]
    lam = sum(held) / sum(fric)
    return -sum(wi * (xi - xm) * (h - lam * f) for wi, xi, h, f in zip(w, x, held, fric))


def resolved_rows(paths):
    """{(beta, n): [(mesh, B)]} of the straight touching rows of n >= 5 (per-sphere tables)."""
    data = {}
    for p in paths:
        for r in csv.DictReader(line for line in open(p) if not line.startswith("#")):
            if float(r["spacing_over_d"]) != 1.0 or int(r["n"]) < 5:
                continue
            k = (float(r["beta"]), int(r["n"]), int(r["cells_per_diameter"]))
            data.setdefault(k, {}).setdefault(r["load"], {})[int(r["sphere"])] = (float(r["x_over_d"]), float(r["perp"]))
    out = {}
    for (beta, n, mesh), loads in sorted(data.items()):
        if set(loads) >= {"driving", "friction"}:
            ids = sorted(loads["friction"])
            out.setdefault((beta, n), []).append(
                (mesh, forces_B([loads["friction"][i][0] for i in ids], [loads["driving"][i][1] for i in ids],
                                [loads["friction"][i][1] for i in ids])))
    return out


def resolved_lambda_perp(n, beta=0.83):
    """lambda_perp of beta-high's straight row of n (calibration/data/resolved_beta_high_series.csv)."""
    for row in csv.DictReader(line for line in open(os.path.join(DATA, "resolved_beta_high_series.csv"))
                              if not line.startswith("#")):
        if abs(float(row["beta"]) - beta) < 1e-9 and int(row["n"]) == n and float(row["spacing"]) == 1.0:
            return float(row["lambda_perp"])
    raise KeyError("no resolved row of %d at beta %g" % (n, beta))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--parts", required=True, help="hsrod_twoway_load_parts")
    ap.add_argument("--plot", default="")
    a = ap.parse_args(argv)
    per_sphere = fig3_bent.read_per_sphere(FIG3)
    res = fig3_bent.resolved_states(per_sphere)
    x_of = {c: res[c][max(res[c])]["x"] for c in BENT}
    with tempfile.TemporaryDirectory() as tmp:
        work = os.path.join(tmp, "w")
        os.mkdir(work)
        # 1. the straight row taken apart
        variants = ["l3", "l3_nf_friction_only", "l4", "l4_nf_off", "l4_nf_friction_only", "l4_nf_driving_only",
                    "l4_cpd4_g1.2", "l4_cpd8", "l4_cpd8_rc4", "l4_cpd4_rc4", "l4_cpd6_rc6", "l4_cpd8_rc8",
                    "l4_cpd8_rc8_nf_off"]
        m = run_parts(a.parts, work, [FIG3, "--case", STRAIGHT], variants)
        r = res[STRAIGHT][max(res[STRAIGHT])]
        print("1. straight row, 15 spheres, beta 0.83 (45-degree split as fig3_bent.py)")
        print("| variant | R_perp | lambda_perp | r | B | tau |\n| --- | ---: | ---: | ---: | ---: | ---: |")
        print("| resolved (mesh 16) | %.1f | %.4f | %.4f | %+.3f | 0 |" % (r["R_perp"], r["lam_perp"], r["r"], r["B"]))
        straight = {}
        for v in variants:
            s = straight[v] = split_states(m, v, x_of[STRAIGHT])
            print("| %s | %.1f | %.4f | %.4f | %+.3f | %+.3f |" % (v, s["R_perp"], s["lam_perp"], s["r"], s["B"], s["tau"]))
        # 2. B along beta
        with tempfile.TemporaryDirectory() as coll:
            subprocess.run([sys.executable, os.path.join(HERE, "hsrod_campaign.py"), "collect",
                            os.path.join(ROOT, "calibration", "campaign", "beta-high"), "--csv",
                            os.path.join(coll, "ps.csv"), "--series", os.path.join(coll, "s.csv"), "--profiles",
                            os.path.join(coll, "p.csv")], check=True, stdout=subprocess.DEVNULL)
            rows = resolved_rows([os.path.join(DATA, "resolved_campaign_per_sphere.csv"), os.path.join(coll, "ps.csv")])
        print("\n2. B of straight rows (sphere forces), resolved finest mesh (change from the next coarser) and levels")
        print("| beta | n | resolved | level 3 | level 4 |\n| ---: | ---: | ---: | ---: | ---: |")
        along = []
        for (beta, n), meshes in sorted(rows.items()):
            if beta > 0.85:  # level 4's table stops at 0.85
                continue
            ml = run_parts(a.parts, work, ["-", "--row", "%g:%d" % (beta, n)], ["l3", "l4"])
            xs = [(i - 0.5 * (n - 1), 0.0) for i in range(n)]
            l3, l4 = split_states(ml, "l3", xs)["B"], split_states(ml, "l4", xs)["B"]
            change = meshes[-1][1] - meshes[-2][1] if len(meshes) > 1 else float("nan")
            along.append((beta, n, meshes[-1][1], l3, l4))
            print("| %.2f | %d | %+.4f (%+.4f) | %+.4f | %+.4f |" % (beta, n, meshes[-1][1], change, l3, l4))
        # 3. the mirror split against direct streams
        print("\n3. B and tau of the Fig. 3 rods: 45-degree mirror split / streams across and along the chord directly")
        print("| bend | level | B split | B direct | tau split | tau direct |\n| ---: | --- | ---: | ---: | ---: | ---: |")
        for c in BENT:
            ms = run_parts(a.parts, work, [FIG3, "--case", c], ["l3", "l4", "l4_cpd4_g1.2"])
            m0 = run_parts(a.parts, work, [FIG3, "--case", c, "--angle", "0"], ["l3", "l4", "l4_cpd4_g1.2"])
            m90 = run_parts(a.parts, work, [FIG3, "--case", c, "--angle", "90"], ["l3", "l4", "l4_cpd4_g1.2"])
            for v in ("l3", "l4", "l4_cpd4_g1.2"):
                s = split_states(ms, v, x_of[c])
                B, tau = direct_states(m0, m90, v, x_of[c])
                print("| %g | %s | %+.3f | %+.3f | %+.3f | %+.3f |" % (res[c][max(res[c])]["bend"], v, s["B"], B,
                                                                      s["tau"], tau))
        # 4. near-field sensitivity
        names = {"0": "kappa x 1.1", "1": "alpha + 0.05", "2": "alpha_e + 0.05", "3": "kappa_e x 1.1"}
        sens = ["l4"] + ["l4_p%s%s%s" % (ld, k, "0.1" if k in "03" else "0.05") for ld in "fd" for k in "0123"]
        m = run_parts(a.parts, work, [FIG3, "--case", STRAIGHT], sens)
        base = split_states(m, "l4", x_of[STRAIGHT])
        print("\n4. level 4, straight row of 15 at beta 0.83: one near-field parameter changed")
        print("| coupling | change | R_perp | lambda_perp | B |\n| --- | --- | ---: | ---: | ---: |")
        bars = []
        for v in sens[1:]:
            s = split_states(m, v, x_of[STRAIGHT])
            load = "friction" if v[4] == "f" else "held load"
            bars.append(("%s %s" % (load, names[v[5]]), s["B"] - base["B"]))
            print("| %s | %s | %+.1f | %+.4f | %+.3f |" % (load, names[v[5]], s["R_perp"] - base["R_perp"],
                                                         s["lam_perp"] - base["lam_perp"], s["B"] - base["B"]))
        # 5. B against lambda_perp
        print("\n5. B (sphere forces) against lambda_perp, straight rows at beta 0.83: line over the model variants")
        print("| n | line B = a lambda_perp + b | largest model distance | resolved lambda_perp, B | resolved distance |")
        print("| ---: | --- | ---: | --- | ---: |")
        line_vars = ["l3", "l3_nf_friction_only", "l4", "l4_nf_off", "l4_nf_friction_only", "l4_pf00.1", "l4_pd10.05",
                     "l4_pd00.1", "l4_cpd6_rc6"]
        lone = run_parts(a.parts, work, ["-", "--row", "0.83:1", "--angle", "90"], ["l4"])
        lone_obstruction = lone[("l4", "driving")]["fy_1"] / 1.5  # zeta_o: the held load c zeta_o u, c = 3/2
        lines = {}
        for shielded in (False, True):
            if shielded:
                print("\nfilm friction shielded like the obstruction friction:")
            for n in (10, 15):
                lines[(n, shielded)] = bending_line(a.parts, work, n, line_vars, rows, shielded, lone_obstruction)
        print("\nthe arcs of 60 and 100 deg (B from the 45-degree split, with the sphere torques):")
        for c in BENT[2:]:
            ml = run_parts(a.parts, work, [FIG3, "--case", c], line_vars)
            pts = [(v, split_states(ml, v, x_of[c])) for v in line_vars]
            pts = [(v, st["lam_perp"], st["B"]) for v, st in pts]
            rc = res[c][max(res[c])]
            print_line("%g deg" % rc["bend"], pts, rc["lam_perp"], rc["B"])
        # 6. the shielded film with the held load's alpha raised
        m = run_parts(a.parts, work, [FIG3, "--case", STRAIGHT], ["l4_pd10.08"])
        st = split_states(m, "l4_pd10.08", x_of[STRAIGHT])
        film = m[("l4_pd10.08", "friction")]["film_1"]
        fric = [(f - film) * (1.0 + film / lone_obstruction) for f in st["fric_y"]]
        lam = sum(st["held_y"]) / sum(fric)
        q = [h - lam * f for h, f in zip(st["held_y"], fric)]
        print("\n6. level 4, film scaled like the obstruction, held alpha + 0.08: lambda_perp %.4f, R_perp %.1f, B %+.3f"
              % (lam, sum(fric), forces_B([p[0] for p in x_of[STRAIGHT]], st["held_y"], fric)))
        print("q_y, spheres 1-8:  " + " ".join("%+.3f" % v for v in q[:8]))
        print("resolved:          " + " ".join("%+.3f" % v for v in r["q_y"][:8]))
        print("| bend | resolved R_perp, lambda_perp, B, tau | level 4 with that film and held alpha + 0.08 |")
        print("| ---: | --- | --- |")
        for c in BENT:
            m = run_parts(a.parts, work, [FIG3, "--case", c], ["l4_pd10.08"])
            st = scaled_film_states(m, "l4_pd10.08", x_of[c], lone_obstruction)
            rc = res[c][max(res[c])]
            print("| %g | %.1f, %.4f, %+.3f, %+.2f | %.1f, %.4f, %+.3f, %+.2f |" % (
                rc["bend"], rc["R_perp"], rc["lam_perp"], rc["B"], rc["tau"], st["R_perp"], st["lam_perp"], st["B"],
                st["tau"]))
    if a.plot:
        plot(a.plot, r, straight, along, bars, {n: lines[(n, False)] for n in (10, 15)})


def scaled_film_states(m, variant, x, lone_obstruction):
    """fig3_bent.states of a variant whose friction has its film scaled like its obstruction part: each sphere's
    45-degree friction F_i = zeta_f e + S_i becomes S_i (1 + zeta_f / zeta_o)."""
    n = len(x)
    f, h = m[(variant, "friction")], m[(variant, "driving")]
    film, e = f["film_1"], 0.5 ** 0.5
    F = [((f["fx_%d" % (i + 1)] - film * e) * (1.0 + film / lone_obstruction),
          (f["fy_%d" % (i + 1)] - film * e) * (1.0 + film / lone_obstruction)) for i in range(n)]
    H = [(h["fx_%d" % (i + 1)], h["fy_%d" % (i + 1)]) for i in range(n)]
    return fig3_bent.states(x, F, H, [f["tz_%d" % (i + 1)] for i in range(n)], [h["tz_%d" % (i + 1)] for i in range(n)])


def bending_line(tool, work, n, variants, rows, shielded, lone_obstruction):
    """B against lambda_perp of the variants on the straight row of n at beta 0.83, its line and the resolved
    rod's distance from it (table 5)."""
    ml = run_parts(tool, work, ["-", "--row", "0.83:%d" % n], variants)
    xs = [(i - 0.5 * (n - 1), 0.0) for i in range(n)]
    pts = []
    for v in variants:
        st = split_states(ml, v, xs)
        fric = st["fric_y"]
        if shielded:
            film = ml[(v, "friction")]["film_1"]
            fric = [(f - film) * (1.0 + film / lone_obstruction) for f in fric]
        lam = sum(st["held_y"]) / sum(fric)
        pts.append((v, lam, forces_B([p[0] for p in xs], st["held_y"], fric)))
    lam_res = resolved_lambda_perp(n)
    b_res = rows[(0.83, n)][-1][1]
    slope, icpt = print_line(str(n), pts, lam_res, b_res)
    return pts, slope, icpt, lam_res, b_res


def print_line(label, pts, lam_res, b_res):
    """Least-squares line B = a lambda_perp + b through the variants (name, lambda_perp, B), as a table row."""
    k = len(pts)
    sx, sy = sum(p[1] for p in pts), sum(p[2] for p in pts)
    slope = (k * sum(p[1] * p[2] for p in pts) - sx * sy) / (k * sum(p[1] ** 2 for p in pts) - sx * sx)
    icpt = (sy - slope * sx) / k
    far = max(abs(p[2] - slope * p[1] - icpt) for p in pts)
    print("| %s | %.2f lambda_perp %+.2f | %.3f | %.4f, %+.3f | %+.3f |" % (
        label, slope, icpt, far, lam_res, b_res, b_res - slope * lam_res - icpt))
    return slope, icpt


def plot(path, r, straight, along, bars, lines):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    ax = [axes[0][0], axes[0][1], axes[1][1], axes[1][0]]
    i = list(range(1, len(r["q_y"]) + 1))
    ax[0].plot(i, r["q_y"], "ko-", label="resolved, B %+.2f" % r["B"])
    for v, st, lab in (("l3", "s--", "level 3"), ("l4", "^-", "level 4"), ("l4_cpd8_rc8", "v:", "level 4, d/8 one scale"),
                       ("l4_nf_friction_only", "x-.", "level 4, held load with the friction's near field")):
        ax[0].plot(i, straight[v]["q_y"], st, ms=4, label="%s, B %+.2f" % (lab, straight[v]["B"]))
    ax[0].axhline(0, color="grey", lw=0.5)
    ax[0].set_xlabel("sphere")
    ax[0].set_ylabel("$q_y$ / ($3\\pi\\mu d U$)")
    ax[0].set_title("straight rod, 15 spheres, $\\beta$ 0.83", fontsize=9)
    ax[0].legend(fontsize=6)
    for n, mk in ((10, "o"), (15, "s"), (20, "^"), (5, "d")):
        pts = sorted(p for p in along if p[1] == n)
        if not pts:
            continue
        b = [p[0] for p in pts]
        ls = ("-", "--", ":") if len(pts) > 3 else ("", "", "")  # lines only along a densely run series
        ax[1].plot(b, [p[2] for p in pts], "k" + mk + ls[0], label="resolved n=%d" % n)
        ax[1].plot(b, [p[3] for p in pts], "C0" + mk + ls[1], label="level 3 n=%d" % n, ms=4)
        ax[1].plot(b, [p[4] for p in pts], "C1" + mk + ls[2], label="level 4 n=%d" % n, ms=4)
    ax[1].axhline(0, color="grey", lw=0.5)
    ax[1].axvline(0.75, color="grey", lw=0.5, ls="--")
    ax[1].set_yscale("symlog", linthresh=0.02)
    ax[1].set_xlabel("$\\beta$ (near field fitted up to 0.75)")
    ax[1].set_ylabel("B of straight rows (sphere forces)")
    ax[1].legend(fontsize=6, ncol=2)
    ax[2].barh([b[0] for b in bars], [b[1] for b in bars], color="C1")
    ax[2].axvline(1.517, color="k", lw=0.8, ls="--")
    ax[2].text(1.55, 0, "resolved - level 4", fontsize=7)
    ax[2].tick_params(axis="y", labelsize=7)
    ax[2].set_xlabel("change of level 4's B (straight rod of 15)")
    for n, mk in ((10, "o"), (15, "s")):
        pts, slope, icpt, lam_res, b_res = lines[n]
        lam = [p[1] for p in pts]
        ax[3].plot(lam, [p[2] for p in pts], "C%d" % (n // 15) + mk, ms=5, mfc="none", label="models, n=%d" % n)
        ax[3].plot([min(lam), max(lam)], [slope * min(lam) + icpt, slope * max(lam) + icpt], "C%d-" % (n // 15), lw=0.8)
        ax[3].plot([lam_res], [b_res], "k" + mk, ms=7, label="resolved, n=%d" % n)
        for v, lv, bv in pts:
            if v in ("l3", "l4"):
                ax[3].annotate({"l3": "level 3", "l4": "level 4"}[v], (lv, bv), fontsize=6, xytext=(3, -8),
                               textcoords="offset points")
    ax[3].axhline(0, color="grey", lw=0.5)
    ax[3].set_xlabel("$\\lambda_\\perp$ (force-free velocity across the row / U)")
    ax[3].set_ylabel("B (sphere forces)")
    ax[3].set_title("straight rows at $\\beta$ 0.83: levels 3-4 variants (near field on/off/changed, finer window)",
                    fontsize=8)
    ax[3].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
