#!/usr/bin/python3
"""Clogged fraction of the rods against the area fraction (bridging_runs.csv).

Rods of L_rod = d_pore released across the flow in x = 120-215 um in front
of the pore, on create_rods' lattice and at random positions (seed 1).
Each point is one run: the lattice is deterministic, so no interval over
seeds is drawn.
  plot_bridging.py [bridging_runs.csv] [bridging.png]
"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "bridging_runs.csv"
    png = sys.argv[2] if len(sys.argv) > 2 else "bridging.png"
    rows = list(csv.DictReader(open(src)))
    fig, ax = plt.subplots(figsize=(5, 3.5))
    for layout, marker in (("lattice", "o"), ("random", "s")):
        pts = sorted((float(r["area_fraction"]), int(r["clogged"]) / int(r["rods"]))
                     for r in rows if r["layout"] == layout)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, label=f"{layout}, alpha = 0")
    ax.set_xlabel("area fraction of the seeding region")
    ax.set_ylabel("fraction of rods clogged")
    ax.set_title("L_rod = d_pore = 30 um, E = 15 MPa, friction 0.5")
    ax.set_ylim(-0.05, 1.0)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    main()
