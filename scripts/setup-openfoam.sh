#!/usr/bin/env bash
# Sets up the resolved-CFD part of hsrod (calibration/): Debian's OpenFOAM
# (ESI v1912) binaries/libraries plus the headers, which Debian ships only in
# its source package. Idempotent: every step is skipped when already done.
#
# Usage: scripts/setup-openfoam.sh [SRC_PARENT_DIR]
#   SRC_PARENT_DIR defaults to <repo>/third_party-build; the OpenFOAM source
#   tree ends up in SRC_PARENT_DIR/openfoam-src/openfoam-<version>/ and a
#   stable symlink SRC_PARENT_DIR/openfoam-src/current points at it.
#   Pass that path to CMake as -DHSROD_OPENFOAM_SRC=... (the default there is
#   the same location, so normally nothing needs to be passed).
#
# Steps (the times are measured on this machine):
#   1. apt-get update; apt-get install -y openfoam                (~15 s)
#   2. deb-src entry made from the deb822 list debian.sources      (once)
#   3. apt-get source --download-only openfoam, unpack (no patches applied
#      needed for headers; dpkg-source -x applies Debian's patches)
#   4. wmake/wmakeLnInclude -u for the libraries whose headers we include
#   Timings of each step are printed.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
parent="${1:-$repo_root/third_party-build}"
srcdir="$parent/openfoam-src"

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive

t0=$(date +%s)
stamp() { echo "[setup-openfoam] $1 ($(( $(date +%s) - t0 )) s elapsed)"; }

# ---- 1. binary package ------------------------------------------------------
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
need=()
for p in openfoam dpkg-dev xz-utils patch; do installed "$p" || need+=("$p"); done
if [ "${#need[@]}" -gt 0 ]; then
  $SUDO apt-get update
  $SUDO apt-get install -y --no-install-recommends "${need[@]}"
fi
stamp "openfoam installed: $(dpkg-query -W -f='${Version}' openfoam)"

# ---- 2. deb-src entry -------------------------------------------------------
srclist=/etc/apt/sources.list.d/hsrod-debian-src.sources
have_src=0
if grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ || \
   grep -qs '^deb-src' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null; then
  have_src=1
fi
if [ "$have_src" -eq 0 ]; then
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources | $SUDO tee "$srclist" >/dev/null
  elif [ -f /etc/apt/sources.list ]; then
    grep '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' | \
      $SUDO tee /etc/apt/sources.list.d/hsrod-debian-src.list >/dev/null
  else
    echo "setup-openfoam: no Debian apt source list found to derive a deb-src entry" >&2
    exit 1
  fi
  $SUDO apt-get update
fi
stamp "deb-src entry present"

# ---- 3. source package ------------------------------------------------------
mkdir -p "$srcdir"
cd "$srcdir"
ver="$(dpkg-query -W -f='${source:Version}' openfoam)"   # binNMU suffix dropped
upver="${ver#*:}"; upver="${upver%-*}"           # e.g. 1912.200626
tree="$srcdir/openfoam-$upver"
if [ ! -f "$tree/src/OpenFOAM/Make/files" ]; then
  if ! ls openfoam_*.dsc >/dev/null 2>&1; then
    # apt-get source as root warns about sandboxing; harmless here.
    apt-get source --download-only "openfoam=$ver" || apt-get source --download-only openfoam
  fi
  dsc="$(ls openfoam_*.dsc | head -n1)"
  rm -rf "$tree"
  dpkg-source --no-check -x "$dsc" "$tree"
fi
ln -sfn "$(basename "$tree")" "$srcdir/current"
stamp "source tree at $tree"

# ---- 4. lnInclude directories -----------------------------------------------
# wmakeLnInclude (a shell script in the source tree) links all headers of a
# library into <lib>/lnInclude; -u updates only when needed.
export WM_PROJECT_DIR="$tree"
libs=(
  src/OpenFOAM src/OSspecific/POSIX src/finiteVolume src/meshTools
  src/sampling src/dynamicMesh src/dynamicFvMesh src/fileFormats
  src/surfMesh src/fvOptions
  src/TurbulenceModels/turbulenceModels src/TurbulenceModels/incompressible
  src/transportModels src/transportModels/incompressible
)
stampfile="$tree/.hsrod-lninclude"
want="${libs[*]}"
if [ ! -f "$stampfile" ] || [ "$(cat "$stampfile")" != "$want" ]; then
  for l in "${libs[@]}"; do
    if [ -d "$tree/$l" ]; then
      (cd "$tree" && bash wmake/wmakeLnInclude -u "$l" >/dev/null)
    else
      echo "setup-openfoam: warning: $l not in the source tree" >&2
    fi
  done
  echo "$want" > "$stampfile"
fi
stamp "lnInclude directories made for ${#libs[@]} libraries"
echo "[setup-openfoam] done. CMake: -DHSROD_WITH_OPENFOAM=ON -DHSROD_OPENFOAM_SRC=$srcdir/current"
echo "[setup-openfoam] run time: export WM_PROJECT_DIR=/usr/share/openfoam"
