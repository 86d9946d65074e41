#!/usr/bin/python3
"""The pore scene's flow and the rods in it, from the files in.pore writes:
the gap-averaged speed |u|/U with streamlines (Braesel et al. 2024, Fig. 1d)
from fix hele_shaw/field's image (flow_0.vti) and walls (flow_walls.vtp),
read with VTK (python3-vtk9), and snapshots of the rods (text dumps
rod_snap_E*.txt) over it (as the paper's Figs. 5, 7).
Usage: plot_flow.py out.png flow_0.vti flow_walls.vtp [snapshots.txt[:label] ...]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import vtk
from matplotlib.collections import PolyCollection
from vtk.util.numpy_support import vtk_to_numpy

U_MEAN = 0.0295  # mean inflow velocity of the scene [m/s] (Re = 2, flow/README.md)


def read_image(path):
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    img = reader.GetOutput()
    nx, ny, _ = img.GetDimensions()
    (x0, y0, _), (hx, hy, _) = img.GetOrigin(), img.GetSpacing()
    arr = lambda name: vtk_to_numpy(img.GetPointData().GetArray(name))
    vel = arr("velocity").reshape(ny, nx, 3)
    return (x0 + hx * np.arange(nx), y0 + hy * np.arange(ny), vel[..., 0], vel[..., 1],
            arr("fluid").reshape(ny, nx), arr("pressure").reshape(ny, nx))


def read_cylinder_facets(path):
    """(x, y) polygons of the cylinders' facets in the plane (wall tag >= 1)."""
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    walls = reader.GetOutput()
    tag = vtk_to_numpy(walls.GetCellData().GetArray("wall"))
    pts = vtk_to_numpy(walls.GetPoints().GetData())
    by_cylinder = {}
    for cid in range(walls.GetNumberOfCells()):
        if tag[cid] >= 1:
            cell = walls.GetCell(cid)
            for end in (0, 1):  # both ends of the facet on the lower gap wall: the arc with its end points
                by_cylinder.setdefault(tag[cid], []).append(pts[cell.GetPointId(end), :2])
    return [np.array(v) for v in by_cylinder.values()]


def read_snapshots(path):
    """{step: array of (id, x, y)} from a LIGGGHTS text dump `id x y`."""
    frames, lines = {}, open(path).read().split("\n")
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            n = int(lines[k + 3])
            start = k + 9
            frames[step] = np.array([[float(v) for v in lines[start + m].split()[:3]] for m in range(n)])
            k = start + n
        else:
            k += 1
    return frames


out, vti, vtp = sys.argv[1:4]
x, y, ux, uy, fluid, p = read_image(vti)
speed = np.hypot(ux, uy) / U_MEAN
speed = np.ma.masked_where(fluid == 0, speed)
um = 1e6
fig, ax = plt.subplots(figsize=(11, 4.2))
mesh = ax.pcolormesh(x * um, y * um, speed, shading="gouraud", cmap="viridis")
fig.colorbar(mesh, ax=ax, label="gap-averaged speed $|u| / U$", pad=0.01)
ax.streamplot(x * um, y * um, np.where(fluid == 1, ux, 0.0), np.where(fluid == 1, uy, 0.0), color="w",
              linewidth=0.6, density=(2.2, 1.1), arrowsize=0.6)
for facets in read_cylinder_facets(vtp):
    order = np.argsort(np.arctan2(facets[:, 1] - facets[:, 1].mean(), facets[:, 0] - facets[:, 0].mean()))
    ax.add_collection(PolyCollection([facets[order] * um], facecolor="0.55", edgecolor="k", lw=0.8))
styles = [dict(color="tab:red", ms=3.5, lw=1.6), dict(color="k", ms=1.5, lw=0.7),
          dict(color="tab:pink", ms=2.5, lw=1.0), dict(color="tab:cyan", ms=2.5, lw=1.0)]
for n, spec in enumerate(sys.argv[4:]):
    path, _, label = spec.partition(":")
    frames = read_snapshots(path)
    steps = sorted(frames)
    for i, step in enumerate(steps[:: max(1, len(steps) // 12)]):
        pos = frames[step][np.argsort(frames[step][:, 0])]
        ax.plot(pos[:, 1] * um, pos[:, 2] * um, "o-", **styles[n % len(styles)],
                label=(label or path) if i == 0 else None)
ax.set_xlim(x[0] * um, x[-1] * um)
ax.set_ylim(y[0] * um, y[-1] * um)
ax.set_aspect("equal")
ax.set_xlabel("x [$\\mu$m]")
ax.set_ylabel("y [$\\mu$m]")
if len(sys.argv) > 4:
    ax.legend(loc="upper left", fontsize=8)
ax.set_title("Pore scene: depth-averaged Brinkman flow (Re = 2, $\\beta$ = 0.15) and rod snapshots (hsrod)")
fig.tight_layout()
fig.savefig(out, dpi=120)
inlet = fluid[:, 0] == 1
print(f"wrote {out}; peak |u|/U = {speed.max():.2f}, mean inlet pressure {p[inlet, 0].mean():.1f} Pa")
