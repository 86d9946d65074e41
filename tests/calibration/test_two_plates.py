"""One sphere held midway between two plane walls, 2a/H = 0.3, creeping
flow: the drag ratio F / (3 pi mu d U) must match the two-wall correction
(data/two_wall_drag.csv: Faxen's midplane series; Ganatos et al. 1980)
within 5 %.

Sphere frame: the sphere is fixed, the plates z = +-H/2 and the far field
move at U (a sphere translating between resting plates). The lateral faces
are 4 H from the sphere; 8 cells per diameter, uniform across the gap.
The ratio to the same-mesh free-space drag (test_stokes_sphere, -0.7 %)
is printed for information.
"""
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct


def reference(lam):
    with open(os.path.join(ct.HERE, "data", "two_wall_drag.csv")) as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    for r in rows:
        if abs(float(r["lambda"]) - lam) < 1e-9:
            return float(r["K"]), r["source"]
    raise KeyError(lam)


def main():
    env = ct.Env(sys.argv)
    with open(os.path.join(ct.HERE, "scenes", "sphere_between_plates.json")) as f:
        scene = json.load(f)
    d, U, mu, beta = scene["sphere"]["d"], scene["U"], scene["fluid"]["mu"], scene["beta"]
    case = env.make_case("sphere_between_plates.json", "two_plates")
    _, log, secs = env.run(case)
    F = float(ct.last_loads(case)[0]["Fx"])
    K = F / (3 * math.pi * mu * d * U)
    K_ref, src = reference(beta)
    err = K / K_ref - 1
    print("2a/H = %.2f: F = %.6e N, K = F/(3 pi mu d U) = %.4f, reference %.4f (%s), error %+.2f %%"
          % (beta, F, K, K_ref, src, 100 * err))
    print("run time %.1f s" % secs)
    ok = ct.check(abs(err) < 0.05, "two-wall drag ratio within 5 %% (%+.2f %%)" % (100 * err))
    ok &= ct.check(K > 1.2, "confinement raises the drag (K = %.3f > 1.2)" % K)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
