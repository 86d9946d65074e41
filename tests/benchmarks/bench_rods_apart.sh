#!/usr/bin/env bash
# Benchmark (not a ctest test): level 3 between rods solved apart (fix
# rod/implicit rod_interaction lagged / iterated N tol) against the joint
# solve (rod_interaction yes) in the many-rods scene
# (tests/benchmarks/scripts/in.many_rods, level 3): loop time beside the
# largest and median difference of the final sphere positions from the
# joint run's, in sphere diameters, and the same for no interaction
# between rods (what the coupling is worth); each rods-apart coupling with
# the rods within the reach only (rod_far_field no) and with the far field
# beyond it (yes). One run each, one core.
# Usage: tests/benchmarks/bench_rods_apart.sh [work-dir]   (after scripts/build.sh)
# Environment: NRODS (default 30), STEPS (default 20), HSROD_BUILD (build/).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HSROD_BUILD:-$root/build}"
work="$(mkdir -p "${1:-$build/bench-rods-apart}" && cd "${1:-$build/bench-rods-apart}" && pwd)"
nrods="${NRODS:-30}"
steps="${STEPS:-20}"
cd "$work"
cp "$root/tests/benchmarks/scripts/in.many_rods" run.in
echo 'write_dump all custom final_${tag}.txt id x y z modify sort id format "%d %.16e %.16e %.16e"' >> run.in
echo "== rods apart vs joint: $nrods rods, level 3, $steps steps of 2 us, load $(cut -d' ' -f1-3 /proc/loadavg), $(git -C "$root" rev-parse --short HEAD)"
printf "%-28s %10s %8s\n" "rod_interaction" "loop [s]" "sweeps"
run() {
  local tag=$1
  shift
  local out
  out=$("$build/hsrod" -in run.in -var nrods "$nrods" -var model nonlocal -var steps "$steps" -var tag "$tag" "$@" \
        -log none -echo none)
  printf "%-28s %10s %8s\n" "$tag" "$(printf "%s\n" "$out" | awk '/^Loop time of/ {t = $4} END {print t}')" \
    "$(printf "%s\n" "$out" | awk '/sweeps over/ {print $5}')"
}
run joint -var coupling yes
run none -var coupling no
# each rods-apart coupling without (_near: rods within the reach only) and
# with the far field of the rods beyond it (rod_far_field yes), interleaved
run lagged_near -var coupling lagged -var far_field no
run lagged -var coupling lagged
run iterated_1e-6_near -var sweeps 100 -var sweep_tolerance 1e-6 -var far_field no
run iterated_1e-6 -var sweeps 100 -var sweep_tolerance 1e-6
run iterated_1e-10_near -var sweeps 100 -var sweep_tolerance 1e-10 -var far_field no
run iterated_1e-10 -var sweeps 100 -var sweep_tolerance 1e-10
/usr/bin/python3 - <<'PY'
import numpy as np
ref = np.loadtxt("final_joint.txt", skiprows=9)
for tag in ("none", "lagged_near", "lagged", "iterated_1e-6_near", "iterated_1e-6", "iterated_1e-10_near",
            "iterated_1e-10"):
    a = np.loadtxt(f"final_{tag}.txt", skiprows=9)
    d = np.linalg.norm(a[:, 1:] - ref[:, 1:], axis=1) / 3e-6
    print(f"{tag:16s} vs joint: largest position difference {d.max():.2e} d, median {np.median(d):.2e} d")
PY
