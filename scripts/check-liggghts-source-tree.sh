#!/usr/bin/env bash
# Checks that the package's sources drop into a LIGGGHTS source tree: copies
# liggghts-package/src into Debian's LIGGGHTS 3.8 source, generates the
# style_*.h files with LIGGGHTS' own `Make.sh style` and compiles our styles
# together with modify.cpp and input.cpp (which instantiate the
# FixStyle/ComputeStyle/CommandStyle entries). Nothing is linked.
# Usage: scripts/check-liggghts-source-tree.sh [work-dir]   (needs deb-src access)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-$root/build/liggghts-source-check}"
mkdir -p "$work"
cd "$work"
if ! ls liggghts_*.orig.tar.* > /dev/null 2>&1; then
  if ! grep -rqs "deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources > /etc/apt/sources.list.d/hsrod-deb-src.sources
    apt-get update
  fi
  apt-get source --download-only liggghts || true   # the Debian patch tarball may be missing; the orig tarball suffices
fi
rm -rf tree && mkdir tree
tar xf liggghts_*.orig.tar.* -C tree --strip-components=1
src="tree/src"
pkg="$root/liggghts-package/src"
cp "$pkg"/styles/* "$pkg"/support/* "$pkg"/app/liggghts_workarounds.* "$pkg"/app/run_signals.* "$src"/   # flat, as LIGGGHTS keeps its src/
(cd "$src" && sh Make.sh style > /dev/null)
# LIGGGHTS 3.8.0's utils.h casts an rvalue stream, which GCC >= 11 rejects in
# any C++11+ mode (Debian built the library with an older compiler): patch
# that one helper in the scratch copy so the check is about our files.
sed -i 's/return static_cast< std::ostringstream & >(( std::ostringstream() << std::dec << a ) ).str();/std::ostringstream s; s << std::dec << a; return s.str();/' "$src/utils.h"
flags="-std=c++17 -c -w -I. -I$root/drag-models -I/usr/include/eigen3 $(pkg-config --cflags ompi-cxx)"
for f in fix_rod_bonds create_rod compute_rod_shape compute_hele_shaw_probe fix_hele_shaw_drag fix_hele_shaw_field fix_rod_implicit rod_gather modify input; do
  (cd "$src" && g++ $flags "$f.cpp" -o "$work/$f.o")
  echo "compiled in the LIGGGHTS tree: $f.cpp"
done
grep -h "rod\|hele_shaw" "$src"/style_fix.h "$src"/style_compute.h "$src"/style_command.h
echo "LIGGGHTS source-tree check passed"
