#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/real_ops.md: guest instructions per +, *, /, sqrt
# and sin for double, float, S47.16 and S40.23 on the emulated PXA270, and the share of them spent
# inside libgcc's soft-float routines. Builds the ARM tree, runs real_ops under the counter.
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

grep '^window ' "$work/stdout" >"$work/labels"
if [ "$(wc -l <"$work/labels")" -ne "$(wc -l <"$work/windows")" ]; then
  echo "real_ops: $(wc -l <"$work/labels") labelled windows but the counter saw $(wc -l <"$work/windows")" >&2
  exit 1
fi

echo "## Instructions per arithmetic operation (real_ops)"
echo
flags=$(sed -n 's/^CMAKE_CXX_FLAGS:STRING=//p; s/^CMAKE_CXX_FLAGS_RELEASE:STRING=//p' "$dir/CMakeCache.txt" | xargs)
echo "\`tests/bench/real_ops/results.sh\`: $(qemu-arm --version | head -n 1 | sed 's/ (.*//'), \`-cpu pxa270\`," \
  "counted by \`toolchains/qemu/count-insns.sh\`; $(arm-linux-gnueabi-g++ --version | head -n 1)," \
  "\`$flags\`, static; host $(bench_machine)."
echo
echo "Guest instructions per operation, averaged over $operands seeded operand pairs in one count"
echo "window, minus the same loop with a copy instead of the operation. In brackets, the share of"
echo "those instructions spent inside libgcc's soft-float routines (\`__aeabi_d*\`, \`__aeabi_f*\`, ...);"
echo "glibc's own \`sqrt\`/\`sin\` code (integer code around those calls) is not counted as soft-float."
echo "Operands: + and * in [-100, 100); / by ±[0.5, 100); sqrt of [0, 1000); sin of [-π, π)."
echo
# labels: "window <type> <op> <n>"; windows: "window <i> insns=<n> softfloat=<n>".
paste -d ' ' "$work/labels" "$work/windows" | awk '
  { type = $2; op = $3; n = $4; split($7, i, "="); split($8, s, "=")
    insns[type, op] = i[2]; soft[type, op] = s[2]; count[type, op] = n; seen[type, op] = 1 }
  function per_op(type, op) { return (insns[type, op] - insns[type, "copy"]) / count[type, op] }
  function cell(type, op,   total, sf) {
    if (!((type, op) in seen)) return "—"
    total = insns[type, op] - insns[type, "copy"]; sf = soft[type, op] - soft[type, "copy"]
    return sprintf("%.0f (%.0f %%)", total / count[type, op], total > 0 ? 100 * sf / total : 0)
  }
  END {
    split("add mul div sqrt sin", ops, " "); split("+ * / sqrt sin", names, " ")
    print "| op | double | float | S47.16 | S40.23 | double ÷ S40.23 |"
    print "|---|---:|---:|---:|---:|---:|"
    for (k = 1; k <= 5; ++k) {
      op = ops[k]
      ratio = "—"
      if ((("double", op) in seen) && (("s40_23", op) in seen) && per_op("s40_23", op) > 0)
        ratio = sprintf("%.1f×", per_op("double", op) / per_op("s40_23", op))
      printf "| %s | %s | %s | %s | %s | %s |\n", names[k], cell("double", op), cell("float", op),
             cell("s47_16", op), cell("s40_23", op), ratio
    }
  }'
echo
grep -q '^window s40_23 sin ' "$work/labels" || echo "—: the fixed-point type has no \`sin\` in this tree yet."
loop=$(paste -d ' ' "$work/labels" "$work/windows" | awk '$2 == "double" && $3 == "copy" { split($7, i, "="); printf "%.1f", i[2] / $4 }')
echo "The copy loop itself (subtracted above) costs $loop instructions per element for double."
# real_ops exits non-zero (and so stops this script) if any fixed-point result saturated.
echo "No fixed-point result saturated ($(sed -n 's/^saturations //p' "$work/stdout") saturations)."
