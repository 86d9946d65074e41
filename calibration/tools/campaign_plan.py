"""campaign_plan: a resolved campaign's plan (PLAN.json, or the built-in
DEFAULT_PLAN) expanded into its cases, and each case's scene for the case
generator (hsrod_case.py). Shared by the campaign runner (hsrod_campaign.py)
and the analysis of its results (campaign_analysis.py). Python 3 standard
library only."""
import copy
import hashlib
import json
import sys


# Session plan (priority order): the main example's beta 0.15 and 0.3 first,
# then the held-out case, then a third mesh for the order of convergence,
# then more betas. Cost measured on the 2-core machine: see
# calibration/campaign/README.md.
_FIT_N = (1, 10, 2, 5)
DEFAULT_PLAN = {
    "name": "session4",
    "d": 3e-6, "U": 1e-3, "mu": 1e-3, "rho": 1000.0,
    "mesh": {"lateral_half_width": 4.0, "core_half_width": 0.75, "ratio_lateral": 1.25, "ratio_z": 1.15,
             "reference_cells_per_diameter": 8},
    "control": {"max_iterations": 1500, "relax_U": 0.95, "tol_U": 1e-5, "tol_p": 1e-4,
                "tol_F_extrapolated": 2e-5, "extrapolation_window": 10},
    "series": (
        [{"beta": b, "n": n, "spacing": 1, "meshes": [6, 8], "role": "fit"} for b in (0.3, 0.15) for n in (1, 10)]
        + [{"beta": b, "n": n, "spacing": 1, "meshes": [6, 8], "role": "fit"} for b in (0.3, 0.15) for n in (2, 5)]
        + [{"beta": 0.25, "n": 7, "spacing": 1, "meshes": [6, 8], "role": "heldout"}]
        + [{"beta": 0.3, "n": n, "spacing": 1, "meshes": [10], "role": "fit"} for n in (1, 10)]
        + [{"beta": 0.15, "n": 1, "spacing": 1, "meshes": [10], "role": "fit"}]
        + [{"beta": b, "n": n, "spacing": 1, "meshes": [6, 8], "role": "fit"} for b in (0.2, 0.45) for n in _FIT_N]
        + [{"beta": 0.15, "n": 2, "spacing": s, "meshes": [6, 8], "role": "pair"} for s in (2, 4)]
        + [{"beta": b, "n": n, "spacing": 1, "meshes": [6, 8], "role": "fit"} for b in (0.6, 0.1) for n in _FIT_N]
    ),
}


def load_plan(path):
    if not path:
        return copy.deepcopy(DEFAULT_PLAN)
    with open(path) as f:
        return json.load(f)


# Geometries of a series ("geometry", default "slit"):
#   slit  a straight row at the mid-plane of a wide slit (slitBody);
#   bent  a bent (C-shaped) rod in the wide slit: n spheres on an arc turning
#         by "bend_deg" (slitBody, body.shape "arc"); loads at 45 degrees to
#         the chord, as for a straight row (the slit is isotropic in its plane);
#   wall  a rigid row near the side wall y = 0 of a channel (channelBody), in-plane
#         angle "row_angle_deg" to the wall (0 parallel, 90 perpendicular),
#         smallest surface gap "gap" d; channel {"W_over_H", "L_over_H"};
#   pore  the same beside the lower cylinder of a pore constriction at the
#         channel's middle, channel {"W_over_H", "L_over_H", "R_over_H"};
#   throat a rigid straight row at a given place in a channel with both pore
#         cylinders, all in SI units: channel {"L", "W", "R", "x"} (cylinders
#         of radius R on both side walls at x), "centre" [x, y] of the row,
#         "row_angle_deg" its lab direction from x (sphere 1 at centre -
#         (n-1)/2 d (cos, sin)); loads "driving" (held in the channel flow),
#         "friction_x" / "friction_y" (translating at +U along x / y through
#         fluid at rest) and "rotation" (turning at U / d about +z about the
#         centroid, spheres spinning with it): the rigid resistance and the
#         held load of one configuration (calibration/validation/pore_passage,
#         the throat configurations of the resolved passage).
# Near a wall the slit is no longer isotropic in its plane: the in-plane angle
# is a parameter, the held run is in the channel flow (along the wall) and the
# dragged run translates the row at "drag_angle_deg" (default 45: along -x and
# towards the wall at once; the totals along and across the wall separate by
# the mirror symmetry x -> -x of these rows).
GEOMETRIES = ("slit", "bent", "wall", "pore", "throat")


def case_spec(plan, series, load, n_d):
    n = int(series["n"])
    geometry = series.get("geometry", "slit")
    if geometry not in GEOMETRIES:
        sys.exit("hsrod_campaign: series geometry must be one of %s (got '%s')" % (", ".join(GEOMETRIES), geometry))
    spec = {
        "beta": float(series["beta"]), "n": n, "spacing": float(series.get("spacing", 1)),
        "load": load, "flow_angle_deg": 0.0 if n == 1 else 45.0, "cells_per_diameter": int(n_d),
        "role": series.get("role", "fit"),
        "d": plan["d"], "U": plan["U"], "mu": plan["mu"], "rho": plan["rho"],
        "mesh": dict(plan.get("mesh", {}), **series.get("mesh", {})),
        "control": dict(plan.get("control", {}), **series.get("control", {})),
    }
    if geometry == "bent":
        spec["geometry"] = {"kind": "bent", "bend_deg": float(series["bend_deg"])}
        tag = "bent_c%g_" % spec["geometry"]["bend_deg"]
    elif geometry in ("wall", "pore"):
        ch = dict(series.get("channel", {}))
        spec["geometry"] = {"kind": geometry, "gap": float(series["gap"]),
                            "row_angle_deg": float(series.get("row_angle_deg", 0.0)), "channel": ch}
        spec["mesh"] = dict(series.get("mesh", {}))        # channelBody: its own mesh keys
        spec["flow_angle_deg"] = float(series.get("drag_angle_deg", 45.0)) if load == "friction" else 0.0
        tag = "%s_a%g_g%g_" % (geometry, spec["geometry"]["row_angle_deg"], spec["geometry"]["gap"])
    elif geometry == "throat":
        ch = dict(series["channel"])
        spec["geometry"] = {"kind": "throat", "centre": [float(v) for v in series["centre"]],
                            "row_angle_deg": float(series["row_angle_deg"]), "channel": ch}
        spec["mesh"] = dict(series.get("mesh", {}))        # channelBody: its own mesh keys
        motions = {"driving": ("driving", 0.0), "friction_x": ("friction", 180.0),
                   "friction_y": ("friction", -90.0), "rotation": ("rotation", 0.0)}
        if load not in motions:
            sys.exit("hsrod_campaign: throat loads are %s (got '%s')" % (", ".join(motions), load))
        spec["motion"] = load
        spec["load"], spec["flow_angle_deg"] = motions[load]
        tag = "throat_x%.2f_y%.2f_a%.1f_" % (spec["geometry"]["centre"][0] * 1e6,
                                     spec["geometry"]["centre"][1] * 1e6,
                                     spec["geometry"]["row_angle_deg"])
    else:
        tag = ""
    key = json.dumps({k: v for k, v in spec.items() if k != "role"}, sort_keys=True)
    spec["id"] = "%sb%.3f_n%d_s%g_%s_m%d_%s" % (tag, spec["beta"], n, spec["spacing"], load, n_d,
                                               hashlib.sha1(key.encode()).hexdigest()[:8])
    return spec


def expand(plan):
    cases = []
    for s in plan["series"]:
        for n_d in s["meshes"]:
            for load in s.get("loads", ["friction", "driving"]):
                cases.append(case_spec(plan, s, load, n_d))
    ids = [c["id"] for c in cases]
    if len(set(ids)) != len(ids):
        sys.exit("hsrod_campaign: the plan lists a case twice")
    return cases


def scene_of(spec):
    ctl = dict(spec["control"])
    geo = spec.get("geometry", {"kind": "slit"})
    if geo["kind"] == "throat":
        ch = geo["channel"]
        return {"kind": "channelBody", "d": spec["d"], "beta": spec["beta"], "U": spec["U"],
                "channel": {"L": ch["L"], "W": ch["W"]},
                "pore": {"R": ch["R"], "x": ch["x"]},
                "body": {"n": spec["n"], "spacing": spec["spacing"], "angle_deg": geo["row_angle_deg"],
                         "near": "given", "centre": geo["centre"]},
                "load": spec["load"], "flow_angle_deg": spec["flow_angle_deg"],
                "fluid": {"mu": spec["mu"], "rho": spec["rho"]},
                "mesh": dict(spec["mesh"], cells_per_diameter=spec["cells_per_diameter"]),
                "ib": {"minCellsPerDiameter": 3}, "control": ctl}
    if geo["kind"] in ("wall", "pore"):
        H = spec["d"] / spec["beta"]
        ch = geo["channel"]
        scene = {"kind": "channelBody", "d": spec["d"], "beta": spec["beta"], "U": spec["U"],
                 "channel": {"L": ch.get("L_over_H", 12.0) * H, "W": ch.get("W_over_H", 5.0) * H},
                 "body": {"n": spec["n"], "spacing": spec["spacing"], "angle_deg": geo["row_angle_deg"],
                          "gap": geo["gap"], "near": geo["kind"]},
                 "load": spec["load"], "flow_angle_deg": spec["flow_angle_deg"],
                 "fluid": {"mu": spec["mu"], "rho": spec["rho"]},
                 "mesh": dict(spec["mesh"], cells_per_diameter=spec["cells_per_diameter"]),
                 "ib": {"minCellsPerDiameter": 3}, "control": ctl}
        if geo["kind"] == "pore":
            scene["pore"] = {"R": ch.get("R_over_H", 1.5) * H, "x": 0.5 * scene["channel"]["L"]}
        return scene
    body = {"n": spec["n"], "spacing": spec["spacing"]}
    if geo["kind"] == "bent":
        body.update(shape="arc", bend_deg=geo["bend_deg"])
    return {"kind": "slitBody", "d": spec["d"], "beta": spec["beta"], "U": spec["U"],
            "body": body, "load": spec["load"],
            "flow_angle_deg": spec["flow_angle_deg"],
            "fluid": {"mu": spec["mu"], "rho": spec["rho"]},
            "mesh": dict(spec["mesh"], cells_per_diameter=spec["cells_per_diameter"]),
            "ib": {"minCellsPerDiameter": 3}, "control": ctl}
