# SPDX-License-Identifier: BSD-3-Clause
# Sourced by tests/bench/mcu/results.sh (its trees, scratch directory and helpers): the markdown
# sections of docs/results/mcu.md on the tracker's steps and on soft float. Guest instructions per
# step of Tracker::track (bench_tracker's StepObserver windows, as docs/results/tracker.md counts the
# PXA270's) for the Cortex-M3 and the PXA270, each in S40.23 and in float (soft float: neither has an
# FPU), and the accuracy of each M3 build's `edgetrack track` on the generated sequences
# against the truth and against the host double build.

steps_frames=60  # bench_tracker's sequence, as docs/results/tracker.md's PXA270 table

# steps_count NAME DIR [TRIPLE]: bench_tracker of tree DIR counted per step (NAME.steps) and per
# frame (NAME.frames) on the cube's generated sequence, on-demand grey; TRIPLE arm-none-eabi for the
# bare-metal trees (qemu-system-arm -M mps2-an385).
steps_count() {
  local name=$1 program=$2/tests/bench/tracker/bench_tracker
  EDGETRACK_COUNT_TRIPLE=${3:-} "$top/toolchains/qemu/count-insns.sh" --out "$name.steps.sum" --windows "$name.steps" \
    "$program" "$steps_frames" cube steps on-demand >"$name.steps.out" 2>&1
  EDGETRACK_COUNT_TRIPLE=${3:-} "$top/toolchains/qemu/count-insns.sh" --out "$name.frames.sum" --windows "$name.frames" \
    "$program" "$steps_frames" cube frame on-demand >"$name.frames.out" 2>&1
}
# steps_row LABEL NAME: a row of the per-step table, each step's mean per frame and its share of the
# frame's window, what the frame does outside the four steps, the frame's mean and largest window.
steps_row() {
  awk -v l="$1" -v f="$steps_frames" 'NR == FNR { split($3, a, "="); s[(FNR - 1) % 4] += a[2]; next }
    { split($3, a, "="); split($4, b, "="); t += a[2]; tf += b[2]; if (a[2] > m) m = a[2] }
    END { o = t - s[0] - s[1] - s[2] - s[3]
      printf "| %s | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M (%.0f %%) | %.3f M | %.3f M | %.0f |\n",
        l, s[0]/f/1e6, 100*s[0]/t, s[1]/f/1e6, 100*s[1]/t, s[2]/f/1e6, 100*s[2]/t, s[3]/f/1e6, 100*s[3]/t,
        o/f/1e6, 100*o/t, t/f/1e6, m/1e6, tf/f }' "$2.steps" "$2.frames"
}
# steps_soft NAME: soft-float instructions per frame in each step, "visible, grey, ME, pose".
steps_soft() {
  awk -v f="$steps_frames" '{ split($4, b, "="); s[(NR - 1) % 4] += b[2] }
    END { printf "%.0f, %.0f, %.0f, %.0f", s[0]/f, s[1]/f, s[2]/f, s[3]/f }' "$1.steps"
}
# steps_error NAME: bench_tracker's mean and largest camera position error against the truth, mm.
steps_error() {
  awk '/^frame/ { s += $12; n++; if ($12 > m) m = $12 } END { printf "%.3f, %.3f", s / n, m }' "$1.frames.out"
}

# accuracy_run NAME FIRMWARE SEQ MODEL: the firmware's `edgetrack track` on the sequence SEQ
# (synth's directory), poses in NAME.csv.
accuracy_run() {
  local last
  last=$(($(ls "$3/frames" | wc -l) - 1))
  EDGETRACK_MCU_FIRMWARE=$2 "$top/toolchains/mcu/edgetrack-mcu.sh" track --model "$4" --camera "$3/camera.xml" \
    --init-pose "$3/first.pos" --images "$3/frames/frame%04d.pgm" --first 0 --last "$last" --quiet --poses "$1.csv" \
    >/dev/null 2>"$1.err"
}
# eval_distance POSES TRUTH: "mean, largest" distance of the camera positions, mm (edgetrack eval).
eval_distance() {
  "$host_double/app/edgetrack" eval --poses "$1" --truth "$2" |
    sed -n 's/^eval: .* distance_mm=\([0-9.]*\) max_distance_mm=\([0-9.]*\).*/\1, \2/p'
}
# eval_within NAME POSES REFERENCE: yes when the largest distance to REFERENCE is at most 0.1 mm.
eval_within() {
  awk -v d="$(eval_distance "$1" "$2" | cut -d, -f2)" 'BEGIN { print (d != "" && d <= 0.1) ? "yes" : "no" }'
}

steps_and_float_section() {
  local float_dir arm_float_dir
  host_double=$(bench_tree host double edgetrack)
  float_dir=$(bench_tree mcu float edgetrack bench_tracker)
  arm_float_dir=$(bench_tree arm float bench_tracker)
  cmake --build "$mcu_dir" --target bench_tracker >"$work/bench_tracker.mcu.log" 2>&1 ||
    { tail -n 40 "$work/bench_tracker.mcu.log" >&2; return 1; }
  cmake --build "$arm_dir" --target bench_tracker >"$work/bench_tracker.arm.log" 2>&1 ||
    { tail -n 40 "$work/bench_tracker.arm.log" >&2; return 1; }
  steps_count m3_s40 "$mcu_dir" arm-none-eabi
  steps_count m3_float "$float_dir" arm-none-eabi
  steps_count pxa_s40 "$arm_dir"
  steps_count pxa_float "$arm_float_dir"

  echo
  echo "### Guest instructions per step: Cortex-M3 and PXA270, in S40.23 and in soft float"
  echo
  echo "\`bench_tracker $steps_frames cube steps on-demand\` (tests/bench/tracker, the program of docs/results/tracker.md's"
  echo "PXA270 table, built in each tree): a StepObserver opens one count window per step of \`Tracker::track\`; the"
  echo "whole frame is one window of \`bench_tracker $steps_frames cube frame on-demand\`. The same $steps_frames generated QVGA"
  echo "frames of the cube, rendered by the program before its windows, paper's settings. Means per frame. The"
  echo "Cortex-M3 float tree is \`-DEDGETRACK_REAL=float\` with the same toolchain file (\`build/bench-mcu-float\`):"
  echo "the M3 has no FPU, so every float operation is a call into libgcc's soft-float routines; the PXA270's float"
  echo "tree (\`build/bench-arm-float\`) likewise."
  echo
  echo "| target, real | visible edges | grey scaling | ME | pose | outside the steps | whole frame | largest frame | in soft-float routines per frame |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
  steps_row "Cortex-M3, S40.23" m3_s40
  steps_row "Cortex-M3, float (soft)" m3_float
  steps_row "PXA270, S40.23" pxa_s40
  steps_row "PXA270, float (soft)" pxa_float
  echo
  echo "Soft-float instructions per frame in each step (visible edges, grey, ME, pose): Cortex-M3 S40.23"
  echo "$(steps_soft m3_s40); Cortex-M3 float $(steps_soft m3_float); PXA270 float $(steps_soft pxa_float)."
  echo "Outside the steps: the whole frame's window less its four steps' (the status rule's measures, the motion"
  echo "model's update and the contrasts remembered for the next frame, tracker/src/tracker.cpp). These frames are RGB565"
  echo "(the command line's above are grey8 PGM, read as they are): the bare-metal"
  echo "tree converts each pixel to grey by the rule, not through the hosted builds' 64 KB table (docs/MCU.md), hence"
  echo "its dearer grey step."
  echo "Camera position error against the truth on these frames (mean, largest, mm): Cortex-M3 S40.23"
  echo "$(steps_error m3_s40), Cortex-M3 float $(steps_error m3_float), PXA270 S40.23 $(steps_error pxa_s40), PXA270 float $(steps_error pxa_float)."

  # The generated sequences of `edgetrack synth` (OSMesa, noise and blur): the cube's and the wood toy's.
  "$host_dir/app/edgetrack" synth --out seq60 --frames 60 --pgm >/dev/null
  "$host_dir/app/edgetrack" synth --out toy60 --frames 60 --pgm --model "$top/data/models/wood_toy.cao" >/dev/null
  echo
  echo "### Accuracy of the Cortex-M3 builds on the generated sequences"
  echo
  echo "\`edgetrack track\` of each build on \`edgetrack synth --frames 60 --pgm\`'s sequences (the cube, and the wood toy"
  echo "with \`--model data/models/wood_toy.cao\`), the firmware by \`toolchains/mcu/edgetrack-mcu.sh\`; distances"
  echo "between camera positions by \`edgetrack eval\` (mean, largest, mm) against synth's truth and against the host"
  echo "double build's poses (its CSV as the truth). The issue asks for within 0.1 mm of the host double build."
  echo
  echo "| sequence | build | frames tracked | against the truth | against host double | within 0.1 mm of double |"
  echo "|---|---|---:|---:|---:|---|"
  local seq model name
  for seq in seq60 toy60; do
    model=$top/data/models/cube60.cao
    [ "$seq" = toy60 ] && model=$top/data/models/wood_toy.cao
    "$host_double/app/edgetrack" track --model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos" \
      --images "$seq/frames/frame%04d.pgm" --first 0 --last 59 --quiet --poses "$seq.double.csv" >/dev/null 2>&1
    { echo "frame,tx,ty,tz,tux,tuy,tuz"; tail -n +2 "$seq.double.csv" | cut -d, -f1-7; } >"$seq.double-truth.csv"
    accuracy_run "$seq.s40_23" "$mcu_dir/app/edgetrack" "$seq" "$model"
    accuracy_run "$seq.float" "$float_dir/app/edgetrack" "$seq" "$model"
    for name in double s40_23 float; do
      local label="host, double"
      [ "$name" = s40_23 ] && label="Cortex-M3, S40.23"
      [ "$name" = float ] && label="Cortex-M3, float (soft)"
      echo "| $([ "$seq" = seq60 ] && echo cube || echo "wood toy") | $label | $(grep -c ',tracked' "$seq.$name.csv") |" \
        "$(eval_distance "$seq.$name.csv" "$seq/truth.csv") | $(eval_distance "$seq.$name.csv" "$seq.double-truth.csv") |" \
        "$(eval_within "$seq.$name.csv" "$seq.double-truth.csv") |"
    done
  done
}
steps_and_float_section
