#!/usr/bin/python3
"""Plot the paper's rod measures (Braesel et al. 2024, Fig. 6) against the
rod's x position for the runs of in.pore: angle (eq. 1), relative
deflection (eq. 2), lateral displacement / W and v_x / U.
Usage: plot_pore.py [--title TITLE] out.png run1.csv[:label] [run2.csv[:label] ...]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

args = sys.argv[1:]
title = "Rod (10 x 3 $\\mu$m) through a pore constriction, $\\beta$ = 0.15, Re = 2 (hsrod reduced model)"
if args[0] == "--title":
    title = args[1] + " (hsrod reduced model)"
    args = args[2:]
out = args[0]
runs = args[1:]
fig, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
panels = [("angle_deg", "angle $\\alpha$ (eq. 1) [deg]"), ("deflection", "relative deflection $\\delta_r$ (eq. 2)"),
          ("lateral_over_W", "lateral displacement $\\Delta y / W$"), ("vx_over_U", "$v_x / U$")]
for spec in runs:
    path, _, label = spec.partition(":")
    data = np.genfromtxt(path, delimiter=",", names=True)
    x_um = data["x_m"] * 1e6
    style = "--" if "MPa" in label else "-"
    for ax, (column, ylabel) in zip(axes.flat, panels):
        ax.plot(x_um, data[column], style, label=label or path)
for ax, (column, ylabel) in zip(axes.flat, panels):
    ax.set_ylabel(ylabel)
    ax.axvline(300, color="0.7", lw=0.8)  # pore centre
    ax.grid(alpha=0.3)
for ax in axes[1]:
    ax.set_xlabel("rod centre x [$\\mu$m] (pore at 300 $\\mu$m)")
axes[0, 0].legend(fontsize=8)
fig.suptitle(title)
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
