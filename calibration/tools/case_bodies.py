"""case_bodies: the scene kinds of one body far from side walls (a sphere in a
box, a sphere or rigid rod between plates, a straight or bent row in a wide
slit), creeping flow on meshes focused on the body."""
import math
import sys

from case_foam import BC_WALL, bc_fixed_u, write_allrun, write_constant, write_fields, write_system
from case_mesh import Axis, outer_cells, write_block_mesh
from case_spheres import rod_spheres, slit_body_spheres


def make_sphere_in_box(scene, case):
    d = scene["sphere"]["d"]
    U = scene["U"]
    m = scene.get("mesh", {})
    n_d = m.get("cells_per_diameter", 8)
    B = m.get("box_half_width", 4.0) * d          # box half width [m]
    core = m.get("core_half_width", 0.75) * d     # uniform core half width [m]
    n_out = m.get("n_outer", 8)
    h = d / n_d
    axes = [Axis.focused(-B, B, -core, core, h, n_out) for _ in range(3)]
    faces = {f: ("farField", "patch") for f in ("xmin", "xmax", "ymin", "ymax", "zmin", "zmax")}
    write_block_mesh(case, *axes, faces)
    # walls: "stokes" = exact unbounded Stokes velocity on the faces (sphere frame);
    #        "uniform" = faces move at U (sphere translating in a closed box, sphere frame)
    # frame: "sphere" (steady, sphere fixed) or "lab" (box at rest, sphere moves at
    #        -U on a prescribed path; transient; needs walls "uniform")
    walls = scene.get("walls", "stokes")
    frame = scene.get("frame", "sphere")
    u_face = [0, 0, 0] if frame == "lab" else [U, 0, 0]
    write_fields(case, {"farField": bc_fixed_u(u_face)}, u_face)
    fl = dict(scene["fluid"], creeping=True)
    ib = dict(scene.get("ib", {}))
    if walls == "stokes":
        if frame != "sphere":
            sys.exit("hsrod_case: walls 'stokes' needs frame 'sphere'")
        ib["farField"] = {"type": "stokes", "Uinf": [U, 0, 0], "patches": ["farField"]}
    sphere = {"id": 1, "d": d, "omega": scene["sphere"].get("omega", [0, 0, 0])}
    # sphere centre: box centre (a cell vertex) plus an optional offset in cells
    sphere["x"] = [o * axes[0].segs[1][0] / axes[0].segs[1][1]
                   for o in scene["sphere"].get("offset_cells", [0, 0, 0])]
    if frame == "lab":
        sphere["v"] = [-U, 0, 0]
        ib["motion"] = "constantVelocity"
    write_constant(case, fl, [sphere], ib)
    ctl = dict(scene.get("control", {}), creeping=True)
    write_system(case, ctl, frame == "sphere", has_pref=True)
    write_allrun(case)


def make_sphere_between_plates(scene, case):
    d = scene["sphere"]["d"]
    U = scene["U"]
    H = d / scene["beta"]                          # beta = 2a/H
    m = scene.get("mesh", {})
    n_d = m.get("cells_per_diameter", 8)
    nz = int(math.ceil(n_d * H / d))
    h = H / nz
    # a rigid rod instead of the sphere: "rod": {"n": N, "angle_deg": a}
    # (centred at the origin, spheres touching); the uniform core and the
    # lateral faces then extend from the rod's ends
    if "rod" in scene:
        spheres = rod_spheres(dict(scene["rod"], d=d, centre=[0.0, 0.0, 0.0]))
    else:
        spheres = [{"id": 1, "x": [0, 0, 0], "d": d}]
    ext = [max(abs(s["x"][k]) for s in spheres) for k in range(2)]
    core_w = m.get("core_half_width", 0.75) * d
    n_out = m.get("n_outer", 10)
    axes = []
    for k in range(2):
        core = ext[k] + core_w
        B = ext[k] + m.get("lateral_half_width", 4.0) * H
        axes.append(Axis.focused(-B, B, -core, core, h, n_out))
    ax, ay = axes
    az = Axis.uniform(-0.5 * H, 0.5 * H, nz)
    write_block_mesh(case, ax, ay, az, {"xmin": ("inlet", "patch"), "xmax": ("outlet", "patch"),
                                       "ymin": ("sides", "patch"), "ymax": ("sides", "patch"),
                                       "zmin": ("plates", "wall"), "zmax": ("plates", "wall")})
    # sphere frame: sphere fixed, plates and far field move at +U
    write_fields(case, {"inlet": bc_fixed_u([U, 0, 0]), "sides": bc_fixed_u([U, 0, 0]),
                        "plates": bc_fixed_u([U, 0, 0]),
                        "outlet": {"U": "        type zeroGradient;\n",
                                   "p": "        type fixedValue;\n        value uniform 0;\n"}},
                 [U, 0, 0])
    fl = dict(scene["fluid"], creeping=True)
    write_constant(case, fl, spheres, scene.get("ib", {}))
    ctl = dict(scene.get("control", {}), creeping=True)
    write_system(case, ctl, True, has_pref=False)
    write_allrun(case)


def make_slit_body(scene, case):
    """A row of n spheres (a rigid rod for spacing 1, a pair for n = 2, a
    bent rod for body.shape "arc": slit_body_spheres) at the mid-plane of a
    wide slit of gap H = d / beta, the row (its chord) along x, in creeping
    flow, steady. The mesh is fixed to the row (uniform cells
    d / cells_per_diameter around it, geometric stretching to lateral faces
    lateral_half_width H beyond the row's ends and to the plates), so one run
    with the load at flow_angle_deg to the row gives the parallel and the
    perpendicular response on the same mesh (Stokes flow is linear and the
    slit isotropic in its plane).
      load "friction": the row translates at -U e through fluid at rest
                       (row frame: plates and lateral faces move at +U e);
      load "driving":  the row is held in the undisturbed plane Poiseuille
                       flow of gap-mean velocity U e (plates at rest; lateral
                       faces: farField slitPoiseuille).
    e = (cos a, sin a, 0), a = flow_angle_deg. The mesh family of a series
    (cells_per_diameter n_d) keeps the outer cell counts proportional to n_d
    (counts fixed at reference_cells_per_diameter by the growth limits), so
    the meshes are refinements of one mapping (Richardson extrapolation)."""
    d, beta, U = scene["d"], scene["beta"], scene["U"]
    H = d / beta
    body = scene.get("body", {})
    m = scene.get("mesh", {})
    n_d = m.get("cells_per_diameter", 8)
    n_ref = m.get("reference_cells_per_diameter", 8)
    h, h_ref = d / n_d, d / n_ref
    scale = float(n_d) / n_ref
    core_w = m.get("core_half_width", 0.75) * d
    lat = m.get("lateral_half_width", 4.0) * H
    spheres = slit_body_spheres(body, d)
    axes = []
    for ext in (max(abs(s["x"][k]) for s in spheres) for k in (0, 1)):
        core = math.ceil((ext + core_w) / h - 1e-9) * h
        n_out = max(1, int(round(scale * outer_cells(ext + lat - core, h_ref, m.get("ratio_lateral", 1.25)))))
        axes.append(Axis.focused(-(ext + lat), ext + lat, -core, core, h, n_out))
    core_z = math.ceil(core_w / h - 1e-9) * h
    if 0.5 * H - core_z < 1.5 * h_ref:
        az = Axis.uniform(-0.5 * H, 0.5 * H, 2 * max(1, int(round(0.5 * H / h))))
    else:
        n_out_z = max(1, int(round(scale * outer_cells(0.5 * H - core_z, h_ref, m.get("ratio_z", 1.15)))))
        az = Axis.focused(-0.5 * H, 0.5 * H, -core_z, core_z, h, n_out_z)
    write_block_mesh(case, axes[0], axes[1], az,
                     {f: ("farField", "patch") for f in ("xmin", "xmax", "ymin", "ymax")} |
                     {"zmin": ("plates", "wall"), "zmax": ("plates", "wall")})
    a = math.radians(scene.get("flow_angle_deg", 0.0))
    e = [U * math.cos(a), U * math.sin(a), 0.0]
    load = scene.get("load", "friction")
    ib = dict(scene.get("ib", {}))
    if load == "friction":
        write_fields(case, {"farField": bc_fixed_u(e), "plates": bc_fixed_u(e)}, e)
    elif load == "driving":
        write_fields(case, {"farField": bc_fixed_u([0, 0, 0]), "plates": BC_WALL}, [0, 0, 0])
        ib["farField"] = {"type": "slitPoiseuille", "Uinf": e, "patches": ["farField"],
                          "z0": -0.5 * H, "z1": 0.5 * H}
    else:
        sys.exit("hsrod_case: slitBody load must be friction or driving (got '%s')" % load)
    write_constant(case, dict(scene["fluid"], creeping=True), spheres, ib)
    write_system(case, dict(scene.get("control", {}), creeping=True), True, has_pref=True)
    write_allrun(case)
    return axes[0].ncells() * axes[1].ncells() * az.ncells()
