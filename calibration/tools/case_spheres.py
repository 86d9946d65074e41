"""case_spheres: where the immersed spheres of each scene kind sit (a rod of
touching beads, a straight or bent row in a slit, a row placed near a wall
or a pore cylinder of a channel)."""
import math
import sys


def rod_spheres(rod):
    n, d = int(rod["n"]), float(rod["d"])
    a = math.radians(rod.get("angle_deg", 0.0))
    c = rod["centre"]
    t = (math.cos(a), math.sin(a), 0.0)
    out = []
    for i in range(n):
        s = (i - 0.5 * (n - 1)) * d
        out.append({"id": i + 1, "x": [c[k] + s * t[k] for k in range(3)], "d": d})
    return out


def scene_spheres(scene):
    if "rod" in scene:
        return rod_spheres(scene["rod"])
    return scene.get("spheres", [])


def slit_body_spheres(body, d):
    """Sphere centres of a slitBody row, its bounding box centred on the
    origin in the mid-plane z = 0:
      shape "straight" (default): n spheres along x, centre spacing
                       body.spacing d;
      shape "arc":     a bent (C-shaped) rod: n spheres on a circular arc in
                       the x-y plane, neighbours body.spacing d apart (chord),
                       turning by body.bend_deg in all (180: a half circle),
                       symmetric about the y axis (chord along x)."""
    n = int(body.get("n", 1))
    spacing = float(body.get("spacing", 1.0)) * d
    shape = body.get("shape", "straight")
    if shape == "straight":
        return [{"id": i + 1, "x": [(i - 0.5 * (n - 1)) * spacing, 0.0, 0.0], "d": d} for i in range(n)]
    if shape != "arc":
        sys.exit("hsrod_case: slitBody body.shape must be straight or arc (got '%s')" % shape)
    bend = math.radians(float(body.get("bend_deg", 0.0)))
    if n < 3 or not (0.0 < bend < 2.0 * math.pi * (n - 1) / n):
        sys.exit("hsrod_case: an arc needs n >= 3 and 0 < bend_deg < 360 (n - 1)/n (got n %d, bend_deg %g)"
                 % (n, math.degrees(bend)))
    step = bend / (n - 1)                            # turn per bond [rad]
    radius = spacing / (2.0 * math.sin(0.5 * step))  # chord = spacing
    pts = [(radius * math.sin(-0.5 * bend + i * step), -radius * math.cos(-0.5 * bend + i * step)) for i in range(n)]
    yc = 0.5 * (min(p[1] for p in pts) + max(p[1] for p in pts))
    return [{"id": i + 1, "x": [p[0], p[1] - yc, 0.0], "d": d} for i, p in enumerate(pts)]


def channel_body_spheres(scene):
    """Sphere centres of a channelBody row: n spheres (centre spacing
    body.spacing d) along the in-plane direction body.angle_deg from x, in
    the mid-plane z = H/2, placed so that the smallest surface gap to the
    obstacle named by body.near is body.gap d:
      near "wall": the side wall y = 0 (the row centred at x = body.x,
                   default L/2);
      near "pore": the lower pore cylinder (axis (pore.x, 0), radius pore.R),
                   the row's centre at x = pore.x (the throat), beside the
                   cylinder;
      near "given": the row's centre at body.centre [x, y] [m] (body.gap is
                   not used), e.g. a tilted rod in the throat between both
                   pore cylinders (campaign geometry "throat")."""
    d, H = scene["d"], scene["d"] / scene["beta"]
    ch, body = scene["channel"], scene["body"]
    n, s = int(body.get("n", 1)), float(body.get("spacing", 1.0)) * d
    a = math.radians(float(body.get("angle_deg", 0.0)))
    near = body.get("near", "wall")
    gap = float(body.get("gap", 0.0)) * d
    offs = [((i - 0.5 * (n - 1)) * s * math.cos(a), (i - 0.5 * (n - 1)) * s * math.sin(a)) for i in range(n)]
    if near == "wall":
        xc = float(body.get("x", 0.5 * ch["L"]))
        yc = gap + 0.5 * d - min(o[1] for o in offs)
    elif near == "pore":
        pore = scene.get("pore")
        if not pore:
            sys.exit("hsrod_case: channelBody body.near pore needs a \"pore\" {R, x}")
        xc, R = pore["x"], pore["R"]
        surface_gap = lambda y: min(math.hypot(xc + o[0] - xc, y + o[1]) for o in offs) - R - 0.5 * d
        lo, hi = R, R + gap + 0.5 * d + n * s + d     # surface_gap(lo) <= gap <= surface_gap(hi)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if surface_gap(mid) < gap else (lo, mid)
        yc = 0.5 * (lo + hi)
    elif near == "given":
        xc, yc = float(body["centre"][0]), float(body["centre"][1])
    else:
        sys.exit("hsrod_case: channelBody body.near must be wall, pore or given (got '%s')" % near)
    out = [{"id": i + 1, "x": [xc + o[0], yc + o[1], 0.5 * H], "d": d} for i, o in enumerate(offs)]
    for sp in out:
        if not (0.5 * d < sp["x"][1] < ch["W"] - 0.5 * d and 0.5 * d < sp["x"][0] < ch["L"] - 0.5 * d):
            sys.exit("hsrod_case: channelBody sphere %d at (%g, %g) leaves the channel" % (sp["id"], sp["x"][0], sp["x"][1]))
    return out
