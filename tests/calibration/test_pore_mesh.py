"""Case generation with the pore constriction: the 12-block body-fitted
mesh must pass checkMesh (non-orthogonality < 50 deg), the flow rate
imposed at the inlet must leave through the outlet, and the fastest fluid
must sit in the pore throat with a speed above the throat's mean velocity
U W / (W - 2R) (continuity).
"""
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct


def read_internal_vectors(path):
    t = open(path).read()
    i = t.index("internalField")
    body = t[i:t.index(")\n;", i)]
    return [tuple(map(float, m)) for m in re.findall(r"\(([-\d.e+]+) ([-\d.e+]+) ([-\d.e+]+)\)", body)]


def main():
    env = ct.Env(sys.argv)
    with open(os.path.join(ct.HERE, "scenes", "pore_channel.json")) as f:
        scene = json.load(f)
    case = env.make_case("pore_channel.json", "pore")
    _, log, secs = env.run(case)
    cm = subprocess.run(["checkMesh", "-case", case, "-latestTime"], env=env.env,
                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout
    nonorth = float(re.search(r"non-orthogonality Max: ([\d.]+)", cm).group(1))
    ok = ct.check("Mesh OK." in cm, "checkMesh: Mesh OK")
    ok &= ct.check(nonorth < 50, "max non-orthogonality %.1f deg < 50" % nonorth)
    ch, pore = scene["channel"], scene["pore"]
    q_in = scene["inflow"]["U"] * ch["W"] * ch["H"]
    flux = ct.last_flux(case)
    ok &= ct.check(abs(flux["outlet"] - q_in) < 1e-6 * q_in, "outlet flux %.6e = inlet flow rate %.6e m^3/s" % (flux["outlet"], q_in))
    # cell centres: written by the solver? use postProcess -func writeCellCentres
    subprocess.run(["postProcess", "-case", case, "-func", "writeCellCentres", "-latestTime"], env=env.env,
                   stdout=subprocess.DEVNULL, check=True)
    last = sorted((d for d in os.listdir(case) if re.fullmatch(r"[\d.e+-]+", d) and d != "0"), key=float)[-1]
    U = read_internal_vectors(os.path.join(case, last, "U"))
    C = read_internal_vectors(os.path.join(case, last, "C"))
    k = max(range(len(U)), key=lambda i: sum(c * c for c in U[i]))
    umax = math.sqrt(sum(c * c for c in U[k]))
    u_gap = scene["inflow"]["U"] * ch["W"] / (ch["W"] - 2 * pore["R"])
    print("max |U| = %.4f m/s at x = %.3g m (pore at %.3g +- %.3g m), throat mean %.4f m/s, %.1f s"
          % (umax, C[k][0], pore["x"], pore["R"], u_gap, secs))
    ok &= ct.check(abs(C[k][0] - pore["x"]) <= pore["R"], "fastest cell in the pore throat")
    ok &= ct.check(umax > u_gap, "max speed above the throat mean velocity")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
