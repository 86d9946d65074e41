#!/usr/bin/python3
"""The paper's measures of in.pore runs as numbers (one row per CSV): angle
at the start, largest and final (eq. 1), largest relative deflection (eq. 2)
and where, lateral displacement / W at the pore centre and at the end, peak
v_x / U. Usage: summarise_pore.py run1.csv[:label] ... [--csv out.csv]"""
import sys

import numpy as np

args = sys.argv[1:]
out = None
if "--csv" in args:
    k = args.index("--csv")
    out = args[k + 1]
    args = args[:k] + args[k + 2:]
header = "case,angle_start_deg,angle_max_deg,angle_final_deg,deflection_max,x_deflection_max_um," \
         "lateral_at_pore,lateral_final,vx_over_U_max"
rows = [header]
for spec in args:
    path, _, label = spec.partition(":")
    d = np.genfromtxt(path, delimiter=",", names=True)
    x = d["x_m"] * 1e6
    k = int(np.argmax(d["deflection"]))
    lateral_pore = float(np.interp(300.0, x, d["lateral_over_W"]))
    name = label or path
    if "," in name or '"' in name:  # labels such as "alpha = 10 deg, 15 kPa": one quoted CSV field
        name = '"' + name.replace('"', '""') + '"'
    rows.append(f"{name},{d['angle_deg'][0]:.2f},{d['angle_deg'].max():.2f},{d['angle_deg'][-1]:.2f},"
                f"{d['deflection'].max():.4f},{x[k]:.0f},{lateral_pore:.4f},{d['lateral_over_W'][-1]:.4f},"
                f"{d['vx_over_U'].max():.2f}")
print("\n".join(rows))
if out:
    with open(out, "w") as f:
        f.write("\n".join(rows) + "\n")
