#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The README's test command: installs what is missing, builds the host trees (double, s40_23,
# s47_16, and double with ASan+UBSan), the fuzz tree (clang's libFuzzer over every parser, a
# short smoke run each), the ARM trees (s40_23, double soft-float), today's handheld trees
# (AArch64 and ARMv7-A hard-float, double) and the Cortex-M3 firmware tree (s40_23), and runs
# ctest in each; ARM tests run on qemu-arm -cpu pxa270, qemu-aarch64 -cpu cortex-a53 and qemu-arm
# -cpu cortex-a7, the firmware's on qemu-system-arm -M mps2-an385. Fails if any build or test fails.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build_root=${EDGETRACK_BUILD_ROOT:-$top/build}
jobs=${EDGETRACK_JOBS:-$(nproc)}

"$top/toolchains/install-deps.sh"

# The trees compile many of the same sources with the same compiler and flags (whatever does not
# depend on `real`: most of vnl, vcl and testlib and their tests, in the three host trees and in the
# two PXA270 trees); ccache compiles each such source once, from a cache of its own in the build root.
export CCACHE_DIR=${EDGETRACK_CCACHE_DIR:-$build_root/ccache}
export CCACHE_BASEDIR=$top
launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

arm_toolchain=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/armv5te-pxa270.cmake")
fuzz=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DEDGETRACK_FUZZ=ON -DEDGETRACK_HOST_EXTRAS=OFF
      -DCMAKE_BUILD_TYPE=RelWithDebInfo)
# The Cortex-M3 firmware tree (docs/MCU.md), on qemu-system-arm -M mps2-an385; its tracking test
# compares the firmware's poses with the host-s40_23 tree's, built before it.
mcu_firmware=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/cortex-m3.cmake"
              -DEDGETRACK_HOST_EDGETRACK="$build_root/host-s40_23/app/edgetrack")
# name | cmake arguments
trees=(
  "host-double|-DEDGETRACK_REAL=double"
  "host-s40_23|-DEDGETRACK_REAL=s40_23"
  "host-s47_16|-DEDGETRACK_REAL=s47_16"
  "host-asan|-DEDGETRACK_REAL=double -DEDGETRACK_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo"
  "host-fuzz|-DEDGETRACK_REAL=double ${fuzz[*]}"
  "arm-s40_23|-DEDGETRACK_REAL=s40_23 ${arm_toolchain[*]}"
  "arm-double|-DEDGETRACK_REAL=double ${arm_toolchain[*]}"
  "aarch64-double|-DEDGETRACK_REAL=double -DCMAKE_TOOLCHAIN_FILE=$top/toolchains/aarch64-linux.cmake"
  "armv7hf-double|-DEDGETRACK_REAL=double -DCMAKE_TOOLCHAIN_FILE=$top/toolchains/armv7a-hf.cmake"
  "mcu-s40_23|-DEDGETRACK_REAL=s40_23 ${mcu_firmware[*]}"
)

# CPU seconds (user + system) of every finished child so far: unlike wall time, this hardly
# depends on what else the machine runs, so a run on a busy machine still shows where CI's time goes.
cpu_so_far() {
  times >"$build_root/.times"   # here, not in $(...): a subshell's children are not this shell's
  cpu=$(awk 'NR == 2 { split($0, f, /[ ms]+/); printf "%.0f", f[1] * 60 + f[2] + f[3] * 60 + f[4] }' \
    "$build_root/.times")
}

mkdir -p "$build_root"
failed=()
start=$SECONDS
cpu_so_far; cpu_start=$cpu
for entry in "${trees[@]}"; do
  name=${entry%%|*}
  read -r -a args <<<"${entry#*|}"
  dir="$build_root/$name"
  echo "=== $name: configure and build"
  t0=$SECONDS
  cpu_so_far; cpu0=$cpu
  if ! cmake -S "$top" -B "$dir" -G Ninja "${launcher[@]}" "${args[@]}" >"$dir.configure.log" 2>&1; then
    cat "$dir.configure.log"; failed+=("$name (configure)"); continue
  fi
  if ! cmake --build "$dir" -j "$jobs" >"$dir.build.log" 2>&1; then
    tail -n 60 "$dir.build.log"; failed+=("$name (build)"); continue
  fi
  if [[ $name == arm-* ]] && ! "$top/toolchains/check-soft-float.sh" "$dir"; then
    failed+=("$name (VFP instructions in a soft-float build)"); continue
  fi
  t1=$SECONDS
  cpu_so_far; cpu1=$cpu
  echo "=== $name: ctest"
  if ! ctest --test-dir "$dir" -j "$jobs" --output-on-failure --timeout 900; then
    failed+=("$name (tests)")
  fi
  cpu_so_far; cpu2=$cpu
  echo "=== $name: $((SECONDS - t0)) s (build $((t1 - t0)) s, $((cpu1 - cpu0)) CPU s; ctest $((SECONDS - t1)) s, $((cpu2 - cpu1)) CPU s)"
done

cpu_so_far
echo "=== all trees: $((SECONDS - start)) s, $((cpu - cpu_start)) CPU s"
ccache --show-stats | grep -iE "hits|misses" | sed 's/^/=== ccache: /' || true
if [ ${#failed[@]} -gt 0 ]; then
  echo "FAILED: ${failed[*]}"
  exit 1
fi
echo "All trees built and passed their tests."
