#!/usr/bin/python3
"""Clogging probability against the area fraction (clog_probability_runs.csv).

Rods of L_rod = d_pore = 30 um on create_rods' lattice in x = 120-215 um,
released across the flow, each moved by up to 0.5 um and turned by up to
2 degrees at random from the seed (jitter 0.5e-6 2). A run is clogged when
fix rod/outcome classed at least one rod clogged (column clogged_run). Per
number of rods: clogged runs over the seeds run, with the 95 % Wilson
interval of liggghts-package/sweep/sweep_aggregate.py.
  plot_clog_probability.py [clog_probability_runs.csv] [clog_probability.png]
"""
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "liggghts-package", "sweep"))
import sweep_aggregate  # noqa: E402

# Area fraction of the seeding region per rod: 10 spheres of 3 um over
# 95 um x 200 um minus the cylinders' share (create_rods' report).
AREA_FRACTION_PER_ROD = 0.004635


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "clog_probability_runs.csv"
    png = sys.argv[2] if len(sys.argv) > 2 else "clog_probability.png"
    rows = list(csv.DictReader(open(src)))
    cells = sweep_aggregate.probability(rows, ["nrods"], "clogged_run", 1)
    phi = [int(c["nrods"]) * AREA_FRACTION_PER_ROD for c in cells]
    p = [c["probability"] for c in cells]
    low = [c["probability"] - c["ci_low"] for c in cells]
    high = [c["ci_high"] - c["probability"] for c in cells]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.errorbar(phi, p, yerr=[low, high], marker="o", capsize=4, label="clogged runs, 95 % Wilson interval")
    for x, c in zip(phi, cells):
        ax.annotate(f"{c['hits']}/{c['cases']}", (x, c["probability"]), textcoords="offset points",
                    xytext=(6, 4), fontsize=8)
        print(f"nrods {c['nrods']} area_fraction {x:.4f} clogged_runs {c['hits']} of {c['cases']} "
              f"p {c['probability']:.2f} wilson95 [{c['ci_low']:.2f}, {c['ci_high']:.2f}]")
    ax.set_xlabel("area fraction of the seeding region")
    ax.set_ylabel("clogging probability")
    ax.set_title("lattice jitter 0.5 um / 2 deg, L_rod = d_pore")
    ax.set_ylim(-0.05, 1.05)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    main()
