#!/usr/bin/python3
"""Plot the relaxation of the bent rod: deflection (paper eq. 2) and bond
energy against time, with the exponential decay rate of the lowest
overdamped bending mode, EI (4.730/L)^4 / zeta_perp, for comparison."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

path = sys.argv[1] if len(sys.argv) > 1 else "relaxation.txt"
out = sys.argv[2] if len(sys.argv) > 2 else "relaxation.png"
data = np.loadtxt(path, comments="#")
timestep = 5e-8  # [s], as in in.relaxing_rod
t = (data[:, 0] - data[0, 0]) * timestep
deflection = data[:, 2]

# Free-free Euler-Bernoulli rod, each sphere dragged with 3 pi mu d.
E, d, n, mu = 15e3, 3e-6, 20, 1e-3
EI = E * np.pi * d**4 / 64
length = n * d
zeta_per_length = 3 * np.pi * mu * d / d
rate = EI * (4.730 / length) ** 4 / zeta_per_length

fig, ax = plt.subplots(figsize=(6, 4))
ax.semilogy(t * 1e3, deflection, label="hsrod (20 spheres, E = 15 kPa)")
ax.semilogy(t * 1e3, deflection[0] * np.exp(-rate * t), "--", label="lowest bending mode, Euler-Bernoulli")
ax.set_xlabel("time after release [ms]")
ax.set_ylabel("relative deflection $\\delta_r$ (eq. 2)")
ax.set_title("Bent rod relaxing under Stokes drag")
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=120)
print(f"wrote {out}: deflection {deflection[0]:.4g} -> {deflection[-1]:.4g}; "
      f"measured decay rate {-np.polyfit(t[len(t)//2:], np.log(deflection[len(t)//2:]), 1)[0]:.4g} 1/s, "
      f"Euler-Bernoulli mode 1 {rate:.4g} 1/s")
