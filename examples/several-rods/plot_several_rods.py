#!/usr/bin/python3
"""Per-rod measures of examples/several-rods/in.several_rods.

Reads the fix ave/time file (rods_<tag>.txt: one row per rod every 20 us:
rod, x, y, angle eq. 1, deflection eq. 2, lateral / W, v_x / U, wall
contact, outcome state), writes them as CSV (rods_<tag>.csv) and plots the
paper's measures along x, one line per rod, with the rods' paths over the
pore (PNG).

    /usr/bin/python3 plot_several_rods.py rods_<tag>.txt several_rods.png [--dt 2e-6]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLUMNS = ["rod", "x_m", "y_m", "angle_deg", "deflection", "lateral_over_W", "vx_over_U", "wall_contact", "outcome_state"]


def read_rows(path, dt):
    rows, step = [], None
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            fields = line.split()
            if len(fields) == 2:  # "TimeStep Number-of-rows"
                step = int(fields[0])
                continue
            values = [float(v) for v in fields[1:]]
            row = dict(zip(COLUMNS, values))
            row["rod"] = int(row["rod"])
            row["time_s"] = step * dt
            rows.append(row)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("rods_file")
    parser.add_argument("png")
    parser.add_argument("--dt", type=float, default=2e-6, help="timestep of the run [s] (TimeStep x dt = time)")
    args = parser.parse_args()
    rows = read_rows(args.rods_file, args.dt)
    csv_path = args.rods_file.rsplit(".", 1)[0] + ".csv"
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["time_s"] + COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row[k] for k in ["time_s"] + COLUMNS})
    rods = sorted({r["rod"] for r in rows})
    fig, axes = plt.subplots(1, 5, figsize=(20, 3.8))
    panels = [("angle_deg", "angle α (deg), eq. 1"), ("deflection", "relative deflection δ_r, eq. 2"),
              ("lateral_over_W", "lateral displacement Δy / W"), ("vx_over_U", "v_x / U")]
    for rod in rods:
        mine = [r for r in rows if r["rod"] == rod]
        x = [1e6 * r["x_m"] for r in mine]
        for ax, (key, label) in zip(axes, panels):
            ax.plot(x, [r[key] for r in mine], label=f"rod {rod}")
            ax.set_xlabel("x of the rod's centre (µm)")
            ax.set_ylabel(label)
        axes[4].plot(x, [1e6 * r["y_m"] for r in mine], label=f"rod {rod}")
    for ax in axes[:4]:
        ax.axvline(300, color="grey", lw=0.8, ls=":")
    # The pore: cylinders of R = 85 um on the side walls at x = 300 um.
    for yc in (0.0, 200.0):
        axes[4].add_patch(plt.Circle((300.0, yc), 85.0, color="lightgrey"))
    axes[4].set_xlim(150, 600)
    axes[4].set_ylim(0, 200)
    axes[4].set_aspect("equal")
    axes[4].set_xlabel("x (µm)")
    axes[4].set_ylabel("y of the rod's centre (µm)")
    axes[0].legend()
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"wrote {csv_path} and {args.png} ({len(rods)} rods, {len(rows)} rows)")


if __name__ == "__main__":
    main()
