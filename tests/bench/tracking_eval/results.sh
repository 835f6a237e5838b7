#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/tracking_eval.md (issue 10's evaluation): generated
# cube and wood-toy sequences (slow, fast, reversing, occluded, cluttered) tracked with the
# defaults and a camera-only XML, our tracker and ViSP's side by side, and the S40.23 build
# against the double one; the tracking status cases (noise, flat, covered, leaving the view);
# ViSP's real mbt/cube with its files as shipped, at 640x480 and QVGA, against ViSP's own edge
# tracker via `edgetrack compare`.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

mkdir -p "$bench_build_root"
work=$(mktemp -d "${TMPDIR:-/tmp}/tracking_eval.XXXXXX")
trap 'rm -rf "$work"' EXIT
bench=$(bench_tree host double edgetrack tracking_eval_me_offsets tracking_eval_clutter_dynamics bench_status_cases)
edgetrack=$bench/app/edgetrack
offsets=$bench/tests/bench/tracking_eval/tracking_eval_me_offsets
dynamics=$bench/tests/bench/tracking_eval/tracking_eval_clutter_dynamics
status_cases=$bench/tests/bench/tracking_eval/bench_status_cases
edgetrack_s40=$(bench_tree host s40_23 edgetrack)/app/edgetrack
if ! "$edgetrack" compare --help >/dev/null 2>&1; then
  echo "tracking_eval: edgetrack has no compare command (ViSP's mbt module not found at configure time)" >&2
  exit 1
fi
mbt=$visp_images/mbt
models=$top/data/models
fast_speed=4.2   # the paper's path 4.2 times faster: about 12 px per QVGA frame
cover_share=0.3
clutter_mm=3
clutter_offsets="3 5 8"   # mm beside the edges: where each tracker breaks
clutter_seeds="1 2 3"     # backdrops and noise: a clutter result must hold on each
reverse_frames=86   # there and back, turning at frame 43, where the fast path moves fastest

# value KEY FILE: the value of KEY=... on the first line of FILE that has it.
value() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" "$2" | head -n 1; }

# synth_kind NAME MODEL OPTIONS...: renders $work/NAME, keeps synth's report in $work/NAME.txt.
synth_kind() {
  local name=$1 model=$2
  shift 2
  "$edgetrack" synth --out "$work/$name" --model "$model" "$@" >"$work/$name.txt"
}

# uncertain_frames POSES.csv: the frames `track` reported uncertain.
uncertain_frames() { awk -F, 'NR > 1 && $10 == "uncertain"' "$1" | wc -l; }

# generated_row LABEL NAME MODEL: our `track` (its lost rule) and both trackers in `compare`;
# the S40.23 build's `track` against the double one's poses (their truth columns).
generated_row() {
  local label=$1 seq=$work/$2 model=$3
  local args=(--model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos"
              --images "$seq/frames/frame%04d.ppm" --quiet)
  "$edgetrack" track "${args[@]}" --poses "$work/poses.csv" >"$work/track.txt"
  "$edgetrack" eval --poses "$work/poses.csv" --truth "$seq/truth.csv" >"$work/eval.txt"
  "$edgetrack_s40" track "${args[@]}" --poses "$work/poses_s40.csv" >/dev/null
  cut -d, -f1-7 "$work/poses.csv" >"$work/double_poses.csv"
  "$edgetrack" eval --poses "$work/poses_s40.csv" --truth "$work/double_poses.csv" >"$work/s40.txt"
  "$edgetrack" compare --model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos" \
    --images "$seq/frames/frame%04d.ppm" --truth "$seq/truth.csv" 2>/dev/null >"$work/compare.txt"
  local motion share retried
  motion=$(sed -n 's/.*largest image motion \([0-9.]*\) px.*/\1/p' "$seq.txt")
  share=$(sed -n 's/.*covers \([0-9.]*\) % .*/\1 %/p' "$seq.txt")
  retried=$(sed -n 's/^ *\([0-9]*\) frames retried.*, \([0-9]*\) of them.*/\1 \/ \2/p' "$work/track.txt")
  printf '| %s | %s | %s | %d | %d | %s | %.3f | %.3f | %.3f | %.4f | %d | %.3f | %.3f | %.3f | %.3f / %.3f |\n' "$label" "$motion" \
    "${share:--}" "$(value lost "$work/eval.txt")" "$(uncertain_frames "$work/poses.csv")" "${retried:-0 / 0}" \
    "$(value distance_mm "$work/eval.txt")" \
    "$(value max_distance_mm "$work/eval.txt")" "$(value rotation_deg "$work/eval.txt")" \
    "$(value max_distance_mm "$work/s40.txt")" "$(value visp_lost "$work/compare.txt")" \
    "$(value visp_distance_mm "$work/compare.txt")" "$(value visp_max_distance_mm "$work/compare.txt")" \
    "$(value visp_rotation_deg "$work/compare.txt")" "$(value ours_median_ms "$work/compare.txt")" \
    "$(value visp_median_ms "$work/compare.txt")"
}

# mbt_row MODEL DOWNSCALE: `track` with cube.xml alone, then `compare`; "refused" with the reason.
mbt_row() {
  local model=$1 factor=$2 size
  [ "$factor" = 1 ] && size=640x480 || size=320x240
  local args=(--model "$mbt/$model" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos"
              --images "$mbt/cube/image%04d.pgm" --downscale "$factor")
  if ! "$edgetrack" track "${args[@]}" --poses "$work/mbt.csv" --quiet >/dev/null 2>"$work/track.err"; then
    printf '| %s | %s | refused: %s | | | | | | | | |\n' "$model" "$size" "$(sed 's/^edgetrack track: //; s/|/\\|/g' "$work/track.err" | head -n 1)"
    return
  fi
  local lost
  lost=$(awk -F, 'NR > 1 && $10 == "lost"' "$work/mbt.csv" | wc -l)
  "$edgetrack" compare "${args[@]}" --repeat 3 2>/dev/null >"$work/compare.txt"
  printf '| %s | %s | %d of %d | %d | %d | %d | %.2f | %.2f | %.3f | %.3f | %.0f / %.0f |\n' "$model" "$size" "$lost" \
    "$(value frames "$work/compare.txt")" "$(uncertain_frames "$work/mbt.csv")" "$(value ours_lost "$work/compare.txt")" \
    "$(value visp_lost "$work/compare.txt")" \
    "$(value corner_px "$work/compare.txt")" "$(value corner_max_px "$work/compare.txt")" \
    "$(value ours_median_ms "$work/compare.txt")" "$(value visp_median_ms "$work/compare.txt")" \
    "$(value ours_points "$work/compare.txt")" "$(value visp_points "$work/compare.txt")"
}

# ours_eval NAME MODEL OPTIONS...: `track` with OPTIONS, then `eval`, into $work/eval.txt.
ours_eval() {
  local seq=$work/$1 model=$2
  shift 2
  "$edgetrack" track --model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos" \
    --images "$seq/frames/frame%04d.ppm" --poses "$work/poses.csv" --quiet "$@" >/dev/null
  "$edgetrack" eval --poses "$work/poses.csv" --truth "$seq/truth.csv" >"$work/eval.txt"
}

# model_name MODEL: the model's name in the tables.
model_name() { [ "$1" = cube60 ] && echo "60 mm cube" || echo "wood toy"; }

# clutter_sequence MODEL MM: the sequence with clutter MM mm beside the edges (0: the slow one).
clutter_sequence() {
  if [ "$2" = 0 ]; then echo "${1}_slow"; elif [ "$2" = "$clutter_mm" ]; then echo "${1}_clutter"; else echo "${1}_clutter$2"; fi
}

# clutter_seed_sequence MODEL MM SEED: the clutter sequence with that backdrop and noise seed.
clutter_seed_sequence() {
  if [ "$3" = 1 ]; then clutter_sequence "$1" "$2"; else echo "${1}_clutter${2}_seed$3"; fi
}

# clutter_seed_row LABEL MM SEED NAME MODEL: ours with the defaults in both builds.
clutter_seed_row() {
  local label=$1 mm=$2 seed=$3 seq=$work/$4 model=$5
  local args=(--model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos"
              --images "$seq/frames/frame%04d.ppm" --quiet)
  ours_eval "$4" "$model"
  "$edgetrack_s40" track "${args[@]}" --poses "$work/poses_s40.csv" >/dev/null
  cut -d, -f1-7 "$work/poses.csv" >"$work/double_poses.csv"
  "$edgetrack" eval --poses "$work/poses_s40.csv" --truth "$work/double_poses.csv" >"$work/s40.txt"
  printf '| %s | %s | %s | %d | %.3f | %.3f | %.4f |\n' "$label" "$mm" "$seed" "$(value lost "$work/eval.txt")" \
    "$(value distance_mm "$work/eval.txt")" "$(value max_distance_mm "$work/eval.txt")" "$(value max_distance_mm "$work/s40.txt")"
}

# clutter_row LABEL MM NAME MODEL: ours with 1 and 3 hypotheses, and ViSP.
clutter_row() {
  local label=$1 mm=$2 seq=$work/$3 model=$4 cells=""
  for options in "" "--hypotheses 3"; do
    # shellcheck disable=SC2086
    ours_eval "$3" "$model" $options
    cells+=$(printf ' %d | %.3f | %.3f |' "$(value lost "$work/eval.txt")" "$(value distance_mm "$work/eval.txt")" \
      "$(value max_distance_mm "$work/eval.txt")")
  done
  "$edgetrack" compare --model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos" \
    --images "$seq/frames/frame%04d.ppm" --truth "$seq/truth.csv" 2>/dev/null >"$work/compare.txt"
  printf '| %s | %s | %s |%s %d | %.3f | %.3f |\n' "$label" "$mm" \
    "$(sed -n 's/.* \([0-9.]*\) px off them.*/\1/p' "$seq.txt")" "$cells" "$(value visp_lost "$work/compare.txt")" \
    "$(value visp_distance_mm "$work/compare.txt")" "$(value visp_max_distance_mm "$work/compare.txt")"
}

for model in cube60 wood_toy; do
  for mm in $clutter_offsets; do
    [ "$mm" = "$clutter_mm" ] || synth_kind "${model}_clutter$mm" "$models/$model.cao" --clutter "$mm"
  done
  for mm in $clutter_offsets; do
    for seed in $clutter_seeds; do
      [ "$seed" = 1 ] || synth_kind "${model}_clutter${mm}_seed$seed" "$models/$model.cao" --clutter "$mm" --seed "$seed"
    done
  done
  synth_kind "${model}_slow" "$models/$model.cao"
  synth_kind "${model}_fast" "$models/$model.cao" --speed "$fast_speed"
  synth_kind "${model}_cover" "$models/$model.cao" --cover "$cover_share"
  synth_kind "${model}_clutter" "$models/$model.cao" --clutter "$clutter_mm"
  synth_kind "${model}_reverse" "$models/$model.cao" --speed "$fast_speed" --reverse --frames "$reverse_frames"
done

echo "## Evaluation sequences: fast motion, occlusion, clutter, and ViSP's mbt/cube (tracking_eval)"
echo
echo "\`tests/bench/tracking_eval/results.sh\`: host double build, $(bench_machine)."
echo
echo "Generated by \`edgetrack synth\` (OSMesa, QVGA, px = py = 220, 60 frames, noise 2, blur 0.6 px):"
echo "\"slow\" is the paper's path; \"fast\" the same path $fast_speed times faster (\`--speed $fast_speed\`);"
echo "\"reversal\" that fast path there and back, $reverse_frames frames (\`--reverse --frames $reverse_frames\`): it turns at"
echo "frame $((reverse_frames / 2)), where it moves fastest, so the motion reverses at once by twice a frame's;"
echo "\"occluder\" a dark board in front sweeping across the object, sized each frame to cover"
echo "$cover_share of its image (\`--cover $cover_share\`); \"clutter\" dark lines parallel to every model edge,"
echo "$clutter_mm mm beside it (\`--clutter $clutter_mm\`, $(sed -n 's/.* \([0-9.]*\) px off them.*/\1/p' "$work/cube60_clutter.txt") px off the cube's edges in the first frame)."
echo "Both trackers start from the true first pose with their defaults and the camera-only XML that"
echo "synth writes. Ours: \`edgetrack track\` (its status: lost, uncertain) and \`edgetrack eval\`; \"retried\": the frames"
echo "it ran again from the last trusted pose / of those, the ones the retry tracked (docs/ARCHITECTURE.md);"
echo "\"S40.23 - double\": the largest per-frame distance between the camera positions of the S40.23 and"
echo "the double builds' \`track\`. ViSP 3.5's"
echo "vpMbGenericTracker (edge): \`edgetrack compare --truth\`, lost when track() throws. Errors: the"
echo "camera position in the object frame (mean and largest distance, mm) and the rotation (degrees);"
echo "median ms of each tracking call in \`compare\`."
echo
echo "| sequence | motion px/frame | covered | lost | uncertain | retried | mean mm | largest mm | rotation deg | S40.23 - double mm | ViSP lost | ViSP mean mm | ViSP largest mm | ViSP rotation deg | median ms ours / ViSP |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for model in cube60 wood_toy; do
  [ "$model" = cube60 ] && name="60 mm cube" || name="wood toy"
  generated_row "$name, slow" "${model}_slow" "$models/$model.cao"
  generated_row "$name, fast" "${model}_fast" "$models/$model.cao"
  generated_row "$name, reversal" "${model}_reverse" "$models/$model.cao"
  generated_row "$name, occluder" "${model}_cover" "$models/$model.cao"
  generated_row "$name, clutter" "${model}_clutter" "$models/$model.cao"
done
echo
echo "Tracking status (\`bench_status_cases\`, the cases of tests/tracker/status_cases.h, checked by"
echo "test_tracking_status.cxx): the generated QVGA cube (the test-image renderer) from the true first pose"
echo "with the defaults, with frames of uniform noise, of one flat grey, or of the background alone (the cube"
echo "fully covered); and leaving the view sideways, accelerating to about 9 px per frame. \"bad\": the"
echo "frames without a trackable object (leaving: from the first whose true pose leaves fewer than 6 control"
echo "points); \"missed\": bad frames not reported lost; \"wrongly lost\": lost frames outside the bad ones"
echo "(leaving: among the frames with the cube wholly in view); \"back\": frames from the object's return"
echo "to the first tracked within 1 mm of the truth (that frame), and the largest error from then on;"
echo "\"largest tracked mm\": the largest camera position error of a frame reported tracked."
echo "On the real sequences, where the overlay stays on the object, no frame is lost: \"track lost\" below."
echo
echo "| case | frames | bad | first lost | lost | uncertain | missed | wrongly lost | largest tracked mm | back | retried |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|"
"$status_cases"
echo
echo "ViSP's real mbt/cube (218 frames) with its files as shipped: \`cube.xml\` alone as \`--camera\`,"
echo "\`cube.0.pos\`, at 640x480 and halved to QVGA (\`--downscale 2\`: camera, sample step and range"
echo "halved for both trackers). \"track lost\", \"track uncertain\": \`edgetrack track\`'s lost and uncertain frames. Then \`edgetrack"
echo "compare --repeat 3\`: ViSP's tracker loads the same XML and .cao; ours takes the XML's <camera>"
echo "and <ecm>; the two alternate frame by frame; lost there: ours when the pose step fails, ViSP"
echo "when track() throws. Corner difference: the mean over frames of the mean distance between the"
echo "model's vertices projected with each tracker's pose (pixels of the tracked size), and its"
echo "largest frame. Times: median ms of the tracking call (ours \`Tracker::track\`, ViSP \`track()\`)."
echo
echo "| model | size | track lost | track uncertain | compare: ours lost | ViSP lost | corner px mean | corner px largest | ours ms | ViSP ms | control points ours / ViSP |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for model in cube.cao cube_and_cylinder.cao; do
  for factor in 1 2; do mbt_row "$model" "$factor"; done
done
echo
echo "Clutter at several distances (\`--clutter MM\`, the lines as above; px: their mean image distance from"
echo "the model's edges in the first frame), from the true first pose with the camera-only XML: ours with"
echo "the defaults (one edge hypothesis) and with \`--hypotheses 3\`; ViSP 3.5 as above. Lost, mean and"
echo "largest camera position error (mm). Then where the moving edges put their matches at the true poses"
echo "(\`tracking_eval_me_offsets\`, docs/ME.md): share within a pixel of the edge, mean offset outwards."
echo
echo "| sequence | clutter mm | px off edges | K=1 lost | K=1 mean mm | K=1 largest mm | K=3 lost | K=3 mean mm | K=3 largest mm | ViSP lost | ViSP mean mm | ViSP largest mm |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for model in cube60 wood_toy; do
  for mm in $clutter_offsets; do clutter_row "$(model_name "$model")" "$mm" "$(clutter_sequence "$model" "$mm")" "$models/$model.cao"; done
done
echo
echo "The same clutter over three backdrop and noise seeds (\`synth --seed\`; seed 1 is the row above), ours"
echo "with the defaults: lost, mean and largest camera position error (mm), and the largest per-frame distance"
echo "between the S40.23 and the double builds' camera positions (mm)."
echo
echo "| sequence | clutter mm | seed | lost | mean mm | largest mm | S40.23 - double mm |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for model in cube60 wood_toy; do
  for mm in $clutter_offsets; do
    for seed in $clutter_seeds; do
      clutter_seed_row "$(model_name "$model")" "$mm" "$seed" "$(clutter_seed_sequence "$model" "$mm" "$seed")" "$models/$model.cao"
    done
  done
done
echo
echo "Where the clutter error comes from (\`tracking_eval_clutter_dynamics\`, docs/ME.md): the mean over the"
echo "frames of the camera position error (mm) of the tracker run through the sequence (\"tracked\"), of each"
echo "frame solved alone from its own true pose with the contrasts taken there (\"alone\": what the moving"
echo "edges leave at that frame), of each frame solved after the previous one was solved from its true"
echo "pose (\"one step\"), and of alone's matches within a pixel of their edge solved again from the true pose"
echo "(\"near\": what is left were every match farther off known to be wrong, so what the edges' own"
echo "localisation beside the lines allows); double, the defaults. Seeds 1 / 2 / 3."
echo
echo "| sequence | clutter mm | tracked mm | alone mm | one step mm | near mm |"
echo "|---|---:|---|---|---|---|"
for model in cube60 wood_toy; do
  for mm in 0 $clutter_offsets; do
    seeds=$clutter_seeds; [ "$mm" = 0 ] && seeds=1
    tracked=() alone=() step=() near=()
    for seed in $seeds; do
      if [ "$mm" = 0 ]; then name=$(clutter_sequence "$model" 0); else name=$(clutter_seed_sequence "$model" "$mm" "$seed"); fi
      read -r _ t a o n < <("$dynamics" "$models/$model.cao" "$work/$name" | grep '^mean ')
      tracked+=("$t") alone+=("$a") step+=("$o") near+=("$n")
    done
    join() { local IFS=/; echo "$*" | sed 's|/| / |g'; }
    printf '| %s | %s | %s | %s | %s | %s |\n' "$(model_name "$model")" "$mm" "$(join "${tracked[@]}")" "$(join "${alone[@]}")" \
      "$(join "${step[@]}")" "$(join "${near[@]}")"
  done
done
echo
echo
echo "The lines are offset in 3D, away from the model's centre, so where that offset points along the line"
echo "of sight a line lands on its edge: \"line within 1.5 / 3 px\" is the share of the control points whose"
echo "line lies within its drawn width (1.5 px: edge and line one feature) and within the 5 px mask's"
echo "half + 1 (3 px: inside the edge's own response) in the image, over the frames at the true poses."
echo
echo "| sequence | clutter mm | strongest, no contrast test | strongest passing the contrast test (K=1) | nearest of 4 hypotheses, no contrast test | nearest of 4, with it | line within 1.5 / 3 px |"
echo "|---|---:|---|---|---|---|---:|"
for model in cube60 wood_toy; do
  for mm in 0 $clutter_offsets; do
    "$offsets" "$models/$model.cao" "$work/$(clutter_sequence "$model" "$mm")" "$mm" >"$work/offsets.txt"
    lines=$(sed -n 's/.* \([0-9.]*\) % within 1.5 px.* \([0-9.]*\) % within 3 px.*/\1 % \/ \2 %/p' "$work/offsets.txt")
    printf '| %s | %s |%s %s |\n' "$(model_name "$model")" "$mm" "$(sed -n 's/.*matches, \([0-9.]*\) % within a pixel of the edge, mean offset \([-+0-9.]*\) px outwards.*/ \1 %, \2 px |/p' "$work/offsets.txt" | tr -d '\n')" "${lines:--}"
  done
done
