#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/detection_sequences.md (issue 14's evaluation over
# whole sequences): generated QVGA sequences of the cube and the wood toy tracked from their first
# frame with `edgetrack track --init-auto` (detection on the first frame and on every frame the
# tracker does not hold), beside the same sequences tracked from the true first pose; then ViSP's
# real mbt/cube from frame 0 with no pose, at 640x480 and QVGA, against the run from cube.0.pos.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

seeds=(1 2 3)
fast_speed=4
hide=30:41      # frames the board covers the whole object on, in the "covered" sequences
mbt=$visp_images/mbt
models=$top/data/models
mkdir -p "$bench_build_root"
work=$(mktemp -d "${TMPDIR:-/tmp}/detection_sequences.XXXXXX")
trap 'rm -rf "$work"' EXIT
dir=$(bench_tree host double edgetrack detection_sequence)
edgetrack=$dir/app/edgetrack
helper=$dir/tests/bench/detection/detection_sequence

value() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" "$2" | head -n 1; }

# detections STDERR: "tried found" of the detections after the first one that found the model
# (the re-detections), from track's "frame N detection: ..." lines.
redetections() {
  awk '/^frame [0-9]+ detection: / { if (initial_done) { tried++; found += ($4 == "found") }
                                     else if ($4 == "found") initial_done = 1 }
       END { printf "%d %d\n", tried, found }' "$1"
}

# track_run NAME SEQ MODEL INIT...: `track` with INIT (--init-auto ... or --init-pose ...), its
# poses in $work/NAME.csv and its stderr in $work/NAME.err.
track_run() {
  local name=$1 seq=$2 model=$3
  shift 3
  "$edgetrack" track --model "$model" --camera "$seq/camera.xml" --images "$seq/frames/frame%04d.ppm" \
    --poses "$work/$name.csv" "$@" >"$work/$name.out" 2>"$work/$name.err"
}

# number_or_dash N: N, or "never" when negative.
never() { [ "$1" -ge 0 ] && echo "$1" || echo "never"; }

# sequence_row KIND SEED MODEL: renders the sequence, runs both starts, prints the table row.
sequence_row() {
  local kind=$1 seed=$2 model=$3 frames=60 shape=steady synth_args=() events=()
  case $kind in
    leave) frames=110 shape=leave ;;
    covered) frames=80 synth_args=(--hide "$hide") ;;
    fast) synth_args=(--speed "$fast_speed") ;;
  esac
  local rows=$frames
  [ "$kind" = fast ] && rows=$((fast_speed * (frames - 1) + 1))
  "$helper" trajectory "$model" "$shape" "$seed" "$rows" "$work/trajectory.csv" >"$work/trajectory.txt"
  rm -rf "$work/seq"  # the frames of a longer sequence before would follow this one's
  "$edgetrack" synth --out "$work/seq" --model "$models/$model.cao" --trajectory "$work/trajectory.csv" \
    --frames "$frames" --seed "$seed" "${synth_args[@]}" >"$work/synth.txt"
  if [ "$kind" = leave ]; then
    events=(--absent "$(value absent_first "$work/trajectory.txt"):$(value absent_last "$work/trajectory.txt")"
            --back "$(value back "$work/trajectory.txt")")
  elif [ "$kind" = covered ]; then
    events=(--absent "$hide" --back $((${hide#*:} + 1)))
  fi
  local cube=()
  [ "$model" = cube60 ] && cube=(--cube)
  track_run auto "$work/seq" "$models/$model.cao" --init-auto --templates "$work/$model.templates"
  track_run truth "$work/seq" "$models/$model.cao" --init-pose "$work/seq/first.pos" --quiet
  "$helper" score "$models/$model.cao" "$work/auto.csv" "$work/seq/truth.csv" "${cube[@]}" "${events[@]}" >"$work/auto.txt"
  "$helper" score "$models/$model.cao" "$work/truth.csv" "$work/seq/truth.csv" "${cube[@]}" "${events[@]}" >"$work/truth.txt"
  local a=$work/auto.txt t=$work/truth.txt back_auto=- back_truth=- absent=-
  if [ ${#events[@]} -gt 0 ]; then
    back_auto=$(never "$(value back_to_tracked "$a")")
    back_truth=$(never "$(value back_to_tracked "$t")")
    absent="$(value tracked_absent "$a") / $(value tracked_absent "$t")"
  fi
  read -r tried found < <(redetections "$work/auto.err")
  printf '| %s | %s | %d | %s | %s | %s | %s | %s of %s | %s | %s | %s / %s | %.2f / %.2f | %s | %s | %s | %.2f / %.2f |\n' \
    "$kind" "$seed" "$frames" "$(sed -n 's/.*largest image motion \([0-9.]*\) px.*/\1/p' "$work/synth.txt")" \
    "$(never "$(value first_tracked "$a")")" "$(value tracked "$a")" "$(value lost "$a")" "$found" "$tried" \
    "$back_auto" "$absent" "$(value tracked_wrong "$a")" "$(value tracked_wrong "$t")" \
    "$(value mean_mm "$a")" "$(value max_mm "$a")" "$(value tracked "$t")" "$(value lost "$t")" "$back_truth" \
    "$(value mean_mm "$t")" "$(value max_mm "$t")"
}

# mbt_row DOWNSCALE: mbt/cube from frame 0 with --init-auto, and from cube.0.pos.
mbt_row() {
  local factor=$1 size=640x480
  [ "$factor" = 2 ] && size=320x240
  local args=(--model "$mbt/cube.cao" --camera "$mbt/cube.xml" --images "$mbt/cube/image%04d.pgm" --downscale "$factor")
  "$edgetrack" track "${args[@]}" --init-auto --init-distance 0.4:0.6 --poses "$work/mbt_auto.csv" \
    >"$work/mbt_auto.out" 2>"$work/mbt_auto.err"
  "$edgetrack" track "${args[@]}" --init-pose "$mbt/cube.0.pos" --poses "$work/mbt_pos.csv" --quiet >/dev/null
  "$helper" score "$mbt/cube.cao" "$work/mbt_auto.csv" "$work/mbt_pos.csv" --cube >"$work/mbt_score.txt"
  "$helper" corners "$mbt/cube.cao" "$mbt/cube.xml" "$factor" "$work/mbt_auto.csv" "$work/mbt_pos.csv" >"$work/mbt_corners.txt"
  local s=$work/mbt_score.txt c=$work/mbt_corners.txt
  printf '| %s | %s | %s | %s | %s | %s | %s | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f |\n' "$size" \
    "$(value frames "$s")" "$(never "$(value first_tracked "$s")")" "$(value tracked "$s")" "$(value uncertain "$s")" \
    "$(value lost "$s")" "$(sed -n 's/^detection: ran on \([0-9]*\) frames, found the model on \([0-9]*\).*/\2 of \1/p' "$work/mbt_auto.out")" \
    "$(value corner_px "$c")" "$(value corner_max_px "$c")" "$(value mean_mm "$s")" "$(value max_mm "$s")" \
    "$(value mean_deg "$s")" "$(value max_deg "$s")"
}

echo "## Detection over whole sequences: --init-auto from the first frame and after losses"
echo
echo "\`tests/bench/detection/results_sequences.sh\`: host double build, $(bench_machine)."
echo
echo "Generated by \`edgetrack synth\` (OSMesa, QVGA, px = py = 220, noise 2, blur 0.6 px, its cluttered"
echo "backdrop, a new one per seed) on trajectories from \`detection_sequence trajectory\`: the model starts"
echo "at a random view inside the single-image evaluation's range (within 60 degrees of its z axis,"
echo "120 to 200 mm, wholly in view; seeds ${seeds[*]}) and turns about its centre by up to 15 degrees while"
echo "drifting towards the image centre. \"steady\": 60 frames of that; \"fast\": the same path $fast_speed times"
echo "faster (\`--speed $fast_speed\`); \"covered\": 80 frames, a board in front covering the whole object on"
echo "frames $hide (\`synth --hide\`) while it moves on; \"leave\": 110 frames, panned out of the view from"
echo "frame 15 (up to 8 px per frame), out for 10 frames, and panned back. Both models' templates:"
echo "\`edgetrack templates --distance 0.12:0.2 --cone 60\`, given to \`track --init-auto --templates\`."
echo
echo "Columns: the first frame reported tracked (a detection frame is reported uncertain until the next"
echo "frame, tracked from it, confirms it); frames tracked and lost (the rest uncertain); re-detections:"
echo "detector runs after the first one that found the model, and how many found it; back: frames from"
echo "the object's return (the first frame it is wholly in view again, or uncovered) to the first tracked"
echo "frame after its absence (0: tracked on its return), \"never\" when no frame is; tracked while absent"
echo "(no vertex in the image, or covered); tracked frames more than 5 mm or 5 degrees off (an overlay"
echo "visibly beside the object); the model centre's error in the camera frame on tracked frames (the"
echo "cube's 24 symmetric poses count as right: the detector may find any). \"From the true pose\": the"
echo "same sequence tracked with \`--init-pose first.pos\` (no detection, the tracker's own recovery)."
echo
for model in cube60 wood_toy; do
  "$edgetrack" synth --out "$work/camera" --frames 1 >/dev/null
  "$edgetrack" templates --model "$models/$model.cao" --camera "$work/camera/camera.xml" --distance 0.12:0.2 --cone 60 \
    --out "$work/$model.templates" >/dev/null
  [ "$model" = cube60 ] && echo "### 60 mm cube" || echo "### Wood toy"
  echo
  echo "| sequence | seed | frames | motion px/frame | first tracked | tracked | lost | re-detections found | back | tracked while absent (auto / true) | > 5 mm or 5 deg (auto / true) | mean / largest mm | from the true pose: tracked | lost | back | mean / largest mm |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for kind in steady fast covered leave; do
    for seed in "${seeds[@]}"; do sequence_row "$kind" "$seed" "$model"; done
  done
  echo
done
echo "### ViSP's mbt/cube from frame 0 with no pose"
echo
echo "\`track --init-auto --init-distance 0.4:0.6\` with \`cube.xml\` alone and \`cube.cao\`, over all 218 frames,"
echo "at 640x480 and halved to QVGA (\`--downscale 2\`), against \`track --init-pose cube.0.pos\` with the same"
echo "files: corner difference (per frame, the mean distance from each cube corner projected with the"
echo "--init-auto pose to the nearest corner projected with the cube.0.pos run's, pixels of the tracked"
echo "size: the same for any of the cube's symmetric poses), the cube centre's distance and the rotation"
echo "between the runs (over the symmetries), on the tracked frames."
echo
echo "| size | frames | first tracked | tracked | uncertain | lost | detections found | corner px mean / largest | centre mm mean / largest | rotation deg mean / largest |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
mbt_row 1
mbt_row 2
