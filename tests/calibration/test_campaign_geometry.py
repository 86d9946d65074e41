"""Case generation of the campaign's geometries beyond straight rows in the
wide slit (calibration/campaign/plan_geometry.json):

  - bent (C-shaped) rods (slitBody, body.shape "arc"): neighbours one
    spacing apart (chord), total turn = bend_deg, mirror symmetric about the
    y axis, bounding box centred on the mesh's uniform core;
  - rows near the side wall y = 0 and beside a pore cylinder (channelBody):
    the smallest surface gap is the requested one, the row lies at the
    requested in-plane angle, in the mid-plane; the dragged case moves every
    sphere at -U e (lab frame, no inflow), the held case has the channel's
    flow rate U W H at the inlet and spheres at rest; the refinement box
    holds every sphere with its margin (reaching the wall for small gaps);
  - the meshes: blockMesh + topoSet + refineMesh of a wall case and a pore
    case pass checkMesh, the cells around the spheres are d / n_d, and the
    generator's cell estimate (used for the campaign's cost) is within 5 %
    of the real count;
  - the straight slit rows keep their case ids (a hash of every parameter):
    every result of calibration/campaign/beta-range is still found, so the
    extension recomputes nothing.

    python3 test_campaign_geometry.py HSROD_CAMPAIGN_PY CAMPAIGN_DIR WORKDIR
"""
import glob
import json
import math
import os
import re
import shutil
import subprocess
import sys


def check(cond, msg):
    print(("PASS: " if cond else "FAIL: ") + msg)
    return bool(cond)


def read_spheres(case):
    rows = [l.strip().split(",") for l in open(os.path.join(case, "constant", "spheres.csv")) if not l.startswith("#")]
    head = rows[0]
    return [dict(zip(head, map(float, r))) for r in rows[1:]]


def run_of(cmd, case, env):
    return subprocess.run(cmd + ["-case", case], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def mesh_and_check(case, env):
    """blockMesh + topoSet + refineMesh as in Allrun; (cells, checkMesh text)."""
    for cmd in (["blockMesh"], ["topoSet", "-dict", "system/topoSetDict"],
                ["refineMesh", "-overwrite", "-dict", "system/refineMeshDict"]):
        r = run_of(cmd, case, env)
        if r.returncode != 0:
            print(r.stdout[-3000:])
            raise RuntimeError("%s failed in %s" % (cmd[0], case))
    cm = run_of(["checkMesh"], case, env).stdout
    cells = int(re.search(r"cells:\s+(\d+)", cm).group(1))
    return cells, cm


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    campaign_py, campaign_dir, work = sys.argv[1:]
    sys.path.insert(0, os.path.dirname(os.path.abspath(campaign_py)))
    import hsrod_campaign as hc
    import hsrod_case
    env = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))
    work = os.path.join(work, "campaign_geometry")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    ok = True
    d, U = 3e-6, 1e-3

    # ---- bent rods
    for n, bend in ((10, 180.0), (10, 90.0), (5, 120.0)):
        sp = hsrod_case.slit_body_spheres({"n": n, "spacing": 1, "shape": "arc", "bend_deg": bend}, d)
        xy = [(s["x"][0], s["x"][1]) for s in sp]
        gaps = [math.hypot(xy[i + 1][0] - xy[i][0], xy[i + 1][1] - xy[i][1]) for i in range(n - 1)]
        t0 = math.atan2(xy[1][1] - xy[0][1], xy[1][0] - xy[0][0])
        t1 = math.atan2(xy[-1][1] - xy[-2][1], xy[-1][0] - xy[-2][0])
        turn = math.degrees((t1 - t0) % (2 * math.pi))
        sym = max(abs(xy[i][0] + xy[n - 1 - i][0]) + abs(xy[i][1] - xy[n - 1 - i][1]) for i in range(n))
        ys = [p[1] for p in xy]
        ok &= check(max(abs(g - d) for g in gaps) < 1e-12 * d, "arc n %d bend %g: neighbours d apart (max dev %.1e d)"
                    % (n, bend, max(abs(g - d) for g in gaps) / d))
        ok &= check(abs(turn - bend * (n - 2) / (n - 1)) < 1e-9,
                    "arc n %d: first to last bond turns by %.6f deg = bend (n-2)/(n-1)" % (n, turn))
        ok &= check(sym < 1e-12 * d and abs(max(ys) + min(ys)) < 1e-12 * d, "arc n %d: mirror symmetric, box centred" % n)
    # a straight row stays the straight row
    st = hsrod_case.slit_body_spheres({"n": 4, "spacing": 2}, d)
    ok &= check([s["x"] for s in st] == [[(i - 1.5) * 2 * d, 0.0, 0.0] for i in range(4)], "straight row unchanged")

    # ---- rows near a wall and beside a pore cylinder (through the campaign's own specs)
    plan = {"name": "geometry test", "d": d, "U": U, "mu": 1e-3, "rho": 1000.0, "mesh": {}, "control": {},
            "series": []}
    ch_wall = {"W_over_H": 5.0, "L_over_H": 12.0}
    ch_pore = {"W_over_H": 6.0, "L_over_H": 12.0, "R_over_H": 1.5}
    meshed = {}
    for geo, ch in (("wall", ch_wall), ("pore", ch_pore)):
        for angle in (0.0, 45.0, 90.0):
            for gap in (0.5, 1.5):
                s = {"geometry": geo, "beta": 0.3, "n": 5, "row_angle_deg": angle, "gap": gap, "channel": ch,
                     "meshes": [6]}
                for load in ("friction", "driving"):
                    spec = hc.case_spec(plan, s, load, 6)
                    scene = hc.scene_of(spec)
                    case = os.path.join(work, spec["id"])
                    est = hsrod_case.make_channel_body(scene, case)
                    sph = read_spheres(case)
                    H = d / 0.3
                    W, L = ch["W_over_H"] * H, ch["L_over_H"] * H
                    if geo == "wall":
                        g = min(p["y"] - 0.5 * p["d"] for p in sph)
                    else:
                        R, xc = ch["R_over_H"] * H, 0.5 * L
                        g = min(math.hypot(p["x"] - xc, p["y"]) - R - 0.5 * p["d"] for p in sph)
                    a = math.degrees(math.atan2(sph[-1]["y"] - sph[0]["y"], sph[-1]["x"] - sph[0]["x"]))
                    nb = max(abs(math.hypot(sph[i + 1]["x"] - sph[i]["x"], sph[i + 1]["y"] - sph[i]["y"]) - d)
                             for i in range(len(sph) - 1))
                    tag = "%s a %g gap %g %s" % (geo, angle, gap, load)
                    ok &= check(abs(g - gap * d) < 1e-9 * d and abs(a - angle) < 1e-9 and nb < 1e-12
                                and all(abs(p["z"] - 0.5 * H) < 1e-15 for p in sph),
                                "%s: surface gap %.6f d, angle %.3f deg, spacing, mid-plane" % (tag, g / d, a))
                    u0 = open(os.path.join(case, "0", "U")).read()
                    q = float(re.search(r"volumetricFlowRate constant ([-\d.e+]+)", u0).group(1))
                    if load == "friction":
                        e = [-U * math.cos(math.radians(45)), -U * math.sin(math.radians(45))]
                        moving = all(abs(p["vx"] - e[0]) < 1e-15 and abs(p["vy"] - e[1]) < 1e-15 for p in sph)
                        ok &= check(moving and q == 0.0, "%s: every sphere at -U e towards the wall, no inflow" % tag)
                    else:
                        still = all(p["vx"] == p["vy"] == 0.0 for p in sph)
                        ok &= check(still and abs(q - U * W * H) < 1e-9 * U * W * H,
                                    "%s: spheres at rest, inlet flow rate U W H" % tag)
                    box = re.search(r"box \(([^)]*)\) \(([^)]*)\)", open(os.path.join(case, "system", "topoSetDict")).read())
                    lo, hi = [list(map(float, box.group(k).split())) for k in (1, 2)]
                    eps = 1e-9 * d
                    inside = all(lo[0] <= p["x"] - 1.5 * d + eps and p["x"] + 1.5 * d <= hi[0] + eps
                                 and max(0.0, p["y"] - 1.5 * d) + eps >= lo[1] and p["y"] + 1.5 * d <= hi[1] + eps
                                 for p in sph)
                    ok &= check(inside and lo[2] < 0 and hi[2] > H, "%s: refinement box holds the spheres + 1 d, full height" % tag)
                    if load == "driving" and gap == 0.5 and angle in (0.0, 90.0):
                        meshed[(geo, angle)] = (case, est)
    for (geo, angle), (case, est) in sorted(meshed.items()):
        if angle != (90.0 if geo == "wall" else 0.0):
            continue
        cells, cm = mesh_and_check(case, env)
        ok &= check("Mesh OK." in cm, "%s a %g: refined mesh passes checkMesh" % (geo, angle))
        ok &= check(abs(est / cells - 1) < 0.05, "%s a %g: estimated cells %d within 5 %% of the mesh's %d"
                    % (geo, angle, est, cells))
        # the smallest cell is (d/6)^3: the spheres sit in the refined zone
        vmin = re.search(r"Min volume = ([\d.]+e[+-]\d+)", cm)
        if geo == "wall":  # uniform cubes (the pore's arc blocks are finer along the arcs)
            ok &= check(abs(float(vmin.group(1)) / (d / 6) ** 3 - 1) < 0.25,
                        "%s a %g: smallest cell %.3g m^3 ~ (d/6)^3 = %.3g" % (geo, angle, float(vmin.group(1)), (d / 6) ** 3))

    # ---- the straight slit rows keep their ids
    bplan = hc.load_plan(os.path.join(campaign_dir, "plan_beta_range.json"))
    ids = {c["id"] for c in hc.expand(bplan)}
    found = {os.path.basename(f)[:-5] for f in glob.glob(os.path.join(campaign_dir, "beta-range", "results", "*.json"))}
    ok &= check(found and found <= ids, "beta-range: all %d result files are cases of its plan (ids unchanged)" % len(found))
    gplan = hc.load_plan(os.path.join(campaign_dir, "plan_geometry.json"))
    gids = [c["id"] for c in hc.expand(gplan)]
    ok &= check(len(set(gids)) == len(gids) and not (set(gids) & ids), "plan_geometry: ids unique and new")
    print("OK" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
