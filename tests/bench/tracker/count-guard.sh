#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The CI guard on the tracker's guest instruction count: runs bench_tracker (an ARM S40.23 build)
# on a few QVGA cube frames under toolchains/qemu/count-insns.sh, one count window per
# Tracker::track call, and compares the mean per frame with the reference kept in the repository.
# Fails when it grew by more than 10 %; a drop of more than 10 % passes with a note asking for
# the reference to be updated. Deterministic: the same binary on the same rendered frames
# executes the same instructions.
#   count-guard.sh <arm-bench_tracker>             check
#   count-guard.sh --update <arm-bench_tracker>    rewrite the reference (on purpose, and commit it)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/../../.." && pwd)
reference=$here/guest_count_reference.txt
frames=5
allowed_growth_percent=10

update=0
if [ "${1:-}" = --update ]; then update=1; shift; fi
[ $# -eq 1 ] || { sed -n '9,10p' "$0" | sed 's/^# *//' >&2; exit 2; }
bench=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/count-guard.XXXXXX")
trap 'rm -rf "$work"' EXIT
export EDGETRACK_PLUGIN_DIR=${EDGETRACK_PLUGIN_DIR:-$work/plugin}

"$top/toolchains/qemu/count-insns.sh" --out "$work/summary" --windows "$work/windows" \
  "$bench" "$frames" cube frame on-demand >"$work/run.txt"
grep -q '^# real=s40_23 ' "$work/run.txt" || { echo "count-guard: $bench is not an S40.23 build" >&2; exit 2; }
windows=$(wc -l <"$work/windows")
[ "$windows" -eq "$frames" ] || { echo "count-guard: $windows count windows, expected $frames" >&2; exit 1; }
per_frame=$(awk '{ split($3, a, "="); t += a[2] } END { printf "%.0f", t / NR }' "$work/windows")
softfloat=$(sed -n 's/.* window_softfloat=\([0-9]*\).*/\1/p' "$work/summary")

if [ "$update" = 1 ]; then
  {
    echo "# Guest instructions per Tracker::track call, mean of the first $frames frames of the generated"
    echo "# QVGA cube sequence, ARM S40.23 build, default TrackerParams (tests/bench/tracker/count-guard.sh)."
    echo "# Rewritten on purpose by: tests/bench/tracker/count-guard.sh --update <arm-s40_23>/tests/bench/tracker/bench_tracker"
    echo "frames=$frames"
    echo "per_frame=$per_frame"
  } >"$reference"
  echo "count-guard: reference set to $per_frame guest instructions per frame"
  exit 0
fi

[ -f "$reference" ] || { echo "count-guard: no reference $reference (run with --update)" >&2; exit 1; }
expected=$(sed -n 's/^per_frame=//p' "$reference")
[ -n "$expected" ] || { echo "count-guard: $reference has no per_frame= line" >&2; exit 1; }
echo "count-guard: $per_frame guest instructions per frame, reference $expected, soft-float $softfloat"
status=0
awk -v now="$per_frame" -v ref="$expected" -v limit="$allowed_growth_percent" 'BEGIN {
  change = 100 * (now - ref) / ref
  printf "count-guard: %+.1f %% against the reference\n", change
  if (change > limit) { printf "count-guard: FAIL: grew by more than %d %%\n", limit; exit 1 }
  if (change < -limit) printf "count-guard: fell by more than %d %%: update the reference (--update) to keep the guard tight\n", limit
}' || status=1
if [ "$softfloat" != 0 ]; then echo "count-guard: FAIL: $softfloat soft-float instructions in the windows"; status=1; fi
exit $status
