#!/usr/bin/env python3
"""A steady stream of rods (in.rod_stream: 4 rods seeded by create_rods, then
fix rod/inflow places one rod every 40 steps in the entrance band x = 0-35 um
and fix rod/outflow deletes rods entirely past x_out = 110 um; 1200 steps)
on 1 and 2 MPI ranks. Facts checked, each of which a wrong insertion or
removal breaks:
 1. conservation: rods seeded + rods inserted = rods removed + rods in the
    box, with every rod in the box whole (10 spheres) and 10 spheres per
    removed rod -- a rod made on one rank only, made twice, or deleted in
    part fails;
 2. every insertion step (1200 / 40 = 30) either inserted its rod or
    counted a refusal: inserted + refused = 30;
 3. the bonds of the inserted rods hold: every pair of neighbouring spheres
    in the box is d apart within 1 % (measured: within 3e-4 d, the
    strain of the drag and the contacts; spheres left without bond rest
    states drift apart by several d in this shear flow);
 4. no rod in the box is entirely past x_out (they are removed), the stream
    flows (rods are both inserted and removed);
 5. 1 and 2 ranks (split across y: rods straddle them where they are
    inserted and removed) give the same rods at the same positions within 1e-10 d
    (create_rods_ranks.py: round-off ~1e-14 d, a step ~0.05 d);
 6. the run split by write_restart / read_restart after 600 steps gives the
    same counts and positions within 1e-10 d (the inflow's attempt counter,
    i.e. its random sequence, and its next IDs are in the restart file:
    without them the second half would seed other rods);
 7. concentration mode (2e9 rods/m^2 kept in the band): the target is
    round(c W (x1 - x0)) = round(2e9 x 60e-6 x 35e-6) = 4 rods, the fix
    reports 4 in the band after its last insertion, and the final positions
    (one step after it) hold 4 rods with their centre in the band, give or
    take the rods within one step's largest motion (0.25 d, the accuracy
    guard's bound) of the band's downstream edge.
Usage: rod_stream.py HSROD MPIRUN"""
import os
import subprocess
import sys
import tempfile

import numpy as np

hsrod, mpirun = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
d = 3e-6          # sphere diameter [m]
x_out = 110e-6    # the removal plane of in.rod_stream [m]
spheres, seeded, every, steps = 10, 4, 40, 1200


def run(ranks, work, name=None, run_steps=steps, extra=()):
    out = os.path.join(work, f"{name or f'stream{ranks}'}.txt")
    cmd = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), hsrod, "-var", "py", str(ranks),
           "-in", os.path.join(here, "in.rod_stream"), "-var", "nrods", str(seeded), "-var", "every", str(every),
           "-var", "count", "1", "-var", "steps", str(run_steps), "-var", "thermo", str(steps), "-var", "out", out,
           "-log", "none", "-echo", "none", *extra]
    p = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
    line = [l for l in p.stdout.splitlines() if l.startswith("STREAM")]
    if p.returncode != 0 or not line:
        print(p.stdout[-3000:], p.stderr[-2000:])
        sys.exit(f"FAIL: the run on {ranks} rank(s) ended with {p.returncode}")
    w = line[0].split()
    counts = {w[k]: int(float(w[k + 1])) for k in range(1, len(w) - 1, 2)}
    return counts, np.loadtxt(out, skiprows=9, ndmin=2)


with tempfile.TemporaryDirectory() as work:
    results = {ranks: run(ranks, work) for ranks in (1, 2)}
    restart = os.path.join(work, "half.restart")
    run(1, work, "first_half", steps // 2, ("-var", "phase", "1", "-var", "restart", restart))
    restarted = run(1, work, "second_half", steps // 2, ("-var", "phase", "2", "-var", "restart", restart))
    by_concentration = run(1, work, "concentration", steps, ("-var", "concentration", "2e9"))

failures = []
counts, a = results[1]
rods = np.unique(a[:, 1]).astype(int)
print(f"seeded {counts['seeded']}, inserted {counts['inserted']} (refused {counts['refused']}), "
      f"removed {counts['removed']}, {len(rods)} rods in the box")
if counts["seeded"] + counts["inserted"] != counts["removed"] + len(rods):
    failures.append("rods seeded + inserted != rods removed + rods in the box")
if counts["spheres_removed"] != spheres * counts["removed"] or counts["atoms"] != a.shape[0]:
    failures.append("spheres removed or atoms left do not match whole rods")
if any(np.count_nonzero(a[:, 1] == m) != spheres for m in rods):
    failures.append("a rod in the box is not whole")
if counts["inserted"] + counts["refused"] != steps // every:
    failures.append(f"inserted + refused != {steps // every} insertion steps")
worst = 0.0
for m in rods:
    rod = a[a[:, 1] == m]
    gaps = np.linalg.norm(np.diff(rod[:, 2:], axis=0), axis=1) / d
    worst = max(worst, np.abs(gaps - 1.0).max())
    if rod[:, 2].min() >= x_out:
        failures.append(f"rod {m} is entirely past x_out and still in the box")
print(f"largest |neighbour distance / d - 1| in the box: {worst:.3e}")
if not worst <= 0.01:
    failures.append("the bonds of some rod do not hold (neighbour distance off d by > 1 %)")
if counts["inserted"] < 1 or counts["removed"] < 1:
    failures.append("the stream must both insert and remove rods")
counts_two, b = results[2]
if counts_two != counts or b.shape != a.shape or not np.array_equal(a[:, :2], b[:, :2]):
    failures.append(f"1 and 2 ranks differ in the rods ({counts} vs {counts_two})")
else:
    difference = np.abs(a[:, 2:] - b[:, 2:]).max() / d
    print(f"1 vs 2 ranks: largest position difference {difference:.3e} d")
    if not difference <= 1e-10:
        failures.append("1 and 2 ranks differ beyond round-off")
counts_restarted, c = restarted
if counts_restarted != counts or c.shape != a.shape or not np.array_equal(a[:, :2], c[:, :2]):
    failures.append(f"the restarted run differs in the rods ({counts} vs {counts_restarted})")
else:
    difference = np.abs(a[:, 2:] - c[:, 2:]).max() / d
    print(f"restarted at step {steps // 2} vs unbroken: largest position difference {difference:.3e} d")
    if not difference <= 1e-10:
        failures.append("the restarted run differs beyond round-off")
counts_c, e = by_concentration
band_x1, target = 35e-6, round(2e9 * 60e-6 * 35e-6)
centres = np.array([e[e[:, 1] == m, 2].mean() for m in np.unique(e[:, 1])])
in_band = int(np.count_nonzero(centres <= band_x1))
near_edge = int(np.count_nonzero(np.abs(centres - band_x1) <= 0.25 * d))
print(f"concentration: target {counts_c['target']} (expected {target}), {counts_c['in_band']} in the band after the "
      f"last insertion, {in_band} one step later ({near_edge} within 0.25 d of its edge); inserted "
      f"{counts_c['inserted']}, refused {counts_c['refused']}, removed {counts_c['removed']}")
if counts_c["target"] != target or counts_c["in_band"] != target:
    failures.append("the concentration's rods in the band differ from round(c W (x1 - x0))")
if abs(in_band - target) > near_edge:
    failures.append("the final positions do not hold the concentration's rods in the band")
if counts_c["seeded"] + counts_c["inserted"] != counts_c["removed"] + len(centres):
    failures.append("concentration mode: rods seeded + inserted != rods removed + rods in the box")
if failures:
    sys.exit("FAIL: " + "; ".join(failures))
print("rod stream conserved, 1 vs 2 ranks match, restart continues")
