#!/usr/bin/python3
"""A suspension of rods bridges the pore that each of its rods passes alone.

Scene: examples/suspension-clogging/in.suspension (the paper's pore scene,
Braesel et al. 2024 Table 1 lower half: d_pore = 30 um, beta = 0.15, Re = 2,
E = 15 MPa, Coulomb friction 0.5 at the walls and between rods, level 2
drag) with rods of L_rod = d_pore = 30 um released across the flow
(alpha = 0) on create_rods' lattice in x = 120-215 um, right in front of the
pore cylinders. The lattice is deterministic (no random seed): the same rods
on every run, so each assertion is a fact that could fail.

(a) Every rod of the 30-rod lattice, run alone from its own place
    (-var only_rod K), passes: the paper's single-rod result for
    L_rod/L_pore = 1 at every E and offset (Figs. 7-8, 10a), independent of
    this model's suspension behaviour.
(b) 20 rods (area fraction 0.093) all pass; 30 rods (0.139) clog: the
    clogged fraction rises with the concentration.
(c) The clog at 30 rods is a bridge: a connected group of clogged rods
    touching both pore cylinders in which no rod touches both
    (bridge_analysis.py on the final sphere positions).
Prints "bridging clog checks passed" when all hold.
"""
import os
import re
import subprocess
import sys
import tempfile

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                       "examples", "suspension-clogging")
SCENE = ["-var", "spheres", "10", "-var", "layout", "lattice", "-var", "angle", "0",
         "-var", "x_min", "120e-6", "-var", "x_max", "215e-6"]


def run(hsrod, workdir, *args):
    cmd = [hsrod, "-in", os.path.join(EXAMPLE, "in.suspension"), "-log", "none"] + SCENE + list(args)
    out = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, timeout=600).stdout
    m = re.search(r"SUSPENSION nrods (\d+) seed \d+ clogged (\d+) passed_with_contact (\d+) "
                  r"passed_without_contact (\d+)", out)
    if not m:
        sys.exit("no SUSPENSION line from: " + " ".join(cmd) + "\n" + out[-2000:])
    return out, int(m.group(2)), int(m.group(3)) + int(m.group(4))


def main():
    hsrod = os.path.abspath(sys.argv[1])
    failures = []
    with tempfile.TemporaryDirectory() as work:
        # (a) each rod of the 30-rod lattice alone
        single_clogs = []
        for k in range(1, 31):
            _, clogged, passed = run(hsrod, work, "-var", "nrods", "30", "-var", "only_rod", str(k),
                                     "-var", "hsrod_sweep", "1")
            if clogged != 0 or passed != 1:
                single_clogs.append(k)
        print(f"single rods of the 30-rod lattice: {30 - len(single_clogs)} of 30 pass alone")
        if single_clogs:
            failures.append(f"rods {single_clogs} clog alone")
        # (b) the suspension at two concentrations
        _, clogged_low, passed_low = run(hsrod, work, "-var", "nrods", "20", "-var", "hsrod_sweep", "1")
        log_high, clogged_high, passed_high = run(hsrod, work, "-var", "nrods", "30", "-var", "final_positions", "1")
        print(f"20 rods: {clogged_low} clogged, {passed_low} passed; 30 rods: {clogged_high} clogged, {passed_high} passed")
        if not clogged_high / 30 > clogged_low / 20:
            failures.append("the clogged fraction does not rise from 20 to 30 rods")
        # (c) the plug at 30 rods
        log_path = os.path.join(work, "run30.txt")
        with open(log_path, "w") as f:
            f.write(log_high)
        positions = os.path.join(work, "final_n30_seed1_s10_E15e6_lattice_angle0.txt")
        bridge = subprocess.run([sys.executable, os.path.join(EXAMPLE, "bridge_analysis.py"), log_path, positions],
                                capture_output=True, text=True).stdout
        print(bridge.strip())
        m = re.search(r"BRIDGE rods_in_plug (\d+) touching_lower (\d+) touching_upper (\d+) spanning_single (\d+) "
                      r"bridge (\d)", bridge)
        if not m or int(m.group(5)) != 1 or int(m.group(1)) < 2:
            failures.append("the 30-rod clog is not a bridge of >= 2 rods")
    if failures:
        print("FAILED: " + "; ".join(failures))
        return 1
    print("bridging clog checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
