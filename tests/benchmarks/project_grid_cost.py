#!/usr/bin/env python3
"""Projects the CPU time of the 468-case Figs. 10-11 grid from
measured hsrod-sweep rows, for two builds run on the same cases.

Usage: project_grid_cost.py --old CSV... --new CSV... [--ar10-cpu 117]
CSVs: hsrod-sweep results of examples/clogging/in.clogging at section 2
(aspect ratio 5), with the columns alpha, E, ratio, cpu_s. A cell of the
aspect-ratio-5 grid (Fig. 10b: 13 E x 9 ratios at alpha 0; Fig. 11b: 13
alpha x 9 ratios at 15 MPa) takes the old build's measured CPU where it
has it, else the value interpolated in L_rod/d_pore at the nearest measured
E (log scale; Fig. 10b) or alpha (Fig. 11b). The new build's estimate is
the old one times the new/old CPU ratio measured on the cases both ran, per
stratum (Fig. 10b at E <= 267 kPa, Fig. 10b above, Fig. 11b at alpha > 0).
The aspect-ratio-10 half (Figs. 10a + 11a) is given (--ar10-cpu, seconds).
Prints the totals and the time on two free cores at busy fraction 0.97.
"""
import argparse
import csv
import math

E13 = ['15e3', '26.67e3', '47.43e3', '84.35e3', '150e3', '266.7e3', '474.3e3', '843.5e3', '1.5e6', '2.667e6',
       '4.743e6', '8.435e6', '15e6']
RATIOS = [1 + 0.5 * i for i in range(9)]


def load(paths):
    table = {}
    for path in paths:
        for row in csv.DictReader(open(path)):
            if row.get('section', '2') == '2' and row.get('cpu_s'):
                table[(float(row['alpha']), float(row['E']), float(row['ratio']))] = float(row['cpu_s'])
    return table


def in_ratio(table, alpha, e, r):
    points = sorted((k[2], v) for k, v in table.items() if k[0] == alpha and k[1] == e)
    if not points:
        return None
    lo = [p for p in points if p[0] <= r]
    hi = [p for p in points if p[0] >= r]
    if not lo:
        return hi[0][1]
    if not hi:
        return lo[-1][1]
    (r0, c0), (r1, c1) = lo[-1], hi[0]
    return c0 if r1 == r0 else c0 + (c1 - c0) * (r - r0) / (r1 - r0)


def estimate(table, alpha, e, r):
    value = in_ratio(table, alpha, e, r)
    if value is not None:
        return value
    if alpha == 0.0:
        measured = sorted({k[1] for k in table if k[0] == 0.0})
        nearest = min(measured, key=lambda m: abs(math.log(m) - math.log(e)))
        return in_ratio(table, 0.0, nearest, r)
    measured = sorted({k[0] for k in table if k[1] == e})
    nearest = min(measured, key=lambda m: abs(m - alpha))
    return in_ratio(table, nearest, e, r)


def stratum(alpha, e):
    return 'fig11b alpha > 0' if alpha > 0 else ('fig10b E <= 267 kPa' if e <= 266.7e3 else 'fig10b E > 267 kPa')


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--old', nargs='+', required=True)
    parser.add_argument('--new', nargs='+', required=True)
    parser.add_argument('--ar10-cpu', type=float, default=117.0)
    args = parser.parse_args()
    old, new = load(args.old), load(args.new)
    sums = {}
    for key in set(old) & set(new):
        s = sums.setdefault(stratum(key[0], key[1]), [0, 0.0, 0.0])
        s[0] += 1
        s[1] += old[key]
        s[2] += new[key]
    for name, (count, o, n) in sorted(sums.items()):
        print(f'{name}: {count} cases in common, old {o:.1f} s, new {n:.1f} s CPU, new/old {n / o:.3f}')
    cells = [(0.0, float(e), r) for e in E13 for r in RATIOS] + [(7.5 * i, 15e6, r) for i in range(13) for r in RATIOS]
    totals = {'old': [0.0, 0.0], 'new': [0.0, 0.0]}
    for alpha, e, r in cells:
        c = estimate(old, alpha, e, r)
        s = sums[stratum(alpha, e)]
        which = 0 if alpha == 0.0 else 1
        totals['old'][which] += c
        totals['new'][which] += c * s[2] / s[1]
    for name, (f10b, f11b) in totals.items():
        total = f10b + f11b + args.ar10_cpu
        print(f'{name}: fig10b {f10b:.0f} s, fig11b {f11b:.0f} s, figs 10a+11a {args.ar10_cpu:.0f} s: '
              f'{total:.0f} s CPU, {total / (2 * 0.97) / 60:.1f} min on 2 free cores')


if __name__ == '__main__':
    main()
