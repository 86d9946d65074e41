#!/usr/bin/env python3
"""Ctrl-C / SIGTERM during the background-flow solve.

The pore scene's flow is solved on first use (an empty cache): ~5-15 s on
these machines. The signal is sent as soon as hsrod reports the sparse LU
factorisation; hsrod must stop with an ERROR naming the interruption within
a few seconds (the solve polls every 20 ms; MPI_Abort adds ~0.5 s), leave
no field in the cache, and exit with 128 + signal (the README's promise;
it exited 1 before). Before, the signal only took
effect after the whole solve.

Usage: interrupt_flow_solve.py HSROD SCRIPT_DIR
"""
import os
import signal
import sys
import tempfile

from signal_harness import main, signal_when

BOUND_S = 3.0  # from the signal to the process's exit [s]


def interrupt(hsrod, script_dir, sig):
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, HSROD_CACHE_DIR=cache)
        output, rc, waited = signal_when([hsrod, "-in", "pore_flow.in", "-log", "none"], script_dir,
                                         lambda line: "factorising the Brinkman system" in line, sig,
                                         env=env, timeout_s=120)
        if waited is None:
            return f"no factorisation reported (rc {rc}):\n" + output
        left = [f for f in os.listdir(cache)]
    name = signal.Signals(sig).name
    print(f"{name}: exit {waited:.2f} s after the signal, rc {rc}, cache entries {len(left)}")
    problems = []
    if "ERROR" not in output or "background flow solve interrupted" not in output:
        problems.append("no ERROR naming the interrupted solve")
    if rc != 128 + sig:
        problems.append(f"exit code {rc}, not 128 + {int(sig)} as the README documents")
    if waited > BOUND_S:
        problems.append(f"took {waited:.2f} s > {BOUND_S} s to stop")
    if any(f.endswith(".bin") for f in left):
        problems.append(f"field left in the cache: {left}")
    return ("; ".join(problems) + "\n" + output) if problems else ""


if __name__ == "__main__":
    sys.exit(main(interrupt))
