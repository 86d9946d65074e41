"""Torque output: a sphere rotating at omega about z in a closed box of
resting walls (half width 4 d) must feel the Stokes torque
T = -8 pi mu a^3 omega (Kirchhoff/Lamb; Happel & Brenner 1965 sec. 5-2)
within 5 %, and no net force.

Box correction: for a concentric spherical container of radius R the
torque is 8 pi mu a^3 omega / (1 - (a/R)^3) (Lamb 1932, art. 334); with the
inscribed sphere R = 4 d, (a/R)^3 = 0.2 %, negligible here.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hsrod_caltest as ct

D, MU, OMEGA = 3e-6, 1e-3, 1000.0   # m, Pa s, rad/s


def main():
    env = ct.Env(sys.argv)
    case = env.make_case("sphere_in_box.json", "rotating",
                         ["walls=\"uniform\"", "U=0", "sphere.omega=[0,0,%g]" % OMEGA,
                          "sphere.offset_cells=[0.3,0.17,0.41]"])
    _, _, secs = env.run(case)
    r = ct.last_loads(case)[0]
    T = float(r["Tz"])
    T_ref = -8 * math.pi * MU * (D / 2) ** 3 * OMEGA
    F = math.sqrt(sum(float(r[k]) ** 2 for k in ("Fx", "Fy", "Fz")))
    err = T / T_ref - 1
    print("T_z = %.6e N m, Stokes %.6e N m, error %+.2f %%, |F| = %.2e N, %.1f s" % (T, T_ref, 100 * err, F, secs))
    ok = ct.check(abs(err) < 0.05, "torque within 5 %% of 8 pi mu a^3 omega (%+.2f %%)" % (100 * err))
    # |F| relative to the force scale mu a (a omega) of the rotation
    ok &= ct.check(F < 0.02 * 6 * math.pi * MU * (D / 2) * (D / 2 * OMEGA), "no net force (|F| < 2 % of 6 pi mu a^2 omega)")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
