#!/usr/bin/env python3
"""hsrod-sweep tests (ctest): run the tool on tiny_rod.in and check its CSV.

Usage: test_sweep.py <test> <hsrod-sweep> <hsrod> <mpirun> <work-dir>
  ranks    the same rows with 1, 2 and 3 MPI ranks (0, 1, 2 workers); the
           swept equal-style U really reaches the run (x - x0 proportional
           to U, as the linear drag model makes it); one case equals a
           direct hsrod run of the same script.
  resume   a 3-rank sweep killed with SIGKILL half way and started again
           ends with every case exactly once and the rows of an
           uninterrupted sweep.
  failure  a case with E < 0 is recorded with LIGGGHTS' ERROR message and a
           case that never ends is killed at --case-timeout; the others run;
           a timeout of 0.03 s is enforced to the millisecond.
  regime   the regime-map path of examples/regime-map/run_maps.sh on two
           cases of examples/clogging/in.clogging (stiff rod, alpha = 0):
           fix rod/outcome read as a measure gives the paper's classes,
           passage without contact at L_rod/d_pore = 1 and clogging at 2
           (Fig. 10a), with the first contact only in the clogged case.
  workers  a sweep of 48 cases on 4 workers (5 MPI ranks) writes every
           case exactly once, all four workers run cases, and the rows
           equal the same sweep on one process (the task farm at the
           width of a small cluster job; see the Slurm job in
           liggghts-package/sweep/slurm/).
  rods     the number of rods swept (examples/several-rods/in.several_rods,
           nrods 1 and 2, rods of 1.1 d_pore at level 2): each case has
           11 x nrods spheres; one rod alone is trapped at the cylinders,
           a second one behind it is clogged too, held by the first.
"""
import csv
import os
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "tiny_rod.in")
# Columns that differ between runs of the same sweep (timing, who ran it).
VOLATILE = ("wall_s", "cpu_s", "rank", "error")

test, sweep, hsrod, mpirun, work = sys.argv[1:6]
os.makedirs(work, exist_ok=True)
failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def command(output, ranks, extra):
    base = [sweep, "--in", SCRIPT, "--output", output] + extra
    if ranks == 1:
        return base
    return [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + base


def run(output, ranks, extra, fresh=True):
    cmd = command(output, ranks, extra + (["--fresh"] if fresh else []))
    done = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=300)
    print(done.stdout[-1500:], done.stderr[-1500:])
    check(done.returncode == 0, f"{' '.join(cmd[:6])} ... exits with 0 (got {done.returncode})")
    return done


def descendants(pid):
    children = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            if ppid == pid:
                children += descendants(int(entry)) + [int(entry)]
    return children


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def rows(output):
    with open(os.path.join(work, output), newline="") as f:
        return list(csv.DictReader(f))


def stable(table):
    """Rows keyed by case ID without the volatile columns."""
    return {int(r["case"]): {k: v for k, v in r.items() if k not in VOLATILE} for r in table}


GRID = ["--var", "E", "15e3,15e6", "--var", "alpha", "0,60", "--var", "U", "0.02:0.04:0.01",
        "--measure", "x=c_shape[2]", "--measure", "angle=c_shape[7]", "--measure", "lateral=c_shape[9]"]
N_CASES = 2 * 2 * 3

if test == "ranks":
    tables = {}
    for ranks in (1, 2, 3):
        run(f"ranks{ranks}.csv", ranks, GRID)
        tables[ranks] = rows(f"ranks{ranks}.csv")
        check(len(tables[ranks]) == N_CASES, f"{ranks} rank(s): {len(tables[ranks])} rows, expected {N_CASES}")
        check(all(r["status"] == "ok" for r in tables[ranks]), f"{ranks} rank(s): every case ok")
    check(stable(tables[1]) == stable(tables[2]), "rows of 1 and 2 ranks are identical")
    check(stable(tables[1]) == stable(tables[3]), "rows of 1 and 3 ranks are identical")
    check({r["rank"] for r in tables[3]} == {"1", "2"}, "with 3 ranks both workers ran cases, the scheduler none")
    # The equal-style U is overridden: with a linear drag model and a rigid
    # translation (alpha = 0, no rotation in a straight channel) the
    # displacement x - x0 is proportional to U (x0 = 100 um).
    by_case = stable(tables[1])
    for E in ("15e3", "15e6"):
        d = {float(r["U"]): float(r["x"]) - 100e-6 for r in by_case.values() if r["E"] == E and r["alpha"] == "0"}
        ratio = [d[U] / U for U in sorted(d)]
        spread = (max(ratio) - min(ratio)) / max(ratio)
        check(len(d) == 3 and spread < 1e-6 and d[0.02] > 0,
              f"E = {E}: (x - x0)/U equal for U = 0.02, 0.03, 0.04 (relative spread {spread:.2e} < 1e-6)")
    # One case against a direct hsrod run of the same script and values.
    probe = os.path.join(work, "direct.in")
    with open(SCRIPT) as f, open(probe, "w") as out:
        out.write(f.read().replace("variable U      equal 0.03", "variable U      equal 0.04"))
        out.write('variable xm equal c_shape[2]\nprint "DIRECT_X ${xm}"\n')
    direct = subprocess.run([hsrod, "-in", probe, "-log", "none", "-var", "E", "15e3", "-var", "alpha", "60"],
                            cwd=work, capture_output=True, text=True, timeout=120)
    line = [l for l in direct.stdout.splitlines() if l.startswith("DIRECT_X")]
    case = [r for r in by_case.values() if (r["E"], r["alpha"], r["U"]) == ("15e3", "60", "0.04")][0]
    x_direct = float(line[-1].split()[1]) if line else float("nan")
    check(abs(x_direct - float(case["x"])) <= 1e-12 * abs(x_direct),
          f"case E=15e3 alpha=60 U=0.04: sweep x {case['x']} equals direct hsrod x {x_direct!r}")

elif test == "workers":
    # 48 short cases (4 x 3 x 4 = 48, 50 steps each) so that the four workers
    # compete for the scheduler's next case many times over.
    grid = ["--var", "E", "15e3,15e4,15e5,15e6", "--var", "alpha", "0,30,60",
            "--var", "U", "0.01:0.04:0.01", "--var", "steps", "50",
            "--measure", "x=c_shape[2]", "--measure", "angle=c_shape[7]"]
    n_cases = 4 * 3 * 4
    run("workers1.csv", 1, grid)
    run("workers4.csv", 5, grid)
    serial, farm = rows("workers1.csv"), rows("workers4.csv")
    ids = sorted(int(r["case"]) for r in farm)
    check(ids == list(range(n_cases)),
          f"4 workers: every one of the {n_cases} cases exactly once (got {len(ids)} rows, "
          f"{len(set(ids))} distinct ids)")
    check(all(r["status"] == "ok" for r in farm), "4 workers: every case ok")
    check({r["rank"] for r in farm} == {"1", "2", "3", "4"},
          f"4 workers: all four ran cases, the scheduler none (ranks {sorted({r['rank'] for r in farm})})")
    check(stable(serial) == stable(farm), "rows of 1 process and 4 workers are identical")

elif test == "resume":
    # Cases of 100 000 steps of 20 ns (~0.4 s each; the rod stays in the box,
    # where a held rod would make steps free): the sweep must still be
    # running when half its rows are on disk. 2000-step cases (~0.03 s since
    # the steps got faster) let all 12 end between two polls, before the kill.
    GRID = GRID + ["--var", "steps", "100000", "--var", "dt", "2e-8", "--var", "every", "10000"]
    run("reference.csv", 1, GRID)
    reference = stable(rows("reference.csv"))
    out = os.path.join(work, "killed.csv")
    if os.path.exists(out):
        os.remove(out)
    cmd = command("killed.csv", 3, GRID + ["--fresh"])
    job = subprocess.Popen(cmd, cwd=work, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                           start_new_session=True)
    deadline = time.time() + 240
    finished_rows = 0
    while time.time() < deadline and job.poll() is None:
        if os.path.exists(out):
            with open(out) as f:
                finished_rows = sum(1 for _ in f) - 1
            if finished_rows >= N_CASES // 2:
                break
        time.sleep(0.02)
    # SIGKILL to every process of the job at once (mpirun, the ranks, the
    # cases' children), as a batch system ending a job does; mpirun alone
    # would leave its ranks running for a moment.
    tree = descendants(job.pid) + [job.pid]
    for pid in tree:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    job.wait()
    time.sleep(1.0)
    check(not any(alive(pid) for pid in tree), f"all {len(tree)} processes of the killed sweep are gone")
    before = rows("killed.csv")
    check(N_CASES // 2 <= len(before) < N_CASES,
          f"killed half way: {len(before)} of {N_CASES} rows on disk when SIGKILL hit")
    done = run("killed.csv", 3, GRID, fresh=False)
    check(f"{len(before)} already in" in done.stdout, f"restart reports the {len(before)} finished cases")
    after = rows("killed.csv")
    ids = [int(r["case"]) for r in after]
    check(sorted(ids) == list(range(N_CASES)), f"every case exactly once after the restart ({len(ids)} rows)")
    check(stable(after) == reference, "rows equal those of an uninterrupted sweep")
    check(after[:len(before)] == before, "the rows written before the kill are kept unchanged")

elif test == "failure":
    extra = ["--var", "E", "15e6,-1", "--var", "steps", "200,1000000000", "--case-timeout", "4",
             "--measure", "x=c_shape[2]"]
    run("failure.csv", 3, extra)
    table = {(r["E"], r["steps"]): r for r in rows("failure.csv")}
    check(len(table) == 4, f"all 4 cases recorded (got {len(table)})")
    good = table.get(("15e6", "200"), {})
    check(good.get("status") == "ok" and good.get("x", "") != "", "the valid case ran and has its measure")
    for steps in ("200", "1000000000"):
        bad = table.get(("-1", steps), {})
        check(bad.get("status") == "failed" and "ERROR: fix rod/bonds: youngs_modulus must be > 0 Pa" in bad.get("error", "")
              and bad.get("x") == "", f"E = -1, steps {steps}: failed with LIGGGHTS' message: {bad.get('error')!r}")
    slow = table.get(("15e6", "1000000000"), {})
    check(slow.get("status") == "failed" and "timed out after --case-timeout" in slow.get("error", ""),
          f"endless case killed at the timeout: {slow.get('error')!r}")
    # A timeout below the tool's old 0.2 s poll slice is enforced too: a
    # case of 20000 steps (~1 s) at --case-timeout 0.03
    # is killed at 0.03 s (it ran to completion before).
    run("short_timeout.csv", 1, ["--var", "E", "15e6", "--var", "steps", "20000", "--case-timeout", "0.03"])
    short = rows("short_timeout.csv")
    check(len(short) == 1 and short[0]["status"] == "failed" and "timed out after --case-timeout 0.03 s" in
          short[0]["error"] and float(short[0]["wall_s"]) < 0.1,
          f"a 0.03 s timeout kills a ~1 s case within 0.1 s: {short}")
    log_dir = os.path.join(work, "failure_logs")
    kept = sorted(f for f in os.listdir(log_dir) if f.startswith("case"))
    check(len(kept) == 3, f"logs kept for the 3 failed cases only: {kept}")
elif test == "regime":
    clogging = os.path.join(HERE, "..", "..", "examples", "clogging")
    cmd = [sweep, "--in", os.path.join(clogging, "in.clogging"), "--workdir", clogging,
           "--output", os.path.join(work, "regime.csv"), "--fresh",
           "--var", "model", "local", "--var", "E", "15e6", "--var", "ratio", "1,2",
           "--measure", "outcome=f_out[2]", "--measure", "first_contact_t=f_out[3]", "--measure", "x=c_shape[2]"]
    before = set(os.listdir(clogging))
    done = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=300)
    print(done.stdout[-1500:], done.stderr[-1500:])
    check(done.returncode == 0, f"hsrod-sweep on in.clogging exits with 0 (got {done.returncode})")
    table = {r["ratio"]: r for r in rows("regime.csv")}
    short, long_ = table.get("1", {}), table.get("2", {})
    check(short.get("status") == "ok" and short.get("outcome") == "1"
          and float(short.get("first_contact_t", "0")) < 0 and float(short.get("x", "0")) > 385e-6,
          f"L_rod = d_pore passes without wall contact, centre past the pore: {short}")
    check(long_.get("status") == "ok" and long_.get("outcome") == "3" and float(long_.get("first_contact_t", "-1")) > 0
          and float(long_.get("x", "1")) < 300e-6,
          f"L_rod = 2 d_pore clogs after a wall contact, centre in front of the throat: {long_}")
    # Files other tests or a user leave there do not count; only this sweep's.
    written = [f for f in set(os.listdir(clogging)) - before if f.startswith("clog_") or f.startswith("dump_")]
    check(not written, f"the swept cases wrote no CSV or VTK files into the example folder: {written}")
elif test == "rods":
    several = os.path.join(HERE, "..", "..", "examples", "several-rods")
    cmd = [sweep, "--in", os.path.join(several, "in.several_rods"), "--workdir", several,
           "--output", os.path.join(work, "rods.csv"), "--fresh",
           "--var", "model", "local", "--var", "spheres", "11", "--var", "nrods", "1,2",
           "--measure", "atoms=atoms", "--measure", "clogged=f_out[7]", "--measure", "held=f_out[11]",
           "--measure", "decided=f_out[1]"]
    done = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=300)
    print(done.stdout[-1500:], done.stderr[-1500:])
    check(done.returncode == 0, f"hsrod-sweep on in.several_rods exits with 0 (got {done.returncode})")
    table = {r["nrods"]: r for r in rows("rods.csv")}
    one, two = table.get("1", {}), table.get("2", {})
    check(one.get("status") == "ok" and one.get("atoms") == "11" and one.get("clogged") == "1"
          and one.get("held") == "0" and one.get("decided") == "1",
          f"one rod of 1.1 d_pore: 11 spheres, trapped at the cylinders: {one}")
    check(two.get("status") == "ok" and two.get("atoms") == "22" and two.get("clogged") == "2"
          and two.get("held") == "1" and two.get("decided") == "1",
          f"two rods: 22 spheres, both clogged, the second held by the first: {two}")
else:
    sys.exit(f"unknown test {test}")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("all checks passed")
