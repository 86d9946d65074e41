#!/usr/bin/python3
"""Lateral displacement per pillar column of each rod (in.pillars dumps).

Reads pillars_s<N>.dump (id mol x y every 0.5 ms), tracks each rod's
centre (mean of its spheres) and measures its lateral displacement per
column: the y-change of the centre between x = 115 um (half a spacing
after the first column at 100 um) and x = 715 um, two whole periods (20
columns) later, inside the array: over whole periods a rod that zigzags
comes back to the same place in its lane (0), one that bumps has moved
eps * lambda_y = 3 um per column. Writes pillar_sorting.png and prints one line per rod.
Usage: plot_pillars.py [spheres ...] (default 2 4 8 12).
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from pillar_tracks import COLUMNS, SHIFT_PER_COLUMN, X_IN, X_OUT, crossing_y, rod_centres

UM = 1e-6


def read_dump(path):
    """{mol: array of (x, y) of the rod centre per frame}"""
    return {mol: np.array(track) for mol, track in rod_centres(path).items()}


def main():
    lengths = [int(a) for a in sys.argv[1:]] or [2, 4, 8, 12]
    fig, (ax_tracks, ax_shift) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = dict(zip(lengths, ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown"]))
    summary = []
    for n in lengths:
        rods = read_dump(f"pillars_s{n}.dump")
        shifts = []
        for mol, track in sorted(rods.items()):
            ax_tracks.plot(track[:, 0] / UM, track[:, 1] / UM, color=colours[n], lw=1,
                           label=f"{n} spheres ({3 * n} um)" if mol == min(rods) else None)
            y_in, y_out = crossing_y(track, X_IN), crossing_y(track, X_OUT)
            if y_in is None or y_out is None:
                print(f"PILLARS spheres {n} rod {mol}: did not cross the array (x end {track[-1, 0] / UM:.0f} um)")
                continue
            shift = (y_out - y_in) / COLUMNS
            shifts.append(shift)
            print(f"PILLARS spheres {n} rod {mol}: y in {y_in / UM:.1f} um, out {y_out / UM:.1f} um, "
                  f"{shift / UM:+.2f} um per column ({shift / SHIFT_PER_COLUMN:+.2f} eps lambda)")
        if shifts:
            summary.append((n, np.mean(shifts), np.min(shifts), np.max(shifts)))
            print(f"PILLARS spheres {n}: mean {np.mean(shifts) / UM:+.2f} um per column over {len(shifts)} rods")
    # The pillars (as laid out by fix hele_shaw/drag pillars 9e-6 100e-6 970e-6 30e-6 30e-6 0.1).
    for i in range(30):
        s = (i * 0.1) % 1.0
        for j in range(-6, 7):
            y = 150 + (j + s) * 30
            if 15 - 1e-9 <= y <= 285 + 1e-9:
                ax_tracks.add_patch(plt.Circle((100 + 30 * i, y), 9, color="0.6"))
    ax_tracks.set_xlim(0, 1100)
    ax_tracks.set_ylim(0, 300)
    ax_tracks.set_aspect("equal")
    ax_tracks.set_xlabel("x [um]")
    ax_tracks.set_ylabel("y [um]")
    ax_tracks.set_title("rod centres, pillars R = 9 um, G = 12 um, eps = 0.1")
    ax_tracks.legend(fontsize=7, loc="lower right")
    for n, mean, lo, hi in summary:
        ax_shift.errorbar([3 * n], [mean / UM], yerr=[[(mean - lo) / UM], [(hi - mean) / UM]], fmt="o",
                          color=colours[n], capsize=4)
    ax_shift.axhline(SHIFT_PER_COLUMN / UM, ls="--", color="k", lw=0.8, label="bump: eps lambda_y = 3 um")
    ax_shift.axhline(0.0, ls=":", color="k", lw=0.8, label="zigzag: 0")
    ax_shift.set_xlabel("rod length [um]")
    ax_shift.set_ylabel("lateral displacement per column [um]")
    ax_shift.set_title("mean (bars: range) over the rods")
    ax_shift.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("pillar_sorting.png", dpi=120)


if __name__ == "__main__":
    main()
