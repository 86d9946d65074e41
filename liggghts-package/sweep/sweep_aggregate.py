"""Aggregates of an hsrod-sweep result over repeated cases (seeds).

A sweep with a seed axis (--var seed 1:20:1) runs every cell of a regime
map several times; a cell's outcome is then a probability. probability()
groups the ok rows by the values of the cell's variables and gives, per
cell, the number of cases, the number whose class measure equals a value
(e.g. fix rod/outcome's 3 = clogged) and that fraction with its Wilson
score interval (Wilson, J. Am. Stat. Assoc. 22, 209 (1927)), which stays
inside [0, 1] and is honest at 0 or n of n, unlike the normal
approximation. Python 3 standard library only.
"""
import math

Z_95 = 1.959963984540054  # two-sided 95 % normal quantile


def wilson_interval(successes, trials, z=Z_95):
    """(low, high) of the Wilson score interval for successes of trials."""
    if trials <= 0:
        raise ValueError("wilson_interval: trials must be >= 1")
    p = successes / trials
    z2 = z * z
    centre = (p + z2 / (2 * trials)) / (1 + z2 / trials)
    half = z * math.sqrt(p * (1 - p) / trials + z2 / (4 * trials * trials)) / (1 + z2 / trials)
    return max(0.0, centre - half), min(1.0, centre + half)


def _number(text):
    try:
        return float(text)
    except ValueError:
        return None


def probability(rows, cell_columns, class_column, value):
    """Per cell (the values of cell_columns): cases, hits (class == value),
    fraction and its 95 % Wilson interval; failed rows are counted apart.
    Returns a list of dicts sorted by the cells' values."""
    cells = {}
    for r in rows:
        key = tuple(r[c] for c in cell_columns)
        cell = cells.setdefault(key, {"cases": 0, "hits": 0, "failed": 0})
        klass = _number(r.get(class_column, ""))
        if r.get("status") != "ok" or klass is None:
            cell["failed"] += 1
            continue
        cell["cases"] += 1
        cell["hits"] += int(round(klass) == value)
    out = []
    for key, c in cells.items():
        row = dict(zip(cell_columns, key))
        row.update(c)
        if c["cases"]:
            row["probability"] = c["hits"] / c["cases"]
            row["ci_low"], row["ci_high"] = wilson_interval(c["hits"], c["cases"])
        else:
            row["probability"] = row["ci_low"] = row["ci_high"] = float("nan")
        out.append(row)
    out.sort(key=lambda r: tuple((_number(r[c]) is None, _number(r[c]) or 0.0, r[c]) for c in cell_columns))
    return out
