#!/usr/bin/env bash
# Builds hsrod and runs the main example: a soft and a stiff rod through a
# pore constriction (examples/pore-constriction), then plots both.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/build.sh"
cd "$root/examples/pore-constriction"
rm -f dump_pore_*.vtk flow_*.vti flow.pvd
for E in 15e3 15e6; do
  "$root/build/hsrod" -in in.pore -var E "$E" -log "log.E$E" -echo none | grep -a "model\|passed"
done
/usr/bin/python3 plot_pore.py pore_constriction.png rod_E15e3_a10.csv:"E = 15 kPa" rod_E15e6_a10.csv:"E = 15 MPa"
/usr/bin/python3 plot_flow.py pore_flow.png flow_0.vti flow_walls.vtp rod_snap_E15e3_a10.txt:"E = 15 kPa" rod_snap_E15e6_a10.txt:"E = 15 MPa"
echo "example done: examples/pore-constriction/pore_constriction.png, pore_flow.png, CSV rod_E*_a10.csv, ParaView: flow.pvd flow_walls.vtp dump_pore_*.vtk"
