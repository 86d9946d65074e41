#!/usr/bin/python3
"""Resolved pore passages over the confinement beta (series.json) and the
reduced levels on the same scenes: the drift, rotation and passage time of
the paper's Fig. 9, from the resolved runs instead of from the model.

    /usr/bin/python3 calibration/validation/passage_series/run_series.py run BUILD_DIR [--work DIR] [--only TAG]
    /usr/bin/python3 calibration/validation/passage_series/run_series.py compare BUILD_DIR [--work DIR]
    /usr/bin/python3 calibration/validation/passage_series/run_series.py status
    /usr/bin/python3 calibration/validation/passage_series/run_series.py salvage BUILD_DIR --work DIR --only TAG

`run` writes each case's scene (scene_<tag>.json here), builds its case with
calibration/tools/hsrod_case.py in the work directory and runs it under
nice -n 19 (rodIbFoam coupled to LIGGGHTS; BUILD_DIR/calibration/rodIbFoam).
A finished case is recorded in <tag>/ beside this file (resolved.csv,
resolved_rodMeasures_raw.csv, resolved_run.json) and skipped by later runs;
an interrupted case is started again from its beginning, so an interrupted
series loses only the case that was running. A run that stops because the
rod reached the outlet after the passage (the DEM side stops when a sphere
leaves the box) is recorded with a note; `salvage` records such a case from
its work directory without running it again. `compare` runs
../pore_passage/in.passage at levels 2-4 and `auto` on every recorded
scene (<tag>/level_<model>.csv) and writes table.md and series.png.
The beta 0.3 member is ../pore_passage's recorded reference.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
PASSAGE = os.path.join(os.path.dirname(HERE), "pore_passage")
sys.path.insert(0, PASSAGE)
import passage_measures as pm  # noqa: E402
import run as passage_run  # noqa: E402

MODELS = ("local", "nonlocal", "twoway", "auto")


def plan():
    with open(os.path.join(HERE, "series.json")) as f:
        return json.load(f)


def case_scene(p, case):
    """The pore_passage scene with gap height H, the channel lengthened
    upstream by `shift` so the inlet lies inlet_over_H * H before the rod."""
    with open(os.path.join(HERE, p["base_scene"])) as f:
        sc = json.load(f)
    H, H0 = case["H"], sc["channel"]["H"]
    upstream0 = sc["rod"]["centre"][0]
    shift = max(0.0, p["inlet_over_H"] * H - upstream0)
    sc["channel"]["H"] = H
    sc["channel"]["L"] += shift
    sc["pore"]["x"] += shift
    sc["rod"]["centre"] = [sc["rod"]["centre"][0] + shift, sc["rod"]["centre"][1], 0.5 * H]
    lo, hi = sc["refine"]["box"]
    sc["refine"]["box"] = [[lo[0] + shift, lo[1], lo[2]], [hi[0] + shift, hi[1], hi[2] - H0 + H]]
    sc["mesh"]["h"] = p["mesh_h"]
    sc["ib"]["minCellsPerDiameter"] = p["min_cells_per_diameter"]
    # the rod moves at ~1.2-1.5 U: the extra upstream length adds shift / U of
    # travel; a more confined rod is slower (paper Fig. 9d), ~ beta^-1/2 here
    beta, beta0 = sc["rod"]["d"] / H, sc["rod"]["d"] / H0
    sc["control"]["end_time"] = (sc["control"]["end_time"] + shift / sc["inflow"]["U"]) * max(1.0, beta / beta0) ** 0.5
    return sc


def scene_path(tag):
    return os.path.join(HERE, "scene_%s.json" % tag)


def recorded(tag):
    return os.path.exists(os.path.join(HERE, tag, "resolved.csv"))


def reached_outlet(case_dir, sc):
    """A note when a run that stopped early had carried the rod past the
    passage measures' last point and to the outlet (its DEM side stops when a
    sphere leaves the box), else None: the run then holds all it was for."""
    raw = os.path.join(case_dir, "postProcessing", "rodIbFoam", "rodMeasures.csv")
    if not os.path.exists(raw):
        return None
    rows = pm.read_run(raw)
    rod_length = sc["rod"]["n"] * sc["rod"]["d"]
    x_end, x_after = rows[-1]["x_com"], sc["pore"]["x"] + 2.0 * sc["pore"]["R"]
    if x_end < x_after + sc["rod"]["d"] or x_end < sc["channel"]["L"] - rod_length:
        return None
    return ("the run stopped at t = %.4g s when the rod reached the outlet (centre x = %.4g m, channel L = %.4g m), "
            "past the last passage measure (x_after = %.4g m)" % (rows[-1]["t"], x_end, sc["channel"]["L"], x_after))


def salvage(build, work, tag):
    """Records a case that stopped at the outlet without running it again:
    CPU from rodIbFoam's own ExecutionTime, wall from its logs' times."""
    case_dir = os.path.join(work, tag)
    with open(scene_path(tag)) as f:
        sc = json.load(f)
    note = reached_outlet(case_dir, sc)
    if note is None:
        sys.exit("run_series.py salvage: %s did not carry the rod to the outlet; run it again" % case_dir)
    log_path = os.path.join(case_dir, "log.rodIbFoam")
    cpu = [float(l.split("=")[1].split()[0]) for l in open(log_path) if l.startswith("ExecutionTime")][-1]
    wall = os.path.getmtime(log_path) - os.path.getmtime(os.path.join(case_dir, "log.blockMesh"))
    os.environ["RODIBFOAM"] = os.path.join(build, "calibration", "rodIbFoam")  # the binary that ran it
    meta = collect(case_dir, tag, sc, cpu, wall, note + "; CPU = rodIbFoam's ExecutionTime, wall from the logs' times")
    print("%s: recorded, %d intervals, %.0f s CPU, %.0f s wall" % (tag, meta["coupling_intervals"], cpu, wall))


def collect(case_dir, tag, sc, cpu, wall, note=None):
    out = os.path.join(HERE, tag)
    os.makedirs(out, exist_ok=True)
    raw = os.path.join(case_dir, "postProcessing", "rodIbFoam", "rodMeasures.csv")
    shutil.copy(raw, os.path.join(out, "resolved_rodMeasures_raw.csv"))
    rows = pm.read_run(raw)
    U = sc["inflow"]["U"]
    for i, r in enumerate(rows):   # v_x from the centre's displacement, as ../pore_passage/run.py
        a, b = rows[max(0, i - 1)], rows[min(len(rows) - 1, i + 1)]
        r["vx_over_U"] = (b["x_com"] - a["x_com"]) / (b["t"] - a["t"]) / U
    pm.write_run(os.path.join(out, "resolved.csv"), rows)
    log = open(os.path.join(case_dir, "log.rodIbFoam")).read()
    head = log.split("Starting time loop")[0]
    meta = {"cpu_s": round(cpu, 1), "wall_s": round(wall, 1), "beta": sc["rod"]["d"] / sc["channel"]["H"],
            "coupling_intervals": len(rows) - 1, "t_end_s": rows[-1]["t"], "x_end_m": rows[-1]["x_com"],
            "report": [l.strip() for l in head.splitlines()[-40:] if l.startswith("  ")],
            "solver_sha256": subprocess.run(["sha256sum", os.environ["RODIBFOAM"]], capture_output=True,
                                            text=True).stdout.split()[0],
            "commit": subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True,
                                     text=True).stdout.strip(),
            "note": "CPU of rodIbFoam with its coupled LIGGGHTS (+ mesh tools), one core, nice -n 19, on a machine "
                    "shared with other jobs" + ("; " + note if note else "")}
    with open(os.path.join(out, "resolved_run.json"), "w") as f:
        json.dump(meta, f, indent=1)
    return meta


def run_case(build, work, case, p):
    tag = case["tag"]
    sc = case_scene(p, case)
    with open(scene_path(tag), "w") as f:
        json.dump(sc, f, indent=1)
    case_dir = os.path.join(work, tag)
    if os.path.exists(case_dir):
        shutil.rmtree(case_dir)   # an interrupted case starts again
    subprocess.run([sys.executable, os.path.join(ROOT, "calibration", "tools", "hsrod_case.py"), scene_path(tag),
                    case_dir], check=True)
    os.environ["RODIBFOAM"] = os.path.join(build, "calibration", "rodIbFoam")
    os.environ.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    print("%s: beta %.3f, H %.3g m, running in %s" % (tag, sc["rod"]["d"] / sc["channel"]["H"], sc["channel"]["H"],
                                                     case_dir), flush=True)
    rc, cpu, wall = passage_run.timed(["nice", "-n", "19", os.path.join(case_dir, "Allrun")], case_dir,
                                      dict(os.environ))
    note = None
    if rc != 0:
        note = reached_outlet(case_dir, sc)
        if note is None:
            sys.exit("%s failed (%s):\n%s" % (tag, case_dir, open(os.path.join(case_dir, "log.rodIbFoam")).read()[-3000:]))
    meta = collect(case_dir, tag, sc, cpu, wall, note)
    print("%s: recorded, %d intervals, %.0f s CPU, %.0f s wall" % (tag, meta["coupling_intervals"], cpu, wall),
          flush=True)


def members():
    """(tag, scene, resolved rows) of every recorded member, beta 0.3 included."""
    out = [("beta0.3", pm.scene(), pm.read_run(os.path.join(PASSAGE, "resolved.csv")))]
    for case in plan()["cases"]:
        if recorded(case["tag"]):
            with open(scene_path(case["tag"])) as f:
                sc = json.load(f)
            out.append((case["tag"], sc, pm.read_run(os.path.join(HERE, case["tag"], "resolved.csv"))))
    return sorted(out, key=lambda m: m[1]["rod"]["d"] / m[1]["channel"]["H"])


def reduced(build, work, tag, sc, model):
    wdir = os.path.join(work, "reduced", tag)
    os.makedirs(wdir, exist_ok=True)
    out = os.path.join(wdir, "level_%s.csv" % model)
    ch = sc["channel"]
    cmd = [os.path.join(build, "hsrod"), "-in", os.path.join(PASSAGE, "in.passage"), "-var", "model", model,
           "-var", "out", out, "-var", "gap", repr(ch["H"]), "-var", "length", repr(ch["L"]),
           "-var", "pore_x", repr(sc["pore"]["x"]), "-var", "x0", repr(sc["rod"]["centre"][0]),
           "-var", "tend", repr(sc["control"]["end_time"]), "-log", os.path.join(wdir, "log.%s" % model),
           "-screen", "none"]
    env = dict(os.environ, HSROD_CACHE_DIR=os.path.join(work, "flow-cache"))
    rc, cpu, wall = passage_run.timed(cmd, wdir, env)
    if rc != 0:
        sys.exit("reduced %s %s failed: %s" % (tag, model, open(os.path.join(wdir, "log.%s" % model)).read()[-2000:]))
    dest = os.path.join(HERE, tag)
    os.makedirs(dest, exist_ok=True)
    shutil.copy(out, os.path.join(dest, "level_%s.csv" % model))
    return pm.read_run(out), cpu


def compare(build, work):
    lines = ["| beta | run | CPU [s] | passage time [ms] | rotation in the pore [deg] | lateral/W after the pore |",
             "| ---: | --- | ---: | ---: | ---: | ---: |"]
    series = {}
    for tag, sc, ref in members():
        beta = sc["rod"]["d"] / sc["channel"]["H"]
        s = pm.summary(ref, sc)
        series.setdefault("resolved", []).append((beta, s))
        lines.append("| %.3g | resolved | - | %.4f | %.2f | %+.4f |" % (beta, s["t_pass"] * 1e3, s["rotation"],
                                                                       s["lateral_after"]))
        for model in MODELS:
            rows, cpu = reduced(build, work, tag, sc, model)
            m = pm.summary(rows, sc)
            series.setdefault(model, []).append((beta, m))
            lines.append("| %.3g | %s | %.2f | %.4f (%+.1f %%) | %.2f (%+.2f) | %+.4f (%+.4f) |"
                         % (beta, model, cpu, m["t_pass"] * 1e3, 100 * (m["t_pass"] / s["t_pass"] - 1),
                            m["rotation"], m["rotation"] - s["rotation"], m["lateral_after"],
                            m["lateral_after"] - s["lateral_after"]))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(HERE, "table.md"), "w") as f:
        f.write(text)
    plot(series, os.path.join(HERE, "series.png"))
    print(text)


def plot(series, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(11, 3.4))
    for ax, (key, label, scale) in zip(axs, (("t_pass", "passage time [ms]", 1e3),
                                             ("rotation", "rotation in the pore [deg]", 1),
                                             ("lateral_after", "lateral displacement / W after the pore", 1))):
        for name, rows in series.items():
            style = dict(color="k", lw=2.2, marker="o") if name == "resolved" else dict(lw=1.1, marker=".")
            ax.plot([b for b, _ in rows], [s[key] * scale for _, s in rows], label=name, **style)
        ax.set_xlabel("beta = d / H")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axs[0].legend(fontsize=8)
    fig.suptitle("4-sphere stiff rod through the pore: resolved (rodIbFoam + LIGGGHTS) against hsrod", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("action", choices=("run", "compare", "status", "salvage"))
    ap.add_argument("build", nargs="?")
    ap.add_argument("--work", default="/tmp/hsrod_passage_series")
    ap.add_argument("--only", help="run only this case tag")
    a = ap.parse_args()
    p = plan()
    if a.action == "status":
        for case in p["cases"]:
            print("%-10s %s" % (case["tag"], "recorded" if recorded(case["tag"]) else "to run"))
        return
    if not a.build:
        sys.exit("run_series.py %s: BUILD_DIR is required" % a.action)
    if a.action == "salvage":
        if not a.only:
            sys.exit("run_series.py salvage: --only TAG is required")
        salvage(os.path.abspath(a.build), os.path.abspath(a.work), a.only)
        return
    build, work = os.path.abspath(a.build), os.path.abspath(a.work)
    os.makedirs(work, exist_ok=True)
    if a.action == "run":
        for case in p["cases"]:
            if (a.only and case["tag"] != a.only) or recorded(case["tag"]):
                continue
            run_case(build, work, case, p)
    else:
        compare(build, work)


if __name__ == "__main__":
    main()
