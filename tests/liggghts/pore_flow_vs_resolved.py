"""hsrod's background flow (fix hele_shaw/drag: the depth-averaged Brinkman
flow of the planform, probed by compute hele_shaw/probe) against the resolved
3-D Stokes flow of the same channel, gap-averaged (rodIbFoam, steady, no rod:
tests/liggghts/data/pore_passage_empty_channel_resolved.csv, its header gives
the source), at the planform points of the validation passage's rod band
(calibration/validation/pore_passage; x 20-72 um, y 11-25 um, around and
through the pore).

Tolerance, per point, on |u_hsrod - u_resolved| / |u_resolved|: 3 %, the
budget for a free rod's velocity (a rod moves with the sampled flow,
so an error of the flow shows up one to one in its free velocity), plus the
resolved flow's own mesh uncertainty at that point (the change of its gap
average from the 1 um to the 0.75 um base mesh, the file's column du_mesh).
Not widened to make the model pass.

Domain: the points at least one sphere diameter (3 um) from every wall. The
passage's sphere centres stay 5.1 um or more from the walls (resolved.csv),
and within ~0.2 H of a wall the depth-averaged model is known to be cruder.
The 20 points closer than that are printed, not asserted: up to 3.8 % there,
at 2 um from a cylinder at the throat.

Usage: pore_flow_vs_resolved.py HSROD_BINARY
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data", "pore_passage_empty_channel_resolved.csv")
BUDGET = 0.03  # relative, the tolerance on a free rod's velocity
SPHERE_DIAMETER = 3e-6  # [m], the passage's rod
WIDTH, PORE_X, PORE_R = 36e-6, 42e-6, 9e-6  # [m], calibration/validation/pore_passage/scene.json


def wall_distance(x, y):
    """Distance [m] of a planform point from the side walls and the two pore cylinders."""
    return min(y, WIDTH - y, math.hypot(x - PORE_X, y) - PORE_R, math.hypot(x - PORE_X, y - WIDTH) - PORE_R)


def main():
    hsrod = os.path.abspath(sys.argv[1])
    with open(DATA) as f:
        ref = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(l for l in f if not l.startswith("#"))]
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "in.probe"), "w") as f:
            f.write("""units si
atom_style hybrid granular molecular
atom_modify map array sort 0 0
boundary f f f
newton off
communicate single cutoff 8e-6 vel yes
region box block 0 84e-6 0 36e-6 0 10e-6 units box
create_box 1 box
create_atoms 1 single 5e-6 18e-6 5e-6 units box
set atom 1 diameter 3e-6 density 1000
fix drag all hele_shaw/drag channel 84e-6 36e-6 10e-6 origin 0 0 0 pore 9e-6 42e-6 &
    viscosity 1e-3 fluid_density 1000 mean_velocity 0.01 model local
""")
            f.write("compute probe all hele_shaw/probe drag " + " ".join(
                "point %.9g %.9g" % (r["x_m"], r["y_m"]) for r in ref) + "\n")
            f.write("fix out all ave/time 1 1 1 c_probe[1] c_probe[2] c_probe[3] c_probe[4] c_probe[11] "
                    "mode vector file probe.txt\nrun 0\n")
        r = subprocess.run([hsrod, "-in", "in.probe", "-log", "none"], cwd=tmp, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
        if r.returncode != 0 or not os.path.exists(os.path.join(tmp, "probe.txt")):
            print(r.stdout[-3000:])
            sys.exit("hsrod probe run failed")
        rows = [l.split() for l in open(os.path.join(tmp, "probe.txt")) if not l.startswith("#")]
        got = [list(map(float, p[1:])) for p in rows if len(p) == 6][-len(ref):]
    checked, near = [], []  # (error / tolerance, x, y, error, tolerance) per point; near the walls
    for q, (x, y, ux, uy, fluid) in zip(ref, got):
        if abs(x - q["x_m"]) > 1e-12 or abs(y - q["y_m"]) > 1e-12 or fluid < 0.5:
            sys.exit("probe point (%g, %g) does not match the data or lies outside the fluid" % (x, y))
        speed = (q["ux_m_s"] ** 2 + q["uy_m_s"] ** 2) ** 0.5
        err = ((ux - q["ux_m_s"]) ** 2 + (uy - q["uy_m_s"]) ** 2) ** 0.5 / speed
        tol = BUDGET + q["du_mesh"]
        (checked if wall_distance(x, y) >= SPHERE_DIAMETER else near).append((err / tol, x, y, err, tol))
    fails = sum(c[0] > 1 for c in checked)
    _, x, y, err, tol = max(checked)
    print("background flow vs resolved gap average, %d points: closest to its tolerance at (%.1f, %.1f) um, "
          "error %.4f of the local speed (tolerance %.4f); largest error %.4f; %d points beyond tolerance"
          % (len(checked), x * 1e6, y * 1e6, err, tol, max(c[3] for c in checked), fails))
    if near:
        print("not asserted: %d points closer than %g m to a wall, largest error %.4f of the local speed"
              % (len(near), SPHERE_DIAMETER, max(c[3] for c in near)))
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
