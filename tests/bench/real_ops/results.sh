#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/real_ops.md: guest instructions per +, *, /, sqrt,
# sin, cos, atan2, asin, exp and log for double, float, S47.16 and S40.23 on the emulated PXA270,
# and the share of them spent inside libgcc's soft-float routines. Builds the ARM tree, runs
# real_ops under the counter.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

operands=1000
mkdir -p "$bench_build_root"
dir=$(bench_tree arm double real_ops)
work=$(mktemp -d "${TMPDIR:-/tmp}/real_ops.XXXXXX")
trap 'rm -rf "$work"' EXIT
"$top/toolchains/qemu/count-insns.sh" --out "$work/summary" --windows "$work/windows" \
  "$dir/tests/bench/real_ops/real_ops" "$operands" >"$work/stdout"

grep '^windows ' "$work/stdout" >"$work/labels"
labelled=$(awk '{ n += $4 } END { print n + 0 }' "$work/labels")
if [ "$labelled" -ne "$(wc -l <"$work/windows")" ]; then
  echo "real_ops: $labelled labelled windows but the counter saw $(wc -l <"$work/windows")" >&2
  exit 1
fi

flags=$(sed -n 's/^CMAKE_CXX_FLAGS:STRING=//p; s/^CMAKE_CXX_FLAGS_RELEASE:STRING=//p' "$dir/CMakeCache.txt" | xargs)
echo "## Instructions per arithmetic operation (real_ops)"
echo
echo "\`tests/bench/real_ops/results.sh\`: $(qemu-arm --version | head -n 1 | sed 's/ (.*//'), \`-cpu pxa270\`," \
  "counted by \`toolchains/qemu/count-insns.sh\`; $(arm-linux-gnueabi-g++ --version | head -n 1)," \
  "\`$flags\`, static; host $(bench_machine)."
echo
echo "Each operation runs on $operands seeded operand pairs, each in its own count window; from each"
echo "window the same window with a copy instead of the operation is subtracted. Operands: + and * in"
echo "[-100, 100); / by ±[0.5, 100); sqrt of [0, 1000); sin and cos of [-π, π); atan2 of y and x in"
echo "[-100, 100); asin of [-1, 1); exp of [-10, 10); log of [0.001, 1000)."
echo
# table <mean|range>: labels are "windows <type> <op> <count>", and the next <count> lines of the
# windows file ("window <i> insns=<n> softfloat=<n>") are theirs.
table() {
  awk -v what="$1" '
  NR == FNR { label_type[NR] = $2; label_op[NR] = $3; label_count[NR] = $4; labels = NR; next }
  FNR == 1 { current = 1; left = label_count[1] }
  { while (left == 0) { ++current; left = label_count[current] }
    type = label_type[current]; op = label_op[current]; --left
    split($3, i, "="); split($4, s, "=")
    key = type SUBSEP op; seen[key] = 1; ++n[key]; insns[key] += i[2]; soft[key] += s[2]
    if (!(key in low) || i[2] < low[key]) low[key] = i[2]
    if (!(key in high) || i[2] > high[key]) high[key] = i[2] }
  function copy_cost(type) { return insns[type, "copy"] / n[type, "copy"] }
  function mean(type, op) { return insns[type, op] / n[type, op] - copy_cost(type) }
  function share(type, op,   total) {
    total = insns[type, op] - n[type, op] * copy_cost(type)
    return total > 0 ? 100 * (soft[type, op] - n[type, op] * soft[type, "copy"] / n[type, "copy"]) / total : 0
  }
  function cell(type, op) {
    if (!((type, op) in seen)) return "—"
    if (what == "mean") return sprintf("%.0f (%.0f %%)", mean(type, op), share(type, op))
    return sprintf("%.0f–%.0f", low[type, op] - copy_cost(type), high[type, op] - copy_cost(type))
  }
  END {
    split("add mul div sqrt sin cos atan2 asin exp log", ops, " ")
    count = split("+ * / sqrt sin cos atan2 asin exp log", names, " ")
    if (what == "mean") {
      print "| op | double | float | S47.16 | S40.23 | double ÷ S40.23 |"
      print "|---|---:|---:|---:|---:|---:|"
    } else {
      print "| op | double | float | S47.16 | S40.23 |"
      print "|---|---:|---:|---:|---:|"
    }
    for (k = 1; k <= count; ++k) {
      op = ops[k]
      row = sprintf("| %s | %s | %s | %s | %s |", names[k], cell("double", op), cell("float", op),
                    cell("s47_16", op), cell("s40_23", op))
      if (what == "mean") {
        ratio = "—"
        if ((("double", op) in seen) && (("s40_23", op) in seen) && mean("s40_23", op) > 0)
          ratio = sprintf("%.1f×", mean("double", op) / mean("s40_23", op))
        row = row " " ratio " |"
      }
      print row
    }
    # The copy window must cost the same every time, or subtracting it would be wrong.
    for (key in seen) {
      split(key, parts, SUBSEP)
      if (parts[2] == "copy" && low[key] != high[key]) {
        print "real_ops: the copy window of " parts[1] " varies" > "/dev/stderr"; exit 1
      }
    }
  }' "$work/labels" "$work/windows"
}

echo "Guest instructions per operation, mean over the operands; in brackets the share of them spent"
echo "inside libgcc's soft-float routines (\`__aeabi_d*\`, \`__aeabi_f*\`, ...). glibc's own code around"
echo "those calls (in \`sqrt\`, \`sin\`, ... \`log\`) is integer code and is not counted as soft-float."
echo
table mean
echo
echo "Fewest and most instructions one operation took (most depend on the operands):"
echo
table range
echo
# real_ops exits non-zero (and so stops this script) if any fixed-point result saturated.
echo "No fixed-point result saturated ($(sed -n 's/^saturations //p' "$work/stdout") saturations)."
