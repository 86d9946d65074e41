#!/usr/bin/env python3
"""hsrod_campaign: the resolved calibration campaign as one command.

Generates (hsrod_case.py, scene kind slitBody) and runs rodIbFoam cases of
straight rows of spheres at the mid-plane of a wide slit (rigid rods of N
touching spheres, sphere pairs at a spacing), each

  - dragged through fluid at rest  (load "friction": lab velocity -U e), and
  - held in plane Poiseuille flow   (load "driving": gap-mean velocity U e),

over a list of beta = d/H and a mesh series (cells per diameter); a series
may also be a bent (C-shaped) rod in the slit or a rigid row near a side
wall or beside a pore cylinder of a channel (series key "geometry", see
GEOMETRIES in campaign_plan.py: lab-frame drag towards the wall, held in
the channel flow). The load direction e is at 45 degrees to the row (0 for
a lone sphere): Stokes flow is linear and a wide slit isotropic in its
plane, so one run gives the parallel (x) and the perpendicular (y) response
of every sphere on the same mesh.
Each finished case is one JSON file in OUT/results/ (written atomically:
temporary file, fsync, rename) with the per-sphere force and torque, the
mesh, the run's iterations and cost and its provenance. A campaign that is
interrupted (Ctrl-C, kill, --max-cases) resumes where it stopped: finished
cases are skipped, an unfinished case is recomputed from scratch.

Usage:
  hsrod_campaign.py plan   [--plan PLAN.json]            cases, cells, estimated cost
  hsrod_campaign.py run    OUT [--plan PLAN.json] [--solver RODIBFOAM] [--max-cases K]
                                 [--only SUBSTRING] [--keep-cases]
  hsrod_campaign.py status OUT [--plan PLAN.json]          done / missing per case
  hsrod_campaign.py collect OUT [OUT ...] --csv FILE [--json FILE] [--points FILE]
                           [--series FILE] [--profiles FILE] [--mesh FILE.md]
                                 per-sphere table of the finished cases of every OUT (result
                                 JSON files, and cases kept only as a per-sphere record:
                                 OUT/per_sphere_record.csv) and the mesh-series summaries
                                 (campaign_analysis.py); the command that writes
                                 calibration/data: calibration/campaign/README.md

PLAN.json (default: the built-in session plan, DEFAULT_PLAN in campaign_plan.py):
  {"name": "...", "d": 3e-6, "U": 1e-3, "mu": 1e-3, "rho": 1000,
   "mesh": {...hsrod_case slitBody mesh keys...}, "control": {...},
   "series": [{"beta": 0.3, "n": 10, "spacing": 1, "meshes": [6, 8],
               "loads": ["friction", "driving"], "role": "fit"}, ...]}
Cases run in the order of the series list (priority order). Python 3
standard library only.
"""
import argparse
import datetime
import hashlib
import json
import math
import os
import platform
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CASE_TOOL = os.path.join(HERE, "hsrod_case.py")
sys.path.insert(0, HERE)
import hsrod_case  # noqa: E402  (the case generator: same directory)
# the plan and its cases (callers also use hsrod_campaign.case_spec)
from campaign_plan import case_spec, expand, load_plan, scene_of  # noqa: E402,F401

SCHEMA = "hsrod-campaign-case 1"


def make_case(scene, case):
    """Write the case of `scene` (hsrod_case.py); returns its (estimated) cell count."""
    return hsrod_case.KINDS[scene["kind"]](scene, case)


def cell_count(spec):
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.devnull, "w") as dn:
            old, sys.stdout = sys.stdout, dn
            try:
                return make_case(scene_of(spec), tmp)
            finally:
                sys.stdout = old


# Cost model: CPU seconds ~ c cells^1.5 (iterations grow like the cells
# across the body); c measured on the reference machine (one core, idle
# other core; README). Updated from the finished cases of a run.
COST_C = 2.0e-6


def predicted_cost(cells, c=COST_C):
    return c * cells ** 1.5


# The plain budget rule (campaign README): 1.6e-6 s CPU per cell-iteration
# (median of the beta-range cases) x ~80 pseudo-time iterations.
COST_PER_CELL_ITERATION, TYPICAL_ITERATIONS = 1.6e-6, 80


def budget_cost(cells):
    return COST_PER_CELL_ITERATION * TYPICAL_ITERATIONS * cells


# ---------------------------------------------------------------- provenance
def sha256_file(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def git_state():
    try:
        commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True, text=True,
                                check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--", "calibration"],
                               capture_output=True, text=True).stdout.strip() != ""
        return commit, dirty
    except (OSError, subprocess.CalledProcessError):
        return "unknown", True


def provenance(solver):
    commit, dirty = git_state()
    return {"solver": solver, "solver_sha256": sha256_file(solver), "git_commit": commit,
            "calibration_tree_dirty": dirty, "hsrod_case_sha256": sha256_file(CASE_TOOL),
            "host": platform.node(), "machine": platform.machine(), "cpus": os.cpu_count(),
            "openfoam": "Debian openfoam (ESI v1912), WM_PROJECT_DIR=%s"
                        % os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam")}


# ---------------------------------------------------------------- results
def result_path(out, cid):
    return os.path.join(out, "results", cid + ".json")


def write_atomic(path, obj):
    d = os.path.dirname(path)
    os.makedirs(d, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=".json", dir=d)
    try:
        with os.fdopen(fd, "w") as f:
            json.dump(obj, f, indent=1)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def read_result(path):
    try:
        with open(path) as f:
            r = json.load(f)
        return r if r.get("schema") == SCHEMA else None
    except (OSError, ValueError):
        return None


def parse_loads(case, spec):
    """Per-sphere loads: the Aitken-extrapolated steady loads when the
    solver wrote them, and the raw loads of the last iteration."""
    pp = os.path.join(case, "postProcessing", "rodIbFoam")
    rows = [l.strip().split(",") for l in open(os.path.join(pp, "sphereForces.csv")) if not l.startswith("#")]
    head, rows = rows[0], rows[1:]
    col = {k: i for i, k in enumerate(head)}
    t_last = rows[-1][col["t"]]
    raw = {int(r[col["id"]]): r for r in rows if r[col["t"]] == t_last}
    ext = {}
    ex_path = os.path.join(pp, "sphereLoadsExtrapolated.csv")
    ex_note = None
    if os.path.exists(ex_path):
        lines = open(ex_path).read().splitlines()
        ex_note = lines[0].lstrip("# ")
        eh = lines[1].split(",")
        for l in lines[2:]:
            v = l.split(",")
            ext[int(v[0])] = [float(v[eh.index(k)]) for k in ("Fx", "Fy", "Fz", "Tx", "Ty", "Tz")]
    spheres = []
    for sid in sorted(raw):
        r = raw[sid]
        fr = [float(r[col[k]]) for k in ("Fx", "Fy", "Fz", "Tx", "Ty", "Tz")]
        fe = ext.get(sid, fr)
        spheres.append({"id": sid, "x": [float(r[col[k]]) for k in ("x", "y", "z")],
                        "F": fe[:3], "T": fe[3:], "F_last_iteration": fr[:3], "T_last_iteration": fr[3:]})
    return spheres, ex_note


def stop_group(proc, grace_s=10.0):
    """Stop the case's process group (Allrun and the solver it started) and
    wait until every member is gone: the shell can exit before the solver,
    which would go on writing into a case directory a resumed run rebuilds."""
    try:
        os.killpg(proc.pid, signal.SIGTERM)
    except ProcessLookupError:
        return
    proc.wait()
    t0 = time.time()
    while True:
        try:
            os.killpg(proc.pid, signal.SIGKILL if time.time() - t0 > grace_s else 0)
        except ProcessLookupError:
            return
        time.sleep(0.05)


def fresh_dir(path):
    """An empty directory at `path` (a leftover writer may still add files
    while it is removed: retry)."""
    for _ in range(50):
        shutil.rmtree(path, ignore_errors=True)
        try:
            os.makedirs(path)
            return
        except FileExistsError:
            time.sleep(0.1)
    raise RuntimeError("cannot make a fresh case directory %s" % path)


def run_case(spec, out, solver, keep):
    case = os.path.join(out, "cases", spec["id"])
    attempts = []
    for relax in (spec["control"].get("relax_U", 0.95), 0.9, 0.8):
        fresh_dir(case)
        scene = scene_of(spec)
        scene["control"]["relax_U"] = relax
        with open(os.devnull, "w") as dn:
            old, sys.stdout = sys.stdout, dn
            try:
                cells_est = make_case(scene, case)
            finally:
                sys.stdout = old
        with open(os.path.join(case, "scene.json"), "w") as f:
            json.dump(scene, f, indent=1)
        t0, c0 = time.time(), os.times()
        proc = subprocess.Popen([os.path.join(case, "Allrun")], env=dict(os.environ, RODIBFOAM=solver),
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
        try:
            proc.communicate()
        except BaseException:
            stop_group(proc)
            raise
        wall = time.time() - t0
        c1 = os.times()
        cpu = (c1.children_user - c0.children_user) + (c1.children_system - c0.children_system)
        log = open(os.path.join(case, "log.rodIbFoam")).read() if os.path.exists(
            os.path.join(case, "log.rodIbFoam")) else ""
        summ = [l for l in log.splitlines() if l.startswith("rodIbFoam:")]
        steady = "steady state reached" in log
        attempts.append({"relax_U": relax, "exit": proc.returncode, "steady": steady, "wall_s": round(wall, 2)})
        if proc.returncode == 0 and steady and summ:
            break
    else:
        raise RuntimeError("case %s did not converge: %s" % (spec["id"], attempts))
    words = summ[0].split()
    iterations, cells = int(words[1]), int(words[3])
    spheres, ex_note = parse_loads(case, spec)
    if not all(math.isfinite(c) for s in spheres for c in s["F"] + s["T"]):
        raise RuntimeError("case %s: non-finite loads" % spec["id"])
    result = {"schema": SCHEMA, "id": spec["id"], "spec": spec, "scene": scene,
              "mesh": {"cells": cells, "cells_per_diameter": spec["cells_per_diameter"],
                       "generator_cells": cells_est, "blockMeshDict": open(os.path.join(
                           case, "system", "blockMeshDict")).read().split("blocks", 1)[1].split("edges")[0].strip()},
              "run": {"iterations": iterations, "cpu_s": round(cpu, 2), "wall_s": round(wall, 2),
                      "relax_U": relax, "attempts": attempts, "steady_state": True,
                      "extrapolation": ex_note or "none (raw loads of the last iteration)"},
              "spheres": spheres,
              "provenance": dict(provenance(solver), date_utc=datetime.datetime.now(
                  datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"))}
    write_atomic(result_path(out, spec["id"]), result)
    if not keep:
        for entry in os.listdir(case):
            p = os.path.join(case, entry)
            if entry[0].isdigit() and entry != "0" and os.path.isdir(p):
                shutil.rmtree(p)           # the written fields: large, not needed
        shutil.rmtree(os.path.join(case, "constant", "polyMesh"), ignore_errors=True)
    return result


# ---------------------------------------------------------------- commands
def fmt_s(s):
    return "%dh%02dm" % (s // 3600, (s % 3600) // 60) if s >= 3600 else "%dm%02ds" % (s // 60, s % 60)


def cmd_plan(a):
    plan = load_plan(a.plan)
    cases = expand(plan)
    total = total_budget = 0.0
    print("%-58s %-8s %9s %10s %10s" % ("case", "role", "cells", "est CPU", "budget"))
    for c in cases:
        cells = cell_count(c)
        cost, budget = predicted_cost(cells), budget_cost(cells)
        total += cost
        total_budget += budget
        print("%-58s %-8s %9d %10s %10s" % (c["id"], c["role"], cells, fmt_s(cost), fmt_s(budget)))
    print("%d cases, estimated %s CPU on one core of the reference machine (cost model CPU = %.3g cells^1.5 s); "
          "budget rule cells x %.2g s x %d iterations: %s"
          % (len(cases), fmt_s(total), COST_C, COST_PER_CELL_ITERATION, TYPICAL_ITERATIONS, fmt_s(total_budget)))


def cmd_status(a):
    plan = load_plan(a.plan)
    cases = expand(plan)
    done = 0
    for c in cases:
        r = read_result(result_path(a.out, c["id"]))
        done += r is not None
        print("%-58s %s" % (c["id"], "done (%d cells, %d it, %.0f s CPU)" % (
            r["mesh"]["cells"], r["run"]["iterations"], r["run"]["cpu_s"]) if r else "missing"))
    print("%d of %d cases done" % (done, len(cases)))


def cmd_run(a):
    solver = os.path.abspath(a.solver or os.environ.get("RODIBFOAM", ""))
    if not os.path.isfile(solver):
        sys.exit("hsrod_campaign: rodIbFoam not found (--solver or RODIBFOAM; got '%s')" % solver)
    os.environ.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    plan = load_plan(a.plan)
    cases = expand(plan)
    if a.only:
        cases = [c for c in cases if a.only in c["id"]]
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "plan.json"), "w") as f:
        json.dump(plan, f, indent=1)
    todo = [c for c in cases if read_result(result_path(a.out, c["id"])) is None]
    print("hsrod_campaign: %d cases, %d done, %d to run; results in %s" % (
        len(cases), len(cases) - len(todo), len(todo), os.path.join(a.out, "results")), flush=True)
    for c in cases:
        if c not in todo:
            print("  skip (done): %s" % c["id"], flush=True)
    # keep Ctrl-C / kill from leaving anything but complete result files
    def on_term(*_):
        raise KeyboardInterrupt()
    signal.signal(signal.SIGTERM, on_term)
    current = [None]
    try:
        return run_all(a, todo, cases, solver, current)
    except KeyboardInterrupt:
        print("hsrod_campaign: interrupted in %s (no result written); run again to resume" % current[0],
              flush=True)
        return 130


def run_all(a, todo, cases, solver, current):
    c_fit, ran, t_start = COST_C, 0, time.time()
    est = {c["id"]: cell_count(c) for c in todo}
    for k, c in enumerate(todo):
        if a.max_cases is not None and ran >= a.max_cases:
            print("hsrod_campaign: stopped after --max-cases %d; run again to resume" % a.max_cases, flush=True)
            return 0
        remaining = sum(predicted_cost(est[x["id"]], c_fit) for x in todo[k:])
        print("[%d/%d] %s (%d cells): running; remaining ~%s CPU" % (
            k + 1, len(todo), c["id"], est[c["id"]], fmt_s(remaining)), flush=True)
        current[0] = c["id"]
        try:
            r = run_case(c, a.out, solver, a.keep_cases)
        except RuntimeError as e:
            print("hsrod_campaign: FAILED %s: %s" % (c["id"], e), flush=True)
            continue
        ran += 1
        c_fit = r["run"]["cpu_s"] / est[c["id"]] ** 1.5 if ran == 1 else 0.5 * (
            c_fit + r["run"]["cpu_s"] / est[c["id"]] ** 1.5)
        print("[%d/%d] %s: done, %d iterations, %.1f s CPU, %.1f s wall (campaign %s wall)" % (
            k + 1, len(todo), c["id"], r["run"]["iterations"], r["run"]["cpu_s"], r["run"]["wall_s"],
            fmt_s(time.time() - t_start)), flush=True)
    print("hsrod_campaign: all %d cases done" % len(cases), flush=True)
    return 0


def cmd_collect(a):
    import campaign_analysis  # numpy; same directory
    return campaign_analysis.collect(a.out, a.csv, a.json, a.points, a.series, a.profiles, a.mesh)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("plan")
    p.add_argument("--plan")
    p = sub.add_parser("status")
    p.add_argument("out")
    p.add_argument("--plan")
    p = sub.add_parser("run")
    p.add_argument("out")
    p.add_argument("--plan")
    p.add_argument("--solver")
    p.add_argument("--max-cases", type=int)
    p.add_argument("--only")
    p.add_argument("--keep-cases", action="store_true")
    p = sub.add_parser("collect")
    p.add_argument("out", nargs="+")
    p.add_argument("--csv", required=True)
    p.add_argument("--json")
    p.add_argument("--points")
    p.add_argument("--series")
    p.add_argument("--profiles")
    p.add_argument("--mesh")
    a = ap.parse_args(argv)
    return {"plan": cmd_plan, "status": cmd_status, "run": cmd_run, "collect": cmd_collect}[a.cmd](a) or 0


if __name__ == "__main__":
    sys.exit(main())
