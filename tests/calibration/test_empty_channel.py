"""Empty rectangular duct driven by a pressure drop: the computed flow rate
must match the analytic rectangular-duct value within 1 %.

Analytic flow rate of a duct -a < z < a, -b < y < b (a <= b), pressure
gradient G = dp/L (White, Viscous Fluid Flow, 3rd ed., eq. 3-48):
    Q = 4 b a^3 G / (3 mu) [1 - 192 a/(pi^5 b) sum_{i=1,3,5..} tanh(i pi b / 2a)/i^5]
Mesh 4 x 48 x 24 (x, y, z), uniform; the FV error is second order
(measured: +1.75 % at 24 x 12, +0.44 % at 48 x 24, +0.25 % at 64 x 32).
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct


def duct_flow_rate(W, H, dp, L, mu):
    a, b = 0.5 * min(W, H), 0.5 * max(W, H)
    G = dp / L
    s = sum(math.tanh(i * math.pi * b / (2 * a)) / i ** 5 for i in range(1, 400, 2))
    return 4 * b * a ** 3 * G / (3 * mu) * (1 - 192 * a / (math.pi ** 5 * b) * s)


def main():
    env = ct.Env(sys.argv)
    with open(os.path.join(ct.HERE, "scenes", "empty_channel.json")) as f:
        scene = json.load(f)
    case = env.make_case("empty_channel.json", "empty_channel")
    _, log, secs = env.run(case)
    ch, fl = scene["channel"], scene["fluid"]
    q_ref = duct_flow_rate(ch["W"], ch["H"], scene["inflow"]["dp"], ch["L"], fl["mu"])
    flux = env and ct.last_flux(case)
    q = flux["outlet"]
    err = q / q_ref - 1
    print("duct %g x %g m, dp %g Pa over %g m: Q = %.6e m^3/s, analytic %.6e m^3/s, error %+.3f %%"
          % (ch["W"], ch["H"], scene["inflow"]["dp"], ch["L"], q, q_ref, 100 * err))
    print("run time %.1f s" % secs)
    ok = ct.check(abs(err) < 0.01, "flow rate within 1 %% of the rectangular-duct value (%.3f %%)" % (100 * err))
    ok &= ct.check(abs(flux["inlet"] + q) < 1e-6 * abs(q), "mass conserved between inlet and outlet")
    ok &= ct.check("steady state reached" in log, "steady state reached")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
