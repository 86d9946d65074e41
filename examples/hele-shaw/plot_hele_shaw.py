#!/usr/bin/python3
"""Plot the rod's angle (eq. 1), deflection (eq. 2) and lateral position
against the distance travelled, as in Braesel et al. 2024, Fig. 3(b, c).
Usage: plot_hele_shaw.py out.png run.csv[:label] ..."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

out = sys.argv[1]
fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
for spec in sys.argv[2:]:
    path, _, label = spec.partition(":")
    d = np.genfromtxt(path, delimiter=",", names=True)
    travelled_mm = (d["x_m"] - d["x_m"][0]) * 1e3
    axes[0].plot(travelled_mm, d["angle_deg"], label=label or path)
    axes[1].plot(travelled_mm, d["deflection"], label=label or path)
    axes[2].plot(travelled_mm, d["lateral_over_W"], label=label or path)
for ax, title in zip(axes, ["angle $\\alpha$ (eq. 1) [deg]", "relative deflection $\\delta_r$ (eq. 2)",
                            "lateral displacement $\\Delta y / W$"]):
    ax.set_xlabel("distance travelled [mm]")
    ax.set_ylabel(title)
    ax.grid(alpha=0.3)
axes[0].legend(fontsize=8)
fig.suptitle("Flexible rod across the flow in a Hele-Shaw channel ($\\beta$ = 0.83, E = 2 kPa): "
             "transition, equilibrium, reorientation")
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
