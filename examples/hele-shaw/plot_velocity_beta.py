#!/usr/bin/python3
"""Fig. 3d: rod velocity over the gap-averaged centre-line velocity u_c against beta
(velocity_beta.csv of run_velocity_beta.sh), one line per model and
orientation, next to the reference trends: the maximal fluid velocity 3/2 U
that a fibre reaches as beta -> 0 and the mid-plane sphere of Faxen's law,
3/2 (1 - beta^2 / 3) (Berthet et al. 2013: fibre velocities decrease with
beta, perpendicular fibres faster than parallel ones, markedly above ~0.5).
Usage: plot_velocity_beta.py velocity_beta.csv velocity_beta.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["status"] == "ok"]
fig, ax = plt.subplots(figsize=(6, 4.5))
names = {"local": "level 2", "nonlocal": "level 3"}
for model, style in (("local", "--"), ("nonlocal", "-")):
    for alpha, colour in (("0", "tab:blue"), ("90", "tab:red")):
        pts = sorted((float(r["beta"]), float(r["vx_over_uc"])) for r in rows if r["model"] == model and r["alpha"] == alpha)
        if pts:
            ax.plot(*zip(*pts), style, marker="o", color=colour,
                    label=f"{names.get(model, model)}, {'perpendicular' if alpha == '0' else 'parallel'}")
beta = np.linspace(0.0, 0.85, 50)
ax.plot(beta, 1.5 * (1 - beta ** 2 / 3), ":", color="k", label="mid-plane sphere, Faxen: 3/2 (1 - beta^2/3)")
ax.axhline(1.5, color="0.6", lw=0.8)
ax.set_xlabel(r"confinement $\beta = d/H$")
ax.set_ylabel(r"rod velocity / centre-line gap-averaged velocity $u_c$")
ax.set_title("Rigid 15-sphere rod in a Hele-Shaw channel (Fig. 3d)")
ax.grid(alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print(f"wrote {sys.argv[2]}")
