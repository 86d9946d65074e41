#!/usr/bin/env python3
"""The main example's output files are named by the run's variables.

`-var model nonlocal` overwrote the default run's CSV, and the VTK frames of
the two runs mixed in one dump_pore_*.vtk series. Two runs of
examples/pore-constriction/in.pore (default, and -var model nonlocal) in one
folder must leave two CSV files, two text dumps and two separate VTK frame
series, each CSV holding its own run's passage; neither run may warn about
its own timestep (the example used to: "moved 0.1 diameters (>
max_displacement 0.1)").

Usage: example_output_names.py HSROD IN_PORE
"""
import glob
import os
import shutil
import subprocess
import sys
import tempfile


def main():
    hsrod, script = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    problems = []
    with tempfile.TemporaryDirectory() as work:
        shutil.copy(script, work)
        outputs = {}
        for extra in ([], ["-var", "model", "nonlocal"]):
            r = subprocess.run([hsrod, "-in", "in.pore", "-log", "none"] + extra, cwd=work, capture_output=True,
                               text=True, errors="backslashreplace", timeout=300)
            label = " ".join(extra) or "default"
            outputs[label] = r.stdout + r.stderr
            if r.returncode != 0 or "rod passed the pore" not in r.stdout:
                problems.append(f"{label}: rc {r.returncode}, no passage:\n{r.stdout[-2000:]}")
            if "WARNING" in outputs[label]:
                problems.append(f"{label}: warnings: " +
                                "; ".join(l for l in outputs[label].splitlines() if "WARNING" in l))
        csvs = sorted(glob.glob(os.path.join(work, "rod_*.csv")))
        snaps = sorted(glob.glob(os.path.join(work, "rod_snap_*.txt")))
        series = sorted({os.path.basename(f).rsplit("_", 1)[0] for f in glob.glob(os.path.join(work, "dump_pore*.vtk"))})
        names = [os.path.basename(f) for f in csvs]
        print("CSV files:", names)
        print("text dumps:", [os.path.basename(f) for f in snaps])
        print("VTK frame series:", series)
        if len(csvs) != 2 or not any("_auto_" in n for n in names) or not any("_nonlocal_" in n for n in names):
            problems.append(f"expected one CSV per run (auto, nonlocal), got {names}")
        if len(snaps) != 2:
            problems.append(f"expected one text dump per run, got {snaps}")
        if len(series) != 2:
            problems.append(f"expected two VTK frame series, got {series}")
        for f in csvs:
            with open(f) as fh:
                rows = fh.read().splitlines()
            if len(rows) < 10:
                problems.append(f"{os.path.basename(f)}: only {len(rows)} rows")
    if problems:
        print("FAILED:\n" + "\n".join(problems))
        return 1
    print("output names: two runs, separate files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
