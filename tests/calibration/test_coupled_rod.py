"""Coupled smoke run with hsrod's own rod: a 3-sphere rod made by
create_rod and held together by fix rod/bonds (the same styles as the
reduced runs, registered in the coupled LIGGGHTS instance as in the hsrod
executable), released in a channel flow at rho_p/rho_f = 1.12 (the paper's
Hele-Shaw scene), rodIbFoam <-> LIGGGHTS through fix couple/cfd (mpi) +
couple/cfd/force/implicit + couple/cfd/torque/implicit (semi-implicit
exchange, calibration/core/momentum_exchange.h), 8 coupling intervals of 50
DEM steps, tiny refined mesh.

Checks (each could fail):
  - momentum exchange: after the first loaded interval the mean DEM velocity
    of the rod equals the velocity-Verlet integration of
        (m_p + m_v) dv/dt = F_mean + Ksl (u_f - v),  u_f = v^n = 0,
    with the load F the solver wrote, Ksl = 3 pi mu d and m_v the printed
    virtual mass (the bond forces cancel in the mean), within 1e-4;
  - the bonds hold: neighbour distances stay d within 1 %;
  - the rod is carried downstream (x grows, mean v_x > 0), stays bounded;
  - rodMeasures.csv: one row per interval (+ the start), its centre of mass
    and v_x / U agree with the sphere data of sphereForces.csv, eq. (1)
    angle -90 deg for a rod along the flow (paper convention: 0 = across),
    deflection eq. (2) and lateral offset ~ 0 in this symmetric set-up;
  - a DEM input without fix couple/cfd/force/implicit is refused with a
    clear error before the first step.
"""
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct


def verlet_mean_velocity(F, Ksl, mstar, dt, N):
    """LIGGGHTS' velocity Verlet over one interval started with `run N pre no`:
    the first half-kick still uses the previous (zero) load; post_force adds
    F + Ksl (0 - v) with the half-step velocity."""
    v, f = 0.0, 0.0
    for _ in range(N):
        v += 0.5 * dt * f / mstar
        f = F - Ksl * v
        v += 0.5 * dt * f / mstar
    return v


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
    dem_log = open(os.path.join(case, "log.liggghts")).read()
    rows = ct.read_csv(os.path.join(case, "postProcessing", "rodIbFoam", "sphereForces.csv"))
    times = sorted({float(x["t"]) for x in rows})
    at = lambda t: sorted([x for x in rows if float(x["t"]) == t], key=lambda x: int(x["id"]))
    dem = scene["dem"]
    d = scene["rod"]["d"]
    mu, rho_f = scene["fluid"]["mu"], scene["fluid"]["rho"]
    vol = math.pi * d ** 3 / 6
    cv = float(re.search(r"virtual mass ([0-9.eE+-]+) rho_f V\)", log).group(1))
    mstar = dem["rho_p"] * vol + cv * rho_f * vol
    N, dt = dem["coupling_interval"], dem["dt"]
    first, second, last = at(times[0]), at(times[1]), at(times[-1])
    Fmean = sum(float(x["Fx"]) for x in first) / len(first)
    v_expect = verlet_mean_velocity(Fmean, 3 * math.pi * mu * d, mstar, dt, N)
    v_dem = sum(float(x["vx"]) for x in second) / len(second)
    err = v_dem / v_expect - 1
    print("virtual mass %.4g rho_f V; first loaded interval: mean load %.6e N, mean DEM v_x %.8e m/s, "
          "semi-implicit Verlet model %.8e m/s, difference %+.2e" % (cv, Fmean, v_dem, v_expect, err))
    # bonds: neighbour distances
    worst = 0.0
    for t in times:
        s = at(t)
        for a, b in zip(s, s[1:]):
            dist = math.sqrt(sum((float(a[k]) - float(b[k])) ** 2 for k in ("x", "y", "z")))
            worst = max(worst, abs(dist / d - 1))
    dx = [float(b["x"]) - float(a["x"]) for a, b in zip(first, last)]
    vmax = max(math.sqrt(sum(float(x[k]) ** 2 for k in ("vx", "vy", "vz"))) for x in rows)
    vmean = sum(float(x["vx"]) for x in last) / len(last)
    U = scene["inflow"]["U"]
    print("after %d intervals: displacement %s m, mean v_x %.4g m/s, max |v| %.4g m/s (mean inflow %.3g m/s); "
          "largest bond strain %.2e" % (len(times), " ".join("%.3g" % v for v in dx), vmean, vmax, U, worst))
    # rod measures
    rm = ct.read_csv(os.path.join(case, "postProcessing", "rodIbFoam", "rodMeasures.csv"))
    print("rodMeasures.csv: %d rows; last: %s" % (len(rm), ", ".join("%s=%s" % kv for kv in rm[-1].items())))
    consistent = True
    for t in times:
        row = [x for x in rm if abs(float(x["t"]) - t) < 1e-12 * max(1.0, t) + 1e-15]
        s = at(t)
        if len(row) != 1:
            consistent = False
            continue
        xc = sum(float(x["x"]) for x in s) / len(s)
        vx = sum(float(x["vx"]) for x in s) / len(s)
        consistent &= abs(float(row[0]["x_com"]) - xc) < 1e-6 * d
        consistent &= abs(float(row[0]["vx_over_U"]) - vx / U) < 1e-6 * max(1.0, abs(vx / U))
    ok = ct.check("coupled to LIGGGHTS: 3 spheres" in log, "LIGGGHTS coupled, 3 spheres")
    ok &= ct.check("create_rod: rod mol 1: 3 spheres" in dem_log and "fix rod/bonds" in dem_log,
                   "rod made by create_rod, bonds by fix rod/bonds")
    ok &= ct.check("exchange semi-implicit gain" in log, "exchange criterion reported")
    ok &= ct.check(abs(err) < 1e-4, "semi-implicit momentum exchange as modelled within 1e-4 (%+.2e)" % err)
    ok &= ct.check(worst < 0.01, "bonds hold: neighbour distance = d within 1 %% (%.2e)" % worst)
    ok &= ct.check(all(v > 0 for v in dx) and vmean > 0, "rod carried downstream")
    ok &= ct.check(vmax < 2 * 2.2 * U, "velocities bounded (max %.3g m/s)" % vmax)
    ok &= ct.check(len(rm) == len(times) + 1, "rod measures: one row per interval plus the start (%d)" % len(rm))
    ok &= ct.check(consistent, "rod measures consistent with the sphere data (centre, v_x / U)")
    ok &= ct.check(all(abs(float(x["angle_deg"]) + 90) < 0.1 for x in rm), "eq. (1) angle -90 deg (along x)")
    ok &= ct.check(all(float(x["deflection"]) < 1e-3 and abs(float(x["lateral_over_W"])) < 1e-3 for x in rm),
                   "deflection eq. (2) and lateral offset ~ 0 (symmetric set-up)")
    # bad input: the DEM script lacks the implicit force fix the exchange needs
    inp = os.path.join(case, "in.liggghts")
    text = open(inp).read()
    text = "\n".join(l for l in text.splitlines() if "couple/cfd/torque/implicit" not in l) + "\n"
    open(inp, "w").write(text.replace("couple/cfd/force/implicit", "couple/cfd/force"))
    rb = subprocess.run([env.solver, "-case", case], env=env.env, stdout=subprocess.PIPE,
                        stderr=subprocess.STDOUT, text=True)
    msg = [l.strip() for l in rb.stdout.splitlines() if "exchange semiImplicit needs" in l]
    print("DEM input without couple/cfd/force/implicit: rc %d, %s" % (rb.returncode, msg[0] if msg else "no message"))
    ok &= ct.check(rb.returncode != 0 and msg and "Time = " not in rb.stdout,
                   "exchange/DEM-input mismatch refused before the first step")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
