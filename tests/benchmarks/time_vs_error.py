#!/usr/bin/env python3
"""time_vs_error: each level's run time against its error to the resolved
reference, for the Hele-Shaw and the pore scene, as a
table (printed, and markdown with --markdown) and one plot (PNG).

Scenes and what each error is measured against:

  Hele-Shaw (examples/hele-shaw/in.velocity_beta at beta 0.3): a rigid rod
    of 15 spheres released across (alpha 0) and along (alpha 90) the flow in
    a wide channel; its steady velocity over the local gap-averaged flow
    (vx_over_uc) is compared with the resolved force-free velocity of the
    same rod (rodIbFoam campaign, beta 0.3, N = 15, role heldout: lambda_perp,
    lambda_par, calibration/data/resolved_campaign_series.csv). Error = the
    larger of the two relative errors; r = U_perp / U_par error beside it.
    Run time: CPU time of the whole `hsrod` process (median of --runs runs
    of each orientation, the two orientations summed).
    Resolved cost: the CPU time of the campaign's two runs that give these
    velocities (friction and held load of the rod on the finest mesh; the
    velocity of a rigid rod needs nothing more: Stokes flow is linear).

  Pore (tests/benchmarks/bench_pore_passage, the paper's pore passage of a
    10-sphere rod at beta 0.15): no resolved run of this passage exists
    (calibration/validation/pore_passage has one of a smaller scene). The
    error against the resolved reference is that of the level's transport of
    the same rod (10 spheres, beta 0.15) away from the pore: the largest
    error of its totals (friction and held load along and across) and of its
    force-free velocity against the campaign, from the cross-check record
    (calibration/data/level_error_record.csv). The passage's difference from
    level 3 at a 10x smaller step (the benchmark's own counters) is printed
    beside it and is a model difference, not an error to the resolved run.
    Run time: the benchmark's CPU time of the passage (median of --runs
    repetitions). Stock LIGGGHTS (explicit DEM, its largest stable step) is
    the same program's row. Resolved cost: an estimate, the campaign's
    measured CPU time of one configuration of this rod (friction + held load,
    finest mesh) times the configurations of a coupled passage with the rod
    moving at most 0.1 d per coupling interval (370 um / 0.3 um); a lower
    bound (the pore mesh is larger than the campaign's slit box).

  Coupled passage (calibration/validation/pore_passage/in.passage: a 4-sphere
    rod at beta 0.3 through a small pore, the scene of the one resolved,
    coupled rodIbFoam + LIGGGHTS passage, resolved.csv): each level's own
    dynamic passage against the resolved one. Error = the largest relative
    error of the paper's three measures (passage_measures.summary): passage
    time from pore entry to exit, rotation in the pore (peak angle - initial
    angle) and lateral displacement / W after the pore, each relative to the
    resolved value (the lateral one is small, +0.0049 W, so its relative
    error dominates). Run time: CPU time of the whole `hsrod` process
    (median of --runs runs, the flow field cached by a first run). Resolved
    cost and error: the run's measured CPU time (resolved_run.json) and its
    numerical uncertainty, the change of each measure over the last halving
    of its CFD step (and of its mesh where a finer run is recorded:
    resolved_uncertainty.json). Level 3 with the walls' images
    (wall_reflection images) and with their reflections (wall_reflection
    reflections) are rows of their own ("3 + images", "3 + reflections").

  Near wall (time_vs_error_near_wall.py): static loads 1 d from a side wall
    and from a pore cylinder against the held-out resolved near-wall cases.

Usage: time_vs_error.py BUILD_DIR OUT.png [--runs 3] [--markdown OUT.md] [--skip-pore] [--skip-passage]
                        [--skip-near-wall] [--skip-twoway]
Python 3 + matplotlib (Debian).
"""
import argparse
import csv
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile

from time_vs_error_near_wall import near_wall

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(ROOT, "calibration", "data")
LEVELS = (("isotropic", 1), ("local", 2), ("nonlocal", 3), ("twoway", 4))
PASSAGE_CONFIGURATIONS = 370e-6 / 0.3e-6  # passage length over 0.1 d per coupling interval


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def resolved_series(beta, n):
    for r in read_rows(os.path.join(DATA, "resolved_campaign_series.csv")):
        if abs(float(r["beta"]) - beta) < 1e-9 and int(r["n"]) == n and float(r["spacing"]) == 1.0:
            return r
    return None


def resolved_cost(beta, n):
    """CPU seconds of the finest-mesh friction and driving runs of (beta, n)."""
    by = {}
    for r in read_rows(os.path.join(DATA, "resolved_campaign_per_sphere.csv")):
        if abs(float(r["beta"]) - beta) < 1e-9 and int(r["n"]) == n and float(r["spacing_over_d"]) == 1.0:
            by[(r["load"], int(r["cells_per_diameter"]))] = float(r["cpu_s"])
    meshes = sorted({m for (_, m) in by if ("friction", m) in by and ("driving", m) in by})
    if not meshes:
        return None, None
    m = meshes[-1]
    return by[("friction", m)] + by[("driving", m)], m


def child_cpu():
    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def run_hele_shaw(build, model, alpha, runs):
    """(median CPU s, vx_over_uc) of in.velocity_beta at beta 0.3."""
    inp = os.path.join(ROOT, "examples", "hele-shaw", "in.velocity_beta")
    times, v = [], None
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(runs):
            c0 = child_cpu()
            out = subprocess.run([os.path.join(build, "hsrod"), "-in", inp, "-var", "beta", "0.3", "-var", "alpha",
                                  str(alpha), "-var", "model", model, "-log", "none", "-echo", "none"],
                                 cwd=tmp, capture_output=True, text=True)
            times.append(child_cpu() - c0)
            m = re.search(r"ROD_VELOCITY .* vx_over_uc (\S+)", out.stdout)
            if out.returncode != 0 or not m:
                sys.exit("time_vs_error: hsrod %s alpha %s failed:\n%s" % (model, alpha, out.stdout[-2000:] + out.stderr[-2000:]))
            v = float(m.group(1))
    return statistics.median(times), v


def hele_shaw(build, runs, levels):
    ref = resolved_series(0.3, 15)
    if ref is None:
        sys.exit("time_vs_error: no resolved rod of 15 spheres at beta 0.3 in resolved_campaign_series.csv")
    lam_perp, lam_par = float(ref["lambda_perp"]), float(ref["lambda_par"])
    rows = []
    for model, level in levels:
        t_perp, v_perp = run_hele_shaw(build, model, 0, runs)
        t_par, v_par = run_hele_shaw(build, model, 90, runs)
        e_perp, e_par = v_perp / lam_perp - 1, v_par / lam_par - 1
        rows.append({"scene": "Hele-Shaw", "level": level, "model": model, "cpu_s": t_perp + t_par,
                     "error": max(abs(e_perp), abs(e_par)),
                     "detail": "U_perp %+.2f %%, U_par %+.2f %%, r %+.3f %%" % (
                         100 * e_perp, 100 * e_par, 100 * ((v_perp / v_par) / (lam_perp / lam_par) - 1))})
    cost, mesh = resolved_cost(0.3, 15)
    unc = max(float(ref["lambda_perp_u"]) / lam_perp, float(ref["lambda_par_u"]) / lam_par)
    rows.append({"scene": "Hele-Shaw", "level": "resolved", "model": "rodIbFoam", "cpu_s": cost, "error": unc,
                 "detail": "2 steady runs at %d cells per d (measured); error = change from d/h 6 to %d" % (mesh, mesh)})
    return rows


def pore(build, runs, levels):
    bench = os.path.join(build, "tests", "benchmarks", "bench_pore_passage")
    names = "|".join("level%d_%s" % (lv, m) for m, lv in levels)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "bench.json")
        r = subprocess.run([bench, "--benchmark_filter=BM_StockLiggghts|BM_ImplicitPassage/(%s)/" % names,
                            "--benchmark_repetitions=%d" % runs, "--benchmark_out=%s" % out,
                            "--benchmark_out_format=json"], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("time_vs_error: bench_pore_passage failed:\n" + r.stderr[-3000:])
        with open(out) as f:
            bj = json.load(f)
    med = {}
    for b in bj["benchmarks"]:
        name = b["run_name"].replace("/iterations:1", "")
        if b.get("aggregate_name") == "median":
            med[name] = b
        elif runs == 1 and b.get("run_type") == "iteration":
            med[name] = b
    record = {(int(r["level"]), float(r["beta"]), int(r["n"])): r
              for r in read_rows(os.path.join(DATA, "level_error_record.csv"))}
    rows = []
    for model, level in levels:
        b = med.get("BM_ImplicitPassage/level%d_%s" % (level, model))
        if b is None:
            continue
        rec = record.get((level, 0.15, 10))
        unit = 1e-3 if b["time_unit"] == "ms" else 1.0
        err = max(float(rec["force_error"]), float(rec["velocity_error"])) if rec else float("nan")
        rows.append({"scene": "pore", "level": level, "model": model, "cpu_s": b["cpu_time"] * unit, "error": err,
                     "detail": "rigid rod N = 10, beta 0.15 vs resolved: loads %.1f %%, velocity %.2f %%; passage vs "
                               "level 3 at 4e-7 s (model difference): %.3f d, %.2f deg, %.4f W" % (
                                   100 * float(rec["force_error"]), 100 * float(rec["velocity_error"]),
                                   b["err_x_d"], b["err_angle_deg"], b["err_lateral_W"])})
    b = med.get("BM_StockLiggghts/manual_time")
    if b:
        unit = 1e-3 if b["time_unit"] == "ms" else 1.0
        rows.append({"scene": "pore", "level": "stock", "model": "stock LIGGGHTS (explicit)",
                     "cpu_s": b["real_time"] * unit, "error": float("nan"),
                     "detail": "LIGGGHTS loop time, 220 000 steps of 2e-8 s; a different model (no flow field): "
                               "%.3f d, %.4f W from level 3" % (b["err_x_d"], b["err_lateral_W"])})
    cost, mesh = resolved_cost(0.15, 10)
    if cost:
        rows.append({"scene": "pore", "level": "resolved", "model": "rodIbFoam (estimate)",
                     "cpu_s": cost * PASSAGE_CONFIGURATIONS, "error": float("nan"),
                     "detail": "%.0f s CPU per configuration (N = 10, beta 0.15, %d cells per d, measured) x %.0f "
                               "configurations (0.1 d per coupling interval); lower bound" % (
                                   cost, mesh, PASSAGE_CONFIGURATIONS)})
    return rows


PASSAGE = os.path.join(ROOT, "calibration", "validation", "pore_passage")
PASSAGE_MEASURES = (("t_pass", "passage time"), ("rotation", "rotation in the pore"),
                    ("lateral_after", "lateral after the pore"))
PASSAGE_UNITS = {"t_pass": (1e3, "%.3f ms"), "rotation": (1.0, "%.2f deg"), "lateral_after": (1.0, "%+.4f W")}


def coupled_passage(build, runs, levels):
    sys.path.insert(0, PASSAGE)
    import passage_measures as pm
    sc = pm.scene()
    ref = pm.summary(pm.read_run(os.path.join(PASSAGE, "resolved.csv")), sc)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, HSROD_CACHE_DIR=os.path.join(tmp, "cache"))
        # level 3 with the walls' images or their reflections (wall_reflection) beside the levels as shipped
        variants = [(m, lv, "none") for m, lv in levels] + [("nonlocal", "3 + images", "images"),
                                                            ("nonlocal", "3 + reflections", "reflections")]
        for model, level, reflection in variants:
            out = os.path.join(tmp, "%s_%s.csv" % (model, reflection))
            cmd = [os.path.join(build, "hsrod"), "-in", os.path.join(PASSAGE, "in.passage"), "-var", "model", model,
                   "-var", "reflection", reflection, "-var", "out", out, "-log", "none", "-screen", "none"]
            times = []
            for k in range(runs + 1):  # the first run solves and caches the background flow: not timed
                c0 = child_cpu()
                r = subprocess.run(cmd, cwd=tmp, env=env, capture_output=True, text=True)
                if r.returncode != 0:
                    sys.exit("time_vs_error: in.passage %s failed:\n%s" % (model, r.stdout[-2000:] + r.stderr[-2000:]))
                if k:
                    times.append(child_cpu() - c0)
            got = pm.summary(pm.read_run(out), sc)
            errs = {k: got[k] / ref[k] - 1 for k, _ in PASSAGE_MEASURES}
            rows.append({"scene": "coupled passage", "level": level, "model": model,
                         "cpu_s": statistics.median(times), "error": max(abs(e) for e in errs.values()),
                         "detail": "; ".join("%s %s vs %s (%+.1f %%)" % (
                             name, PASSAGE_UNITS[k][1] % (got[k] * PASSAGE_UNITS[k][0]),
                             PASSAGE_UNITS[k][1] % (ref[k] * PASSAGE_UNITS[k][0]), 100 * errs[k])
                             for k, name in PASSAGE_MEASURES)})
    with open(os.path.join(PASSAGE, "resolved_run.json")) as f:
        meta = json.load(f)
    unc_path = os.path.join(PASSAGE, "resolved_uncertainty.json")
    with open(unc_path) as f:
        unc = json.load(f)
    rel = {k: abs(unc["uncertainty"][k] / ref[k]) for k, _ in PASSAGE_MEASURES}
    rows.append({"scene": "coupled passage", "level": "resolved", "model": "rodIbFoam + LIGGGHTS",
                 "cpu_s": float(meta["cpu_s"]), "error": max(rel.values()),
                 "detail": "measured CPU; error = its numerical uncertainty (%s): %s" % (
                     unc["what"], ", ".join("%s %.1f %%" % (name, 100 * rel[k]) for k, name in PASSAGE_MEASURES))})
    return rows


def fmt_err(e):
    return "-" if e != e else "%.2f %%" % (100 * e)


def table(rows):
    lines = ["| scene | level | CPU time | error to the resolved reference | what |", "|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %s | %s | %s |" % (r["scene"], r["level"], "%.3g s" % r["cpu_s"] if r["cpu_s"] else "-",
                                                   fmt_err(r["error"]), r["detail"]))
    return "\n".join(lines)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 5))
    marks = {"Hele-Shaw": "o", "pore": "s", "coupled passage": "^", "near wall": "D"}
    colours = {1: "tab:blue", 2: "tab:orange", 3: "tab:green", "3 + images": "tab:olive", "3 + reflections": "tab:cyan",
               4: "tab:red",
               "resolved": "black", "stock": "grey"}
    floor = 1e-4
    for r in rows:
        if not r["cpu_s"]:
            continue
        e = r["error"]
        if e != e:  # no error to the resolved reference: a vertical line at its cost
            ax.axvline(r["cpu_s"], color=colours[r["level"]], ls="--" if r["level"] == "stock" else ":", lw=1)
            ax.text(r["cpu_s"], 0.6, " %s, %s scene" % (r["model"], r["scene"]), rotation=90, va="top", fontsize=7,
                    transform=ax.get_xaxis_transform())
            continue
        label = ("level %s" % r["level"]) if r["level"] not in ("resolved", "stock") else r["model"]
        ax.scatter(r["cpu_s"], max(e, floor) * 100, marker=marks[r["scene"]], color=colours[r["level"]], s=50,
                   label="%s, %s scene" % (label, r["scene"]))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("CPU time [s] (median of several runs; resolved: measured / estimated)")
    ax.set_ylabel("error to the resolved reference [%]")
    ax.set_title("hsrod levels: run time against error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("png")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--markdown")
    ap.add_argument("--skip-pore", action="store_true")
    ap.add_argument("--skip-passage", action="store_true")
    ap.add_argument("--skip-near-wall", action="store_true")
    ap.add_argument("--skip-twoway", action="store_true", help="leave level 4 out (its pore passage takes minutes)")
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    levels = [l for l in LEVELS if not (a.skip_twoway and l[1] == 4)]
    rows = hele_shaw(build, a.runs, levels)
    if not a.skip_pore:
        rows += pore(build, a.runs, levels)
    if not a.skip_passage:
        rows += coupled_passage(build, a.runs, levels)
    if not a.skip_near_wall:
        rows += near_wall(build, a.runs, a.skip_twoway)
    text = table(rows)
    print(text)
    plot(rows, a.png)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write(text + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
