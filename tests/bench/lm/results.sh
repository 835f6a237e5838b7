#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/lm.md: the host comparison of our LM (double,
# float, S47.16, S40.23) with cminpack and Eigen on 200 seeded pose problems (lm_compare), then
# the guest instructions per pose solve on the emulated PXA270 for the ARM double (soft-float)
# and S40.23 builds (lm_pose_insns under toolchains/qemu/count-insns.sh).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

problems=200
passes=20
mkdir -p "$bench_build_root"
host=$(bench_tree host double lm_compare)
arm_double=$(bench_tree arm double lm_pose_insns)
arm_s40=$(bench_tree arm s40_23 lm_pose_insns)
work=$(mktemp -d "${TMPDIR:-/tmp}/lm.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "## Levenberg–Marquardt: our port against cminpack and Eigen, per scalar (lm)"
echo
echo "\`tests/bench/lm/results.sh\` on $(bench_machine); $(g++ --version | head -n 1); the instruction"
echo "counts on $(qemu-arm --version | head -n 1 | sed 's/ (.*//'), \`-cpu pxa270\`, counted by"
echo "\`toolchains/qemu/count-insns.sh\`, built with $(arm-linux-gnueabi-g++ --version | head -n 1)."
echo
echo "$problems seeded pose problems (\`tests/ports/netlib/pose_problem.h\`): camera px = py = 300,"
echo "u0 = 160, v0 = 120; a 60 mm cube in a random orientation, its centre 150 mm away and within"
echo "10 mm of the optical axis; 60 control points spread evenly over the visible edges; observations"
echo "moved along the projected edge normal by Gaussian noise of σ = 0.3 px; start poses off by up to"
echo "5° and 5 mm. Residual: the paper's eq. (3) without the absolute value, (q − p(x))·n, in pixels;"
echo "6 parameters (exponential map and translation in millimetres); analytic Jacobian, and the"
echo "projection as u0 + x·(px / z), the form that rounds least in fixed point. Millimetres, not"
echo "metres, keep the Jacobian's translation columns near 2 px/mm instead of 2000 px/m, within the"
echo "range where S40.23's multiply is one 32 × 32-bit product, and give the fixed-point model points"
echo "1000× finer resolution (S47.16: 2^-16 mm instead of 0.015 mm); MINPACK scales columns by their"
echo "norms, so in exact arithmetic the unit does not change the iterations. Every solver uses VXL's"
echo "defaults (ftol 1e-10, xtol 1e-8, gtol 1e-5, 2400 evaluations, factor 100), which"
echo "\`vnl_levenberg_marquardt\` raises to one ulp for the fixed-point types. Iterations are MINPACK's"
echo "(Jacobian evaluations); evaluations are residual evaluations (what VXL's"
echo "\`get_num_iterations()\` counts with lmder). RMS residual and pose errors are evaluated in double"
echo "at each solver's answer. A failure is a solve that does not report convergence or ends more"
echo "than 1° or 5 mm from the true pose. Microseconds: the fastest of $passes passes over all"
echo "problems, the rows interleaved within each pass, on a machine shared with other jobs."
echo
"$host/tests/bench/lm/lm_compare" "$problems" "$passes"
echo
echo "### The same problems in the paper's unit, metres"
echo
echo "Only the solver's length unit differs (translation parameters and model points in metres; one"
echo "timing pass). Here the Jacobian's translation columns (~2000 px/m) and S47.16's resolution of"
echo "the model points (2^-16 m = 0.015 mm) are what the paper's fixed-point types faced."
echo
"$host/tests/bench/lm/lm_compare" "$problems" 1 metres
echo

count() {  # count <build dir> <label>: per-solve windows and solve lines of lm_pose_insns
  "$top/toolchains/qemu/count-insns.sh" --out "$work/$2.summary" --windows "$work/$2.windows" \
    "$1/tests/bench/lm/lm_pose_insns" "$problems" >"$work/$2.stdout"
  "$top/toolchains/qemu/count-insns.sh" --out "$work/$2.parts.summary" --windows "$work/$2.parts" \
    "$1/tests/bench/lm/lm_pose_insns" parts >/dev/null
}
count "$arm_double" double
count "$arm_s40" s40_23

row() {  # row <label> <name>
  awk -v name="$2" '
    NR == FNR { split($3, i, "="); split($4, s, "="); insns += i[2]; soft += s[2]; ++n
                if (n == 1 || i[2] < low) low = i[2]; if (i[2] > high) high = i[2]; next }
    /^solve / { it += $8; ev += $10; ++solves }
    END { printf "| %s | %.0f | %.0f–%.0f | %.0f | %.2f | %.2f |\n", name, insns / n, low, high, soft, it / solves, ev / solves }
  ' "$work/$1.windows" "$work/$1.stdout"
}
echo "### Guest instructions per pose solve on the emulated PXA270"
echo
echo "One count window per solve (constructing \`vnl_levenberg_marquardt\` and calling \`minimize\`)"
echo "on the same $problems problems (problem set-up outside the windows). The problems are"
echo "generated on the target, in double; its libm may round differently from the host's in the last"
echo "bit, so the iteration and evaluation counts can differ slightly from the host table."
echo
echo "| ARM build | instructions per solve, mean | min–max | soft-float instructions inside all solves | iterations, mean | evaluations, mean |"
echo "|---|---:|---:|---:|---:|---:|"
row double "double (soft-float)"
row s40_23 "S40.23"
echo
mean() { awk '{ split($3, i, "="); t += i[2]; ++n } END { printf "%.0f", t / n }' "$work/$1.windows"; }
evals() { awk '/^solve / { e += $10; ++n } END { printf "%.4f", e / n }' "$work/$1.stdout"; }
double_mean=$(mean double)
s40_mean=$(mean s40_23)
s40_soft=$(awk '{ split($4, s, "="); t += s[2] } END { print t + 0 }' "$work/s40_23.windows")
ratio=$(awk -v a="$double_mean" -v b="$s40_mean" 'BEGIN { printf "%.2f", a / b }')
per_eval=$(awk -v a="$double_mean" -v b="$s40_mean" -v ea="$(evals double)" -v eb="$(evals s40_23)" \
  'BEGIN { printf "%.2f", (a / ea) / (b / eb) }')
met=$(awk -v r="$ratio" -v s="$s40_soft" 'BEGIN { print (r >= 3 && s == 0) ? "met" : "NOT met" }')
echo "Double ÷ S40.23 instructions per solve: **${ratio}×** (per residual evaluation: ${per_eval}×);"
echo "soft-float instructions inside the S40.23 solves: $s40_soft. Target (at least 3× fewer, and"
echo "no soft-float routine inside the solve): **$met**."
echo
echo "Where the instructions go: one call of each building block on problem 1 (60 residuals, 6"
echo "unknowns; lmpar with a step bound that makes it iterate on the damping parameter):"
echo
echo "| building block | double (soft-float) | S40.23 | double ÷ S40.23 |"
echo "|---|---:|---:|---:|"
paste -d' ' "$work/double.parts" "$work/s40_23.parts" | awk '
  BEGIN { split("residuals,_60 Jacobian,_60×6 qrfac lmpar qrsolv enorm_of_60", label, " ") }
  { split($3, a, "="); split($7, b, "="); ++n; gsub("_", " ", label[n])
    printf "| %s | %d | %d | %.2f× |\n", label[n], a[2], b[2], a[2] / b[2] }'
