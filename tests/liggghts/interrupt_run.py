#!/usr/bin/env python3
"""Ctrl-C / SIGTERM during a run.

LIGGGHTS' own handler made every Ctrl-C or `timeout` drop a
restart_forced_liggghts_<step>.data file into the working directory and
the interrupted script ended with exit code 0, like a finished one. hsrod
must stop at the next step, write no restart file, print an ERROR line
naming the signal and the step, and exit with 128 + the signal number.

Usage: interrupt_run.py HSROD SCRIPT_DIR
"""
import os
import shutil
import signal
import sys
import tempfile

from signal_harness import main, signal_when

BOUND_S = 3.0  # from the signal to the process's exit [s]


def interrupt(hsrod, script_dir, sig):
    with tempfile.TemporaryDirectory() as work:
        for name in ("long_run.in", "pore_common.in"):
            shutil.copy(os.path.join(script_dir, name), work)
        # the run is stepping once thermo prints step 2000 (every 1000 steps)
        output, rc, waited = signal_when([hsrod, "-in", "long_run.in", "-log", "none"], work,
                                         lambda line: line.split()[:1] == ["2000"], sig)
        if waited is None:
            return f"the run did not start (rc {rc}):\n" + output
        left = sorted(f for f in os.listdir(work) if f.startswith("restart"))
    name = signal.Signals(sig).name
    print(f"{name}: exit {waited:.2f} s after the signal, rc {rc}, restart files {left}")
    problems = []
    if f"ERROR: hsrod: stopped by signal {int(sig)} ({name}) at step" not in output:
        problems.append("no ERROR naming the signal and the step")
    if rc != 128 + int(sig):
        problems.append(f"exit code {rc}, expected {128 + int(sig)}")
    if "script finished" in output:
        problems.append("the script ran on after the signal")
    if left:
        problems.append(f"restart files written into the working directory: {left}")
    if waited > BOUND_S:
        problems.append(f"took {waited:.2f} s > {BOUND_S} s to stop")
    return ("; ".join(problems) + "\n" + output[-3000:]) if problems else ""


if __name__ == "__main__":
    sys.exit(main(interrupt))
