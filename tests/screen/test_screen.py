#!/usr/bin/env python3
"""Screening a resolved CFD-DEM script (hsrod -var hsrod_screen scene.json).

Usage: test_screen.py <hsrod> <hsrod_case.py> <work-dir>
The coupled rod case of the calibration tests (scene
tests/calibration/scenes/coupled_rod.json, its in.liggghts written by
calibration/tools/hsrod_case.py) is screened unchanged; then two copies
differing in one line each: a timestep of 5e-8 s (above the rods' explicit
bond limit) and the rod centre 1 um above the bottom wall (spheres of
r = 1.5 um: overlap 0.5 um = 1/3 of the radius).
"""
import os
import re
import subprocess
import sys

hsrod, case_tool, work = sys.argv[1:4]
here = os.path.dirname(os.path.abspath(__file__))
scene = os.path.join(here, "..", "calibration", "scenes", "coupled_rod.json")
case = os.path.join(work, "coupled_rod")
subprocess.run([sys.executable, case_tool, scene, case], check=True, capture_output=True)
failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def screen(script):
    done = subprocess.run([hsrod, "-in", script, "-log", "none", "-var", "hsrod_screen", "scene.json"], cwd=case,
                          capture_output=True, text=True, timeout=120)
    report = done.stdout[done.stdout.find("==== hsrod screen: pre-flight report"):]
    print(report)
    check(done.returncode == 0 and "ERROR" not in done.stdout, f"{script}: screened without an ERROR")
    return report


original = open(os.path.join(case, "in.liggghts")).read()
for style in ("couple/cfd", "couple/cfd/force/implicit", "nve/sphere", "wall/gran"):
    check(f" {style}" in original, f"the generated resolved script uses fix {style}")

report = screen("in.liggghts")
for fix in ("cfd couple/cfd", "cfd2 couple/cfd/force/implicit", "cfd3 couple/cfd/torque/implicit", "integr nve/sphere"):
    check(f"replaced: fix {fix} ->" in report, f"report lists the replaced fix {fix}")
check(len(re.findall(r"replaced: fix w\w+ wall/gran -> recorded as a scene wall", report)) == 4, "4 walls recorded")
m = re.search(r"timestep: the script's dt = 1e-08 s is below the explicit bond limit ([0-9.e-]+) s", report)
check(m is not None and 1.5e-8 < float(m.group(1)) < 2.0e-8,
      "dt 1e-8 s passes; the limit lies between the measured stable 1.5e-8 s and unstable 2e-8 s of stock LIGGGHTS "
      "(DESIGN.md, 15 MPa rods of 3 um)")
check("overlaps between rods: none" in report and "sphere-wall overlaps (4 fix wall/gran walls): none" in report,
      "no overlaps reported for the valid script")
m = re.search(r"rod centre x = ([0-9.e-]+) m", report)
# The reduced prediction over the resolved run's 4 us: the rod (at x = 25 um)
# moves downstream by a fraction of a sphere diameter (U = 0.05 m/s: ~0.2-0.5 um).
check(m is not None and 25.05e-6 < float(m.group(1)) < 25.6e-6, f"predicted rod centre moved downstream: {m and m.group(1)}")
check(re.search(r"cost: resolved run ~\d+ cells x 8 CFD steps \(couple_every 50\) \+ 400 DEM steps", report) is not None,
      "cost: 4e-6 s / 1e-8 s = 400 DEM steps, / 50 = 8 CFD steps")
check("==== hsrod screen: 0 problem(s) ====" in report, "valid script: 0 problems")

with open(os.path.join(case, "in.unstable"), "w") as f:
    f.write(original.replace("timestep 1e-08", "timestep 5e-08"))
report = screen("in.unstable")
check(re.search(r"UNSTABLE timestep: the script's dt = 5e-08 s exceeds the explicit bond limit 1\.\d+e-08 s", report)
      is not None, "dt 5e-8 s flagged as unstable")
check("==== hsrod screen: 1 problem(s) ====" in report, "unstable script: 1 problem")

with open(os.path.join(case, "in.overlap"), "w") as f:
    f.write(original.replace("centre 2.5e-05 1.5e-05 7.5e-06", "centre 2.5e-05 1.5e-05 1e-06"))
report = screen("in.overlap")
check("OVERLAP: 3 sphere-wall overlap(s) with the script's fix wall/gran walls (worst 0.333 of the radius)" in report,
      "3 spheres overlapping the bottom wall by 1/3 of their radius flagged")
check("prediction skipped" in report, "no prediction from an overlapping start")

# Bad scene files: the error names the file, the key and the type (the JSON
# library's raw "type_error.302 type must be number, but is string" named
# neither), and an inflow.U outside the model's regime is refused before the
# script runs (1e300 m/s failed as a sphere moving inf d per step).
import json
scene_values = json.load(open(os.path.join(case, "scene.json")))
for name, change, expected in (
        ("string_U", lambda j: j["inflow"].update(U="fast"),
         "ERROR: hsrod screen: scene file 'bad_string_U.json': inflow.U must be a number, got string \"fast\""),
        ("string_mu", lambda j: j.setdefault("fluid", {}).update(mu="1e-3"),
         "ERROR: hsrod screen: scene file 'bad_string_mu.json': fluid.mu must be a number, got string \"1e-3\""),
        ("huge_U", lambda j: j["inflow"].update(U=1e300),
         "ERROR: hsrod screen: scene file 'bad_huge_U.json': inflow.U: mean inflow velocity U = 1e+300 m/s")):
    bad = json.loads(json.dumps(scene_values))
    change(bad)
    with open(os.path.join(case, f"bad_{name}.json"), "w") as f:
        json.dump(bad, f)
    done = subprocess.run([hsrod, "-in", "in.liggghts", "-log", "none", "-var", "hsrod_screen", f"bad_{name}.json"],
                          cwd=case, capture_output=True, text=True, timeout=120)
    first = [l for l in done.stdout.splitlines() if l.startswith("ERROR")][:1]
    check(done.returncode != 0 and first and first[0].startswith(expected) and "json.exception" not in done.stdout,
          f"scene file with {name}: refused naming the key: {first}")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("all checks passed")
