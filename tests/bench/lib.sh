# SPDX-License-Identifier: BSD-3-Clause
# Sourced by tests/bench/*/results.sh: builds the trees a benchmark needs, once, under build/bench-*.
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bench_build_root=${EDGETRACK_BUILD_ROOT:-$top/build}
source "$top/tests/visp_images.sh"

# bench_tree <host|arm|aarch64|armv7hf|mcu> <real> <target>...: configures build/bench-<kind>-<real>
# (arm: the ARMv5TE PXA270; aarch64 and armv7hf: the hard-float Linux targets; mcu: the Cortex-M3
# firmware), builds the
# targets, and prints the build directory.
bench_tree() {
  local kind=$1 real=$2; shift 2
  local dir="$bench_build_root/bench-$kind-$real"
  mkdir -p "$bench_build_root"
  local args=(-DEDGETRACK_REAL="$real" -DCMAKE_BUILD_TYPE=Release)
  case $kind in
    arm) args+=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/armv5te-pxa270.cmake") ;;
    aarch64) args+=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/aarch64-linux.cmake") ;;
    armv7hf) args+=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/armv7a-hf.cmake") ;;
    mcu) args+=(-DCMAKE_TOOLCHAIN_FILE="$top/toolchains/cortex-m3.cmake") ;;
  esac
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

# callgrind_steps CALLGRIND_FILE FRAMES: "visible | grey | ME | pose | other | total" per frame,
# from the inclusive cost of each call Tracker::track makes, itself or through its State::attempt (a
# frame's tracking from one start pose; the rest, their own code included, is "other").
callgrind_steps() {
  callgrind_annotate --tree=calling --inclusive=yes "$1" 2>/dev/null | awk -v f="$2" '
    /\*  .*edgetrack::Tracker::track\(/ { gsub(",", "", $1); total = $1; go = 1; next }
    /\*  .*edgetrack::Tracker::(State::)?attempt\(/ { go = 1; next }
    go && /^ *$/ { go = 0 }
    go && / >   / {
      c = $1; gsub(",", "", c); name = $0
      if (name ~ /EdgeIdBuffer::render|EdgeIdSource|ContrastMemory::references|sample_control_points|keep_visible|FaceVisibility/) v += c
      else if (name ~ /grey_scale|convert_to_grey|BoxGreyScaler/) g += c
      else if (name ~ /search_moving_edges|contrasts_at_points/) m += c
      else if (name ~ /solve_pose/) p += c
    }
    END {
      o = total - v - g - m - p
      printf "%.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M | %.3f M",
        v/f/1e6, 100*v/total, g/f/1e6, 100*g/total, m/f/1e6, 100*m/total, p/f/1e6, 100*p/total, o/f/1e6, total/f/1e6
    }'
}

# The boilerplate of a results script (used by tests/bench/camera_eval/*.sh):
# bench_scratch NAME: sets $work to a new scratch directory, removed when the script exits.
bench_scratch() {
  work=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX")
  trap 'rm -rf "$work"' EXIT
}
# bench_heading TITLE BUILDS: the section's title, then the script that prints it, the builds it
# ran and the machine.
bench_heading() {
  echo "## $1"
  echo
  echo "\`${BASH_SOURCE[1]#"$top"/}\`: $2, $(bench_machine)."
  echo
}
# bench_value KEY FILE: the value of KEY=... on the first line of FILE that has it.
bench_value() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" "$2" | head -n 1; }
