"""Rod tracks through the pillar array (in.pillars dumps), without numpy.

Shared by plot_pillars.py and the ctest tests/liggghts/pillar_sorting_by_length.py:
a rod's lateral displacement per column is the y-change of its centre between
X_IN (half a spacing after the first column at 100 um) and X_OUT, two whole
periods (COLUMNS columns) later, inside the array, over SHIFT_PER_COLUMN
(eps * lambda_y): 1 for a bumping rod, 0 for a zigzagging one.
"""

X_IN, X_OUT, COLUMNS = 115e-6, 715e-6, 20  # [m], [m], [-]
SHIFT_PER_COLUMN = 0.1 * 30e-6             # eps * lambda_y [m]


def rod_centres(path):
    """{mol: [(x, y) of the rod centre per frame]} from a dump of id mol x y."""
    rods, lines, i = {}, open(path).read().split("\n"), 0
    while i < len(lines):
        if lines[i].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[i + 1])
            while not lines[i].startswith("ITEM: ATOMS"):
                i += 1
            frame = {}
            for row in lines[i + 1:i + 1 + n]:
                _, mol, x, y = row.split()[:4]
                frame.setdefault(int(mol), []).append((float(x), float(y)))
            for mol, pts in frame.items():
                rods.setdefault(mol, []).append((sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts)))
            i += n
        i += 1
    return rods


def crossing_y(track, x):
    """y of the centre when it first passes x (linear between frames), or None."""
    for k in range(1, len(track)):
        if track[k][0] >= x:
            (x0, y0), (x1, y1) = track[k - 1], track[k]
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return None
