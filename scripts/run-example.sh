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
# Output files are named by the run's variables (in.pore: variable run).
run=a10_o0_b0.15_auto_dt2e-6
/usr/bin/python3 plot_pore.py pore_constriction.png rod_E15e3_$run.csv:"E = 15 kPa" rod_E15e6_$run.csv:"E = 15 MPa"
/usr/bin/python3 plot_flow.py pore_flow.png flow_0.vti flow_walls.vtp rod_snap_E15e3_$run.txt:"E = 15 kPa" rod_snap_E15e6_$run.txt:"E = 15 MPa"
echo "example done: examples/pore-constriction/pore_constriction.png, pore_flow.png, CSV rod_E*_$run.csv, ParaView: flow.pvd flow_walls.vtp dump_pore_*.vtk"
