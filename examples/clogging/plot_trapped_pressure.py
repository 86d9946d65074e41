#!/usr/bin/python3
"""The pressure around a rod trapped at the pore (Braesel et al. 2024,
Fig. 10c) from in.trapped_pressure's files: left, the gap pressure of the
flow disturbed by the trapped rod at level 4 (fix hele_shaw/field's
flow_trapped_*.vti: the rod's window flow added to the background, read
with VTK) near the pore with the rod's spheres (trapped_rod.txt, last
frame) over it; right, the rod's pressure disturbance (minus the
background, background_trapped_*.vti) with the disturbed flow's
streamlines; in the title the channel's pressure drop with and without the
rod's load (compute hele_shaw/pressure_drop, from the TRAPPED_PRESSURE
line of the run's screen output).
A third panel shows the disturbed flow's speed |u|/U with streamlines
(Fig. 11c: the velocity field around a trapped rod).
What it is not: a resolved 3-D pressure; the window flow is gap-averaged
and its pressure counts the rod's obstruction forces only
(doc/fix_hele_shaw_field.txt, Restrictions).
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
values_line = dict(zip(line[1::2], map(float, line[2::2])))



def last_frame(pattern):
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(sorted(glob.glob(pattern), key=lambda f: int(f.rsplit("_", 1)[1][:-4]))[-1])
    reader.Update()
    img = reader.GetOutput()
    nx, ny, _ = img.GetDimensions()
    data = {name: vtk_to_numpy(img.GetPointData().GetArray(name)) for name in ("pressure", "fluid", "velocity")}
    return img, nx, ny, data


img, nx, ny, field = last_frame("flow_trapped_[0-9]*.vti")
_, _, _, background = last_frame("background_trapped_[0-9]*.vti")
(x0, y0, _), (hx, hy, _) = img.GetOrigin(), img.GetSpacing()
pressure = field["pressure"].reshape(ny, nx)
disturbance = pressure - background["pressure"].reshape(ny, nx)
fluid = field["fluid"].reshape(ny, nx)
ux, uy = field["velocity"][:, 0].reshape(ny, nx), field["velocity"][:, 1].reshape(ny, nx)
x, y = x0 + hx * np.arange(nx), y0 + hy * np.arange(ny)

lines = open("trapped_rod.txt").read().split("\n")
frames = [k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS")]
n = int(lines[frames[-1] - 5])
rod = np.array([[float(v) for v in lines[frames[-1] + 1 + m].split()[1:3]] for m in range(n)])
# Pressure jump of the disturbance across the rod's middle (5 um up- and downstream of the sphere nearest y = 100 um).
middle = rod[np.argmin(np.abs(rod[:, 1] - 100e-6))]
j_mid = int(np.argmin(np.abs(y - middle[1])))
jump = (disturbance[j_mid, int(np.argmin(np.abs(x - middle[0] + 5e-6)))]
        - disturbance[j_mid, int(np.argmin(np.abs(x - middle[0] - 5e-6)))])
print(f"rod middle at x = {middle[0] * 1e6:.1f} um: pressure disturbance jump across it {jump:.1f} Pa, "
      f"disturbance range {disturbance[fluid == 1].min():.1f} .. {disturbance[fluid == 1].max():.1f} Pa")

um = 1e6
fig, axes = plt.subplots(1, 3, figsize=(19, 5))
keep = (x > 180e-6) & (x < 420e-6)
xs, ys = x[keep] * um, y * um
wall = fluid[:, keep] == 0
limit = np.abs(disturbance[:, keep][~wall]).max()
panels = ((axes[0], pressure, "coolwarm", None, "gap pressure p, trapped rod at level 4 [Pa]"),
          (axes[1], disturbance, "RdBu_r", (-limit, limit), "pressure disturbance of the rod p - p_bg [Pa]"))
for ax, values, cmap, limits, label in panels:
    shown = np.ma.masked_where(wall, values[:, keep])
    mesh = ax.pcolormesh(xs, ys, shown, shading="gouraud", cmap=cmap,
                         **({} if limits is None else dict(vmin=limits[0], vmax=limits[1])))
    fig.colorbar(mesh, ax=ax, label=label, shrink=0.85)
    ax.contour(xs, ys, shown, 15, colors="k", linewidths=0.4)
    for cx, cy in ((300.0, 0.0), (300.0, 200.0)):
        ax.add_patch(Circle((cx, cy), 85.0, facecolor="0.6", edgecolor="k"))
    for px, py in rod:
        ax.add_patch(Circle((px * um, py * um), 1.5, facecolor="gold", edgecolor="k", lw=0.5))
    ax.set_xlim(180, 420)
    ax.set_ylim(0, 200)
    ax.set_aspect("equal")
    ax.set_xlabel("x [µm]")
    ax.set_ylabel("y [µm]")
U_MEAN = 0.0295  # mean inflow velocity of the scene [m/s] (Re = 2)
speed = np.ma.masked_where(wall, np.hypot(ux[:, keep], uy[:, keep]) / U_MEAN)
mesh = axes[2].pcolormesh(xs, ys, speed, shading="gouraud", cmap="viridis")
fig.colorbar(mesh, ax=axes[2], label="gap-averaged speed |u| / U, trapped rod at level 4", shrink=0.85)
axes[2].streamplot(xs, ys, np.where(wall, 0.0, ux[:, keep]), np.where(wall, 0.0, uy[:, keep]), color="w",
                   density=1.4, linewidth=0.5, arrowsize=0.6)
for cx, cy in ((300.0, 0.0), (300.0, 200.0)):
    axes[2].add_patch(Circle((cx, cy), 85.0, facecolor="0.6", edgecolor="k"))
for px, py in rod:
    axes[2].add_patch(Circle((px * um, py * um), 1.5, facecolor="gold", edgecolor="k", lw=0.5))
axes[2].set_xlim(180, 420)
axes[2].set_ylim(0, 200)
axes[2].set_aspect("equal")
axes[2].set_xlabel("x [µm]")
axes[1].streamplot(xs, ys, np.where(wall, 0.0, ux[:, keep]), np.where(wall, 0.0, uy[:, keep]), color="0.2",
                   density=1.4, linewidth=0.5, arrowsize=0.6)
case = values_line.get("ratio", 2.0), values_line.get("alpha", 0.0), values_line.get("E", 15e6) / 1e6
fig.suptitle("Rod at the pore (E = %g MPa, L_rod = %g d_pore, alpha = %g deg); channel pressure drop " % (case[2], case[0], case[1])
             + f"{values_line['background_Pa']:.0f} Pa without the rod, +{values_line['rise_level4_Pa']:.0f} Pa with it "
             f"at level 4 (+{values_line['rise_level2_Pa']:.0f} Pa at level 2); "
             f"window pressure jump across the rod {jump:.0f} Pa", fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=120)
print(f"wrote {out}")
