#!/usr/bin/python3
"""The pressure around a rod trapped at the pore (Braesel et al. 2024,
Fig. 10c) from in.trapped_pressure's files: the gap pressure of the
background flow (fix hele_shaw/field's flow_trapped_*.vti, read with VTK)
near the pore, the trapped rod's spheres (trapped_rod.txt, last frame) over
it, and the channel's pressure drop with and without the rod's load
(compute hele_shaw/pressure_drop, from the TRAPPED_PRESSURE line of the
run's screen output).
What it is not: the pressure disturbed by the rod (the level-4 window
field is not written yet); the rise is the reciprocal-theorem estimate
from the rod's loads (doc/compute_hele_shaw_pressure_drop.txt).
Usage: hsrod -in in.trapped_pressure > log.trapped
       plot_trapped_pressure.py log.trapped trapped_pressure.png"""
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

log, out = sys.argv[1:3]
line = [l for l in open(log, errors="replace") if l.startswith("TRAPPED_PRESSURE")][-1].split()
values = dict(zip(line[1::2], map(float, line[2::2])))

reader = vtk.vtkXMLImageDataReader()
reader.SetFileName(sorted(glob.glob("flow_trapped_*.vti"))[-1])
reader.Update()
img = reader.GetOutput()
nx, ny, _ = img.GetDimensions()
(x0, y0, _), (hx, hy, _) = img.GetOrigin(), img.GetSpacing()
pressure = vtk_to_numpy(img.GetPointData().GetArray("pressure")).reshape(ny, nx)
fluid = vtk_to_numpy(img.GetPointData().GetArray("fluid")).reshape(ny, nx)
x, y = x0 + hx * np.arange(nx), y0 + hy * np.arange(ny)

lines = open("trapped_rod.txt").read().split("\n")
frames = [k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS")]
n = int(lines[frames[-1] - 5])
rod = np.array([[float(v) for v in lines[frames[-1] + 1 + m].split()[1:3]] for m in range(n)])

um = 1e6
fig, ax = plt.subplots(figsize=(7.5, 5))
keep = (x > 180e-6) & (x < 420e-6)
mesh = ax.pcolormesh(x[keep] * um, y * um, np.ma.masked_where(fluid[:, keep] == 0, pressure[:, keep]),
                     shading="gouraud", cmap="coolwarm")
fig.colorbar(mesh, ax=ax, label="gap pressure p of the background flow [Pa]")
ax.contour(x[keep] * um, y * um, np.ma.masked_where(fluid[:, keep] == 0, pressure[:, keep]), 15, colors="k",
           linewidths=0.4)
for cx, cy in ((300.0, 0.0), (300.0, 200.0)):
    ax.add_patch(Circle((cx, cy), 85.0, facecolor="0.6", edgecolor="k"))
for px, py in rod:
    ax.add_patch(Circle((px * um, py * um), 1.5, facecolor="gold", edgecolor="k", lw=0.5))
ax.set_xlim(180, 420)
ax.set_ylim(0, 200)
ax.set_aspect("equal")
ax.set_xlabel("x [µm]")
ax.set_ylabel("y [µm]")
ax.set_title("Rod trapped at the pore (E = 15 MPa, L_rod = 2 d_pore); channel pressure drop\n"
             f"{values['background_Pa']:.0f} Pa without the rod, +{values['rise_level4_Pa']:.0f} Pa with it at level 4 "
             f"(+{values['rise_level2_Pa']:.0f} Pa at level 2)", fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=120)
print(f"wrote {out}")
