"""Shared helpers of the calibration tests: build a case from a scene with
calibration/tools/hsrod_case.py, run blockMesh + rodIbFoam, read the CSVs.

Every test script is called by ctest as
    python3 test_x.py <rodIbFoam> <hsrod_case.py> <work dir>
"""
import csv
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


class Env:
    def __init__(self, argv):
        if len(argv) != 4:
            sys.exit("usage: %s RODIBFOAM HSROD_CASE WORKDIR" % argv[0])
        self.solver, self.tool, self.work = argv[1], argv[2], argv[3]
        os.makedirs(self.work, exist_ok=True)
        self.env = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))

    def make_case(self, scene, name, sets=()):
        case = os.path.join(self.work, name)
        shutil.rmtree(case, ignore_errors=True)
        cmd = [sys.executable, self.tool, os.path.join(HERE, "scenes", scene), case]
        for s in sets:
            cmd += ["--set", s]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        return case

    def run(self, case, expect_ok=True):
        """blockMesh + rodIbFoam; returns (returncode, solver log text, seconds)."""
        t0 = time.time()
        bm = subprocess.run(["blockMesh", "-case", case], env=self.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if bm.returncode != 0:
            print(bm.stdout[-3000:])
            raise RuntimeError("blockMesh failed in " + case)
        r = subprocess.run([self.solver, "-case", case], env=self.env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        dt = time.time() - t0
        with open(os.path.join(case, "log.rodIbFoam"), "w") as f:
            f.write(r.stdout)
        if expect_ok and r.returncode != 0:
            print(r.stdout[-4000:])
            raise RuntimeError("rodIbFoam failed in " + case)
        return r.returncode, r.stdout, dt


def read_csv(path):
    with open(path) as f:
        rows = [l for l in f if not l.startswith("#")]
    return list(csv.DictReader(rows))


def last_loads(case):
    rows = read_csv(os.path.join(case, "postProcessing", "rodIbFoam", "sphereForces.csv"))
    t = rows[-1]["t"]
    return [r for r in rows if r["t"] == t]


def last_flux(case):
    rows = read_csv(os.path.join(case, "postProcessing", "rodIbFoam", "patchFlux.csv"))
    return {k: float(v) for k, v in rows[-1].items()}


def check(cond, msg):
    print(("PASS: " if cond else "FAIL: ") + msg)
    return bool(cond)
