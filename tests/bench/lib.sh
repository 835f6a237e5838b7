# SPDX-License-Identifier: BSD-3-Clause
# Sourced by tests/bench/*/results.sh: builds the trees a benchmark needs, once, under build/bench-*.
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bench_build_root=${EDGETRACK_BUILD_ROOT:-$top/build}

# bench_tree <host|arm|mcu> <real> <target>...: configures build/bench-<kind>-<real>, builds the
# targets, and prints the build directory.
bench_tree() {
  local kind=$1 real=$2; shift 2
  local dir="$bench_build_root/bench-$kind-$real"
  mkdir -p "$bench_build_root"
  local args=(-DEDGETRACK_REAL="$real" -DCMAKE_BUILD_TYPE=Release)
  [ "$kind" = arm ] && args+=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/armv5te-pxa270.cmake")
  [ "$kind" = mcu ] && args+=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/cortex-m3.cmake")
  cmake -S "$top" -B "$dir" -G Ninja "${args[@]}" >"$dir.configure.log" 2>&1 ||
    { cat "$dir.configure.log" >&2; return 1; }
  cmake --build "$dir" --target "$@" >"$dir.build.log" 2>&1 ||
    { tail -n 40 "$dir.build.log" >&2; return 1; }
  echo "$dir"
}

# The machine a result was measured on, for the header of each generated section.
bench_machine() {
  printf '%s, %s cores, %s' "$(uname -m)" "$(nproc)" \
    "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
}
