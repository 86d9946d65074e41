#!/usr/bin/env bash
# Installs every Debian package hsrod needs (idempotent).
# Usage: scripts/setup-debian.sh [--with-openfoam]
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  liggghts libliggghts-dev
  libopenmpi-dev openmpi-bin
  libeigen3-dev libsuitesparse-dev
  # OpenBLAS (single-threaded: MPI ranks and sweep workers share the cores)
  # as the system's libblas.so.3: UMFPACK's dense kernels in level 4's window
  # factorisations run ~2x faster than on the reference BLAS (level 4's pore
  # passage 0.85 -> 0.75 s, tests/benchmarks/RESULTS.md)
  libopenblas0-serial
  libgtest-dev googletest libbenchmark-dev
  libcli11-dev nlohmann-json3-dev
  python3-numpy python3-matplotlib python3-vtk9
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ "${#missing[@]}" -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update
  $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
echo "hsrod setup: all Debian packages present"
