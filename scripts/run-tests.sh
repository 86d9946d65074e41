#!/usr/bin/env bash
# Builds hsrod with the resolved OpenFOAM reference and runs every test
# (unit, integration, MPI, error checks, calibration).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/setup-debian.sh"
bash "$root/scripts/setup-openfoam.sh"
bash "$root/scripts/build.sh" -DHSROD_WITH_OPENFOAM=ON
# Without arguments: every test but the full stress matrix (label `stress`,
# hours; run it with: ctest --test-dir build -L '^stress$').
if [ "$#" -eq 0 ]; then set -- -LE '^stress$'; fi
ctest --test-dir "$root/build" --output-on-failure -j 2 "$@"
