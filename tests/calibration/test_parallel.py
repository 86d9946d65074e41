"""Parallel runs: a 3-sphere rod in a channel (locally refined with
topoSet + refineMesh, transient PIMPLE, 10 steps) on 1 and on 2 MPI ranks
(decomposePar, simple 2x1x1) must give the same sphere forces within the
linear-solver tolerance (relative difference < 1e-3 of the largest force).
Also exercises the generated Allrun (blockMesh, 2 refinement levels).
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct


def main():
    env = ct.Env(sys.argv)
    case = env.make_case("rod_in_channel.json", "rod_serial")
    e = dict(env.env, RODIBFOAM=env.solver)
    r = subprocess.run([os.path.join(case, "Allrun")], env=e, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    print(r.stdout)
    if r.returncode != 0:
        sys.exit("serial Allrun failed")
    par = os.path.join(env.work, "rod_parallel")
    shutil.rmtree(par, ignore_errors=True)
    shutil.copytree(case, par, ignore=shutil.ignore_patterns("postProcessing", "[1-9]*", "log.*"))
    for d in os.listdir(par):
        if d.replace(".", "").replace("e-", "").isdigit() and d != "0":
            shutil.rmtree(os.path.join(par, d))
    with open(os.path.join(par, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n")
    subprocess.run(["decomposePar", "-case", par], env=env.env, check=True, stdout=subprocess.DEVNULL)
    mpi = ["mpirun", "-np", "2"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    r = subprocess.run(mpi + [env.solver, "-case", par, "-parallel"], env=env.env,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        print(r.stdout[-3000:])
        sys.exit("parallel run failed")
    s, p = ct.last_loads(case), ct.last_loads(par)
    fmax = max(abs(float(x[k])) for x in s for k in ("Fx", "Fy", "Fz"))
    diff = max(abs(float(a[k]) - float(b[k])) for a, b in zip(s, p) for k in ("Fx", "Fy", "Fz"))
    for a, b in zip(s, p):
        print("sphere %s: serial Fx %.6e  parallel Fx %.6e" % (a["id"], float(a["Fx"]), float(b["Fx"])))
    ok = ct.check(len(s) == 3 and len(p) == 3, "three spheres reported by both runs")
    ok &= ct.check(diff < 1e-3 * fmax, "1 and 2 ranks agree: max |dF| / max |F| = %.2e < 1e-3" % (diff / fmax))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
