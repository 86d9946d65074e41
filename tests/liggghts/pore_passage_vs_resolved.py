"""hsrod's default level on the dynamic pore-passage scene against the
recorded resolved run (calibration/validation/pore_passage/).

Runs calibration/validation/pore_passage/in.passage with model auto (the
default; it chooses level 2 here, as printed) and compares the paper's
measures with the recorded coupled rodIbFoam + LIGGGHTS run (resolved.csv):

  - passage time from the pore entry (pore centre - 1.5 R) to the exit
    (pore centre + 1.5 R), station to station;
  - rotation in the pore: peak angle (eq. 1) minus the initial 10 deg;
  - lateral displacement / W after the pore (rod centre at pore centre + 2 R).

Tolerances, from the uncertainty of the resolved run (README.md beside the
run): the larger of 3 % of the resolved value (the mesh uncertainty of
rodIbFoam's rod driving by its own record; velocities, hence times, rotation
rates and drift, scale with it) and the reference's estimated numerical
error (resolved_uncertainty.json: Richardson estimates of its mesh and step
errors from its recorded mesh and step series, root sum of squares; it is
what bounds the small lateral drift, a difference of two loads of ~0.9 U
each), plus the resolved run's
own sampling noise (the interval-to-interval wobble of the measure from the
exchange's oscillatory root, measured in the record). Not widened to make a
level pass.

Usage: pore_passage_vs_resolved.py HSROD_BINARY [--only-passage-time] [--model M] [--reflection R]

--only-passage-time checks the first measure alone (the part the default
level meets today; the whole check is a disabled test until the drift is right).
--model M, --reflection R: in.passage's model (default auto) and level 3's
wall_reflection (default none) in place of the default level.
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
PASSAGE = os.path.join(ROOT, "calibration", "validation", "pore_passage")
sys.path.insert(0, PASSAGE)
import passage_measures as pm  # noqa: E402

MESH_UNCERTAINTY = 0.03  # relative, rodIbFoam's rod driving (calibration/README.md)


def wobble(rows, col):
    """Largest deviation of a sample from the mean of its neighbours (the
    resolved run's interval-to-interval noise of a measure)."""
    return max(abs(rows[i][col] - 0.5 * (rows[i - 1][col] + rows[i + 1][col])) for i in range(1, len(rows) - 1))


def option(name, default):
    args = sys.argv[2:]
    return args[args.index(name) + 1] if name in args else default


def main():
    hsrod = os.path.abspath(sys.argv[1])
    model, reflection = option("--model", "auto"), option("--reflection", "none")
    ref = pm.read_run(os.path.join(PASSAGE, "resolved.csv"))
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "run.csv")
        r = subprocess.run([hsrod, "-in", os.path.join(PASSAGE, "in.passage"), "-var", "model", model,
                            "-var", "reflection", reflection, "-var", "out", out, "-log", os.path.join(tmp, "log.run")],
                           cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if r.returncode != 0:
            print(r.stdout[-3000:])
            sys.exit("hsrod run failed")
        choice = [l for l in r.stdout.splitlines() if "auto:" in l]
        run = pm.read_run(out)
    print(choice[0] if choice else "model %s, wall_reflection %s" % (model, reflection))
    sc = pm.scene()
    s_ref, s = pm.summary(ref, sc), pm.summary(run, sc)
    rot_ref, rot = s_ref["rotation"], s["rotation"]  # peak angle - the paper's initial angle
    with open(os.path.join(PASSAGE, "resolved_uncertainty.json")) as f:
        measured = json.load(f)["uncertainty"]  # t_pass [s], rotation [deg], lateral_after [-]
    checks = [
        ("passage time entry -> exit [ms]", s["t_pass"] * 1e3, s_ref["t_pass"] * 1e3,
         max(MESH_UNCERTAINTY * s_ref["t_pass"], measured["t_pass"]) * 1e3),
        ("rotation in the pore, peak angle - initial [deg]", rot, rot_ref,
         max(MESH_UNCERTAINTY * abs(rot_ref), measured["rotation"]) + wobble(ref, "angle_deg")),
        ("lateral displacement / W after the pore", s["lateral_after"], s_ref["lateral_after"],
         max(MESH_UNCERTAINTY * abs(s_ref["lateral_after"]), measured["lateral_after"])
         + wobble(ref, "lateral_over_W")),
    ]
    if "--only-passage-time" in sys.argv[2:]:
        checks = checks[:1]
    ok = True
    for name, got, want, tol in checks:
        good = abs(got - want) <= tol
        ok &= good
        print("%s %s: reduced model %.5g, resolved %.5g, difference %+.3g (tolerance %.3g)"
              % ("PASS" if good else "FAIL", name, got, want, got - want, tol))
    print("pore passage: the reduced model %s the resolved run" % ("agrees with" if ok else "DISAGREES with"))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
