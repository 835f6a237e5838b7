#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Compiles each of VXL's own vnl tests (core/vnl/tests/test_*.cxx in upstream's driver, and
# vnl_algo's test_levenberg_marquardt.cxx) unchanged against ports/ and our testlib, runs it, and
# prints one line per test: name, compiled (yes/no), passed (yes/no/-), then the totals.
# It fetches nothing and copies nothing into the repository: the upstream checkout is an
# argument, the per-test driver and the build live in the work folder.
# Usage: tests/ports/upstream/check-vxl-tests.sh VXL_CHECKOUT BUILD WORK_DIR
#   BUILD: host-double, host-s40_23 or arm-double (ARM runs under qemu-arm -cpu pxa270)
set -euo pipefail
top=$(cd "$(dirname "$0")/../../.." && pwd)
[ $# -eq 3 ] || { echo "usage: $0 VXL_CHECKOUT host-double|host-s40_23|arm-double WORK_DIR" >&2; exit 2; }
vxl=$(cd "$1" && pwd) build=$2 work=$3
[ -f "$vxl/core/vnl/tests/CMakeLists.txt" ] || { echo "$0: $vxl/core/vnl/tests/CMakeLists.txt: not a VXL checkout" >&2; exit 2; }
case $build in
  host-double) real=double toolchain=() ;;
  host-s40_23) real=s40_23 toolchain=() ;;
  arm-double) real=double toolchain=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/armv5te-pxa270.cmake") ;;
  *) echo "$0: unknown build '$build' (host-double, host-s40_23 or arm-double)" >&2; exit 2 ;;
esac

# The tests upstream's vnl driver registers (its add_test lines), plus the LM test of vnl_algo.
mapfile -t tests < <(sed -n 's/.*COMMAND vnl_test_[a-z_]* \(test_[a-z0-9_]*\).*/\1/p' "$vxl/core/vnl/tests/CMakeLists.txt")
tests+=(test_levenberg_marquardt)
source_of() { [ "$1" = test_levenberg_marquardt ] && echo "$vxl/core/vnl/algo/tests/$1.cxx" || echo "$vxl/core/vnl/tests/$1.cxx"; }

mkdir -p "$work/drivers"
{
  echo "cmake_minimum_required(VERSION 3.20)"
  echo "project(vxl_tests_on_ports C CXX)"
  echo "set(CMAKE_CXX_STANDARD 17)"
  echo "set(CMAKE_CXX_STANDARD_REQUIRED ON)"
  echo "set(EDGETRACK_REAL $real)"
  echo "include($top/toolchains/install/edgetrack_install_dirs.cmake)"
  echo "add_subdirectory($top/ports ports)"
  for t in "${tests[@]}"; do
    printf '#include "testlib/testlib_register.h"\nDECLARE(%s);\nvoid register_tests() { REGISTER(%s); }\nDEFINE_MAIN\n' "$t" "$t" \
      >"$work/drivers/$t.cxx.new"
    cmp -s "$work/drivers/$t.cxx.new" "$work/drivers/$t.cxx" || mv "$work/drivers/$t.cxx.new" "$work/drivers/$t.cxx"
    rm -f "$work/drivers/$t.cxx.new"
    echo "add_executable($t $(source_of "$t") drivers/$t.cxx)"
    echo "target_link_libraries($t vnl_algo testlib)"
  done
} >"$work/CMakeLists.txt"
cmake -S "$work" -B "$work/build" -G Ninja "${toolchain[@]}" >"$work/configure.log" 2>&1 ||
  { echo "$0: configuring failed, see $work/configure.log" >&2; exit 1; }
cmake --build "$work/build" -j2 -- -k 0 >"$work/build.log" 2>&1 || true

run() {
  if [ "$build" = arm-double ]; then
    qemu-arm -cpu pxa270 -L /usr/arm-linux-gnueabi "$@"
  else
    "$@"
  fi
}
compiled=0 passed=0
printf 'test\tcompiled\tpassed\n'
for t in "${tests[@]}"; do
  if [ -x "$work/build/$t" ]; then
    compiled=$((compiled + 1))
    if (cd "$work/build" && VXLSRC=$vxl timeout 300 bash -c "$(declare -f run); build=$build; run ./$t $t" >"$work/$t.log" 2>&1); then
      passed=$((passed + 1)) result=yes
    else
      result=no
    fi
    printf '%s\tyes\t%s\n' "$t" "$result"
  else
    printf '%s\tno\t-\n' "$t"
  fi
done
printf 'total %s\t%d of %d compile\t%d of %d pass\n' "$build" "$compiled" "${#tests[@]}" "$passed" "${#tests[@]}"
