"""Bad input must stop rodIbFoam with a clear message before any time step:
  1. a sphere outside the mesh,
  2. a mesh too coarse for the sphere (below minCellsPerDiameter),
  3. a coupling interval that breaks the solid-fluid criterion,
and the same scene with good input must pass the checks (-checkOnly).
The scene asks for 1e4 time steps, so "before any time is spent" is
checked as: no "Time =" line in the log and the run ends within 20 s.
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct

CASES = [
    ("outside", ['spheres=[{"id":7,"x":[30e-6,45e-6,7.5e-6],"d":4e-6}]'], "lies outside the mesh"),
    ("coarse", ['spheres=[{"id":7,"x":[30e-6,15e-6,7.5e-6],"d":4e-6}]'], "mesh too coarse for the spheres"),
    ("coupling", ["ib.rhoParticle=1170", "ib.demTimeStep=1e-7", "ib.couplingInterval=100"],
     "breaks the solid-fluid criterion"),
]


def main():
    env = ct.Env(sys.argv)
    ok = True
    for name, sets, expect in CASES:
        case = env.make_case("bad_input.json", "bad_" + name, sets)
        rc, log, secs = env.run(case, expect_ok=False)
        msg = [l.strip() for l in log.splitlines() if expect in l]
        print("%-9s rc=%d %.1f s: %s" % (name, rc, secs, msg[0] if msg else "(message missing)"))
        ok &= ct.check(rc != 0, "%s: solver refuses the input" % name)
        ok &= ct.check(bool(msg), "%s: message '%s' given" % (name, expect))
        ok &= ct.check("Time = " not in log and secs < 20, "%s: stopped before the first time step" % name)
    # the unmodified scene (d = 8 um: 4.3 cells per diameter, limit 4) passes the checks
    case = env.make_case("bad_input.json", "good_input")
    subprocess.run(["blockMesh", "-case", case], env=env.env, stdout=subprocess.DEVNULL, check=True)
    r = subprocess.run([env.solver, "-case", case, "-checkOnly"], env=env.env,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print("\n".join(l for l in r.stdout.splitlines() if l.startswith("  ")))
    ok &= ct.check(r.returncode == 0 and "input accepted" in r.stdout, "good input accepted")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
