#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/camera_eval.md (issue 26's evaluation): generated cube
# and wood-toy sequences seen as a real camera sees them (a barrel and a pincushion lens, motion
# blur, an exposure step, rolling shutter, JPEG, all at once), tracked by our double and S40.23
# builds with the defaults, and by ViSP 3.5's edge tracker where it gets the same camera.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

bench_scratch camera_eval
double_tree=$(bench_tree host double edgetrack camera_eval_frames)
edgetrack=$double_tree/app/edgetrack
frames_tool=$double_tree/tests/bench/camera_eval/camera_eval_frames
s40_tree=$(bench_tree host s40_23 edgetrack camera_eval_frames)
edgetrack_s40=$s40_tree/app/edgetrack
frames_tool_s40=$s40_tree/tests/bench/camera_eval/camera_eval_frames
if ! "$edgetrack" compare --help >/dev/null 2>&1; then
  echo "camera_eval: edgetrack has no compare command (ViSP's mbt module not found at configure time)" >&2
  exit 1
fi
models=$top/data/models
fast_speed=4.2           # the paper's path 4.2 times faster: about 12 px per QVGA frame
step_up=0:1,29:1,30:1.4   # 40 % brighter from frame 30 on
step_down=0:1,29:1,30:0.6 # 40 % darker from frame 30 on
jpeg_quality=50
# All at once: through the barrel lens, fast, the shutter open and the rows read over a whole
# frame interval, the step up, JPEG. Rendered at 2 x 2 samples a pixel (its 25 renders a frame
# average the motion; GL draws the lens's pinhole image at twice the size).
all_at_once=(--kud -0.25 --speed "$fast_speed" --shutter 1 --readout 1 --exposure "$step_up" --jpeg "$jpeg_quality"
             --supersample 2)

# The rows over 0.5 mm, measured frame by frame (`camera_eval_frames`) for the second table;
# the rows whose S40.23 poses leave the double's by more than 0.1 mm, where the two part.
target_mm=0.5
over_target=()
s40_target_mm=0.1
s40_parting=()

# first_parting POSES REFERENCE: the first frame whose camera positions differ by more than 0.01 mm.
first_parting() {
  local last
  last=$(tail -n 1 "$1" | cut -d, -f1)
  for ((frame = 0; frame <= last; ++frame)); do
    awk -F, -v f="$frame" 'NR == 1 || $1 <= f' "$1" >"$work/part.csv"
    "$edgetrack" eval --poses "$work/part.csv" --truth "$2" --coverage >"$work/part.txt"
    awk -v d="$(bench_value max_distance_mm "$work/part.txt")" 'BEGIN { exit !(d > 0.01) }' && { echo "$frame"; return; }
  done
  echo none
}

# parting_line LABEL SEQ MODEL INTRINSICS... : where S40.23 and double part, and what differs there.
parting_line() {
  local label=$1 seq=$2 model=$3
  shift 3
  local frame
  frame=$(first_parting "$work/poses_s40.csv" "$work/double_poses.csv")
  [ "$frame" = none ] && return
  "$frames_tool" "$model" "$seq" 0 "$@" --matches "$frame" >"$work/matches.txt"
  "$frames_tool_s40" "$model" "$seq" 0 "$@" --matches "$frame" >"$work/matches_s40.txt"
  printf -- '- %s: first over 0.01 mm apart at frame %d, where double sees %d control points (%d matches, %d outliers) and S40.23 %d (%d matches, %d outliers).\n' \
    "$label" "$frame" "$(grep -c '^point' "$work/matches.txt")" "$(grep -c ' found ' "$work/matches.txt")" \
    "$(grep -c ' outlier 1 ' "$work/matches.txt")" "$(grep -c '^point' "$work/matches_s40.txt")" \
    "$(grep -c ' found ' "$work/matches_s40.txt")" "$(grep -c ' outlier 1 ' "$work/matches_s40.txt")"
}

# row LABEL NAME MODEL LENS [READOUT [TRACKED_READOUT]]: ours in double (`track`, `eval`) and S40.23
# (against the double's poses), with synth's intrinsics.xml when LENS is "given"; ViSP's tracker
# (`compare`) on the sequence's pinhole camera.xml unless the lens or the readout is given (compare
# passes neither to ViSP). READOUT: synth's --readout of the sequence (0 when not given), for the
# frame-by-frame measure; TRACKED_READOUT: `track --readout`, the readout given to our tracker (the
# frame-by-frame measures are those of a tracker of one rigid pose per frame: not for these rows).
row() {
  local label=$1 seq=$work/$2 model=$3 lens=$4 readout=${5:-0} tracked_readout=${6:-}
  local args=(--model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos"
              --images "$seq/frames/frame%04d.pgm" --quiet)
  [ "$lens" = given ] && args+=(--intrinsics "$seq/intrinsics.xml")
  [ -n "$tracked_readout" ] && args+=(--readout "$tracked_readout")
  "$edgetrack" track "${args[@]}" --poses "$work/poses.csv" >/dev/null
  "$edgetrack" eval --poses "$work/poses.csv" --truth "$seq/truth.csv" >"$work/eval.txt"
  "$edgetrack_s40" track "${args[@]}" --poses "$work/poses_s40.csv" >/dev/null
  "$edgetrack" eval --poses "$work/poses_s40.csv" --truth "$seq/truth.csv" >"$work/eval_s40.txt"
  cut -d, -f1-7 "$work/poses.csv" >"$work/double_poses.csv"
  "$edgetrack" eval --poses "$work/poses_s40.csv" --truth "$work/double_poses.csv" >"$work/s40.txt"
  local visp="| - | - | - "
  if [ "$lens" != given ] && [ -z "$tracked_readout" ]; then
    "$edgetrack" compare --model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos" \
      --images "$seq/frames/frame%04d.pgm" --truth "$seq/truth.csv" 2>/dev/null >"$work/compare.txt"
    visp=$(printf '| %d | %.3f | %.3f ' "$(bench_value visp_lost "$work/compare.txt")" \
      "$(bench_value visp_distance_mm "$work/compare.txt")" "$(bench_value visp_max_distance_mm "$work/compare.txt")")
  fi
  printf '| %s | %s | %d | %.3f | %.3f | %d | %.3f | %.4f %s|\n' "$label" \
    "$(sed -n 's/.*largest image motion \([0-9.]*\) px.*/\1/p' "$seq.txt")" "$(bench_value lost "$work/eval.txt")" \
    "$(bench_value distance_mm "$work/eval.txt")" "$(bench_value max_distance_mm "$work/eval.txt")" \
    "$(bench_value lost "$work/eval_s40.txt")" "$(bench_value distance_mm "$work/eval_s40.txt")" \
    "$(bench_value max_distance_mm "$work/s40.txt")" "$visp"
  [ -n "$tracked_readout" ] && return
  local intrinsics=()
  [ "$lens" = given ] && intrinsics=("$seq/intrinsics.xml")
  if awk -v a="$(bench_value max_distance_mm "$work/s40.txt")" -v b="$s40_target_mm" 'BEGIN { exit !(a > b) }'; then
    s40_parting+=("$(parting_line "$label" "$seq" "$model" "${intrinsics[@]}")")
  fi
  # A lens not given is the cause of its own rows (beside the same sequence's "given" row).
  [ -e "$seq/intrinsics.xml" ] && [ "$lens" != given ] && return
  if awk -v a="$(bench_value distance_mm "$work/eval.txt")" -v b="$target_mm" 'BEGIN { exit !(a >= b) }'; then
    "$frames_tool" "$model" "$seq" "$readout" "${intrinsics[@]}" >"$work/frames.txt"
    over_target+=("$label|$(tail -n 1 "$work/frames.txt")")
  fi
}

# cause_row LABEL|MEASURES: one row of the second table, its cause the first of: the rigid pose
# fitted to exact edge places over target (the rolling shutter's shear), the frames solved alone
# from their true poses over target (the image as the moving edges read it), else the tracking
# from frame to frame (the start each frame gets from the one before).
cause_row() {
  local label=${1%%|*} measures=" ${1#*|}"
  measure() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$measures"; }
  awk -v label="$label" -v target="$target_mm" -v tracked="$(measure tracked_mm)" -v early="$(measure early_mm)" \
      -v alone="$(measure alone_mm)" \
      -v rigid="$(measure rigid_mm)" -v offset="$(measure offset_px)" -v within="$(measure within_pixel)" 'BEGIN {
    if (rigid >= target) cause = sprintf("the rolling shutter: one rigid pose fitted to the exact edges of the rows, each where it was at its row'"'"'s read time, is %.3f mm off", rigid)
    else if (alone >= target) cause = sprintf("the image as the moving edges read it: each frame solved alone from its true pose is %.3f mm off", alone)
    else cause = sprintf("the tracking from frame to frame: each frame alone from its true pose is %.3f mm off, under %.1f mm; the start each frame gets from the one before adds %.3f mm", alone, target, tracked - alone)
    printf "| %s | %.3f | %.3f | %.3f | %.3f | %.2f | %.1f | %s |\n", label, tracked, early, alone, rigid, offset, 100 * within, cause
  }'
}

# synth_kind NAME MODEL OPTIONS...: renders $work/NAME as grey PGM, synth's report in $work/NAME.txt.
synth_kind() {
  local name=$1 model=$2
  shift 2
  "$edgetrack" synth --out "$work/$name" --model "$models/$model.cao" --pgm "$@" >"$work/$name.txt"
}

# render_all MODEL: every sequence of one model.
render_all() {
  local model=$1
  synth_kind "${model}_pinhole" "$model"
  synth_kind "${model}_pinhole_fine" "$model" --supersample 2
  synth_kind "${model}_barrel" "$model" --kud -0.25
  synth_kind "${model}_pincushion" "$model" --kud 0.12
  synth_kind "${model}_fast" "$model" --speed "$fast_speed"
  synth_kind "${model}_blur" "$model" --speed "$fast_speed" --shutter 1
  synth_kind "${model}_rolling" "$model" --speed "$fast_speed" --readout 1
  synth_kind "${model}_brighter" "$model" --exposure "$step_up"
  synth_kind "${model}_darker" "$model" --exposure "$step_down"
  synth_kind "${model}_jpeg" "$model" --jpeg "$jpeg_quality"
  synth_kind "${model}_all" "$model" "${all_at_once[@]}"
}
# The two models' sequences are rendered side by side (synth runs on one core).
render_all cube60 &
cube_renders=$!
render_all wood_toy
wait "$cube_renders"

bench_heading "Real cameras: lens, motion blur, exposure, rolling shutter, JPEG (camera_eval)" "host double and S40.23 builds"
echo "Generated by \`edgetrack synth --pgm\` (OSMesa, QVGA, px = py = 220, 60 frames, noise 2, blur 0.6 px, the"
echo "paper's path; docs/APP.md, \"synth\", says what each effect models): \"pinhole\" as before; \"2 x 2 samples\""
echo "the same drawn at 2 x 2 samples a pixel (\`--supersample 2\`), as synth draws every frame through a lens (the"
echo "pinhole image at twice the size, read through the lens at 2 x 2 samples a pixel): the lens rows' fair reference; \"barrel\" and"
echo "\"pincushion\" through ViSP's radial lens kud = -0.25 and +0.12 (\`--kud\`), tracked with synth's"
echo "\`intrinsics.xml\` (\`--intrinsics\`, \"given\") and without it (the pinhole camera.xml alone); \"fast\" the"
echo "path $fast_speed times faster (\`--speed $fast_speed\`, 12 px per frame); \"motion blur\" that with the"
echo "shutter open the whole frame interval (\`--shutter 1\`: each edge smeared over its motion, up to 12 px);"
echo "\"rolling shutter\" that with the rows read over the whole frame interval (\`--readout 1\`: the bottom"
echo "row 12 px of motion after the top); \"exposure\" 40 % brighter or darker from frame 30 on"
echo "(\`--exposure $step_up\` or \`$step_down\`; bright faces saturate at 255); \"JPEG\" quality"
echo "$jpeg_quality (\`--jpeg $jpeg_quality\`); \"all at once\" \`${all_at_once[*]}\`, tracked with the lens given."
echo "Every tracker starts from the true first pose with the defaults and the camera-only XML synth writes."
echo "Ours: \`edgetrack track\` and \`edgetrack eval\` (camera position in the object frame: mean and largest"
echo "distance to the truth, mm) in the double and S40.23 builds; \"S40.23 - double\": the largest per-frame"
echo "distance between their camera positions. ViSP 3.5's vpMbGenericTracker (edge) through"
echo "\`edgetrack compare --truth\` (lost when track() throws) on the pinhole camera: \"-\" where our tracker is"
echo "given the lens, which \`compare\` does not pass to ViSP. \"readout given\": the same frames tracked with the rows'"
echo "readout given to our tracker (\`track --readout 1\`: each row seen at its own time, docs/ARCHITECTURE.md,"
echo "\"Rolling shutter\"); ViSP has no such setting."
echo
echo "| sequence | motion px/frame | lost | mean mm | largest mm | S40.23 lost | S40.23 mean mm | S40.23 - double mm | ViSP lost | ViSP mean mm | ViSP largest mm |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for model in cube60 wood_toy; do
  [ "$model" = cube60 ] && name="60 mm cube" || name="wood toy"
  row "$name, pinhole" "${model}_pinhole" "$models/$model.cao" none
  row "$name, pinhole, 2 x 2 samples" "${model}_pinhole_fine" "$models/$model.cao" none
  row "$name, barrel kud -0.25, given" "${model}_barrel" "$models/$model.cao" given
  row "$name, barrel kud -0.25, not given" "${model}_barrel" "$models/$model.cao" none
  row "$name, pincushion kud +0.12, given" "${model}_pincushion" "$models/$model.cao" given
  row "$name, pincushion kud +0.12, not given" "${model}_pincushion" "$models/$model.cao" none
  row "$name, fast" "${model}_fast" "$models/$model.cao" none
  row "$name, fast, motion blur" "${model}_blur" "$models/$model.cao" none
  row "$name, fast, rolling shutter" "${model}_rolling" "$models/$model.cao" none 1
  row "$name, fast, rolling shutter, readout given" "${model}_rolling" "$models/$model.cao" none 1 1
  row "$name, exposure +40 %" "${model}_brighter" "$models/$model.cao" none
  row "$name, exposure -40 %" "${model}_darker" "$models/$model.cao" none
  row "$name, JPEG $jpeg_quality" "${model}_jpeg" "$models/$model.cao" none
  row "$name, all at once" "${model}_all" "$models/$model.cao" given 1
  row "$name, all at once, readout given" "${model}_all" "$models/$model.cao" given 1 1
done
echo
echo "The rows over $target_mm mm but those of a lens not given, frame by frame (\`camera_eval_frames\`, double): \"tracked\" the run above; \"half a"
echo "frame earlier\" the same poses against the true pose at the start of the frame interval (the shutter's opening,"
echo "the top row's read), were the truth stamped there; \"alone\""
echo "each frame solved alone from its own true pose (what the frame allows the tracker); \"rigid fit\" one"
echo "rigid pose fitted, from the true pose, to where each of those control points is at its row's read time (a"
echo "blurred edge's ramp is centred on the middle of its exposure, the read time): what a rolling shutter's"
echo "shear leaves to any tracker of one rigid pose per frame, with perfect edges; of alone's matches, the mean"
echo "distance along the normal from that place and the share within a pixel. The cause is the first of the"
echo "rigid fit, alone, the tracking that reaches $target_mm mm. The true pose is the frame's time, the middle"
echo "of the exposure and of the rows' readout (docs/FORMATS.md)."
echo
echo "| sequence | tracked mm | half a frame earlier mm | alone mm | rigid fit mm | matches off mean px | within 1 px % | cause |"
echo "|---|---:|---:|---:|---:|---:|---:|---|"
for measured in "${over_target[@]}"; do cause_row "$measured"; done
if [ ${#s40_parting[@]} -gt 0 ]; then
  echo
  echo "The rows whose S40.23 poses leave the double's by more than $s40_target_mm mm on some frame (\`camera_eval_frames"
  echo "--matches\` in both builds, the control points visible at the start pose and the matches the pose step kept or"
  echo "gave no weight): a control point one build's Edge-ID buffer shows and the other's does not, or a match on the"
  echo "edge of the robust weight, changes the set the pose solves with; the poses part from there."
  echo
  printf '%s\n' "${s40_parting[@]}"
fi
