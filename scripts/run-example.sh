#!/usr/bin/env bash
# Builds hsrod and runs the main example, then writes its plot.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/build.sh"
cd "$root/examples/relaxing-rod"
rm -f dump_rod_*.vtk relaxation.txt
"$root/build/hsrod" -in in.relaxing_rod -log log.lammps
/usr/bin/python3 plot_relaxation.py relaxation.txt relaxation.png
echo "example done: examples/relaxing-rod/relaxation.png, VTK frames dump_rod_*.vtk (ParaView)"
