#!/usr/bin/python3
"""Which clogged rods of a suspension run form the plug at the pore, and is it a bridge?

Reads the run's screen output (fix rod/outcome's lines "rod K clogged ..." and
"rod K clogged (held by rod J) ...") and the sphere positions at the end
(in.suspension -var final_positions 1: final_<tag>.txt, columns id mol x y z).
A sphere touches a pore cylinder when its centre is within d/2 + tol of the
cylinder surface, two rods touch when two of their spheres are within d + tol
(tol = 0.05 d: Hertz overlaps and the gaps the implicit step leaves are far
below that, the lattice of a neighbour rod one d away is not).
Bridge: a connected group of clogged rods (rod-rod contacts) that touches
both cylinders while none of its rods touches both: the pore is held shut by
the rods together, not by one rod trapped across it (wall entrapment).

  bridge_analysis.py run.txt final_<tag>.txt [--pore-x 300e-6 --radius 85e-6 --width 200e-6 --d 3e-6]
Prints one line: BRIDGE rods_in_plug N touching_lower A touching_upper B spanning_single S bridge 0|1
"""
import argparse
import math
import re
import sys


def read_clogged(log_path):
    clogged = set()
    for line in open(log_path):
        m = re.search(r"fix rod/outcome: rod (\d+) clogged", line)
        if m:
            clogged.add(int(m.group(1)))
    return clogged


def read_spheres(dump_path):
    lines = open(dump_path).read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    rods = {}
    for l in lines[start:]:
        f = l.split()
        if len(f) < 5:
            continue
        rods.setdefault(int(f[1]), []).append((float(f[2]), float(f[3])))
    return rods


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("log")
    ap.add_argument("positions")
    ap.add_argument("--pore-x", type=float, default=300e-6)   # cylinder centres' x [m]
    ap.add_argument("--radius", type=float, default=85e-6)    # cylinder radius R [m]
    ap.add_argument("--width", type=float, default=200e-6)    # channel width W [m]; centres at y = 0, W
    ap.add_argument("--d", type=float, default=3e-6)          # sphere diameter [m]
    a = ap.parse_args()
    tol = 0.05 * a.d
    clogged = read_clogged(a.log)
    rods = read_spheres(a.positions)
    centres = {"lower": (a.pore_x, 0.0), "upper": (a.pore_x, a.width)}

    def touches(mol, side):
        cx, cy = centres[side]
        return any(math.hypot(x - cx, y - cy) < a.radius + 0.5 * a.d + tol for x, y in rods[mol])

    def in_contact(m1, m2):
        return any(math.hypot(x1 - x2, y1 - y2) < a.d + tol for x1, y1 in rods[m1] for x2, y2 in rods[m2])

    walls = {m: {s for s in centres if touches(m, s)} for m in clogged}
    # Groups of clogged rods connected by contacts (union over the contact graph).
    todo, groups = set(clogged), []
    while todo:
        seed = todo.pop()
        group, front = {seed}, [seed]
        while front:
            m = front.pop()
            for n in list(todo):
                if in_contact(m, n):
                    todo.discard(n)
                    group.add(n)
                    front.append(n)
        groups.append(group)
    best = None
    for g in groups:
        lower = sum("lower" in walls[m] for m in g)
        upper = sum("upper" in walls[m] for m in g)
        single = sum(len(walls[m]) == 2 for m in g)
        bridge = int(lower > 0 and upper > 0 and single == 0)
        key = (bridge, lower > 0 and upper > 0, len(g))
        if best is None or key > best[0]:
            best = (key, len(g), lower, upper, single, bridge, sorted(g))
    if best is None:
        print("BRIDGE rods_in_plug 0 touching_lower 0 touching_upper 0 spanning_single 0 bridge 0")
        return 0
    _, n, lower, upper, single, bridge, members = best
    wall_rods = [m for m in members if walls[m]]
    print("plug rods touching a cylinder: " + ", ".join(f"{m} ({'/'.join(sorted(walls[m]))})" for m in wall_rods))
    print(f"BRIDGE rods_in_plug {n} touching_lower {lower} touching_upper {upper} spanning_single {single} bridge {bridge}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
