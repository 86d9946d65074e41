#!/usr/bin/env python3
"""hsrod_case: OpenFOAM case generation for rodIbFoam (hsrod calibration/).

Writes a complete case (blockMesh dictionary, boundary conditions, numerics,
immersed spheres, Allrun) from a JSON scene.  Python 3 standard library only.

Usage:
    hsrod_case.py SCENE.json CASE_DIR [--set key=value ...]

`--set` overrides scene entries with dotted keys, e.g.
    --set mesh.cells_per_diameter=12 --set control.max_iterations=400

Scene kinds (key "kind"); all quantities in SI units:

  channel             straight channel L x W x H (x flow, y width, z height),
                      inflow {"type": "pressureDrop", "dp": Pa} or
                      {"type": "meanVelocity", "U": m/s}, outlet p = 0,
                      no-slip side/top/bottom walls; optional spheres/rod;
                      optional static refinement box around the spheres
                      ("refine": {"levels", "margin"}) or a given box
                      ("refine": {"levels", "box": [[x0,y0,z0],[x1,y1,z1]]},
                      e.g. the band a moving rod sweeps) (topoSet +
                      refineMesh in Allrun).
  sphereInBox         one sphere at the centre of a box with the exact Stokes
                      velocity on all faces (no wall correction), creeping flow.
  slitBody            a straight row of spheres (rigid rod, pair) at the
                      mid-plane of a wide slit, dragged ("load": "friction")
                      or held in plane Poiseuille flow ("driving") at
                      flow_angle_deg to the row; see make_slit_body; a
                      bent (C-shaped) rod: body.shape "arc", body.bend_deg.
  channelBody         a rigid row near a side wall or a pore cylinder of a
                      channel, dragged in the lab frame or held in the
                      channel flow; see make_channel_body.
  sphereBetweenPlates one sphere (or a rigid rod, "rod": {"n", "angle_deg"})
                      midway between no-slip plates z = 0, H moving at -U
                      relative to the body (body-fixed frame: plates and
                      inflow move at +U); the lateral faces far away.

Spheres: "spheres": [{"id":1, "x":[..], "d":.., "v":[..], "omega":[..]}] or a
rod: "rod": {"n": N, "d": d, "centre": [..], "angle_deg": a} (beads touching,
axis in the x-y plane at angle a to x).  Pore constriction (channel kind):
"pore": {"R": R, "x": x_c} gives two z-cylinders of radius R centred on the
side walls at x_c (body-fitted 12-block mesh, target cell size mesh.h,
patch "pore"); pore width W - 2R.
"""
import argparse
import copy
import json
import os
import sys

from case_bodies import make_slit_body, make_sphere_between_plates, make_sphere_in_box
from case_channel import make_channel, make_channel_body
from case_foam import BC_WALL, bc_fixed_u, bc_flowrate_inlet, bc_outlet, foam_file, vec
from case_mesh import Axis, write_block_mesh
from case_spheres import channel_body_spheres, slit_body_spheres

# the case generator's interface: the scene kinds, and the pieces the
# validation scripts and tests build their own cases from (hsrod_case.<name>)
__all__ = ["KINDS", "main", "set_dotted", "make_channel", "make_channel_body", "make_slit_body",
           "make_sphere_between_plates", "make_sphere_in_box", "BC_WALL", "bc_fixed_u", "bc_flowrate_inlet",
           "bc_outlet", "foam_file", "vec", "Axis", "write_block_mesh", "channel_body_spheres", "slit_body_spheres"]


KINDS = {"channel": make_channel, "channelBody": make_channel_body, "sphereInBox": make_sphere_in_box,
         "sphereBetweenPlates": make_sphere_between_plates, "slitBody": make_slit_body}


def set_dotted(d, key, value):
    parts = key.split(".")
    for p in parts[:-1]:
        d = d.setdefault(p, {})
    try:
        value = json.loads(value)
    except ValueError:
        pass
    d[parts[-1]] = value


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("case")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    a = ap.parse_args(argv)
    with open(a.scene) as f:
        scene = json.load(f)
    scene = copy.deepcopy(scene)
    for kv in a.set:
        k, _, v = kv.partition("=")
        set_dotted(scene, k, v)
    kind = scene.get("kind", "channel")
    if kind not in KINDS:
        sys.exit("hsrod_case: unknown scene kind '%s' (%s)" % (kind, ", ".join(KINDS)))
    os.makedirs(a.case, exist_ok=True)
    KINDS[kind](scene, a.case)
    with open(os.path.join(a.case, "scene.json"), "w") as f:
        json.dump(scene, f, indent=2)
    print("hsrod_case: wrote %s case in %s" % (kind, a.case))


if __name__ == "__main__":
    main()
