#!/usr/bin/env python3
"""Ctrl-C / SIGTERM during the background-flow solve (issue 10, item 2).

The pore scene's flow is solved on first use (an empty cache): ~5-15 s on
these machines. The signal is sent as soon as hsrod reports the sparse LU
factorisation; hsrod must stop with an ERROR naming the interruption within
a few seconds (the solve polls every 20 ms; MPI_Abort adds ~0.5 s), leave
no field in the cache, and exit non-zero. Before, the signal only took
effect after the whole solve.

Usage: interrupt_flow_solve.py HSROD SCRIPT_DIR
"""
import os
import signal
import subprocess
import sys
import tempfile
import time

BOUND_S = 3.0  # from the signal to the process's exit [s]


def interrupt(hsrod, script_dir, sig):
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, HSROD_CACHE_DIR=cache)
        p = subprocess.Popen([hsrod, "-in", "pore_flow.in", "-log", "none"], cwd=script_dir, env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="backslashreplace")
        lines = []
        for line in p.stdout:
            lines.append(line)
            if "factorising the Brinkman system" in line:
                break
        else:
            p.wait()
            return f"no factorisation reported (rc {p.returncode}):\n" + "".join(lines)
        sent = time.monotonic()
        p.send_signal(sig)
        rest, _ = p.communicate(timeout=120)
        waited = time.monotonic() - sent
        output = "".join(lines) + rest
        left = [f for f in os.listdir(cache)]
    name = signal.Signals(sig).name
    print(f"{name}: exit {waited:.2f} s after the signal, rc {p.returncode}, cache entries {len(left)}")
    problems = []
    if "ERROR" not in output or "background flow solve interrupted" not in output:
        problems.append("no ERROR naming the interrupted solve")
    if p.returncode == 0:
        problems.append("exit code 0")
    if waited > BOUND_S:
        problems.append(f"took {waited:.2f} s > {BOUND_S} s to stop")
    if any(f.endswith(".bin") for f in left):
        problems.append(f"field left in the cache: {left}")
    return ("; ".join(problems) + "\n" + output) if problems else ""


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
