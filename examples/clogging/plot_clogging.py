#!/usr/bin/python3
"""Plots of the clogging study (Braesel et al. 2024, Figs. 10-11) from the
runs of in.clogging:
  map.csv (run_map.sh)      -> clogging_map.png: outcome over E x L_rod/d_pore,
                               one panel per aspect ratio, like Fig. 10 (a, b)
  clog_*.csv [label ...]    -> clogging_runs.png: x, <v_x>/U and deflection
                               against time and the measures along x
Usage: plot_clogging.py map.csv clogging_map.png
       plot_clogging.py --runs clogging_runs.png run1.csv:label [run2.csv:label ...]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

NAMES = {1: "passage, no contact", 2: "passage with contact", 3: "clogged (wall entrapment)",
         0: "undecided (40 ms)", -1: "run failed"}
STYLE = {1: ("o", "tab:green"), 2: ("s", "tab:orange"), 3: ("X", "tab:red"), 0: ("?", "0.5"), -1: ("x", "k")}


def plot_map(csv, out):
    data = np.genfromtxt(csv, delimiter=",", names=True)
    sections = sorted(set(int(s) for s in np.atleast_1d(data["section"])))
    fig, axes = plt.subplots(1, len(sections), figsize=(5 * len(sections), 4), squeeze=False)
    for ax, s in zip(axes[0], sections):
        rows = np.atleast_1d(data)[np.atleast_1d(data["section"]) == s]
        seen = set()
        for row in rows:
            code = int(row["outcome"])
            marker, colour = STYLE.get(code, STYLE[-1])
            ax.scatter(row["E_Pa"], row["ratio"], marker=marker, s=120, color=colour,
                       label=None if code in seen else NAMES.get(code, str(code)))
            seen.add(code)
        ax.set_xscale("log")
        ax.set_xlabel("Young's modulus E [Pa]")
        ax.set_ylabel("$L_{rod} / d_{pore}$")
        ax.set_title(f"aspect ratio {10 if s == 1 else 5} ({s}x{s} spheres per section), $\\alpha$ = 0")
        ax.set_yticks(sorted(set(rows["ratio"])))
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    fig.suptitle("Clogging regime map, hsrod reduced model ($\\beta$ = 0.15, Re = 2, $\\mu_{fr}$ = 0.5)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def plot_runs(out, specs):
    fig, axes = plt.subplots(2, 2, figsize=(10, 6.5))
    for spec in specs:
        path, _, label = spec.partition(":")
        d = np.genfromtxt(path, delimiter=",", names=True)
        t_ms = d["time_s"] * 1e3
        axes[0, 0].plot(t_ms, d["x_m"] * 1e6, label=label or path)
        axes[0, 1].plot(t_ms, d["vx_over_U_averaged"], label=label or path)
        axes[1, 0].plot(d["x_m"] * 1e6, d["deflection"], label=label or path)
        axes[1, 1].plot(t_ms, d["wall_force_N"] * 1e9, label=label or path)
    axes[0, 0].axhline(300, color="0.7", lw=0.8)
    axes[0, 0].set(xlabel="t [ms]", ylabel="rod centre x [$\\mu$m] (pore at 300)")
    axes[0, 1].axhline(0.05, color="r", lw=0.8, ls=":")
    axes[0, 1].set(xlabel="t [ms]", ylabel="$\\langle v_x \\rangle / U$ (averaged, stall below 0.05)")
    axes[1, 0].set(xlabel="rod centre x [$\\mu$m]", ylabel="relative deflection $\\delta_r$ (eq. 2)")
    axes[1, 1].set(xlabel="t [ms]", ylabel="wall contact force [nN]")
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("Rods at the pore: entrapment vs passage (hsrod reduced model)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    if sys.argv[1] == "--runs":
        plot_runs(sys.argv[2], sys.argv[3:])
    else:
        plot_map(sys.argv[1], sys.argv[2])
