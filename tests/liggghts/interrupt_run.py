#!/usr/bin/env python3
"""Ctrl-C / SIGTERM during a run (issue 10, "first-hour annoyances").

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
import subprocess
import sys
import tempfile
import time

BOUND_S = 3.0  # from the signal to the process's exit [s]


def interrupt(hsrod, script_dir, sig):
    with tempfile.TemporaryDirectory() as work:
        for name in ("long_run.in", "pore_common.in"):
            shutil.copy(os.path.join(script_dir, name), work)
        p = subprocess.Popen([hsrod, "-in", "long_run.in", "-log", "none"], cwd=work,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="backslashreplace")
        lines = []
        for line in p.stdout:
            lines.append(line)
            if line.split()[:1] == ["2000"]:  # the run is stepping (thermo every 1000 steps)
                break
        else:
            p.wait()
            return f"the run did not start (rc {p.returncode}):\n" + "".join(lines)
        sent = time.monotonic()
        p.send_signal(sig)
        rest, _ = p.communicate(timeout=60)
        waited = time.monotonic() - sent
        output = "".join(lines) + rest
        left = sorted(f for f in os.listdir(work) if f.startswith("restart"))
    name = signal.Signals(sig).name
    print(f"{name}: exit {waited:.2f} s after the signal, rc {p.returncode}, restart files {left}")
    problems = []
    if f"ERROR: hsrod: stopped by signal {int(sig)} ({name}) at step" not in output:
        problems.append("no ERROR naming the signal and the step")
    if p.returncode != 128 + int(sig):
        problems.append(f"exit code {p.returncode}, expected {128 + int(sig)}")
    if "script finished" in output:
        problems.append("the script ran on after the signal")
    if left:
        problems.append(f"restart files written into the working directory: {left}")
    if waited > BOUND_S:
        problems.append(f"took {waited:.2f} s > {BOUND_S} s to stop")
    return ("; ".join(problems) + "\n" + output[-3000:]) if problems else ""


def main():
    hsrod, script_dir = os.path.abspath(sys.argv[1]), sys.argv[2]
    failed = False
    for sig in (signal.SIGINT, signal.SIGTERM):
        problem = interrupt(hsrod, script_dir, sig)
        if problem:
            print(f"FAILED ({signal.Signals(sig).name}): {problem}")
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
