#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Checks the instruction counter on count_probe (an ARM binary built with the ARMv5TE toolchain):
# window counts grow by exactly 2 instructions per loop iteration, the per-block and
# per-instruction modes agree, integer code has no soft-float instructions while double/float
# arithmetic does, nesting counts the outer pair once and a stray end is reported.
#   test-count-insns.sh <count_probe>
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
probe=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/test-count-insns.XXXXXX")
trap 'rm -rf "$work"' EXIT
export EDGETRACK_PLUGIN_DIR=${EDGETRACK_PLUGIN_DIR:-$work/plugin}

failures=0
check() {  # check <description> <condition...>
  local what=$1; shift
  if "$@"; then echo "ok:   $what"; else echo "FAIL: $what"; failures=$((failures + 1)); fi
}

# count <mode> <name> <probe args...>: runs the probe under the counter, summary in $work/<name>.
count() {
  local mode=$1 name=$2; shift 2
  "$here/count-insns.sh" --mode "$mode" --out "$work/$name" --windows "$work/$name.windows" "$probe" "$@" >/dev/null
}
field() { sed -n "s/.* $2=\([0-9]*\).*/\1/p" "$work/$1"; }

count tb spin1k spin 1000 5
count tb spin3k spin 3000 5
count insn spin1k-insn spin 1000 5
count insn spin3k-insn spin 3000 5
count tb float float 3
count insn float-insn float 3
count tb nested nested

plugin=$EDGETRACK_PLUGIN_DIR/insn_count.so
exports=$(nm -D --defined-only "$plugin")
check "plugin exports qemu_plugin_version" \
  grep -q ' qemu_plugin_version$' <<<"$exports"
check "plugin exports qemu_plugin_install" grep -q ' qemu_plugin_install$' <<<"$exports"

check "five spin windows are reported" test "$(field spin1k windows)" -eq 5 -a "$(field spin3k windows)" -eq 5
window_growth=$(($(field spin3k window_total) - $(field spin1k window_total)))
check "2000 more iterations in 5 windows add exactly 20000 window instructions (got $window_growth)" \
  test "$window_growth" -eq 20000
total_growth=$(($(field spin3k total) - $(field spin1k total)))
check "and exactly 20000 instructions in total (got $total_growth)" test "$total_growth" -eq 20000
check "each spin window of 1000 iterations holds 2000 loop instructions plus a few" \
  awk '{ split($3, f, "="); if (f[2] < 2000 || f[2] > 2020) exit 1 }' "$work/spin1k.windows"
check "integer code runs no soft-float instructions" \
  test "$(field spin1k softfloat)" -eq 0 -a "$(field spin1k window_softfloat)" -eq 0

check "per-block and per-instruction counting agree on the spin run" \
  cmp -s "$work/spin3k" "$work/spin3k-insn"
check "and on the windows, one by one" cmp -s "$work/spin1k.windows" "$work/spin1k-insn.windows"
check "and on the float run" cmp -s "$work/float" "$work/float-insn"

check "float windows are reported" test "$(field float windows)" -eq 3
check "double and float arithmetic runs soft-float instructions inside the windows" \
  test "$(field float window_softfloat)" -gt 0
check "soft-float instructions are a part of the window, not more" \
  test "$(field float window_softfloat)" -lt "$(field float window_total)"

check "nested begin/end pairs count as one window" test "$(field nested windows)" -eq 1
check "the stray end is reported as unbalanced" test "$(field nested unbalanced)" -eq 1
check "the outer window holds both 10-iteration loops" test "$(field nested window_total)" -ge 40

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all counter checks passed"
