#!/usr/bin/env python3
"""Calibration of the sphere columns of hsrod's confinement table against
rodIbFoam (not a CI test). For each beta = d/H, a sphere of d = 3 um at the
mid-plane, creeping flow, steady (pseudo-time) runs:

  friction  sphere dragged at U through fluid between resting plates
            (scene kind sphereBetweenPlates, sphere frame; lateral faces 4 H
            away, 8 cells per d)                      -> sample (u = 0, v = -U)
  driving   sphere held in pressure-driven flow in a W = L = 4 H channel
            (flow-rate inlet, side walls, base mesh 3.6/beta cells across H,
            two refinement levels around the sphere: d/h ~ 14; at d/h = 7.2
            the force was 3 % lower, see results.md);
            u = the undisturbed gap-averaged velocity at the sphere, from the
            rectangular-duct series (centre line of a W x H duct)
                                                      -> sample (u, v = 0)

The samples go to calibration/data/resolved_sphere_samples.csv and through
hsrod_fit_confinement (calibration/core/confinement_fit.h) into
calibration/data/confinement_rodibfoam.txt (format
"hsrod-confinement-coefficients 1"). With --rod-betas, a rigid rod of
10 touching spheres along / across the flow is dragged (same plates scene,
"rod") and held in channel flow (u = mean of the duct series over its
spheres) for the rod columns; columns without runs stay the defaults. The
fitted values are compared with Faxen's two-wall friction and Faxen's law
1.5 (1 - beta^2/3) in calibration/validation/results.md (section 4).

Usage: run_fit.py RODIBFOAM HSROD_FIT_CONFINEMENT [WORKDIR] [--betas 0.2,0.3]
"""
import argparse
import math
import os
import platform
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TOOL = os.path.join(ROOT, "calibration", "tools", "hsrod_case.py")
SCENES = os.path.join(ROOT, "tests", "calibration", "scenes")
DATA = os.path.join(ROOT, "calibration", "data")
D, MU, RHO, U = 3e-6, 1e-3, 1000.0, 1e-3


def env():
    return dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))


def make(scene, case, sets):
    shutil.rmtree(case, ignore_errors=True)
    cmd = [sys.executable, TOOL, scene, case]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def run(solver, case, total=False):
    t0 = time.time()
    r = subprocess.run([os.path.join(case, "Allrun")], env=dict(env(), RODIBFOAM=solver),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        raise RuntimeError(case + " failed:\n" + r.stdout[-3000:])
    log = open(os.path.join(case, "log.rodIbFoam")).read()
    summ = [l for l in log.splitlines() if l.startswith("rodIbFoam:")][0].split()
    rows = [l.strip().split(",") for l in open(os.path.join(case, "postProcessing", "rodIbFoam",
                                                            "sphereForces.csv")) if not l.startswith("#")]
    t_last = rows[-1][0]
    fxs = [float(r[rows[0].index("Fx")]) for r in rows[1:] if r[0] == t_last]
    fx = sum(fxs) if total else fxs[-1]
    return fx, time.time() - t0, int(summ[3]), int(summ[1]), "steady state reached" in log


def duct_gap_velocity_over_mean(y, W, H, nmax=201):
    """Gap-averaged velocity at lateral position y (0 <= y <= W) of fully
    developed flow in a W x H duct over the duct's mean velocity (Fourier
    series of rectangular Poiseuille flow)."""
    num = den = 0.0
    s = abs(2 * y / W - 1)
    for n in range(1, nmax, 2):
        k = n * math.pi * W / (2 * H)
        ratio = math.exp(k * (s - 1)) * (1 + math.exp(-2 * k * s)) / (1 + math.exp(-2 * k))  # cosh(k s)/cosh(k)
        num += (1 - ratio) / n ** 4
        den += (1 - math.tanh(k) / k) / n ** 4
    return num / den


def duct_centre_over_mean(W, H, nmax=201):
    """Gap-averaged velocity on the centre line y = W/2 of a W x H duct over
    the duct's mean velocity (Fourier series of rectangular Poiseuille flow)."""
    num = den = 0.0
    for n in range(1, nmax, 2):
        k = n * math.pi * W / (2 * H)
        num += (1 - 2 * math.exp(-k) / (1 + math.exp(-2 * k))) / n ** 4
        den += (1 - math.tanh(k) / k) / n ** 4
    return num / den


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("solver")
    ap.add_argument("fit")
    ap.add_argument("work", nargs="?", default="/tmp/hsrod-fit")
    ap.add_argument("--betas", default="0.2,0.3,0.45")
    ap.add_argument("--rod-betas", default="0.3", help="betas of the rigid 10-sphere rod runs ('' for none)")
    a = ap.parse_args()
    a.solver, a.fit = os.path.abspath(a.solver), os.path.abspath(a.fit)
    os.makedirs(a.work, exist_ok=True)
    os.makedirs(DATA, exist_ok=True)
    betas = [float(b) for b in a.betas.split(",")]
    samples = ["# resolved rodIbFoam runs (run_fit.py, %s); SI" % time.strftime("%Y-%m-%d"),
               "beta,body,n_spheres,d,mu,u_mean,v,force"]
    record = []
    for beta in betas:
        H = D / beta
        # friction: sphere frame, plates and far field at +U = sphere at -U in the lab
        case = os.path.join(a.work, "friction_%g" % beta)
        make(os.path.join(SCENES, "sphere_between_plates.json"), case,
             ["beta=%g" % beta, "U=%g" % U, "mesh.cells_per_diameter=8"])
        fx, secs, cells, its, conv = run(a.solver, case)
        samples.append("%g,sphere,1,%g,%g,0,%g,%.10e" % (beta, D, MU, -U, fx))
        record.append((beta, "friction", fx, fx / (3 * math.pi * MU * D * U), cells, its, conv, secs))
        print(record[-1], flush=True)
        # driving: sphere held in channel flow
        W = L = 4 * H
        nz = int(round(3.6 / beta))          # base cells across H; 2 refinement levels -> d/h ~ 14
        nxy = int(round(4 * nz))
        case = os.path.join(a.work, "driving_%g" % beta)
        make(os.path.join(SCENES, "sphere_in_channel_flow.json"), case,
             ["channel.L=%g" % L, "channel.W=%g" % W, "channel.H=%g" % H,
              "mesh.nx=%d" % nxy, "mesh.ny=%d" % nxy, "mesh.nz=%d" % nz,
              "spheres=[{\"id\":1,\"x\":[%g,%g,%g],\"d\":%g}]" % (0.5 * L, 0.5 * W, 0.5 * H, D),
              "refine.margin=%g" % (0.5 * D)])
        fx, secs, cells, its, conv = run(a.solver, case)
        u_loc = U * duct_centre_over_mean(W, H)
        samples.append("%g,sphere,1,%g,%g,%.10e,0,%.10e" % (beta, D, MU, u_loc, fx))
        record.append((beta, "driving", fx, fx / (3 * math.pi * MU * D * u_loc), cells, its, conv, secs))
        print(record[-1], "u_loc/U = %.5f" % (u_loc / U), flush=True)
    # rigid rod of 10 touching spheres along (parallel) / across (perpendicular) the flow
    rod_betas = [float(b) for b in a.rod_betas.split(",") if b.strip()]
    n_rod = 10
    for beta in rod_betas:
        H = D / beta
        for body, angle in (("rod_parallel", 0.0), ("rod_perpendicular", 90.0)):
            case = os.path.join(a.work, "%s_friction_%g" % (body, beta))
            make(os.path.join(SCENES, "sphere_between_plates.json"), case,
                 ["beta=%g" % beta, "U=%g" % U, "mesh.cells_per_diameter=8",
                  "rod={\"n\":%d,\"angle_deg\":%g}" % (n_rod, angle)])
            fx, secs, cells, its, conv = run(a.solver, case, total=True)
            samples.append("%g,%s,%d,%g,%g,0,%g,%.10e" % (beta, body, n_rod, D, MU, -U, fx))
            record.append((beta, body + " friction", fx, fx / n_rod / (3 * math.pi * MU * D * U), cells, its,
                           conv, secs))
            print(record[-1], flush=True)
            along = angle == 0.0
            Lr = n_rod * D
            L = 4 * H + (Lr if along else D)
            W = 4 * H + (D if along else Lr)
            nz = int(math.ceil(2.0 / beta))      # 2 refinement levels -> d/h ~ 8
            h = H / nz
            case = os.path.join(a.work, "%s_driving_%g" % (body, beta))
            make(os.path.join(SCENES, "sphere_in_channel_flow.json"), case,
                 ["channel.L=%g" % L, "channel.W=%g" % W, "channel.H=%g" % H,
                  "mesh.nx=%d" % int(round(L / h)), "mesh.ny=%d" % int(round(W / h)), "mesh.nz=%d" % nz,
                  "spheres=[]", "rod={\"n\":%d,\"d\":%g,\"centre\":[%g,%g,%g],\"angle_deg\":%g}"
                  % (n_rod, D, 0.5 * L, 0.5 * W, 0.5 * H, angle),
                  "refine.margin=%g" % (0.5 * D)])
            fx, secs, cells, its, conv = run(a.solver, case, total=True)
            ys = [0.5 * W + (i - 0.5 * (n_rod - 1)) * D * (0.0 if along else 1.0) for i in range(n_rod)]
            u_loc = U * sum(duct_gap_velocity_over_mean(y, W, H) for y in ys) / n_rod
            samples.append("%g,%s,%d,%g,%g,%.10e,0,%.10e" % (beta, body, n_rod, D, MU, u_loc, fx))
            record.append((beta, body + " driving", fx, fx / n_rod / (3 * math.pi * MU * D * u_loc), cells, its,
                           conv, secs))
            print(record[-1], "u_loc/U = %.5f" % (u_loc / U), flush=True)

    spath = os.path.join(DATA, "resolved_sphere_samples.csv")
    with open(spath, "w") as f:
        f.write("\n".join(samples) + "\n")
    tpath = os.path.join(DATA, "confinement_rodibfoam.txt")
    r = subprocess.run([a.fit, spath, tpath, "--source",
                        "rodIbFoam steady runs, d = 3 um, 8 cells/d (friction) and d/h ~ 14 (driving); "
                        "calibration/validation/run_fit.py"],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, check=True)
    print(r.stdout)
    # table for results.md
    fitted = {}
    for line in r.stdout.splitlines():
        if line.startswith("beta") and "sphere_friction" in line:
            p = line.replace(":", "").split()
            fitted[float(p[1])] = tuple(float(p[k]) for k in (3, 5, 7, 9, 11, 13))
    md = ["## 4. Sphere columns of the confinement table from resolved runs (run_fit.py, %s, %s)"
          % (time.strftime("%Y-%m-%d"), platform.node()), "",
          "Fit: `hsrod_fit_confinement` (F = a u - b v per beta); output "
          "`calibration/data/confinement_rodibfoam.txt`, samples `calibration/data/resolved_sphere_samples.csv`.", "",
          "| beta | sphere_friction | Faxen | diff | sphere_driving | 1.5 (1 - beta^2/3) | diff | cells (friction / driving) | time [s] |",
          "|---|---|---|---|---|---|---|---|---|"]
    for beta in betas:
        sf, sd = fitted[beta][:2]
        fax = 1 / (1 - 1.004 * beta + 0.418 * beta ** 3 + 0.21 * beta ** 4 - 0.169 * beta ** 5)
        law = 1.5 * (1 - beta ** 2 / 3)
        rr = [x for x in record if x[0] == beta]
        md.append("| %.2f | %.4f | %.4f | %+.2f %% | %.4f | %.4f | %+.2f %% | %d / %d | %.0f |"
                  % (beta, sf, fax, 100 * (sf / fax - 1), sd, law, 100 * (sd / law - 1),
                     rr[0][4], rr[1][4], rr[0][7] + rr[1][7]))
    if rod_betas:
        md += ["", "Rigid rod of %d touching spheres (8 cells per d dragged; d/h ~ 8 held in flow):" % n_rod, "",
               "| beta | parallel_friction | perpendicular_friction | parallel_driving | perpendicular_driving | time [s] |",
               "|---|---|---|---|---|---|"]
        for beta in rod_betas:
            c = fitted[beta]
            secs = sum(x[7] for x in record if x[0] == beta and x[1].startswith("rod"))
            md.append("| %.2f | %.4f | %.4f | %.4f | %.4f | %.0f |" % (beta, c[2], c[3], c[4], c[5], secs))
    conv = all(x[6] for x in record)
    md += ["", "All runs reached the steady tolerance: %s." % ("yes" if conv else "NO (see the work directory)"), ""]
    with open(os.path.join(a.work, "results_fit.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
