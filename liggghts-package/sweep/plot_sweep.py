#!/usr/bin/python3
"""Plots of an hsrod-sweep result CSV (doc: liggghts-package/doc/hsrod_sweep.txt).

  plot_sweep.py map SWEEP.csv --x E --y ratio --class outcome [--logx] -o map.png
      regime map: the class measure (e.g. compute rod/shape column 14) of
      every case over two swept variables, one marker per case (as the
      paper's Figs. 10-11); failed cases drawn as black crosses.
  plot_sweep.py measure SWEEP.csv --x E --y angle [--group ratio] [--logx] -o angle.png
      any measure against any swept variable, one line per value of --group.
  --where NAME=VALUE (repeatable) keeps only the cases with that value of a
  further swept variable.
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=["map", "measure"])
    parser.add_argument("csv")
    parser.add_argument("--x", required=True, help="swept variable on the x axis")
    parser.add_argument("--y", required=True, help="map: swept variable on the y axis; measure: the measure")
    parser.add_argument("--class", dest="klass", default="outcome", help="map: the class measure (default outcome)")
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
    fig = regime_map(args, table) if args.kind == "map" else measure_plot(args, table)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120, bbox_inches="tight")
    print(f"plot_sweep: wrote {args.output}")


if __name__ == "__main__":
    main()
