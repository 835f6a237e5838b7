#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/tracker.md: the paper's Table 1 on the generated
# QVGA cube sequence (60 frames), with the grey step on demand (the tracker's default) and over
# the whole frame (the paper's way). Host: milliseconds per step per frame for each real build
# (steady clock, mean of 60 frames, best of 5 runs). Emulated PXA270: guest instructions per frame
# and per step for double (soft-float) and S40.23, counted by toolchains/qemu/count-insns.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

frames=60
runs=5
cpi=1.5  # assumed XScale cycles per instruction for the 624 MHz estimate
target=2000000  # the issue's S40.23 target, guest instructions per frame
visp_xml=$visp_images/mbt/cube.xml  # ViSP's settings for the per-point row
mkdir -p "$bench_build_root"
work=$(mktemp -d "${TMPDIR:-/tmp}/tracker_bench.XXXXXX")
trap 'rm -rf "$work"' EXIT

grey_modes=(on-demand whole)
grey_label() { [ "$1" = whole ] && echo "whole frame" || echo "on demand"; }

# The camera the benchmark tracks with, from its header line (the sequence may change it).
host_double=$(bench_tree host double bench_tracker)
"$host_double/tests/bench/tracker/bench_tracker" 1 >"$work/header.txt"
camera=$(sed -n 's/^# .*camera=\([0-9x]*\) px=\([0-9.]*\) py=\([0-9.]*\).*/\1, px = \2, py = \3/p' "$work/header.txt")
rounds=$(sed -n 's/^# .*robust_rounds=\([0-9]*\).*/\1/p' "$work/header.txt")
robust_evaluations=$(sed -n 's/^# .*robust_evaluations=\([0-9]*\).*/\1/p' "$work/header.txt")
if [ "$robust_evaluations" = 2 ]; then robust_solve="one Levenberg-Marquardt step each"
else robust_solve="at most $robust_evaluations residual evaluations each"; fi

echo "## Tracker: the paper's Table 1 on the generated cube sequence"
echo
echo "\`tests/bench/tracker/results.sh\`: host $(bench_machine); guest counts on $(qemu-arm --version | head -n 1 | sed 's/ (.*//'),"
echo "\`-cpu pxa270\`, counted by \`toolchains/qemu/count-insns.sh\`."
echo
echo "Sequence: the 60 mm cube about 150 mm from a QVGA camera ($camera), $frames frames rendered"
echo "in-process by the test-image renderer, smooth motion of up to 3 pixels per frame, tracked from the"
echo "true first pose with the default TrackerParams (sampling step 10 px, ME range 4; pose: a plain"
echo "Levenberg-Marquardt solve, then $rounds Tukey re-weighted rounds of $robust_solve)."
echo "The frames are rendered before the clock starts. Grey scaling \"on demand\""
echo "(the default) converts only each visible control point's search box (\`tracker/src/me_search_box.cpp\`);"
echo "\"whole frame\" converts every pixel, as the paper does. Both give bit-identical poses and matches"
echo "(\`tests/tracker/test_tracker_grey.cxx\`)."
echo
echo "### Host: milliseconds per frame (mean of $frames frames, best of $runs runs)"
echo
echo "LM evaluations: residual evaluations per frame over all the pose step's solves."
echo
echo "| real | grey | visible edges | grey scaling | ME | pose | total ms | points sampled | matched | grey pixels | LM evaluations | mean error mm |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for real in double float s47_16 s40_23; do
  if ! dir=$(bench_tree host "$real" bench_tracker 2>"$work/build.err"); then
    echo "| $real | | build failed | | | | | | | | | |"
    continue
  fi
  for grey in "${grey_modes[@]}"; do
    best=""
    for _ in $(seq "$runs"); do
      "$dir/tests/bench/tracker/bench_tracker" "$frames" cube frame "$grey" >"$work/run.txt"
      line=$(awk '/^frame/ { n++; v += $3; g += $4; m += $5; p += $6; s += $7; t += $8; e += $12; px += $13; ev += $11 }
        END { printf "%.3f %.3f %.3f %.3f %.3f %.1f %.1f %.3f %.0f %.2f", v/n/1e6, g/n/1e6, m/n/1e6, p/n/1e6, (v+g+m+p)/n/1e6, s/n, t/n, e/n, px/n, ev/n }' "$work/run.txt")
      total=$(echo "$line" | cut -d' ' -f5)
      if [ -z "$best" ] || awk -v a="$total" -v b="$(echo "$best" | cut -d' ' -f5)" 'BEGIN { exit !(a < b) }'; then best=$line; fi
    done
    echo "$best" | awk -v r="$real" -v gl="$(grey_label "$grey")" '{ t = $5; printf "| %s | %s | %.3f (%.0f %%) | %.3f (%.0f %%) | %.3f (%.0f %%) | %.3f (%.0f %%) | %.3f | %.1f | %.1f | %d | %.2f | %.3f |\n",
      r, gl, $1, 100*$1/t, $2, 100*$2/t, $3, 100*$3/t, $4, 100*$4/t, t, $6, $7, $9, $10, $8 }'
  done
done
echo "| paper, PXA270 | whole frame | 28 % | 19 % | 37 % | 16 % | 64 | about 60 | | | | 6.12 |"
echo
echo "### Emulated PXA270: guest instructions per frame"
echo
echo "Per step: a StepObserver on \`Tracker::track\` opens one count window per step"
echo "(\`bench_tracker $frames cube steps <grey>\`); total: one window per \`Tracker::track\` call"
echo "(\`bench_tracker $frames cube frame <grey>\`). The estimate at 624 MHz assumes $cpi cycles per"
echo "instruction (an assumption, not a measurement)."
echo
echo "| real (ARM build) | grey | visible edges | grey scaling | ME | pose | total per frame | in soft-float routines | estimate at 624 MHz |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
s40_on_demand="" s40_on_demand_soft=""
for real in double s40_23; do
  dir=$(bench_tree arm "$real" bench_tracker)
  for grey in "${grey_modes[@]}"; do
    "$top/toolchains/qemu/count-insns.sh" --out "$work/steps.sum" --windows "$work/steps.win" \
      "$dir/tests/bench/tracker/bench_tracker" "$frames" cube steps "$grey" >/dev/null
    "$top/toolchains/qemu/count-insns.sh" --out "$work/frames.sum" --windows "$work/frames.win" \
      "$dir/tests/bench/tracker/bench_tracker" "$frames" cube frame "$grey" >/dev/null
    read -r v g m p < <(awk '{ split($3, a, "="); s[(NR-1)%4] += a[2] } END { f = NR/4; printf "%.0f %.0f %.0f %.0f\n", s[0]/f, s[1]/f, s[2]/f, s[3]/f }' "$work/steps.win")
    read -r total soft < <(awk '{ split($3, a, "="); split($4, b, "="); t += a[2]; s += b[2] } END { printf "%.0f %.0f\n", t/NR, s/NR }' "$work/frames.win")
    awk -v r="$real" -v gl="$(grey_label "$grey")" -v v="$v" -v g="$g" -v m="$m" -v p="$p" -v t="$total" -v s="$soft" -v cpi="$cpi" 'BEGIN {
      st = v + g + m + p
      printf "| %s | %s | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M | %.0f | %.1f ms |\n",
        r, gl, v/1e6, 100*v/st, g/1e6, 100*g/st, m/1e6, 100*m/st, p/1e6, 100*p/st, t/1e6, s, t*cpi/624e6*1e3 }'
    if [ "$real" = s40_23 ] && [ "$grey" = on-demand ]; then s40_on_demand=$total s40_on_demand_soft=$soft; fi
  done
done
echo
echo "Target from the issue: at most 2.0 M guest instructions per S40.23 frame and no soft-float routine"
echo "executed per frame. The paper's 64 ms at 624 MHz is about 40 M cycles."
awk -v t="$s40_on_demand" -v s="$s40_on_demand_soft" -v target="$target" 'BEGIN {
  printf "S40.23 with on-demand grey: %.3f M per frame (%s), %d instructions in soft-float routines (%s).\n",
    t/1e6, t <= target ? "at most 2.0 M: met" : "above 2.0 M: not met", s, s == 0 ? "met" : "not met" }'

echo
echo "### Emulated PXA270, S40.23: the pose solver and ViSP's settings"
echo
echo "Whole \`Tracker::track\` per frame (on-demand grey, $frames frames), with MINPACK's lmder (the default) and"
echo "with the 6 x 6 normal-equations option (\`PoseSolver::kNormalEquations\`, \`bench_tracker ... normal\`); at the"
echo "paper's settings (TrackerParams, sampling step 10 px, range 4) and at ViSP's settings"
echo "(\`$visp_xml\` applied as ViSP reads it: sample step and range from its <ecm>, on the"
echo "sequence's QVGA camera). Per control point: the frame's count over the points sampled."
echo
echo "| settings | solver | total per frame | control points | per control point | LM evaluations | Jacobians |"
echo "|---|---|---:|---:|---:|---:|---:|"
dir=$(bench_tree arm s40_23 bench_tracker)
for settings in paper visp; do
  for solver in lmder normal; do
    extra=()
    [ "$settings" = visp ] && extra=("$visp_xml")
    "$top/toolchains/qemu/count-insns.sh" --out "$work/solver.sum" --windows "$work/solver.win" \
      "$dir/tests/bench/tracker/bench_tracker" "$frames" cube frame on-demand 1 "$solver" "${extra[@]}" >"$work/solver.txt"
    step=$(sed -n 's/^# .*sample_step=\([0-9.]*\) range=\([0-9]*\).*/step \1 px, range \2/p' "$work/solver.txt")
    label=$([ "$settings" = visp ] && echo "ViSP's cube.xml ($step)" || echo "paper's ($step)")
    awk -v l="$label" -v s="$solver" 'NR == FNR { split($3, a, "="); t += a[2]; n++; next }
      /^frame/ { p += $7; e += $11; j += $14; f++ }
      END { printf "| %s | %s | %.3f M | %.1f | %.0f | %.2f | %.2f |\n", l, s, t/n/1e6, p/f, t/n/(p/f), e/f, j/f }' \
      "$work/solver.win" "$work/solver.txt"
  done
done
