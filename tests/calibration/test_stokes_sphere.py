"""One sphere held fixed in a box, creeping flow: drag against Stokes'
F = 3 pi mu d U within 5 % at 8 cells per diameter, plus the mesh
convergence table at 4, 8 and 12 cells per diameter.

Box correction: none is needed. The box faces (half width 4 d) carry the
exact Stokes velocity of the unbounded flow around the sphere
(farField type stokes, Happel & Brenner 1965 eq. 4-17.16), so a finite box
reproduces the unbounded problem up to discretisation. The mesh is uniform
(h = d/n) in a core of +-0.75 d and stretched geometrically outside.
The sphere centre is shifted by (0.3, 0.17, 0.41) cells off the grid
vertex so the test does not profit from symmetry.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct

D, U, MU = 3e-6, 1e-3, 1e-3          # m, m/s, Pa s (scene file)
F_STOKES = 3 * math.pi * MU * D * U  # N


def main():
    env = ct.Env(sys.argv)
    rows, ok = [], True
    for n in (4, 8, 12):
        case = env.make_case("sphere_in_box.json", "stokes_n%d" % n,
                             ["mesh.cells_per_diameter=%d" % n, "sphere.offset_cells=[0.3,0.17,0.41]"])
        _, log, secs = env.run(case)
        load = ct.last_loads(case)[0]
        F = float(load["Fx"])
        side = math.hypot(float(load["Fy"]), float(load["Fz"]))
        ncells = [l for l in log.splitlines() if l.startswith("rodIbFoam:")][0].split()[3]
        rows.append((n, ncells, F, F / F_STOKES - 1, side / F, secs))
    print("\nmesh convergence, sphere d = %g m in creeping flow U = %g m/s (Stokes drag %.5e N)" % (D, U, F_STOKES))
    print("%6s %8s %14s %10s %12s %8s" % ("d/h", "cells", "F_x [N]", "error", "|F_perp|/F", "time[s]"))
    for n, nc, F, e, s, t in rows:
        print("%6d %8s %14.6e %+9.2f%% %12.2e %8.1f" % (n, nc, F, 100 * e, s, t))
    e8 = rows[1][3]
    ok &= ct.check(abs(e8) < 0.05, "drag within 5 %% of Stokes at 8 cells/diameter (%+.2f %%)" % (100 * e8))
    ok &= ct.check(abs(rows[2][3]) < 0.05, "drag within 5 %% at 12 cells/diameter (%+.2f %%)" % (100 * rows[2][3]))
    ok &= ct.check(abs(rows[2][3]) <= abs(rows[0][3]), "error at 12 cells/d not above the error at 4 cells/d")
    ok &= ct.check(all(r[4] < 0.01 for r in rows), "side force below 1 % of drag")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
