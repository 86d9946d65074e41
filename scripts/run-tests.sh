#!/usr/bin/env bash
# Builds hsrod with the resolved OpenFOAM reference and runs every test
# (unit, integration, MPI, error checks, calibration).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/setup-debian.sh"
bash "$root/scripts/setup-openfoam.sh"
bash "$root/scripts/build.sh" -DHSROD_WITH_OPENFOAM=ON
ctest --test-dir "$root/build" --output-on-failure -j 2 "$@"
