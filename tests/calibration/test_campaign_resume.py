#!/usr/bin/env python3
"""calibration.campaign_resume: the resolved campaign tool
(calibration/tools/hsrod_campaign.py) on a tiny plan of four rodIbFoam cases
(lone sphere and touching pair at beta = 0.45, dragged and held, 4 cells per
d, lateral faces 1 H away):

  1. `--max-cases 1` stops after one finished case: one result file;
  2. a second run is killed (SIGTERM) while its second case runs: it exits
     130, leaves only complete result files (2) and no temporary file;
  3. a third run resumes: the two finished cases are skipped, not recomputed
     (files byte-identical, same mtime), the other two are computed;
  4. the results are physical: the mirror symmetry of the pair (both
     spheres carry the same parallel and the same perpendicular force, to
     the plan's stopping tolerance 1e-4), drag along the motion, the lone sphere's friction above
     Faxen's unbounded-slit value (the near lateral faces add resistance) and
     its force-free velocity below the mid-plane velocity 3/2 U.

Usage: test_campaign_resume.py RODIBFOAM CAMPAIGN_TOOL PLAN WORKDIR
"""
import glob
import json
import math
import os
import shutil
import signal
import subprocess
import sys


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def results(out):
    return sorted(glob.glob(os.path.join(out, "results", "*.json")))


def main():
    solver, tool, plan, work = sys.argv[1:5]
    out = os.path.join(work, "campaign_resume")
    shutil.rmtree(out, ignore_errors=True)
    base = [sys.executable, tool, "run", out, "--plan", plan, "--solver", solver]

    # 1. limited run
    r = subprocess.run(base + ["--max-cases", "1"], capture_output=True, text=True)
    print(r.stdout)
    if r.returncode != 0 or "stopped after --max-cases 1" not in r.stdout:
        fail("limited run: exit %d\n%s" % (r.returncode, r.stderr))
    first = results(out)
    if len(first) != 1:
        fail("limited run left %d result files, expected 1" % len(first))
    first_bytes, first_mtime = open(first[0], "rb").read(), os.stat(first[0]).st_mtime_ns

    # 2. killed run: SIGTERM as soon as its second case starts
    p = subprocess.Popen(base, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    killed = False
    lines = []
    for line in p.stdout:
        lines.append(line)
        if line.startswith("[2/3]") and line.rstrip().endswith("CPU") and "running" in line:
            p.send_signal(signal.SIGTERM)
            killed = True
    p.wait()
    print("".join(lines))
    if not killed or p.returncode != 130:
        fail("killed run: killed %s, exit %s (expected 130)" % (killed, p.returncode))
    if "interrupted in" not in "".join(lines):
        fail("killed run did not report the interrupted case")
    done = results(out)
    if len(done) != 2:
        fail("after the kill %d result files, expected 2" % len(done))
    if glob.glob(os.path.join(out, "results", ".tmp-*")):
        fail("temporary result file left behind")
    for f in done:
        json.load(open(f))  # complete JSON

    # 3. resume
    r = subprocess.run(base, capture_output=True, text=True)
    print(r.stdout)
    if r.returncode != 0 or "all 4 cases done" not in r.stdout:
        fail("resumed run: exit %d\n%s" % (r.returncode, r.stderr))
    if r.stdout.count("skip (done)") != 2 or "2 to run" not in r.stdout:
        fail("resumed run did not skip exactly the 2 finished cases")
    if open(first[0], "rb").read() != first_bytes or os.stat(first[0]).st_mtime_ns != first_mtime:
        fail("a finished case was recomputed")
    res = {json.load(open(f))["id"].rsplit("_", 1)[0]: json.load(open(f)) for f in results(out)}
    if len(res) != 4:
        fail("%d results after resume, expected 4" % len(res))
    st = subprocess.run([sys.executable, tool, "status", out, "--plan", plan], capture_output=True, text=True)
    if "4 of 4 cases done" not in st.stdout:
        fail("status: " + st.stdout)

    # 4. physics of the recorded loads
    for key in ("b0.450_n2_s1_friction_m4", "b0.450_n2_s1_driving_m4"):
        s = res[key]["spheres"]
        fx = [x["F"][0] for x in s]
        fy = [x["F"][1] for x in s]
        print("%s: Fx %s Fy %s" % (key, fx, fy))
        if not (fx[0] > 0 and fy[0] > 0):
            fail("%s: force not along the motion (45 degrees)" % key)
        for f in (fx, fy):
            # to the plan's stopping tolerance (tol_F_extrapolated 1e-4)
            if abs(f[0] - f[1]) > 1e-4 * abs(f[0]):
                fail("%s: the pair's mirror symmetry is broken: %s" % (key, f))
    sph = res["b0.450_n1_s1_friction_m4"]
    held = res["b0.450_n1_s1_driving_m4"]
    beta = sph["spec"]["beta"]
    k = sph["spheres"][0]["F"][0] / (3 * math.pi * sph["spec"]["mu"] * sph["spec"]["d"] * sph["spec"]["U"])
    lam = held["spheres"][0]["F"][0] / sph["spheres"][0]["F"][0]   # force-free velocity / gap-mean
    faxen = 1 / (1 - 1.004 * beta + 0.418 * beta ** 3 + 0.21 * beta ** 4 - 0.169 * beta ** 5)
    print("lone sphere friction %.4f (Faxen, unbounded slit: %.4f), free velocity / mean %.4f" % (k, faxen, lam))
    # the lateral faces 1 H away only add resistance (minimum dissipation),
    # and a free sphere lags the mid-plane velocity 3/2 U (Faxen's law)
    if not (k > faxen and 0.5 < lam < 1.5):
        fail("lone sphere: friction %.4f (must exceed %.4f), velocity ratio %.4f" % (k, faxen, lam))
    for r_ in res.values():
        pv = r_["provenance"]
        if not (len(pv["solver_sha256"]) == 64 and r_["mesh"]["cells"] > 0 and r_["run"]["iterations"] > 0):
            fail("provenance/mesh record incomplete in " + r_["id"])
    print("PASS")


if __name__ == "__main__":
    main()
