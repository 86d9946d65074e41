#!/usr/bin/env python3
"""A create_rods suspension (in.create_rods_ranks: 30 rods of 10 spheres at
area fraction 0.3, rod-rod Hertz contact on) run on 1 and 2 MPI ranks: every
rank gathers every rod whole, sorted by atom ID (rod_gather.cpp), and steps
it with the same arithmetic, so the final sphere positions agree to
round-off. Tolerance 1e-10 d: the positions are ~100 d from the origin,
where a double resolves ~2e-14 d; a difference in how ranks order the rods
or miss a partner rod would move a sphere by far more (a step is ~0.02 d).
Usage: create_rods_ranks.py HSROD MPIRUN"""
import os
import subprocess
import sys
import tempfile

import numpy as np

hsrod, mpirun = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
d = 3e-6  # sphere diameter [m]
final = {}
with tempfile.TemporaryDirectory() as work:
    for ranks in (1, 2):
        out = os.path.join(work, f"final{ranks}.txt")
        run = subprocess.run([mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), hsrod,
                              "-in", os.path.join(here, "in.create_rods_ranks"), "-var", "nrods", "30",
                              "-var", "phi", "0.3", "-var", "steps", "40", "-var", "out", out,
                              "-log", "none", "-echo", "none"], cwd=work, capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout[-2000:], run.stderr[-2000:])
            sys.exit(f"FAIL: the run on {ranks} rank(s) ended with {run.returncode}")
        final[ranks] = np.loadtxt(out, skiprows=9)
one, two = final[1], final[2]
if one.shape != two.shape or one.shape[0] != 300 or not np.array_equal(one[:, 0], two[:, 0]):
    sys.exit(f"FAIL: not the same 300 spheres on 1 and 2 ranks ({one.shape} vs {two.shape})")
difference = np.abs(one[:, 1:] - two[:, 1:]).max() / d
print(f"30 rods, 40 steps: largest position difference 1 vs 2 ranks {difference:.3e} d")
if not difference <= 1e-10:
    sys.exit("FAIL: 1 and 2 ranks differ beyond round-off (1e-10 d)")
print("create_rods 1 vs 2 ranks match")
