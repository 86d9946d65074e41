#!/usr/bin/python3
"""The clogging probability of the paper's pore scene rises with concentration.

Scene: examples/suspension-clogging/in.suspension (Braesel et al. 2024,
Table 1 lower half: d_pore = 30 um, beta = 0.15, Re = 2, E = 15 MPa,
Coulomb friction 0.5 at the walls and between rods, level 2 drag) with
rods of L_rod = d_pore released across the flow on create_rods' lattice in
x = 120-215 um, each rod moved by up to 0.5 um and turned by up to 2 degrees
at random from the seed (jitter 0.5e-6 2): a seed set is a set of
suspensions whose rows still arrive at the pore together.

Over the same seeds, at a low and a high number of rods, the number of
clogged runs (runs in which fix rod/outcome classed at least one rod
clogged) must be larger at the high number. A rod of this length alone
passes the pore (paper Fig. 10a; suspension_bridges_pore_its_single_rods_pass),
so a clogged run is the suspension's doing, and the count could as well be
equal or fall: the test fails then.
  clog_probability.py HSROD LOW_RODS HIGH_RODS SEED [SEED ...]
Prints "clog probability rises with concentration" when it holds.
"""
import os
import re
import subprocess
import sys
import tempfile

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                       "examples", "suspension-clogging")
SCENE = ["-var", "spheres", "10", "-var", "layout", "lattice", "-var", "angle", "0",
         "-var", "x_min", "120e-6", "-var", "x_max", "215e-6",
         "-var", "jitter_x", "0.5e-6", "-var", "jitter_angle", "2", "-var", "hsrod_sweep", "1"]


def clogged_rods(hsrod, workdir, nrods, seed):
    cmd = [hsrod, "-in", os.path.join(EXAMPLE, "in.suspension"), "-log", "none"] + SCENE + [
        "-var", "nrods", str(nrods), "-var", "seed", str(seed)]
    out = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, timeout=3600).stdout
    m = re.search(r"SUSPENSION nrods \d+ seed \d+ clogged (\d+) ", out)
    if not m:
        sys.exit("no SUSPENSION line from: " + " ".join(cmd) + "\n" + out[-2000:])
    return int(m.group(1))


def main():
    hsrod = os.path.abspath(sys.argv[1])
    low, high = int(sys.argv[2]), int(sys.argv[3])
    seeds = [int(s) for s in sys.argv[4:]]
    counts = {}
    with tempfile.TemporaryDirectory() as work:
        for nrods in (low, high):
            clogged = [clogged_rods(hsrod, work, nrods, s) for s in seeds]
            counts[nrods] = sum(1 for c in clogged if c > 0)
            print(f"{nrods} rods, seeds {seeds}: rods clogged {clogged}, "
                  f"{counts[nrods]} of {len(seeds)} runs clogged")
    if not counts[high] > counts[low]:
        print(f"FAILED: {counts[high]} clogged runs at {high} rods, not more than {counts[low]} at {low}")
        return 1
    print("clog probability rises with concentration")
    return 0


if __name__ == "__main__":
    sys.exit(main())
