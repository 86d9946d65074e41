"""Coupled smoke run: three touching spheres (a 3-bead rod without bonds,
stock LIGGGHTS granular spheres, Hertz contacts, wall/gran planes) released
in a channel flow, rodIbFoam <-> LIGGGHTS through fix couple/cfd (mpi) +
couple/cfd/force with torque, 8 coupling intervals of 50 DEM steps.

Checks (each could fail):
  - momentum exchange: after the first interval the total DEM momentum
    sum m v equals the pushed impulse sum F (N - 1/2) dt_DEM within 1 %
    (velocity Verlet applies the new force from the second half-step on);
  - the spheres are carried downstream (x grows, mean v_x > 0) and stay
    bounded (|v| below twice the peak channel speed);
  - the report of the coupling criteria was printed.
Dense spheres (rho_p = 8000 kg/m^3) keep the explicit exchange stable
(gain G = 0.28); light ones are refused by the solver (see test_core).
"""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct


def main():
    env = ct.Env(sys.argv)
    with open(os.path.join(ct.HERE, "scenes", "coupled_rod.json")) as f:
        scene = json.load(f)
    case = env.make_case("coupled_rod.json", "coupled_rod")
    e = dict(env.env, RODIBFOAM=env.solver)
    r = subprocess.run([os.path.join(case, "Allrun")], env=e, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    log = open(os.path.join(case, "log.rodIbFoam")).read()
    if r.returncode != 0:
        print(r.stdout, log[-3000:])
        sys.exit("coupled run failed")
    rows = ct.read_csv(os.path.join(case, "postProcessing", "rodIbFoam", "sphereForces.csv"))
    times = sorted({float(x["t"]) for x in rows})
    at = lambda t: [x for x in rows if float(x["t"]) == t]
    dem = scene["dem"]
    d = scene["rod"]["d"]
    m = dem["rho_p"] * math.pi * d ** 3 / 6
    N, dt = dem["coupling_interval"], dem["dt"]
    first, second, last = at(times[0]), at(times[1]), at(times[-1])
    impulse = sum(float(x["Fx"]) for x in first) * (N - 0.5) * dt
    momentum = sum(m * float(x["vx"]) for x in second)
    err = momentum / impulse - 1
    print("first interval: impulse %.6e N s, DEM momentum %.6e N s, difference %+.3f %%"
          % (impulse, momentum, 100 * err))
    dx = [float(b["x"]) - float(a["x"]) for a, b in zip(first, last)]
    vmax = max(math.sqrt(sum(float(x[k]) ** 2 for k in ("vx", "vy", "vz"))) for x in rows)
    vmean = sum(float(x["vx"]) for x in last) / len(last)
    U = scene["inflow"]["U"]
    print("after %d intervals: displacement %s m, mean v_x %.4g m/s, max |v| %.4g m/s (mean inflow %.3g m/s)"
          % (len(times), " ".join("%.3g" % v for v in dx), vmean, vmax, U))
    ok = ct.check("coupled to LIGGGHTS: 3 spheres" in log, "LIGGGHTS coupled, 3 spheres")
    ok &= ct.check("explicit coupling gain G" in log, "coupling criteria reported")
    ok &= ct.check(abs(err) < 0.01, "momentum exchange consistent within 1 %% (%+.3f %%)" % (100 * err))
    ok &= ct.check(all(v > 0 for v in dx) and vmean > 0, "spheres carried downstream")
    ok &= ct.check(vmax < 2 * 2.2 * U, "velocities bounded (max %.3g m/s)" % vmax)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
