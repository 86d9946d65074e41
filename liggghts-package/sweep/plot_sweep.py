#!/usr/bin/python3
"""Plots of an hsrod-sweep result CSV (doc: liggghts-package/doc/hsrod_sweep.txt).

  plot_sweep.py map SWEEP.csv --x E --y ratio --class outcome [--logx] -o map.png
      regime map: the class measure (e.g. compute rod/shape column 14) of
      every case over two swept variables, one marker per case (as the
      paper's Figs. 10-11); failed cases drawn as black crosses.
  plot_sweep.py measure SWEEP.csv --x E --y angle [--group ratio] [--logx] -o angle.png
      any measure against any swept variable, one line per value of --group.
  plot_sweep.py probability SWEEP.csv --x conc --y ratio [--class outcome] [--value 3]
                            [--table cells.csv] -o p.png
      a regime map of a probability: the cases of each (x, y) cell (every
      value of the other swept variables, e.g. a seed axis) that end in
      class --value (default 3, clogged), as a colour with the fraction and
      its 95 % Wilson interval written in the cell (sweep_aggregate.py);
      --table writes the cells as CSV.
  --where NAME=VALUE (repeatable) keeps only the cases with that value of a
  further swept variable.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sweep_aggregate  # noqa: E402

# fix rod/outcome output [2] = compute rod/shape column 14 (liggghts-package/doc/fix_rod_outcome.txt)
OUTCOME_LABELS = {0: "en route (undecided)", 1: "passed without contact", 2: "passed with contact", 3: "clogged"}
MARKERS = {0: ("o", "0.6"), 1: ("o", "tab:green"), 2: ("s", "tab:orange"), 3: ("X", "tab:red")}


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def load(path, where):
    with open(path, newline="") as f:
        table = list(csv.DictReader(f))
    for condition in where:
        name, _, value = condition.partition("=")
        if not table or name not in table[0]:
            sys.exit(f"plot_sweep: --where {condition}: no column '{name}' in {path}")
        table = [r for r in table if r[name] == value or number(r[name]) == number(value)]
    if not table:
        sys.exit(f"plot_sweep: no cases left in {path}")
    return table


def need(table, *names):
    for n in names:
        if n not in table[0]:
            sys.exit(f"plot_sweep: no column '{n}' (columns: {', '.join(table[0])})")


def regime_map(args, table):
    need(table, args.x, args.y, args.klass)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    classes = {}
    failed = []
    for r in table:
        x, y = number(r[args.x]), number(r[args.y])
        if r["status"] != "ok" or number(r[args.klass]) is None:
            failed.append((x, y))
            continue
        classes.setdefault(int(round(float(r[args.klass]))), []).append((x, y))
    for k in sorted(classes):
        marker, colour = MARKERS.get(k, ("D", f"C{k % 10}"))
        xs, ys = zip(*classes[k])
        ax.scatter(xs, ys, marker=marker, s=90, c=colour, edgecolors="k", linewidths=0.5,
                   label=OUTCOME_LABELS.get(k, f"class {k}") if args.klass_is_outcome else f"{args.klass} = {k}")
    if failed:
        xs, ys = zip(*failed)
        ax.scatter(xs, ys, marker="x", s=70, c="k", label="failed (see the error column)")
    if args.logx:
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    ax.set_xlabel(args.xlabel or args.x)
    ax.set_ylabel(args.ylabel or args.y)
    ax.set_title(args.title or f"{args.klass} over {args.x} and {args.y} ({len(table)} cases)")
    # Outside the axes: a regime map fills its whole plot area.
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    return fig


def measure_plot(args, table):
    need(table, args.x, args.y)
    if args.group:
        need(table, args.group)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    groups = {}
    for r in table:
        if r["status"] != "ok":
            continue
        key = r[args.group] if args.group else ""
        groups.setdefault(key, []).append((number(r[args.x]), number(r[args.y])))
    for key in sorted(groups, key=lambda k: (number(k) is None, number(k) or 0, k)):
        points = sorted(groups[key])
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label=f"{args.group} = {key}" if args.group else None)
    if args.logx:
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    ax.set_xlabel(args.xlabel or args.x)
    ax.set_ylabel(args.ylabel or args.y)
    failed = sum(1 for r in table if r["status"] != "ok")
    ax.set_title(args.title or f"{args.y} against {args.x}" + (f" ({failed} failed cases not shown)" if failed else ""))
    if args.group:
        ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def probability_map(args, table):
    need(table, args.x, args.y, args.klass)
    cells = sweep_aggregate.probability(table, [args.x, args.y], args.klass, args.value)
    if args.table:
        with open(args.table, "w", newline="") as f:
            columns = [args.x, args.y, "cases", "hits", "failed", "probability", "ci_low", "ci_high"]
            w = csv.DictWriter(f, fieldnames=columns)
            w.writeheader()
            for c in cells:
                w.writerow({k: c[k] for k in columns})
        print(f"plot_sweep: wrote {args.table}")
    xs = sorted({c[args.x] for c in cells}, key=lambda v: number(v) if number(v) is not None else 0)
    ys = sorted({c[args.y] for c in cells}, key=lambda v: number(v) if number(v) is not None else 0)
    fig, ax = plt.subplots(figsize=(1.3 * len(xs) + 3, 0.9 * len(ys) + 2))
    grid = [[float("nan")] * len(xs) for _ in ys]
    for c in cells:
        i, j = ys.index(c[args.y]), xs.index(c[args.x])
        grid[i][j] = c["probability"]
        ax.text(j, i, f"{c['probability']:.2f}\n[{c['ci_low']:.2f}, {c['ci_high']:.2f}]\nn = {c['cases']}",
                ha="center", va="center", fontsize=7, color="white" if c["probability"] > 0.6 else "black")
    image = ax.imshow(grid, origin="lower", cmap="Reds", vmin=0, vmax=1, aspect="auto")
    fig.colorbar(image, ax=ax, label=f"P({args.klass} = {args.value:g})")
    ax.set_xticks(range(len(xs)), xs)
    ax.set_yticks(range(len(ys)), ys)
    ax.set_xlabel(args.xlabel or args.x)
    ax.set_ylabel(args.ylabel or args.y)
    ax.set_title(args.title or f"P({args.klass} = {args.value:g}) per cell, 95 % Wilson intervals")
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=["map", "measure", "probability"])
    parser.add_argument("csv")
    parser.add_argument("--x", required=True, help="swept variable on the x axis")
    parser.add_argument("--y", required=True, help="map: swept variable on the y axis; measure: the measure")
    parser.add_argument("--class", dest="klass", default="outcome", help="map: the class measure (default outcome)")
    parser.add_argument("--value", type=float, default=3, help="probability: the class counted (default 3, clogged)")
    parser.add_argument("--table", help="probability: also write the cells as CSV")
    parser.add_argument("--group", help="measure: one line per value of this swept variable")
    parser.add_argument("--where", action="append", default=[], help="NAME=VALUE filter, repeatable")
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    parser.add_argument("--xlabel")
    parser.add_argument("--ylabel")
    parser.add_argument("--title")
    parser.add_argument("-o", "--output", required=True, help="PNG file")
    args = parser.parse_args()
    args.klass_is_outcome = args.klass == "outcome"
    table = load(args.csv, args.where)
    plots = {"map": regime_map, "measure": measure_plot, "probability": probability_map}
    fig = plots[args.kind](args, table)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120, bbox_inches="tight")
    print(f"plot_sweep: wrote {args.output}")


if __name__ == "__main__":
    main()
