#!/usr/bin/env python3
"""Body-fitted cross-check of rodIbFoam's immersed boundary.

The same case as a campaign channelBody case -- channel L x W x H, side
walls y = 0 and y = W, plates z = 0 and H, flow-rate inlet at x = 0, outlet
p = 0 -- with the spheres cut out of the mesh instead of immersed:
Debian's OpenFOAM blockMesh (uniform background cells 2 d / 6) +
snappyHexMesh (sphere surface refined to level `lvl`, i.e. cells d / (3 2^lvl)
at the surface, three refinement shells around it) + simpleFoam (steady,
SIMPLEC, laminar, Re = U d / nu = 3e-6: Stokes flow), the force on the sphere
patch from the `forces` function object. Loads as in the campaign:
  friction: the spheres translate at -U e (e at drag_angle_deg = 45 degrees:
            along -x and towards the wall at once), lab frame, no inflow
            (sphere patch: fixedValue -U e);
  driving:  the spheres held (noSlip) in the channel flow of mean velocity U.
Forces over 3 pi mu d U, compared with the rodIbFoam results of the same
cases in calibration/campaign/geometry/results (meshes 6 / 8 / 10 cells per d).

    /usr/bin/python3 calibration/validation/body_fitted/run.py [--work DIR] [--levels 2 3] [--gaps 0.5 1.5]
writes calibration/validation/body_fitted/results.json and table.md.
The mesh is built in micrometres and scaled to metres (transformPoints): the
mesh-quality thresholds of snappyHexMesh are partly absolute.
"""
import argparse
import glob
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(ROOT, "calibration", "tools"))
import hsrod_case  # noqa: E402
import hsrod_campaign  # noqa: E402

PLAN = os.path.join(ROOT, "calibration", "campaign", "plan_geometry.json")
RESULTS = os.path.join(ROOT, "calibration", "campaign", "geometry", "results")
# Rows of spheres (--rows): three spheres 0.25 d apart (a near-contact chain a
# body-fitted mesh can resolve), their own small IBM campaign.
ROWS_PLAN = os.path.join(ROOT, "calibration", "campaign", "plan_body_fitted_rows.json")
ROWS_RESULTS = os.path.join(ROOT, "calibration", "campaign", "body-fitted-rows", "results")
UM = 1e-6
# Pseudo-time iterations per surface level: a lone sphere and the held rows
# meet the residual tolerances at levels 2-3 in ~300 iterations; on level 4,
# and for the dragged rows, the residuals stall above them while the force is
# steady to 1e-7 or better after ~300-400 (measured; the dragged row at level
# 2: 1e-10 at 480), so runs stop at 400 (level 4) or 800 iterations and are
# judged by the force change over the last 100 iterations.
END_TIME = {2: 800, 3: 800, 4: 400}
FORCE_CHANGE_TOLERANCE = 1e-5
ROWS_GAP = 1.5  # the rows' nearest surface gap to the wall [d] (plan_body_fitted_rows.json)

# snappyHexMeshDict of write_snappy: % (geometry, refinementSurfaces, refinementRegions, locationInMesh)
SNAPPY_HEX_MESH_DICT = """
castellatedMesh true;
snap true;
addLayers false;
geometry
{
%s}
castellatedMeshControls
{
    maxLocalCells 2000000;
    maxGlobalCells 4000000;
    minRefinementCells 0;
    maxLoadUnbalance 0.10;
    nCellsBetweenLevels 3;
    features ();
    refinementSurfaces
    {
%s    }
    resolveFeatureAngle 30;
    refinementRegions
    {
%s    }
    locationInMesh %s;
    allowFreeStandingZoneFaces true;
}
snapControls
{
    nSmoothPatch 3;
    tolerance 2.0;
    nSolveIter 100;
    nRelaxIter 5;
    nFeatureSnapIter 10;
    implicitFeatureSnap false;
    explicitFeatureSnap false;
    multiRegionFeatureSnap false;
}
addLayersControls
{
    relativeSizes true;
    layers {}
    expansionRatio 1.0;
    finalLayerThickness 0.3;
    minThickness 0.1;
    nGrow 0;
    featureAngle 60;
    nRelaxIter 3;
    nSmoothSurfaceNormals 1;
    nSmoothNormals 3;
    nSmoothThickness 10;
    maxFaceThicknessRatio 0.5;
    maxThicknessToMedialRatio 0.3;
    minMedialAxisAngle 90;
    nBufferCellsNoExtrude 0;
    nLayerIter 50;
}
meshQualityControls
{
    maxNonOrtho 65;
    maxBoundarySkewness 20;
    maxInternalSkewness 4;
    maxConcave 80;
    minVol 1e-13;
    minTetQuality 1e-15;
    minArea -1;
    minTwist 0.02;
    minDeterminant 0.001;
    minFaceWeight 0.05;
    minVolRatio 0.01;
    minTriangleTwist -1;
    nSmoothScale 4;
    errorReduction 0.75;
    relaxed { maxNonOrtho 75; }
}
mergeTolerance 1e-6;
"""


def foam(path, obj, body, cls="dictionary"):
    hsrod_case.foam_file(path, cls, obj, body)


def ibm_series(gap, n=1, plan_path=PLAN, angle=None):
    """The campaign's specs of the row of n spheres (a lone sphere by default)
    near the wall at `gap` (row angle `angle`, any if None): {(load, n_d): spec}."""
    plan = hsrod_campaign.load_plan(plan_path)
    out = {}
    for spec in hsrod_campaign.expand(plan):
        g = spec.get("geometry", {})
        if g.get("kind") == "wall" and spec["n"] == n and abs(g["gap"] - gap) < 1e-12 and (
                angle is None or abs(g["row_angle_deg"] - angle) < 1e-9):
            out[(spec["load"], spec["cells_per_diameter"])] = spec
    return out


def write_case(case, spec, level):
    """Body-fitted case of campaign spec `spec` (geometry wall) with sphere surface level `level`."""
    scene = hsrod_campaign.scene_of(spec)
    spheres = hsrod_case.channel_body_spheres(scene)
    d = scene["d"]
    H = d / scene["beta"]
    L, W = scene["channel"]["L"], scene["channel"]["W"]
    h0 = 2 * d / 6                                 # background cells, as the IBM's mesh 6 before refinement
    write_background_mesh(case, L, W, H, h0)
    write_snappy(case, spheres, level, d, L, W, H, h0)
    rho = write_fields(case, scene, W, H)
    write_controls(case, spheres, rho, level)
    return spheres, scene


def write_background_mesh(case, L, W, H, h0):
    """blockMesh of the channel in micrometres: uniform cells of about h0 [m]."""
    nx, ny, nz = (int(round(v / h0)) for v in (L, W, H))
    ax, ay, az = (hsrod_case.Axis.uniform(0, v / UM, k) for v, k in ((L, nx), (W, ny), (H, nz)))
    hsrod_case.write_block_mesh(case, ax, ay, az, {"xmin": ("inlet", "patch"), "xmax": ("outlet", "patch"),
                                                   "ymin": ("walls", "wall"), "ymax": ("walls", "wall"),
                                                   "zmin": ("walls", "wall"), "zmax": ("walls", "wall")})


def write_snappy(case, spheres, level, d, L, W, H, h0):
    """snappyHexMeshDict (micrometres): the spheres cut out of the background
    mesh, their surfaces refined to `level` inside three distance shells."""
    geo = "".join("    sphere%d { type searchableSphere; centre %s; radius %.12g; }\n"
                  % (s["id"], hsrod_case.vec([c / UM for c in s["x"]]), 0.5 * s["d"] / UM) for s in spheres)
    surf = "".join("        sphere%d { level (%d %d); patchInfo { type wall; inGroups (spheres); } }\n"
                   % (s["id"], level, level) for s in spheres)
    # refinement shells: distance from the surfaces (um) -> level
    shells = "".join("        sphere%d { mode distance; levels ((%.6g %d) (%.6g %d) (%.6g %d)); }\n"
                     % (s["id"], 0.25 * d / UM, level, 0.6 * d / UM, max(level - 1, 1), 1.4 * d / UM, max(level - 2, 1))
                     for s in spheres)
    # a fluid point away from the spheres and off the cell faces
    loc = (0.137 * L / UM + 0.01 * h0 / UM, 0.813 * W / UM + 0.013 * h0 / UM, 0.5 * H / UM + 0.017 * h0 / UM)
    foam(os.path.join(case, "system", "snappyHexMeshDict"), "snappyHexMeshDict",
         SNAPPY_HEX_MESH_DICT % (geo, surf, shells, hsrod_case.vec(loc)))


def write_fields(case, scene, W, H):
    """0/U, 0/p and the fluid's properties of the load (friction: the spheres
    translate, no inflow; driving: held spheres, flow-rate inlet); returns the
    density rho [kg/m^3] the forces are scaled with."""
    U = scene["U"]
    # SI; the mesh is scaled to metres before the solver runs
    nu = 1e-3                                      # m^2/s: Re = U d / nu = 3e-6 (Stokes); mu = rho nu
    rho = scene["fluid"]["mu"] / nu                # kg/m^3, so that mu = 1e-3 Pa s as in the campaign
    load = scene["load"]
    f = math.radians(scene.get("flow_angle_deg", 0.0))
    v = [-U * math.cos(f), -U * math.sin(f), 0.0] if load == "friction" else [0.0, 0.0, 0.0]
    q = U * W * H if load == "driving" else 0.0
    bcs = {"inlet": hsrod_case.bc_flowrate_inlet(q), "outlet": hsrod_case.bc_outlet(), "walls": hsrod_case.BC_WALL,
           "spheres": hsrod_case.bc_fixed_u(v)}
    ub = "".join("    %s\n    {\n%s    }\n" % (k, b["U"]) for k, b in bcs.items())
    pb = "".join("    %s\n    {\n%s    }\n" % (k, b["p"]) for k, b in bcs.items())
    ub = ub.replace("    spheres\n", "    \"spheres|sphere.*\"\n")
    pb = pb.replace("    spheres\n", "    \"spheres|sphere.*\"\n")
    foam(os.path.join(case, "0", "U"), "U", "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
         "boundaryField\n{\n%s}\n" % ub, "volVectorField")
    foam(os.path.join(case, "0", "p"), "p", "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\n"
         "boundaryField\n{\n%s}\n" % pb, "volScalarField")
    foam(os.path.join(case, "constant", "transportProperties"), "transportProperties",
         "transportModel Newtonian;\nnu %.12g;\n" % nu)
    foam(os.path.join(case, "constant", "turbulenceProperties"), "turbulenceProperties", "simulationType laminar;\n")
    return rho


def write_controls(case, spheres, rho, level):
    """controlDict (simpleFoam, `forces` function objects of the spheres),
    fvSchemes, fvSolution and decomposeParDict."""
    centre = [sum(s["x"][k] for s in spheres) / len(spheres) for k in range(3)]
    # the total on the sphere patches and, for a row, one forces object per sphere (patch sphere<id>)
    forces = forces_object("sphereForces", "spheres", rho, centre) + "".join(
        forces_object("sphere%dForces" % sp["id"], "sphere%d" % sp["id"], rho, sp["x"])
        for sp in spheres if len(spheres) > 1)
    foam(os.path.join(case, "system", "controlDict"), "controlDict", """application simpleFoam;
startFrom latestTime;
startTime 0;
stopAt endTime;
endTime %d;
deltaT 1;
writeControl timeStep;
writeInterval 100000;
purgeWrite 1;
writeFormat ascii;
writePrecision 10;
timeFormat general;
runTimeModifiable false;
functions
{
%s}
""" % (END_TIME.get(level, 3000), forces))
    foam(os.path.join(case, "system", "fvSchemes"), "fvSchemes",
         "ddtSchemes { default steadyState; }\ngradSchemes { default Gauss linear; }\n"
         "divSchemes { default none; div(phi,U) bounded Gauss linear; div((nuEff*dev2(T(grad(U))))) Gauss linear; }\n"
         "laplacianSchemes { default Gauss linear limited corrected 0.5; }\ninterpolationSchemes { default linear; }\n"
         "snGradSchemes { default limited corrected 0.5; }\nwallDist { method meshWave; }\n")
    foam(os.path.join(case, "system", "fvSolution"), "fvSolution", """solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-12; relTol 0.01; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-14; relTol 0.1; }
}
SIMPLE
{
    nNonOrthogonalCorrectors 1;
    consistent yes;
    residualControl { p 1e-7; U 1e-8; }
}
relaxationFactors
{
    equations { U 0.95; }
    fields { p 1; }
}
""")
    foam(os.path.join(case, "system", "decomposeParDict"), "decomposeParDict", "numberOfSubdomains 1;\nmethod none;\n")


def forces_object(name, patches, rho, cofr):
    """A `forces` function object of the controlDict: the load on `patches` every iteration."""
    return """    %s
    {
        type forces;
        libs ("libforces.so");
        patches (%s);
        rho rhoInf;
        rhoInf %.12g;
        CofR %s;
        writeControl timeStep;
        writeInterval 1;
        log false;
    }
""" % (name, patches, rho, hsrod_case.vec(cofr))


def run(cmd, case, env, log):
    t0, c0 = time.time(), os.times()
    r = subprocess.run(cmd + ["-case", case], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    c1 = os.times()
    with open(os.path.join(case, log), "w") as f:
        f.write(r.stdout)
    if r.returncode != 0:
        print(r.stdout[-3000:])
        raise RuntimeError("%s failed in %s" % (cmd[0], case))
    return r.stdout, (c1.children_user - c0.children_user) + (c1.children_system - c0.children_system), time.time() - t0


def read_forces(case, name="sphereForces"):
    """Total force [N] per iteration from the forces function object `name` (v1912 force.dat)."""
    files = sorted(glob.glob(os.path.join(case, "postProcessing", name, "*", "force.dat")))
    rows = []
    for fn in files:
        for line in open(fn):
            if line.startswith("#") or not line.strip():
                continue
            # v1912: Time (total_x total_y total_z) (pressure_...) (viscous_...)
            nums = [float(x) for x in line.replace("(", " ").replace(")", " ").split()]
            rows.append((nums[0], nums[1:4]))
    return rows


def body_fitted(spec, level, work, env, reuse=False):
    case = os.path.join(work, "%s_L%d" % (spec["id"], level))
    if reuse and os.path.exists(os.path.join(case, "log.checkMesh")) and read_forces(case):
        # a run stopped by hand after its force had settled (the log of the
        # stopped solver is not kept; its CPU time is not known)
        spheres, scene = write_case(os.path.join(work, "scratch"), spec, level)
        cm = open(os.path.join(case, "log.checkMesh")).read()
        log, cpu, mesh_cpu = "", float("nan"), float("nan")
    else:
        shutil.rmtree(case, ignore_errors=True)
        spheres, scene = write_case(case, spec, level)
        cpu = 0.0
        for cmd, logname in ((["blockMesh"], "log.blockMesh"), (["snappyHexMesh", "-overwrite"], "log.snappyHexMesh"),
                             (["transformPoints", "-scale", "(1e-6 1e-6 1e-6)"], "log.transformPoints")):
            _, c, _ = run(cmd, case, env, logname)
            cpu += c
        cm, _, _ = run(["checkMesh"], case, env, "log.checkMesh")
        mesh_cpu = cpu
        log, c, wall = run(["simpleFoam"], case, env, "log.simpleFoam")
        cpu += c
    cells = int(re.search(r"cells:\s+(\d+)", cm).group(1))
    nonorth = float(re.search(r"non-orthogonality Max: ([\d.]+)", cm).group(1))
    hist = read_forces(case)
    iters = len(hist)
    F = hist[-1][1]
    # convergence: relative change of |F| over the last 100 iterations
    F100 = hist[-101][1] if len(hist) > 101 else hist[0][1]
    change = math.sqrt(sum((a - b) ** 2 for a, b in zip(F, F100))) / math.sqrt(sum(a * a for a in F))
    converged = "SIMPLE solution converged" in log or change < FORCE_CHANGE_TOLERANCE
    z0 = 3 * math.pi * scene["fluid"]["mu"] * scene["d"] * scene["U"]
    out = {"id": spec["id"], "surface_level": level, "cells_at_surface_per_d": 3 * 2 ** level, "cells": cells,
           "max_non_orthogonality_deg": nonorth, "iterations": iters, "converged": converged,
           "force_change_last_100_it": change, "cpu_s_mesh": None if math.isnan(mesh_cpu) else round(mesh_cpu, 1),
           "cpu_s": None if math.isnan(cpu) else round(cpu, 1),
           "F_over_3pi_mu_d_U": [x / z0 for x in F]}
    if len(spheres) > 1:
        out["spheres_F_over_3pi_mu_d_U"] = [[x / z0 for x in read_forces(case, "sphere%dForces" % sp["id"])[-1][1]]
                                            for sp in spheres]
    print("  body-fitted %s level %d: %d cells, %d it (converged %s, change %.1e), F/(3 pi mu d U) = %s, %s s CPU"
          % (spec["id"], level, cells, iters, converged, change, ["%.4f" % x for x in out["F_over_3pi_mu_d_U"]],
             out["cpu_s"]), flush=True)
    return out


def ibm_result(spec, results=RESULTS):
    p = os.path.join(results, spec["id"] + ".json")
    if not os.path.exists(p):
        return None
    r = json.load(open(p))
    z0 = 3 * math.pi * spec["mu"] * spec["d"] * spec["U"]
    F = [sum(s["F"][k] for s in r["spheres"]) for k in range(3)]
    out = {"id": spec["id"], "cells_per_diameter": spec["cells_per_diameter"], "cells": r["mesh"]["cells"],
           "cpu_s": r["run"]["cpu_s"], "F_over_3pi_mu_d_U": [x / z0 for x in F]}
    if len(r["spheres"]) > 1:
        out["spheres_F_over_3pi_mu_d_U"] = [[x / z0 for x in s["F"]] for s in sorted(r["spheres"], key=lambda s: s["id"])]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--work", default="/tmp/hsrod_body_fitted")
    ap.add_argument("--levels", type=int, nargs="+", default=[2, 3])
    ap.add_argument("--gaps", type=float, nargs="+", default=[0.5, 1.5])
    ap.add_argument("--loads", nargs="+", default=["friction", "driving"])
    ap.add_argument("--rows", action="store_true",
                    help="the rows of three spheres (plan_body_fitted_rows.json) instead of the lone sphere")
    ap.add_argument("--table-only", action="store_true", help="refresh the IBM side and the table, run nothing")
    ap.add_argument("--reuse", action="store_true", help="read a finished or stopped run of a case instead of rerunning it")
    a = ap.parse_args()
    if a.table_only:
        a.levels = []
    env = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))
    os.makedirs(a.work, exist_ok=True)
    out_path = os.path.join(HERE, "results.json")
    results = json.load(open(out_path)) if os.path.exists(out_path) else {"cases": {}}
    groups = []  # (key prefix, configuration text, specs, IBM results directory)
    if a.rows:
        for angle in (0.0, 90.0):
            specs = ibm_series(ROWS_GAP, n=3, plan_path=ROWS_PLAN, angle=angle)
            s6 = next(iter(specs.values()))
            groups.append(("row of 3 at %g d, %s, wall gap %g d" % (s6["spacing"], "along the wall" if angle == 0
                                                                    else "normal to the wall", ROWS_GAP),
                           "three spheres in a row, centre spacing %g d (surface gap %g d), beta %.2f, row %s, "
                           "nearest surface gap %g d to the side wall y = 0, channel %s" % (
                               s6["spacing"], s6["spacing"] - 1, s6["beta"],
                               "along the wall" if angle == 0 else "normal to the wall", ROWS_GAP,
                               s6["geometry"]["channel"]), specs, ROWS_RESULTS))
    else:
        for gap in a.gaps:
            specs = ibm_series(gap)
            s6 = next(iter(specs.values()))
            groups.append(("wall gap %g d" % gap, "lone sphere, beta %.2f, surface gap %g d to the side wall y = 0, "
                           "channel %s" % (s6["beta"], gap, s6["geometry"]["channel"]), specs, RESULTS))
    for prefix, configuration, specs, ibm_dir in groups:
        for load in a.loads:
            spec6 = specs[(load, 6)]
            key = "%s, %s" % (prefix, load)
            entry = results["cases"].setdefault(key, {"body_fitted": {}, "ibm": {}})
            entry["configuration"] = configuration + "; " + (
                "dragged at -U (cos 45, sin 45): along -x and towards the wall" if load == "friction"
                else "held in the channel flow (mean U along x)")
            for lvl in a.levels:
                entry["body_fitted"][str(lvl)] = body_fitted(spec6, lvl, a.work, env, a.reuse)
                with open(out_path, "w") as f:
                    json.dump(results, f, indent=1)
            for (ld, n_d), spec in sorted(specs.items()):
                if ld == load:
                    r = ibm_result(spec, ibm_dir)
                    if r:
                        entry["ibm"][str(n_d)] = r
    with open(out_path, "w") as f:
        json.dump(results, f, indent=1)
    write_table(results)


def write_table(results):
    lines = ["# Body-fitted (snappyHexMesh + simpleFoam) against rodIbFoam, same cases", "",
             "Generated by `calibration/validation/body_fitted/run.py` (docstring: method). Forces on the sphere over "
             "3 pi mu d U; x along the wall (and the flow), y towards (-) / away from (+) the wall. Body-fitted "
             "surface level l: d / (3 2^l) cells at the sphere surface. IBM: rodIbFoam, d / n cells per diameter "
             "around the sphere (campaign `geometry`). Difference: IBM finest over body-fitted finest.", "",
             "| case | run | cells | CPU [s] | F_x | F_y |", "| --- | --- | --- | --- | --- | --- |"]
    for key, e in results["cases"].items():
        bf = sorted(e["body_fitted"].items(), key=lambda kv: int(kv[0]))
        ib = sorted(e["ibm"].items(), key=lambda kv: int(kv[0]))
        for lvl, r in bf:
            lines.append("| %s | body-fitted, level %s (d/%d at the surface)%s | %d | %s | %.4f | %.4f |" % (
                key, lvl, r["cells_at_surface_per_d"], "" if r["converged"] else " (not converged: change %.1e)"
                % r["force_change_last_100_it"], r["cells"], "-" if r["cpu_s"] is None else "%.0f" % r["cpu_s"],
                r["F_over_3pi_mu_d_U"][0], r["F_over_3pi_mu_d_U"][1]))
        for n_d, r in ib:
            lines.append("| %s | rodIbFoam, d/%s | %d | %.0f | %.4f | %.4f |" % (
                key, n_d, r["cells"], r["cpu_s"], r["F_over_3pi_mu_d_U"][0], r["F_over_3pi_mu_d_U"][1]))
        ref, ref_name = None, None
        if len(bf) >= 2:
            # Richardson with the surface cell size halving per level: p = 2, or the
            # observed order from three levels
            f1, f2 = bf[-1][1]["F_over_3pi_mu_d_U"], bf[-2][1]["F_over_3pi_mu_d_U"]
            order = 2.0
            if len(bf) >= 3:
                f3 = bf[-3][1]["F_over_3pi_mu_d_U"]
                if (f2[0] - f1[0]) * (f3[0] - f2[0]) > 0:
                    order = math.log((f3[0] - f2[0]) / (f2[0] - f1[0])) / math.log(2.0)
            ref = [f1[k] + (f1[k] - f2[k]) / (2 ** order - 1) for k in range(3)]
            ref_name = "body-fitted, Richardson of levels %s, %s (order %.2f%s)" % (
                bf[-2][0], bf[-1][0], order, ", observed from 3 levels" if len(bf) >= 3 else ", assumed")
            lines.append("| %s | %s | | | %.4f | %.4f |" % (key, ref_name, ref[0], ref[1]))
        if bf and ib:
            fi = ib[-1][1]["F_over_3pi_mu_d_U"]
            for name, fb in (("body-fitted level %s" % bf[-1][0], bf[-1][1]["F_over_3pi_mu_d_U"]),
                             ("the Richardson value", ref)):
                if fb is None:
                    continue
                dif = ["%+.2f %%" % (100 * (fi[k] / fb[k] - 1)) if abs(fb[k]) > 1e-3 else "-" for k in (0, 1)]
                lines.append("| %s | **IBM d/%s vs %s** | | | %s | %s |" % (key, ib[-1][0], name, dif[0], dif[1]))
        # rows: per sphere, the finest of each side (the row's sphere 1 at the lowest x / nearest the wall)
        if bf and ib and "spheres_F_over_3pi_mu_d_U" in bf[-1][1] and "spheres_F_over_3pi_mu_d_U" in ib[-1][1]:
            fb_s, fi_s = bf[-1][1]["spheres_F_over_3pi_mu_d_U"], ib[-1][1]["spheres_F_over_3pi_mu_d_U"]
            mean = sum(math.hypot(f[0], f[1]) for f in fb_s) / len(fb_s)
            for i, (fb, fi) in enumerate(zip(fb_s, fi_s)):
                lines.append("| %s | sphere %d: body-fitted level %s / IBM d/%s (IBM - body-fitted over the mean "
                             "per-sphere abs F) | | | %.4f / %.4f (%+.2f %%) | %.4f / %.4f (%+.2f %%) |" % (
                                 key, i + 1, bf[-1][0], ib[-1][0], fb[0], fi[0], 100 * (fi[0] - fb[0]) / mean,
                                 fb[1], fi[1], 100 * (fi[1] - fb[1]) / mean))
    with open(os.path.join(HERE, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
