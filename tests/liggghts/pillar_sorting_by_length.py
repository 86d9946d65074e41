#!/usr/bin/env python3
"""The pillar-sorting example sorts rods by length (examples/pillar-sorting).

Runs examples/pillar-sorting/in.pillars for rods of 2 spheres (6 um) and of
8 spheres (24 um), four rods each, and measures each rod's lateral
displacement per column over two whole periods inside the array
(as plot_pillars.py does). DLD's two modes give known values: a bumping rod moves
eps * lambda_y = 3 um per column (1 in these units), a zigzagging one comes
back to its place in the lane after each period (0). Each rod is classified
by the midpoint 0.5: the short rods must all stay below it and the long ones
all above it. The margin is what the flow itself allows: 1 um tracers
(width far below D_c = 4.6 um, pure zigzag) drift 0.08-0.33 per column in
this array (side walls trimming the lattice, 6 cells across G), and one
dropped lane over the 20 columns lowers a bumping rod by exactly 0.5, so
below 0.5 no rod of the long ones may drop a lane. A model where length
does not turn a rod (both lengths zigzag) or where both bump fails.
Measured: 2 spheres 0.04-0.33, 8 spheres 0.87-1.08.

Usage: pillar_sorting_by_length.py HSROD EXAMPLE_FOLDER
"""
import os
import shutil
import subprocess
import sys
import tempfile

# The example's own measurement of the tracks (numpy-free).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "pillar-sorting"))
from pillar_tracks import COLUMNS, SHIFT_PER_COLUMN, X_IN, X_OUT, crossing_y, rod_centres  # noqa: E402

MIDPOINT = 0.5  # between zigzag (0) and bump (1), in eps * lambda_y per column


def displacements(hsrod, folder, work, spheres):
    r = subprocess.run([hsrod, "-in", "in.pillars", "-log", "none", "-var", "spheres", str(spheres)], cwd=work,
                       capture_output=True, text=True, errors="backslashreplace", timeout=600)
    if r.returncode != 0:
        sys.exit(f"FAIL: spheres {spheres}: rc {r.returncode}\n{r.stdout[-2000:]}\n{r.stderr[-2000:]}")
    rods = rod_centres(os.path.join(work, f"pillars_s{spheres}.dump"))
    out = []
    for mol, track in sorted(rods.items()):
        y_in, y_out = crossing_y(track, X_IN), crossing_y(track, X_OUT)
        out.append(None if y_in is None or y_out is None else round((y_out - y_in) / COLUMNS / SHIFT_PER_COLUMN, 3))
    return out


def main():
    hsrod, folder = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    problems = []
    with tempfile.TemporaryDirectory() as work:
        shutil.copy(os.path.join(folder, "in.pillars"), work)
        short, long_ = displacements(hsrod, folder, work, 2), displacements(hsrod, folder, work, 8)
    print("PILLAR_SORT spheres 2:", short, "spheres 8:", long_)
    if len(short) != 4 or any(s is None or s >= MIDPOINT for s in short):
        problems.append(f"6 um rods should all zigzag (< {MIDPOINT}): {short}")
    if len(long_) != 4 or any(s is None or s <= MIDPOINT for s in long_):
        problems.append(f"24 um rods should all bump (> {MIDPOINT}): {long_}")
    if problems:
        sys.exit("FAIL: " + "; ".join(problems))
    print("PILLAR_SORT long rods bump, short rods zigzag")


if __name__ == "__main__":
    main()
