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

MIDPOINT = 0.5  # between zigzag (0) and bump (1), in eps * lambda_y per column
# The example's measurement (examples/pillar-sorting/plot_pillars.py, which
# needs numpy and matplotlib): y of the rod centre at x = 115 and 715 um,
# 20 columns, eps * lambda_y = 3 um.
X_IN, X_OUT, COLUMNS, SHIFT_PER_COLUMN = 115e-6, 715e-6, 20, 3e-6


def rod_centres(path):
    """{mol: [(x, y) of the rod centre per frame]} from a dump of id mol x y."""
    rods, lines, i = {}, open(path).read().split("\n"), 0
    while i < len(lines):
        if lines[i].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[i + 1])
            while not lines[i].startswith("ITEM: ATOMS"):
                i += 1
            frame = {}
            for row in lines[i + 1:i + 1 + n]:
                _, mol, x, y = row.split()[:4]
                frame.setdefault(int(mol), []).append((float(x), float(y)))
            for mol, pts in frame.items():
                rods.setdefault(mol, []).append((sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts)))
            i += n
        i += 1
    return rods


def crossing_y(track, x):
    """y of the centre when it first passes x (linear between frames), or None."""
    for k in range(1, len(track)):
        if track[k][0] >= x:
            (x0, y0), (x1, y1) = track[k - 1], track[k]
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return None


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
