#!/usr/bin/env python3
"""geometry_cases: the campaign's cases beyond straight rows in the wide slit
(bent rods, rows near a side wall or a pore cylinder; hsrod_campaign.py
GEOMETRIES) as one per-sphere table for the cross-check of levels 1-4
(hsrod_crosscheck_scenes).

    geometry_cases.py OUT [OUT ...] --csv calibration/data/resolved_geometry_per_sphere.csv

One row per sphere, case (configuration and load) and mesh:
  case            the configuration (geometry, beta, n, gap, angles), without load and mesh
  geometry        bent | wall | pore
  load            friction (the row translates at -U e, e = (cos a, sin a), a = drag_angle_deg),
                  driving (held: wide slit: stream U e; channel: channel flow of mean U along x),
                  rotation (channel: the row turns rigidly at U / d about +z about its centroid, the
                  spheres spinning with it) or orbit (the same sphere translations, no spin)
  finest          1 on the finest mesh of the case (the cross-check uses these), else 0
  x, y, z         sphere centre [m] (slit: row frame, origin at the body's centre; channel: the
                  channel's frame, side wall y = 0, plates z = 0 and H)
  fx, fy          force on the sphere over 3 pi mu d U
  dfx, dfy        finest mesh only: change from the next coarser mesh (nan without one)
  channel_L, channel_W, pore_R, pore_x [m]: wall and pore cases (0 otherwise)
  role            the plan's role of the case (fit, or *_heldout: left out of every fit)
  tz, dtz         torque on the sphere about its centre, z component, over 3 pi mu d^2 U, and its
                  change from the next coarser mesh
Python 3 standard library only.
"""
import argparse
import glob
import json
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COLUMNS = ("case,geometry,beta,n,spacing,gap_over_d,row_angle_deg,bend_deg,load,drag_angle_deg,cells_per_diameter,"
           "finest,d,mu,U,gap_height,channel_L,channel_W,pore_R,pore_x,sphere,x,y,z,fx,fy,dfx,dfy,role,source,tz,dtz")


def case_key(spec):
    g = spec["geometry"]
    if g["kind"] == "bent":
        return "bent_c%g_b%.3f_n%d" % (g["bend_deg"], spec["beta"], spec["n"])
    return "%s_a%g_g%g_b%.3f_n%d" % (g["kind"], g["row_angle_deg"], g["gap"], spec["beta"], spec["n"])


def load_cases(outs):
    """{(case, load): {n_d: result}} of every geometry result in the campaign directories."""
    cases = {}
    for out in outs:
        for f in sorted(glob.glob(os.path.join(out, "results", "*.json"))):
            with open(f) as fh:
                r = json.load(fh)
            if r.get("schema") != "hsrod-campaign-case 1" or "geometry" not in r["spec"] \
                    or r["spec"]["geometry"]["kind"] == "throat":   # pore_passage/throat.py reads these
                continue
            r["source"] = os.path.relpath(os.path.abspath(f), ROOT)
            s = r["spec"]
            cases.setdefault((case_key(s), s["load"]), {})[s["cells_per_diameter"]] = r
    return cases


def write_csv(cases, path, campaigns):
    lines = ["# resolved cases beyond straight slit rows (calibration/tools/geometry_cases.py; rodIbFoam, "
             "campaign %s); forces over 3 pi mu d U" % ", ".join(campaigns), COLUMNS]
    for (key, load), meshes in sorted(cases.items()):
        order = sorted(meshes)
        for k, n_d in enumerate(order):
            r = meshes[n_d]
            s = r["spec"]
            g = s["geometry"]
            z0 = 3 * math.pi * s["mu"] * s["d"] * s["U"]
            H = s["d"] / s["beta"]
            finest = n_d == order[-1]
            coarse = meshes[order[-2]] if finest and len(order) > 1 else None
            sc = r["scene"]
            ch = sc.get("channel", {})
            pore = sc.get("pore", {})
            for i, sp in enumerate(r["spheres"]):
                fx, fy = sp["F"][0] / z0, sp["F"][1] / z0
                tz = sp["T"][2] / (z0 * s["d"])
                if coarse:
                    dfx = fx - coarse["spheres"][i]["F"][0] / z0
                    dfy = fy - coarse["spheres"][i]["F"][1] / z0
                    dtz = tz - coarse["spheres"][i]["T"][2] / (z0 * s["d"])
                else:
                    dfx = dfy = dtz = float("nan")
                lines.append(",".join(str(v) for v in (
                    key, g["kind"], s["beta"], s["n"], s["spacing"], g.get("gap", 0), g.get("row_angle_deg", 0),
                    g.get("bend_deg", 0), load, s["flow_angle_deg"], n_d, int(finest), s["d"], s["mu"], s["U"],
                    "%.9g" % H, "%.9g" % ch.get("L", 0), "%.9g" % ch.get("W", 0), "%.9g" % pore.get("R", 0),
                    "%.9g" % pore.get("x", 0), sp["id"],
                    "%.9g" % sp["x"][0], "%.9g" % sp["x"][1], "%.9g" % sp["x"][2], "%.8g" % fx, "%.8g" % fy,
                    "%.3g" % dfx, "%.3g" % dfy, s.get("role", "fit"), r["source"], "%.8g" % tz, "%.3g" % dtz)))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return len(lines) - 2


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", nargs="+")
    ap.add_argument("--csv", required=True)
    a = ap.parse_args(argv)
    cases = load_cases(a.out)
    n = write_csv(cases, a.csv, ["'%s'" % os.path.basename(os.path.normpath(o)) for o in a.out])
    print("geometry_cases: %d cases (%d sphere rows) -> %s" % (len(cases), n, a.csv))
    return 0


if __name__ == "__main__":
    sys.exit(main())
