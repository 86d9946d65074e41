#!/usr/bin/python3
"""Dynamic pore passage cross-check: one resolved, coupled
rodIbFoam + LIGGGHTS run of a short rod passing a pore against hsrod's
reduced levels 1-4 on the same scene, the paper's measures along x.

    /usr/bin/python3 calibration/validation/pore_passage/run.py BUILD_DIR [--work DIR] [--rerun-resolved]

BUILD_DIR holds calibration/rodIbFoam (configured with -DHSROD_WITH_OPENFOAM=ON)
and hsrod. Steps:
  1. resolved: scene.json -> case (calibration/tools/hsrod_case.py: channel
     with the body-fitted pore, a refined band along the rod's path, the rod
     as create_rod + fix rod/bonds in the coupled LIGGGHTS), run under
     nice -n 10; its rodMeasures.csv becomes resolved.csv, its cost
     resolved_run.json. Skipped when resolved.csv exists (--rerun-resolved
     forces it; ~14 min CPU on one core: 762 s for 226 of its 240 intervals).
  2. reduced: in.passage with model isotropic / local / nonlocal / twoway
     (levels 1-4) -> level<k>_<model>.csv, CPU and wall time of each run.
  3. comparison: measures along x (resolved vs levels 1-4) -> passage.png,
     errors per level and run times -> table.md and the table section of
     README.md.
Environment: export WM_PROJECT_DIR=/usr/share/openfoam (set here if unset).
"""
import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, HERE)
import passage_measures as pm  # noqa: E402

LEVELS = [(1, "isotropic"), (2, "local"), (3, "nonlocal"), (4, "twoway")]


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(cmd, cwd, env=None, log=None):
    """Run cmd; return (returncode, cpu seconds of the children, wall seconds)."""
    c0, w0 = children_cpu(), time.time()
    with open(log or os.devnull, "w") as out:
        rc = subprocess.run(cmd, cwd=cwd, env=env, stdout=out, stderr=subprocess.STDOUT).returncode
    return rc, children_cpu() - c0, time.time() - w0


def run_resolved(build, work):
    case = os.path.join(work, "resolved")
    if os.path.exists(case):
        shutil.rmtree(case)
    subprocess.run([sys.executable, os.path.join(ROOT, "calibration", "tools", "hsrod_case.py"),
                    os.path.join(HERE, "scene.json"), case], check=True)
    env = dict(os.environ, RODIBFOAM=os.path.join(build, "calibration", "rodIbFoam"))
    env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    rc, cpu, wall = timed(["nice", "-n", "10", os.path.join(case, "Allrun")], case, env)
    if rc != 0:
        sys.exit("resolved run failed (%s):\n%s" % (case, open(os.path.join(case, "log.rodIbFoam")).read()[-3000:]))
    collect_resolved(case, cpu, wall, "complete")


def collect_resolved(case, cpu=None, wall=None, state="complete"):
    """resolved.csv, resolved_rodMeasures_raw.csv and resolved_run.json from
    a case; without measured times (a case collected afterwards, e.g. one
    stopped once the rod had left the pore) the solver's own last
    ExecutionTime / ClockTime are used."""
    log = open(os.path.join(case, "log.rodIbFoam")).read()
    if cpu is None:
        last = re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", log)
        cpu = float(last[-1]) if last else float("nan")
        wall = os.path.getmtime(os.path.join(case, "log.rodIbFoam")) - os.path.getmtime(
            os.path.join(case, "log.blockMesh"))
    raw = os.path.join(case, "postProcessing", "rodIbFoam", "rodMeasures.csv")
    shutil.copy(raw, os.path.join(HERE, "resolved_rodMeasures_raw.csv"))
    rows = pm.read_run(raw)
    # v_x/U from the centre's displacement (central difference over two
    # intervals): the DEM velocity at the coupling instants alternates from
    # interval to interval with the exchange's oscillatory root (report:
    # 0.74), the positions do not
    U = pm.scene()["inflow"]["U"]
    for i, r in enumerate(rows):
        a, b = rows[max(0, i - 1)], rows[min(len(rows) - 1, i + 1)]
        r["vx_over_U"] = (b["x_com"] - a["x_com"]) / (b["t"] - a["t"]) / U
    pm.write_run(os.path.join(HERE, "resolved.csv"), rows)
    head = log.split("Starting time loop")[0]
    report = [l.strip() for l in head.splitlines()[-40:] if l.startswith("  ") or "coupled to" in l
              or "momentum exchange" in l]
    cells = re.search(r"cells (\d+)", log)
    meta = {"cpu_s": round(cpu, 1), "wall_s": round(wall, 1), "cells": int(cells.group(1)) if cells else None,
            "coupling_intervals": len(rows) - 1, "report": report,
            "state": state, "t_end_s": rows[-1]["t"], "x_end_m": rows[-1]["x_com"],
            "note": "CPU: rodIbFoam with its coupled LIGGGHTS (+ blockMesh, topoSet, refineMesh when run by "
            "run.py), one core, nice -n 10, machine shared with other jobs (load ~13 on 2 cores)"}
    with open(os.path.join(HERE, "resolved_run.json"), "w") as f:
        json.dump(meta, f, indent=1)
    print("resolved: %d intervals, %.0f s CPU, %.0f s wall" % (len(rows) - 1, cpu, wall))


def run_reduced(build, work, model):
    wdir = os.path.join(work, "reduced")
    os.makedirs(wdir, exist_ok=True)
    out = os.path.join(wdir, "reduced_%s.csv" % model)
    if os.path.exists(out):
        os.remove(out)
    env = dict(os.environ, HSROD_CACHE_DIR=os.path.join(work, "flow-cache"))
    cmd = [os.path.join(build, "hsrod"), "-in", os.path.join(HERE, "in.passage"), "-var", "model", model,
           "-var", "out", out, "-log", os.path.join(wdir, "log.%s" % model), "-screen", "none"]
    # the background flow is solved once per scene and cached: a first run
    # pays it, so time the second run of each model (the solve is reported apart)
    rc, cpu0, wall0 = timed(cmd, wdir, env)
    rc, cpu, wall = timed(cmd, wdir, env)
    if rc != 0:
        sys.exit("reduced run %s failed: %s" % (model, open(os.path.join(wdir, "log.%s" % model)).read()[-2000:]))
    return pm.read_run(out), cpu, wall, cpu0


def plot(ref, runs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    sc = pm.scene()
    xc, R, W = sc["pore"]["x"], sc["pore"]["R"], sc["channel"]["W"]
    panels = [("t", "time t [ms]", 1e3), ("vx_over_U", "$v_x / U$", 1), ("angle_deg", "angle eq. (1) [deg]", 1),
              ("lateral_over_W", "lateral displacement / W", 1), ("deflection", "deflection eq. (2)", 1)]
    fig, axs = plt.subplots(len(panels), 1, figsize=(6.5, 11), sharex=True)
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    for ax, (col, label, s) in zip(axs, panels):
        m = pm.monotone_in_x(ref)
        ax.plot([r["x_com"] * 1e6 for r in m], [r[col] * s for r in m], "k-", lw=2.2, label="resolved (rodIbFoam)")
        for (lev, model), c in zip(LEVELS, colours):
            if model in runs:
                mm = pm.monotone_in_x(runs[model])
                ax.plot([r["x_com"] * 1e6 for r in mm], [r[col] * s for r in mm], "-", color=c, lw=1.2,
                        label="level %d (%s)" % (lev, model))
        ax.axvspan((xc - R) * 1e6, (xc + R) * 1e6, color="0.9", zorder=0)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axs[0].legend(fontsize=8)
    axs[0].set_title("4-sphere rod through a pore (beta = 0.3, pore width %.0f um = 1.5 L_rod)"
                     % ((W - 2 * R) * 1e6), fontsize=9)
    axs[-1].set_xlabel("rod centre x [um] (grey: pore cylinders)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def table(ref, runs, times, resolved_meta):
    sc = pm.scene()
    d = sc["rod"]["d"]
    s_ref = pm.summary(ref, sc)
    lines = ["| run | CPU [s] | wall [s] | max abs dx/d at equal t | t to pore centre | passage time (entry to exit) | "
             "rms / max abs d(v_x/U) along x | rms / max abs d(v_x/U), pore entry to after | max abs d angle [deg] | peak angle [deg] | "
             "max abs d(lateral/W) | lateral/W after the pore | angle after the pore [deg] | max abs d deflection |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    lines.append("| resolved (rodIbFoam + LIGGGHTS, %s cells) | %.0f | %.0f | - | %.3f ms | %.3f ms | - | - | - | "
                 "%.1f | - | %+.4f | %.1f | - |" % (resolved_meta.get("cells"), resolved_meta["cpu_s"],
                                                   resolved_meta["wall_s"], s_ref["t_pore"] * 1e3,
                                                   s_ref["t_pass"] * 1e3, s_ref["peak_angle_deg"],
                                                   s_ref["lateral_after"], s_ref["angle_after"]))
    rows = {}
    for lev, model in LEVELS:
        if model not in runs:
            continue
        s = pm.summary(runs[model], sc)
        e = pm.errors_along_x(runs[model], ref, d, (s["x_in"], s["x_after"]))
        cpu, wall = times[model]
        rows[model] = dict(e, **s)
        lines.append("| level %d (%s) | %.2f | %.2f | %.2f | %.3f ms (%+.1f %%) | %.3f ms (%+.1f %%) | %.3f / %.3f | %.3f / %.3f | "
                     "%.1f | %.1f | %.4f | %+.4f | %.1f | %.2g |"
                     % (lev, model, cpu, wall, e["dx_over_d_max"], s["t_pore"] * 1e3,
                        100 * (s["t_pore"] / s_ref["t_pore"] - 1), s["t_pass"] * 1e3,
                        100 * (s["t_pass"] / s_ref["t_pass"] - 1), e["dvx_rms"], e["dvx_max"],
                        e["dvx_rms_passage"], e["dvx_max_passage"], e["dangle_max"],
                        s["peak_angle_deg"], e["dlateral_max"], s["lateral_after"], s["angle_after"],
                        e["ddefl_max"]))
    return "\n".join(lines) + "\n", rows, s_ref


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--work", default="/tmp/hsrod_pore_passage")
    ap.add_argument("--rerun-resolved", action="store_true")
    ap.add_argument("--resolved-only", action="store_true", help="stop after the resolved run")
    ap.add_argument("--collect-resolved", metavar="CASE", help="take the resolved record from this (finished "
                    "or stopped) case instead of running it")
    ap.add_argument("--stopped", action="store_true", help="with --collect-resolved: the case was stopped early")
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    os.makedirs(a.work, exist_ok=True)
    if a.collect_resolved:
        collect_resolved(a.collect_resolved, state="stopped early" if a.stopped else "complete")
    elif a.rerun_resolved or not os.path.exists(os.path.join(HERE, "resolved.csv")):
        run_resolved(build, a.work)
    else:
        print("resolved: recorded resolved.csv used (--rerun-resolved to recompute)")
    if a.resolved_only:
        return
    ref = pm.read_run(os.path.join(HERE, "resolved.csv"))
    with open(os.path.join(HERE, "resolved_run.json")) as f:
        meta = json.load(f)
    runs, times = {}, {}
    for lev, model in LEVELS:
        rows, cpu, wall, cpu_first = run_reduced(build, a.work, model)
        runs[model], times[model] = rows, (cpu, wall)
        pm.write_run(os.path.join(HERE, "level%d_%s.csv" % (lev, model)), rows)
        print("level %d (%s): %d samples, %.2f s CPU, %.2f s wall (first run incl. background flow solve %.2f s CPU)"
              % (lev, model, len(rows), cpu, wall, cpu_first))
    plot(ref, runs, os.path.join(HERE, "passage.png"))
    text, rows, s_ref = table(ref, runs, times, meta)
    with open(os.path.join(HERE, "table.md"), "w") as f:
        f.write(text)
    with open(os.path.join(HERE, "summary.json"), "w") as f:
        json.dump({"resolved": s_ref, "levels": rows}, f, indent=1)
    readme = os.path.join(HERE, "README.md")
    if os.path.exists(readme):
        body = open(readme).read()
        a0, a1 = "<!-- table begin (run.py) -->", "<!-- table end -->"
        if a0 in body and a1 in body:
            body = body[:body.index(a0) + len(a0)] + "\n" + text + body[body.index(a1):]
            open(readme, "w").write(body)
    print(text)


if __name__ == "__main__":
    main()
