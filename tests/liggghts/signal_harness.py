"""Shared harness of the signal tests (interrupt_run.py, interrupt_flow_solve.py).

Starts hsrod, waits for a line of its output that says the moment has come
(the run is stepping, the flow solve is factorising), sends one signal and
measures how long the process takes to exit.
"""
import os
import signal
import subprocess
import sys
import time


def signal_when(command, cwd, trigger, sig, env=None, timeout_s=60):
    """Run `command`, send `sig` after the first output line for which
    trigger(line) is true. Returns (output, returncode, seconds from the signal
    to the exit); seconds is None when the process ended before the trigger."""
    p = subprocess.Popen(command, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, errors="backslashreplace")
    lines = []
    for line in p.stdout:
        lines.append(line)
        if trigger(line):
            break
    else:
        p.wait()
        return "".join(lines), p.returncode, None
    sent = time.monotonic()
    p.send_signal(sig)
    rest, _ = p.communicate(timeout=timeout_s)
    return "".join(lines) + rest, p.returncode, time.monotonic() - sent


def run_for_both_signals(interrupt, hsrod, script_dir):
    """The tests' main: interrupt(hsrod, script_dir, sig) returns '' or the
    problems found; SIGINT (Ctrl-C) and SIGTERM (timeout, kill) both tried."""
    failed = False
    for sig in (signal.SIGINT, signal.SIGTERM):
        problem = interrupt(hsrod, script_dir, sig)
        if problem:
            print(f"FAILED ({signal.Signals(sig).name}): {problem}")
            failed = True
    return 1 if failed else 0


def main(interrupt):
    """Usage: SCRIPT HSROD SCRIPT_DIR."""
    return run_for_both_signals(interrupt, os.path.abspath(sys.argv[1]), sys.argv[2])
