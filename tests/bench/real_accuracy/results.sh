#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/real_accuracy.md: the worst error of each fixed64
# operation for S47.16 and S40.23, measured by the accuracy sweeps of tests/ports/real (10^5
# seeded arguments per function and type, against an exact integer reference for + - * / sqrt
# and against long double for the rest) on the host, where long double has 64 digits.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

mkdir -p "$bench_build_root"
dir=$(bench_tree host double real_test_all)
work=$(mktemp -d "${TMPDIR:-/tmp}/real_accuracy.XXXXXX")
trap 'rm -rf "$work"' EXIT
for test in add_subtract multiply divide sqrt sin_cos tan atan_atan2 asin_acos exp_log; do
  if ! "$dir/tests/ports/real/real_test_all" "test_fixed64_$test" >"$work/$test.log"; then
    cat "$work/$test.log" >&2
    echo "real_accuracy: test_fixed64_$test failed" >&2
    exit 1
  fi
  cat "$work/$test.log" >>"$work/all"
done

echo "## Accuracy of the fixed-point operations (real_accuracy)"
echo
echo "\`tests/bench/real_accuracy/results.sh\`: the sweeps of \`tests/ports/real\` run natively;" \
  "$(g++ --version | head -n 1), host $(bench_machine)."
echo
echo "Worst error in ulp of the result type (2^-16 for S47.16, 2^-23 for S40.23) over 10^5 seeded"
echo "arguments per operation and type, spread over the whole range and its ends (\`tan\`: |x| <= 2^20;"
echo "\`asin\`, \`acos\`: [-1, 1], a quarter within 1024 ulp of ±1; \`exp\`: up to past the range end)."
echo "\`+ - * / sqrt\` are checked against exact integer arithmetic, the others against long double"
echo "(64 digits here). The bound is what the test enforces in every build, under QEMU too, plus"
echo "the reference's own rounding (for \`exp\` near the range end up to 0.5 ulp here, 2^10 ulp under"
echo "QEMU, where long double is double)."
echo
echo "| operation | S47.16 | S40.23 | tested bound |"
echo "|---|---:|---:|---|"
awk '
  /^measured worst error of / {
    op = $5; type = $7; sub(":", "", type)
    worst[op, type] = $8
    if (!(op in seen)) { seen[op] = 1; order[++n] = op }
  }
  END {
    bound["addition"] = "exact"; bound["subtraction"] = "exact"
    bound["multiplication"] = "0.5 ulp (correctly rounded)"; bound["division"] = "0.5 ulp (correctly rounded)"
    bound["sqrt"] = "0.5 ulp (correctly rounded)"
    bound["sin"] = "1 ulp"; bound["cos"] = "1 ulp"; bound["atan"] = "1 ulp"; bound["atan2"] = "1 ulp"
    bound["asin"] = "1 ulp"; bound["acos"] = "1 ulp"; bound["log"] = "1 ulp"
    bound["tan"] = "1 ulp + (1 + tan²) 2^(F-58) ulp"; bound["exp"] = "1 ulp + 2^-60 exp(x)"
    for (k = 1; k <= n; ++k) {
      op = order[k]
      if (!((op, "s47_16") in worst) || !((op, "s40_23") in worst)) {
        print "real_accuracy: no measurement of " op " for both types" > "/dev/stderr"; exit 1
      }
      printf "| %s | %.4f | %.4f | %s |\n", op, worst[op, "s47_16"], worst[op, "s40_23"], bound[op]
    }
  }' "$work/all"
echo
echo "Saturation is checked in the same sweeps: every result past the range is the range end and"
echo "counted exactly once, and no in-range result counts."
