#!/usr/bin/env python3
"""Outflow removal (in.rod_outflow: 12 rods of 10 spheres streaming down a
straight channel, fix rod/outflow at x_out = 110 um), three runs:

 A. removal on 1 MPI rank,  B. removal on 2 ranks,
 R. no removal, in a channel long enough (400 um) that no rod reaches its end.

Facts checked, each of which a wrong deletion breaks:
 1. conservation: rods seeded = rods removed (f_out[1]) + rods in the box,
    spheres removed (f_out[2]) = 10 x rods removed, every rod left whole
    (10 spheres) -- a rod deleted in part, or counted twice, fails;
 2. the rods removed are exactly the rods R carries entirely past x_out
    (the flow carries every rod downstream, so a rod once entirely past the
    plane stays past it in R), and at least one rod stays and one goes;
 3. the rods left move as in R: removal deletes atoms, it must not disturb
    the other rods' steps (a stale per-rod record, a mis-mapped atom after
    the deletion or a lost bond would). Tolerance 1e-10 d as in
    create_rods_ranks.py: the same arithmetic on the same rods agrees to
    round-off (~1e-14 d at ~50 d from the origin), a step is ~0.05 d;
 4. A and B identical to the same 1e-10 d (every rank takes the same
    removal decision from an all-rank reduction; the two ranks split the
    channel across y, so rods straddle them where they are removed).
Usage: rod_outflow.py HSROD MPIRUN"""
import os
import subprocess
import sys
import tempfile

import numpy as np

hsrod, mpirun = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
d = 3e-6          # sphere diameter [m]
x_out = 110e-6    # the removal plane of in.rod_outflow [m]
nrods, spheres = 12, 10
tolerance = 1e-10  # [d]


def run(ranks, work, name, extra):
    out = os.path.join(work, name + ".txt")
    cmd = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), hsrod, "-var", "py", str(ranks),
           "-in", os.path.join(here, "in.rod_outflow"), "-var", "nrods", str(nrods), "-var", "steps", "440",
           "-var", "dt", "5e-6", "-var", "out", out, "-log", "none", "-echo", "none"] + extra
    p = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
    line = [l for l in p.stdout.splitlines() if l.startswith("OUTFLOW")]
    if p.returncode != 0 or not line:
        print(p.stdout[-3000:], p.stderr[-2000:])
        sys.exit(f"FAIL: run {name} on {ranks} rank(s) ended with {p.returncode}")
    w = line[0].split()
    counts = {"seeded": int(w[2]), "removed": int(float(w[4])), "spheres": int(float(w[6])),
              "atoms": int(float(w[9])), "held": int(float(w[12]))}
    return counts, np.loadtxt(out, skiprows=9, ndmin=2)


with tempfile.TemporaryDirectory() as work:
    count_a, a = run(1, work, "one_rank", [])
    count_b, b = run(2, work, "two_ranks", [])
    count_r, ref = run(1, work, "no_removal", ["-var", "remove", "0", "-var", "L", "400e-6"])

failures = []
rods_left = np.unique(a[:, 1]).astype(int)
print(f"seeded {count_a['seeded']}, removed {count_a['removed']} rods ({count_a['spheres']} spheres), "
      f"{len(rods_left)} rods ({count_a['atoms']} atoms) left, {count_a['held']} held at the face")
# 1. conservation
if count_a["seeded"] != count_a["removed"] + len(rods_left):
    failures.append("rods seeded != rods removed + rods in the box")
if count_a["spheres"] != spheres * count_a["removed"] or count_a["atoms"] != a.shape[0]:
    failures.append("spheres removed or atoms left do not match whole rods")
if any(np.count_nonzero(a[:, 1] == m) != spheres for m in rods_left):
    failures.append("a rod left in the box is not whole")
# 2. which rods go
past_in_reference = sorted(int(m) for m in np.unique(ref[:, 1]) if ref[ref[:, 1] == m, 2].min() >= x_out)
removed = sorted(set(range(1, nrods + 1)) - set(rods_left.tolist()))
print(f"removed {removed}; entirely past x_out in the run without removal {past_in_reference}")
if removed != past_in_reference:
    failures.append("the rods removed are not the rods entirely past x_out")
if not 0 < len(removed) < nrods:
    failures.append("the scene must keep some rods and remove some")
# 3. the rods left move as without removal
kept = ref[np.isin(ref[:, 0], a[:, 0])]
if kept.shape != a.shape or not np.array_equal(kept[:, :2], a[:, :2]):
    failures.append("the rods left are not the same spheres as in the run without removal")
else:
    moved = np.abs(kept[:, 2:] - a[:, 2:]).max() / d
    print(f"rods left vs the run without removal: largest position difference {moved:.3e} d")
    if not moved <= tolerance:
        failures.append("removal disturbed the rods left beyond round-off")
# 4. one vs two ranks
if count_b != count_a or b.shape != a.shape or not np.array_equal(a[:, :2], b[:, :2]):
    failures.append(f"1 and 2 ranks removed different rods ({count_a} vs {count_b})")
else:
    ranks = np.abs(a[:, 2:] - b[:, 2:]).max() / d
    print(f"1 vs 2 ranks: largest position difference {ranks:.3e} d")
    if not ranks <= tolerance:
        failures.append("1 and 2 ranks differ beyond round-off")
if failures:
    sys.exit("FAIL: " + "; ".join(failures))
print("rod outflow conserved, undisturbed, 1 vs 2 ranks match")
