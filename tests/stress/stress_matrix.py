#!/usr/bin/env python3
"""Stress and fuzz matrix for hsrod.

Runs build/hsrod on generated input scripts of the pore scene and classifies
each case:
  passed   exit code 0, every thermo value finite, no atom lost, the largest
           bond strain below 0.5 and the rod inside the box;
  refused  a non-zero exit code with an "ERROR:" line naming the problem;
  failed   anything else: a crash (signal, no ERROR line), a hang past the
           time bound (CPU seconds, --timeout; 6x that in wall time), or exit
           code 0 with non-finite or lost output.
A generated family of combinations (extreme moduli, viscosities, inflows,
pore openings, spacings; each value accepted alone) is judged further: a
refusal must name the varied keyword and must not blame the timestep or
name options the fix does not accept, and a run with exit code 0 must move
the rod (else "silent"); both count as failed.
Usage:  stress_matrix.py HSROD [--short] [--family all|combinations] [--out RESULTS.md] [--jobs N] [--progress FILE]
--short is the ctest subset (label `stress`, < 2 min); the default is the
full matrix. Exit code 1 if any case failed. --progress appends each case's
line to FILE as it finishes and skips the cases FILE already holds (a long
run can be read while it goes and resumed after an interruption); a later
line of a case replaces an earlier one. --rerun REGEX re-runs the matching
cases unless FILE holds them from this very binary (e.g. after a fix).
"""
import argparse
import hashlib
import concurrent.futures
import itertools
import math
import os
import re
import resource
import signal
import subprocess
import sys
import tempfile
import threading

SCENE = """units si
atom_style hybrid granular molecular
atom_modify map array sort 0 0
boundary f f f
newton off
communicate single cutoff {cutoff} vel yes
neighbor {skin} nsq
region box block 0 {length} 0 200e-6 0 {gap} units box
create_box 1 box
create_rod spheres {n} diameter {d} type 1 density 1170 centre {xc} {yc} {zc} angle {angle}
fix bonds all rod/bonds youngs_modulus {E} timestep_check no
fix drag all hele_shaw/drag reynolds 2 fluid_density 1170 {pore} model {model} {extra_drag}
fix step all rod/implicit bonds bonds drag drag {extra_step}
compute shape all rod/shape
thermo_style custom step f_step[1] f_step[4] f_step[5] c_shape[2] c_shape[3] c_shape[7]
thermo {thermo}
timestep {dt}
run {steps}
"""


# Largest rod speed in these scenes [m/s]: the mean flow at reynolds 2 is
# ~0.06 m/s, a rod moves at up to ~1.5x it (measured: 0.09 m/s at beta 0.3).
ROD_SPEED_BOUND = 0.15


def scene(dt=4e-6, beta=0.15, E=15e6, n=10, model="local", angle=0, steps=50, **over):
    """The paper's pore scene (W 200 um, a pore of 30 um between two cylinders
    R = 85 um at x = 300 um) with the rod across the flow (along y) at
    x = 100 um. A rod longer than the channel is wide (N = 200: 600 um) lies
    along the flow instead, in a channel lengthened by the rod's length: its
    downstream end 200 um before the pore. N = 10 000 (a 30 mm rod) lies along
    a straight channel without a pore (the pore scene's background grid
    would need ~70 GB and is refused), long enough for the rod to stay inside
    it for the run's physical time (steps x dt at ROD_SPEED_BOUND). In the
    pore scenes a rod that reaches the channel's end stops there (the
    trajectory check compares every output time, not only the last)."""
    d = 3e-6
    gap = d / beta if not isinstance(beta, str) else beta
    rod = n * d  # [m]
    try:
        travel = ROD_SPEED_BOUND * steps * float(over.get("dt", dt))  # [m]
        travel = travel if math.isfinite(travel) and travel > 0 else 0.0
    except (TypeError, ValueError):
        travel = 0.0
    pore = True
    if rod < 200e-6:
        length, xc, pore_x = 600e-6, 100e-6, 300e-6
    else:
        angle = float(angle) + 90 if str(angle) not in ("nan", "inf") else angle
        xc = rod / 2 + 10 * d
        pore_x = xc + rod / 2 + 200e-6
        length = pore_x + 100e-6
        pore = rod < 1e-3
        if not pore:
            length = xc + rod / 2 + travel + 50e-6
    # yc: 1 um (0.5 % of W) off the centre line. In a mirror-symmetric scene
    # a rod pinned at both cylinders sits on an unstable equilibrium that it
    # leaves when round-off has grown, at a time (and to a side) set by the
    # round-off and the step: dt = 1e-4 s and dt/10 left it 1-2 outputs apart
    # (y 100 vs 126 um), level 3 to the other side (74 um). The offset lets
    # the physics choose, and the trajectory check compare like with like.
    p = dict(dt=dt, gap=gap, zc=gap / 2, yc=101e-6, E=E, n=n, d=d, model=model, angle=angle, length=length,
             steps=steps, thermo=max(1, steps // 5), xc=xc,
             pore=f"pore 85e-6 {pore_x}" if pore else "",
             cutoff=2 * d, skin=0.3 * d, extra_drag="", extra_step="")
    if rod >= 200e-6 and model == "nonlocal":
        # Level 3 at N = 200 costs ~2.5 s per evaluation here (dense 600 x 600
        # coupling and a dense 1200 x 1200 step): 2 steps, the accuracy guard's
        # substeps down to dt/4 (else up to 2047 evaluations before its refusal).
        p.update(steps=2, thermo=1, extra_step="max_substeps 4")
    p.update(over)
    return SCENE.format(**p)


# A case's wall-clock bound over its CPU bound: the machine is shared (load
# up to ~10 on 2 cores while the matrix runs beside other work).
WALL_OVER_CPU = 6


def time_bound(text, timeout):
    """The case's CPU time bound [s]: `timeout`, three times it for level 3 at N = 200."""
    return 3 * timeout if "max_substeps 4" in text else timeout


def classify(hsrod, text, timeout):
    length = float(re.search(r"region box block 0 (\S+)", text).group(1))
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.case")
        with open(path, "w") as f:
            f.write(text)
        env = dict(os.environ, HSROD_CACHE_DIR=os.path.join(tempfile.gettempdir(), "hsrod-stress-cache"))
        # The bound is on the case's CPU time (RLIMIT_CPU: SIGXCPU past it),
        # which the load of a shared machine does not stretch; a case that
        # waits without working (a deadlock) meets the wall bound instead.
        cpu = int(math.ceil(timeout))
        try:
            r = subprocess.run([hsrod, "-in", path, "-log", "none"], cwd=tmp, env=env,
                               capture_output=True, text=True, errors="backslashreplace",
                               timeout=WALL_OVER_CPU * timeout,
                               preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5)))
        except subprocess.TimeoutExpired:
            return "failed", f"hang: no result within {WALL_OVER_CPU * timeout:g} s wall"
        if r.returncode in (-signal.SIGXCPU, -signal.SIGKILL):
            return "failed", f"hang: no result within {cpu} s CPU"
    out = r.stdout + r.stderr
    errors = [l for l in out.splitlines() if l.startswith("ERROR")]
    if r.returncode != 0:
        if errors and r.returncode > 0:
            return "refused", errors[0][:600]
        return "failed", f"rc {r.returncode} without a clean ERROR line"
    if errors:
        return "failed", "rc 0 but an ERROR line: " + errors[0][:120]
    rows = re.findall(r"^\s*\d+\s+(.*)$", out, re.M)
    values = []
    for row in rows:
        try:
            values.append([float(v) for v in row.split()])
        except ValueError:
            pass
    if not values:
        return "failed", "rc 0 without thermo output"
    if any(not math.isfinite(v) for row in values for v in row):
        return "failed", "rc 0 with non-finite output"
    if "Lost atoms" in out or "lost" in out.lower() and "atoms" in out.lower() and "WARNING" in out:
        return "failed", "rc 0 with lost atoms"
    strain = max(row[2] for row in values if len(row) > 2)
    if strain > 0.5:
        return "failed", f"rc 0 with bond strain {strain:.3g}"
    x = values[-1][3] if len(values[-1]) > 3 else 0.0
    if not (0.0 <= x <= length):
        return "failed", f"rc 0 with the rod centre outside the box (x = {x:.3g} m)"
    return "passed", f"strain {strain:.2g}, x {x * 1e6:.0f} um", [row[3:6] for row in values]


# The trajectory check. A passed case is run again over the same physical
# time with a step REFINE times smaller (REFINE_COSTLY for level 3 at
# N = 200 and for N = 10 000). The implicit step is first order, so the
# difference estimates the case's own step error to within 1/REFINE (1/4).
# Tolerance: 5 % of what the rod did (its displacement along and across the
# channel, its turn) plus one sphere diameter / 2 degrees. That is below the
# reduced model's own error against the resolved runs (3-10 %, see
# calibration/validation/crosscheck.md), so
# a large step costs no more accuracy than the model already lacks.
REFINE, REFINE_COSTLY = 10, 4
REFINE_SECOND = 4  # the second reference, when the first disagrees: dt/40 (dt/16)
REL_TOL, ABS_TOL_POS, ABS_TOL_ANGLE = 0.05, 3e-6, 2.0  # [-], [m], [deg]


def refined(text, k):
    """The same scene over the same physical time with a step k times smaller."""
    dt = float(re.search(r"^timestep (\S+)", text, re.M).group(1))
    steps = int(re.search(r"^run (\d+)", text, re.M).group(1))
    thermo = int(re.search(r"^thermo (\d+)", text, re.M).group(1))
    text = re.sub(r"^timestep \S+", f"timestep {dt / k!r}", text, flags=re.M)
    text = re.sub(r"^run \d+", f"run {steps * k}", text, flags=re.M)
    return re.sub(r"^thermo \d+", f"thermo {thermo * k}", text, flags=re.M)


def trajectory_error(case, reference):
    """'' if the case's state at every output time is within tolerance of the
    reference's at the same time, else why not (the first time it is not)."""
    if len(case) != len(reference):
        return f"{len(case)} output rows vs {len(reference)}"
    x0, y0, a0 = case[0]
    for row, (values, ref) in enumerate(zip(case, reference)):
        why = []
        for name, v, vr, v0, floor, unit, scale in (("x", values[0], ref[0], x0, ABS_TOL_POS, "um", 1e6),
                                                     ("y", values[1], ref[1], y0, ABS_TOL_POS, "um", 1e6),
                                                     ("angle", values[2], ref[2], a0, ABS_TOL_ANGLE, "deg", 1.0)):
            tol = REL_TOL * abs(vr - v0) + floor
            if abs(v - vr) > tol:
                why.append(f"{name} {v * scale:.4g} vs {vr * scale:.4g} {unit} (tolerance {tol * scale:.2g})")
        if why:
            return f"output {row} of {len(case) - 1}: " + "; ".join(why)
    return ""


def largest_difference(case, reference):
    """The largest differences in x, y [m] and angle [deg] over the output times."""
    return [max(abs(c[i] - r[i]) for c, r in zip(case, reference)) for i in range(3)]


def check(hsrod, name, text, timeout):
    """Classify one case and, when it passed, check its trajectory against the refined run."""
    r = classify(hsrod, text, time_bound(text, timeout))
    if name in EXPECTED_KEYWORD:
        verdict = combination_verdict(hsrod, text, time_bound(text, timeout), (name,) + r, EXPECTED_KEYWORD[name])
        if verdict[1] != r[0] or verdict[1] == "refused":
            return verdict
    if r[0] != "passed":
        return (name,) + r
    k = REFINE_COSTLY if ("max_substeps 4" in text or "spheres 10000 " in text) else REFINE
    ref = classify(hsrod, refined(text, k), k * time_bound(text, timeout))
    if ref[0] != "passed":
        return name, "failed", f"the dt/{k} reference did not pass: {ref[0]}: {ref[1]}"
    err = trajectory_error(r[2], ref[2])
    if err:
        # A rod held by friction at the cylinders can end in one of several
        # stuck states, chosen by its path: a reference one refinement away
        # may sit in another one. Judge against a second, finer reference: the
        # case passes only if it agrees with it AND the two references
        # disagree with each other (the coarser one is not converged). If the
        # references agree, the case is off a converged reference: failed.
        k2 = REFINE_SECOND * k
        fine = classify(hsrod, refined(text, k2), k2 * time_bound(text, timeout))
        if fine[0] != "passed":
            return name, "failed", f"trajectory off the dt/{k} reference: {err}; the dt/{k2} reference: {fine[1]}"
        refs_differ = trajectory_error(ref[2], fine[2])
        err2 = trajectory_error(r[2], fine[2])
        if err2 or not refs_differ:
            return name, "failed", f"trajectory off the dt/{k} reference: {err}; vs dt/{k2}: {err2 or 'agrees with dt/' + str(k)}"
        dx, dy, da = largest_difference(r[2], fine[2])
        return (name, "passed", f"{r[1]}; multi-stable: vs dt/{k2}: dx {dx * 1e6:.2g} um, dy {dy * 1e6:.2g} um, "
                f"dangle {da:.2g} deg (dt/{k} ends elsewhere: {refs_differ})")
    dx, dy, da = largest_difference(r[2], ref[2])
    return name, "passed", f"{r[1]}; vs dt/{k}: dx {dx * 1e6:.2g} um, dy {dy * 1e6:.2g} um, dangle {da:.2g} deg"


# Combinations of values each keyword accepts alone (extreme moduli,
# viscosities, inflows, pore openings, spacings). Each case names the
# keyword(s) a refusal must name; a refusal that blames the timestep or
# names options the fix does not accept is misleading, and a run that ends
# with exit code 0 but a rod that did not move is silent nonsense: both
# count as failed (combination_verdict).
MISLEADING = re.compile(r"cell_size|cells_per_wall_layer|cells_across_opening|raise the flow|coarsen the grid|"
                        r"json\.exception")
# A refusal whose advice is a smaller timestep is right when the scene at
# dt/10 passes; when it does not, the step was blamed for another cause.
BLAMES_STEP = re.compile(r"smaller timestep")
EXPECTED_KEYWORD = {}  # case name -> regex the refusal must contain


def combinations(short):
    """(name, scene, keyword regex, expected rod motion [m]) of the generated
    family. The motion is the scene's ~4 um over its 20 steps (U ~ 0.05 m/s
    at reynolds 2), scaled with the case's inflow; below 1e-10 m the thermo
    output (8 digits of x ~ 1e-4 m) cannot show it."""
    family = []
    moduli = ["1e13", "1e15", "1e16", "1e18", "1e20", "1e25", "1e50", "1e100", "1e200", "1e299", "1e300"]
    viscosities = ["1e-300", "1e-9", "1e-6", "1e-2", "1", "1e2", "1e8", "1e9", "1e300"]
    inflows = [("mean_velocity", v) for v in ("1e-12", "1e-6", "1", "100", "1e3", "1e300")] + \
              [("flow_rate", v) for v in ("1e-20", "1e-9", "1e-6", "1e300")] + \
              [("reynolds", v) for v in ("1e-9", "100", "2300", "3000", "1e300")]
    pores = ["90e-6", "95e-6", "98e-6", "98.4e-6", "98.6e-6", "99e-6", "99.9e-6"]
    spacings = ["0", "1e-9", "1e-6", "2.9e-6", "3e-6", "4.5e-6", "6e-6", "3e-5"]
    if short:
        moduli, viscosities, pores, spacings = ["1e25", "1e100", "1e300"], ["1e-300", "1e8"], ["99.9e-6"], ["1e-6"]
        inflows = [("reynolds", "1e300"), ("flow_rate", "1e300")]
    for E in moduli:
        family.append((f"combination youngs_modulus {E}", scene(E=E, steps=20), r"youngs_modulus", 4e-6))
    for mu in viscosities:
        family.append((f"combination viscosity {mu} with reynolds 2",
                       scene(steps=20, extra_drag=f"viscosity {mu}"), r"viscosity", 4e-6 * float(mu) / 1e-3))
    for key, value in inflows:
        text = scene(steps=20).replace("hele_shaw/drag reynolds 2 ", f"hele_shaw/drag {key} {value} ")
        U = {"mean_velocity": float(value), "flow_rate": float(value) / (200e-6 * 20e-6),
             "reynolds": 0.0295 * float(value) / 2}[key]
        family.append((f"combination {key} {value}", text, key, 20 * 4e-6 * U))
    for R in pores:
        family.append((f"combination pore {R}", scene(steps=20, pore=f"pore {R} 300e-6"), r"pore|opening", 4e-6))
    for sp in spacings:
        family.append((f"combination spacing {sp}", scene(steps=20, angle=f"0 spacing {sp}"), r"spacing", 4e-6))
    return family


def combination_verdict(hsrod, text, timeout, result, expected):
    """A combination case's result, failed when its refusal misleads or its
    run silently froze (moved less than a tenth of its expected motion)."""
    name, kind, why = result[:3]
    keyword, motion = expected
    if kind == "refused":
        if BLAMES_STEP.search(why) and not MISLEADING.search(why):
            finer = classify(hsrod, refined(text, 10), 10 * timeout)
            if finer[0] == "passed":
                return name, kind, why + " (dt/10 passes: the advice holds)"
            return name, "failed", f"misleading error: blames the step, but dt/10 fails too ({finer[1]}): {why}"
        if MISLEADING.search(why) or not re.search(keyword, why):
            return name, "failed", f"misleading error (must name {keyword!r}): {why}"
    elif kind == "passed" and len(result) > 3:
        rows = result[3]
        moved = max(abs(r[0] - rows[0][0]) + abs(r[1] - rows[0][1]) for r in rows)
        if motion > 1e-10 and moved < 0.1 * motion:
            return name, "failed", f"silent: exit code 0 but the rod moved {moved:.3g} m of ~{motion:.3g} m ({why})"
    return name, kind, why


def matrix(short):
    cases = []
    if short:
        for dt, beta, E, n, model in [
            (4e-6, 0.15, 15e6, 10, "local"), (1e-3, 0.15, 15e6, 10, "local"),
            (4e-6, 0.85, 15e6, 10, "auto"), (4e-6, 0.95, 15e6, 10, "auto"),
            (2e-6, 0.15, 1.5e12, 10, "nonlocal"), (1e-5, 0.3, 15e3, 5, "isotropic"),
            (4e-6, 0.15, 15e6, 200, "auto"), (4e-6, 0.6, 15e9, 2, "local"),
            # A guard for level 4's kept resistance: carrying the fine
            # lattice's sub-cell noise of each sphere's self term, it turns
            # this 2-sphere rod ~3 deg more at dt/10 than at dt past the
            # pore (-5.58 vs -2.87 deg).
            (1e-4, 0.85, 15e3, 2, "twoway"),
        ]:
            cases.append((f"dt={dt} beta={beta} E={E} N={n} model={model}", scene(dt, beta, E, n, model, steps=20)))
    else:
        # Level 4 last: its cases cost the most (window factorisations).
        for models in (["isotropic", "local", "nonlocal", "auto"], ["twoway"]):
            for dt, beta, E, n, model in itertools.product(
                    [2e-6, 1e-5, 1e-4, 1e-3], [0.05, 0.3, 0.6, 0.85, 0.95], [15e3, 15e6, 15e9, 1.5e12],
                    [2, 5, 50, 200, 10000], models):
                cases.append((f"dt={dt} beta={beta} E={E} N={n} model={model}",
                              scene(dt, beta, E, n, model, steps=20)))
    # Generated bad input: every numeric keyword of the scene x {nan, inf, 0, -1}.
    bad = ["nan", "inf", "0", "-1"]
    keys = {"E": "youngs_modulus", "angle": "angle", "dt": "timestep", "xc": "centre x", "zc": "centre z",
            "gap": "box height"}
    for key, value in itertools.product(keys if not short else ["E", "angle", "dt"], bad if not short else ["nan", "-1"]):
        cases.append((f"{keys[key]} = {value}", scene(steps=5, **{key: value})))
    for name, text, keyword, motion in combinations(short):
        EXPECTED_KEYWORD[name] = (keyword, motion)
        cases.append((name, text))
    return cases


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("hsrod")
    ap.add_argument("--short", action="store_true")
    ap.add_argument("--family", choices=("all", "combinations"), default="all",
                    help="combinations: only the generated family of combinations (RESULTS_combinations.md)")
    ap.add_argument("--out")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--progress")
    ap.add_argument("--rerun", metavar="REGEX",
                    help="cases whose name matches count as done only if recorded with this very binary "
                         "(its sha256 in the progress line): re-runs them after a fix, resumably")
    ap.add_argument("--also-accept", metavar="SHA12", action="append", default=[],
                    help="with --rerun: lines recorded with this binary (first 12 hex digits of its sha256) count "
                         "as done too (a binary whose changes cannot affect those cases)")
    a = ap.parse_args()
    a.hsrod = os.path.abspath(a.hsrod)
    with open(a.hsrod, "rb") as f:
        binary = "bin " + hashlib.sha256(f.read()).hexdigest()[:12]
    accepted = {binary} | {"bin " + sha for sha in a.also_accept}
    cases = matrix(a.short)
    if a.family == "combinations":
        cases = [c for c in cases if c[0] in EXPECTED_KEYWORD]
    done = {}
    if a.progress and os.path.exists(a.progress):
        with open(a.progress) as f:
            for line in f:
                cells = [c.strip() for c in line.strip().strip("|").split("|")]
                if len(cells) not in (3, 4):
                    continue
                if a.rerun and re.search(a.rerun, cells[0]) and (len(cells) < 4 or cells[3] not in accepted):
                    continue
                done[cells[0]] = tuple(cells[:3])
    lock = threading.Lock()

    def run(case):
        if case[0] in done:
            return done[case[0]]
        result = check(a.hsrod, case[0], case[1], a.timeout)
        if a.progress:
            with lock, open(a.progress, "a") as f:
                f.write(f"| {result[0]} | {result[1]} | {result[2]} | {binary} |\n")
        return result

    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(run, cases))
    counts = {k: sum(1 for r in results if r[1] == k) for k in ("passed", "refused", "failed")}
    lines = [f"| {name} | {kind} | {why} |" for name, kind, why in results]
    table = ["| case | outcome | detail |", "| --- | --- | --- |"] + lines
    summary = (f"cases {len(results)}, passed {counts['passed']}, refused with a clear error "
               f"{counts['refused']}, failed {counts['failed']}")
    print("\n".join(table))
    print(summary)
    if a.out:
        with open(a.out, "w") as f:
            f.write("# Stress matrix results (tests/stress/stress_matrix.py)\n\n" + summary + "\n\n" +
                    "\n".join(table) + "\n")
    return 1 if counts["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
