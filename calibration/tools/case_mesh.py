"""case_mesh: blockMesh dictionaries of the cases: graded axes, the single
hex block of boxes and slits, the body-fitted 12-block pore constriction."""
import math
import os
import sys

from case_foam import foam_file, vec


# ---------------------------------------------------------------- grading
def stretch_ratio(length, h, n):
    """Geometric factor r with h (r^n - 1)/(r - 1) = length (first cell h)."""
    if n <= 0:
        raise ValueError("need n > 0")
    if abs(n * h - length) < 1e-12 * length:
        return 1.0
    f = lambda r: h * (r ** n - 1) / (r - 1) - length if abs(r - 1) > 1e-12 else n * h - length
    lo, hi = (1.0 + 1e-9, 10.0) if n * h < length else (1e-3, 1.0 - 1e-9)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (f(mid) > 0) == (f(hi) > 0):
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


class Axis:
    """1-D grading of one axis: list of (length, ncells, expansion last/first)."""

    def __init__(self, lo, hi):
        self.lo, self.hi, self.segs = lo, hi, []

    @staticmethod
    def uniform(lo, hi, n):
        a = Axis(lo, hi)
        a.segs = [(hi - lo, n, 1.0)]
        return a

    @staticmethod
    def focused(lo, hi, c_lo, c_hi, h, n_out):
        """Uniform cells of size ~h on [c_lo, c_hi], geometric stretching
        outward with n_out cells on each side (first outer cell = h)."""
        a = Axis(lo, hi)
        n_core = max(1, int(round((c_hi - c_lo) / h)))
        h = (c_hi - c_lo) / n_core
        for length, side in ((c_lo - lo, "lo"), (hi - c_hi, "hi")):
            if length <= 0:
                continue
            n = n_out
            r = stretch_ratio(length, h, n)
            exp = r ** (n - 1)
            seg = (length, n, 1.0 / exp if side == "lo" else exp)
            if side == "lo":
                a.segs.append(seg)
            else:
                a._hi_seg = seg
        a.segs.append((c_hi - c_lo, n_core, 1.0))
        if hasattr(a, "_hi_seg"):
            a.segs.append(a._hi_seg)
        return a

    def ncells(self):
        return sum(s[1] for s in self.segs)

    def grading(self):
        L, N = self.hi - self.lo, self.ncells()
        if len(self.segs) == 1:
            return "%.12g" % self.segs[0][2]
        return "(" + " ".join("(%.12g %.12g %.12g)" % (s[0] / L, s[1] / N, s[2])
                              for s in self.segs) + ")"


def write_block_mesh(case, ax, ay, az, patch_names):
    """Single hex block; patch_names: dict face -> (name, type)."""
    x0, x1, y0, y1, z0, z1 = ax.lo, ax.hi, ay.lo, ay.hi, az.lo, az.hi
    pts = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
           (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = {"xmin": "(0 4 7 3)", "xmax": "(1 2 6 5)", "ymin": "(0 1 5 4)",
             "ymax": "(3 7 6 2)", "zmin": "(0 3 2 1)", "zmax": "(4 5 6 7)"}
    groups = {}
    for face, (name, ptype) in patch_names.items():
        groups.setdefault((name, ptype), []).append(faces[face])
    body = "scale 1;\n\nvertices\n(\n%s);\n\n" % "".join("    %s\n" % vec(p) for p in pts)
    body += "blocks\n(\n    hex (0 1 2 3 4 5 6 7) (%d %d %d)\n    simpleGrading\n    (\n        %s\n        %s\n        %s\n    )\n);\n\n" % (
        ax.ncells(), ay.ncells(), az.ncells(), ax.grading(), ay.grading(), az.grading())
    body += "edges ();\n\nboundary\n(\n"
    for (name, ptype), fl in groups.items():
        body += "    %s\n    {\n        type %s;\n        faces (%s);\n    }\n" % (name, ptype, " ".join(fl))
    body += ");\n\nmergePatchPairs ();\n"
    foam_file(os.path.join(case, "system", "blockMeshDict"), "dictionary", "blockMeshDict", body)


def write_pore_block_mesh(case, L, W, H, xc, R, h):
    """Body-fitted channel with the pore constriction: two z-cylinders of
    radius R centred on the side walls at (xc, 0) and (xc, W). Twelve hex
    blocks: per half channel an upstream and a downstream rectangle and four
    blocks around the quarter circles (block edges along the 180/135/90/45/0
    degree rays), mirrored at y = W/2. h: target cell size [m]."""
    if not (0 < R < 0.5 * W):
        sys.exit("hsrod_case: pore cylinders need 0 < R < W/2")
    if not (xc - 0.5 * W > 0 and xc + 0.5 * W < L):
        sys.exit("hsrod_case: the pore (x_c +- W/2) must lie inside the channel length")
    a = R / math.sqrt(2.0)
    hw = 0.5 * W
    n_half = max(2, int(round(hw / h)))
    n_rad = max(2, int(round((hw * math.sqrt(2.0) - R) / h)))
    n_t = max(2, int(round(hw / h)))
    n_up = max(1, int(round((xc - hw) / h)))
    n_dn = max(1, int(round((L - xc - hw) / h)))
    nz = max(2, int(round(H / h)))
    P = {"O0": (0, 0), "A0": (xc - hw, 0), "P180": (xc - R, 0), "P135": (xc - a, a), "P90": (xc, R),
         "P45": (xc + a, a), "P0": (xc + R, 0), "B0": (xc + hw, 0), "E0": (L, 0),
         "O1": (0, hw), "M135": (xc - hw, hw), "M90": (xc, hw), "M45": (xc + hw, hw), "E1": (L, hw)}
    arcs = [("P180", "P135", 157.5), ("P135", "P90", 112.5), ("P90", "P45", 67.5), ("P45", "P0", 22.5)]
    blocks = [(("O0", "A0", "M135", "O1"), n_up, n_half), (("A0", "P180", "P135", "M135"), n_rad, n_half),
              (("P135", "P90", "M90", "M135"), n_t, n_rad), (("P90", "P45", "M45", "M90"), n_t, n_rad),
              (("P45", "P0", "B0", "M45"), n_half, n_rad), (("B0", "E0", "E1", "M45"), n_dn, n_half)]
    # mirror to the upper half (y -> W - y): reverse orientation, swap i/j counts
    for k, (x, y) in list(P.items()):
        if y != hw:
            P[k + "m"] = (x, W - y)
    mir = lambda k: k if P[k][1] == hw else k + "m"
    for (p0, p1, p2, p3), ni, nj in list(blocks):
        blocks.append(((mir(p0), mir(p3), mir(p2), mir(p1)), nj, ni))
    arcs += [(mir(b), mir(e), -ang) for b, e, ang in arcs]
    names = list(P)
    idx = {k: i for i, k in enumerate(names)}
    nv = len(names)
    verts = [(P[k][0], P[k][1], 0.0) for k in names] + [(P[k][0], P[k][1], H) for k in names]
    body = "scale 1;\n\nvertices\n(\n%s);\n\nblocks\n(\n" % "".join("    %s\n" % vec(v) for v in verts)
    for quad, ni, nj in blocks:
        q = [P[k] for k in quad]
        area = sum(q[i][0] * q[(i + 1) % 4][1] - q[(i + 1) % 4][0] * q[i][1] for i in range(4))
        assert area > 0, quad
        ids = [idx[k] for k in quad]
        body += "    hex (%s %s) (%d %d %d) simpleGrading (1 1 1)\n" % (
            " ".join(map(str, ids)), " ".join(str(i + nv) for i in ids), ni, nj, nz)
    body += ");\n\nedges\n(\n"
    for b, e, ang in arcs:
        cy = 0.0 if ang > 0 else W
        t = math.radians(abs(ang))
        mid = (xc + R * math.cos(t), cy + (R * math.sin(t) if ang > 0 else -R * math.sin(t)))
        for z, off in ((0.0, 0), (H, nv)):
            body += "    arc %d %d %s\n" % (idx[b] + off, idx[e] + off, vec((mid[0], mid[1], z)))
    body += ");\n\n"
    arcset = {frozenset((b, e)) for b, e, _ in arcs}
    patches = {"inlet": [], "outlet": [], "walls": [], "pore": []}
    for quad, _, _ in blocks:
        for i in range(4):
            b, e = quad[i], quad[(i + 1) % 4]
            (xb, yb), (xe, ye) = P[b], P[e]
            if frozenset((b, e)) in arcset:
                kind = "pore"
            elif xb == xe == 0:
                kind = "inlet"
            elif xb == xe == L:
                kind = "outlet"
            elif (yb == ye == 0) or (yb == ye == W):
                kind = "walls"
            else:
                continue
            patches[kind].append("(%d %d %d %d)" % (idx[b], idx[e], idx[e] + nv, idx[b] + nv))
        ids = [idx[k] for k in quad]
        patches["walls"].append("(%d %d %d %d)" % (ids[0], ids[3], ids[2], ids[1]))
        patches["walls"].append("(%d %d %d %d)" % tuple(i + nv for i in ids))
    body += "boundary\n(\n"
    for name, faces in patches.items():
        ptype = "patch" if name in ("inlet", "outlet") else "wall"
        body += "    %s\n    {\n        type %s;\n        faces\n        (\n%s        );\n    }\n" % (
            name, ptype, "".join("            %s\n" % f for f in faces))
    body += ");\n\nmergePatchPairs ();\n"
    foam_file(os.path.join(case, "system", "blockMeshDict"), "dictionary", "blockMeshDict", body)
    # planform cell centres (bilinear in each block: the arcs are ignored),
    # for cell estimates (make_channel_body); cells = len(centres) * nz
    centres = []
    for quad, ni, nj in blocks:
        q = [P[k] for k in quad]
        for i in range(ni):
            for j in range(nj):
                u, v = (i + 0.5) / ni, (j + 0.5) / nj
                centres.append(tuple((1 - u) * (1 - v) * q[0][k] + u * (1 - v) * q[1][k] + u * v * q[2][k]
                                     + (1 - u) * v * q[3][k] for k in (0, 1)))
    return centres, nz


def outer_cells(length, h, ratio_max):
    """Fewest cells (first cell h, geometric growth at most ratio_max per
    cell) that cover length; at most as many as uniform cells of size h."""
    n_uniform = max(1, int(math.ceil(length / h - 1e-9)))
    n = 1
    while n < n_uniform and h * (ratio_max ** n - 1) / (ratio_max - 1) < length:
        n += 1
    return n
