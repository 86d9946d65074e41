#!/usr/bin/env bash
# Builds hsrod and runs every test (unit, integration, MPI, error checks).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/build.sh"
ctest --test-dir "$root/build" --output-on-failure -j 2 "$@"
