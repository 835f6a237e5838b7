#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/tracking_eval_thin_lines.md (issue 27, drift in
# clutter): the thin-line test (tracker/include/edgetrack/thin_lines.h) as the drift check
# (drift_check.h, the default) and switched on as a filter, against no check, on the generated clutter sequences (the cube and the wood toy, dark lines 3,
# 5 and 8 mm beside every edge, three seeds) in the double and S40.23 builds, how well it tells the
# matches on the lines from those on the edges, and what it takes from ViSP's real sequences.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

mkdir -p "$bench_build_root"
bench_scratch thin_lines
bench=$(bench_tree host double edgetrack tracking_eval_drift_profiles tracking_eval_clutter_dynamics)
edgetrack=$bench/app/edgetrack
profiles=$bench/tests/bench/tracking_eval/tracking_eval_drift_profiles
dynamics=$bench/tests/bench/tracking_eval/tracking_eval_clutter_dynamics
edgetrack_s40=$(bench_tree host s40_23 edgetrack)/app/edgetrack
mbt=$visp_images/mbt
castel=$visp_images/mbt-depth/castel
castle_simu=$visp_images/mbt-depth/Castle-simu
models=$top/data/models
on=(--thin-lines enabled=1)
off=(--thin-lines check=0)
checked=()  # the defaults: the drift check, correcting

# track_eval EDGETRACK SEQUENCE MODEL OUT [TRACK ARGS...]: tracks a generated sequence from its first
# pose and evaluates it against its truth into OUT.eval; the poses in OUT.csv.
track_eval() {
  local tracker=$1 seq=$2 model=$3 out=$4
  shift 4
  "$tracker" track --model "$model" --camera "$seq/camera.xml" --init-pose "$seq/first.pos" \
    --images "$seq/frames/frame%04d.ppm" --poses "$out.csv" --quiet "$@" >/dev/null
  "$edgetrack" eval --poses "$out.csv" --truth "$seq/truth.csv" >"$out.eval"
}

# s40_apart NAME: the largest per-frame distance between the S40.23 run NAME_s40 and the double run NAME (mm).
s40_apart() {
  cut -d, -f1-7 "$work/$1.csv" >"$work/$1_poses.csv"
  "$edgetrack" eval --poses "$work/$1_s40.csv" --truth "$work/$1_poses.csv" >"$work/$1_s40.eval"
  bench_value max_distance_mm "$work/$1_s40.eval"
}

# clutter_row MODEL MM SEED: no check, the defaults (the drift check, correcting) and the test on as a filter,
# double and S40.23; each frame alone from its true pose (tracking_eval_clutter_dynamics).
clutter_row() {
  local model=$1 mm=$2 seed=$3 seq=$work/seq
  rm -rf "$seq"
  "$edgetrack" synth --out "$seq" --model "$models/$model.cao" --clutter "$mm" --seed "$seed" >/dev/null
  track_eval "$edgetrack" "$seq" "$models/$model.cao" "$work/off" "${off[@]}"
  track_eval "$edgetrack" "$seq" "$models/$model.cao" "$work/defaults" "${checked[@]}"
  track_eval "$edgetrack_s40" "$seq" "$models/$model.cao" "$work/defaults_s40" "${checked[@]}"
  track_eval "$edgetrack" "$seq" "$models/$model.cao" "$work/on" "${on[@]}"
  track_eval "$edgetrack_s40" "$seq" "$models/$model.cao" "$work/on_s40" "${on[@]}"
  local alone
  alone=$("$dynamics" "$models/$model.cao" "$seq" | awk '$1 == "mean" { print $3 }')
  local name="60 mm cube"
  [ "$model" = wood_toy ] && name="wood toy"
  printf '| %s | %s | %s | %.3f | %.3f | %.3f | %s | %s | %.3f | %.3f | %.3f | %s | %.3f | %.3f | %.3f |\n' "$name" "$mm" "$seed" \
    "$alone" "$(awk -v a="$alone" 'BEGIN { print 1.5 * a }')" "$(bench_value distance_mm "$work/off.eval")" \
    "$(bench_value lost "$work/defaults.eval")" \
    "$(awk -F, 'NR > 1 { u += ($10 == "uncertain") } END { print u + 0 }' "$work/defaults.csv")" \
    "$(bench_value distance_mm "$work/defaults.eval")" "$(bench_value max_distance_mm "$work/defaults.eval")" \
    "$(s40_apart defaults)" "$(bench_value lost "$work/on.eval")" "$(bench_value distance_mm "$work/on.eval")" \
    "$(bench_value max_distance_mm "$work/on.eval")" "$(s40_apart on)"
  [ "$seed" != 1 ] || "$profiles" "$models/$model.cao" "$seq" >"$work/profiles.$model.$mm.txt"
}

# real_row NAME MODEL CAMERA POS IMAGES [TRACK ARGS...]: points per frame and frames tracked with no
# check, the defaults' drift check (and the frames whose pose it changed) and the test on.
real_row() {
  local name=$1 model=$2 camera=$3 pos=$4 images=$5
  shift 5
  local cells="" run
  for run in off defaults on; do
    local extra=()
    [ "$run" = on ] && extra=("${on[@]}")
    [ "$run" = off ] && extra=("${off[@]}")
    [ "$run" = defaults ] && extra=("${checked[@]}")
    "$edgetrack" track --model "$model" --camera "$camera" --init-pose "$pos" --images "$images" \
      --poses "$work/real_$run.csv" --quiet "$@" "${extra[@]}" >/dev/null
    cells+=$(awk -F, 'NR > 1 { p += $8; n++; t += ($10 == "tracked") }
      END { printf " %.1f | %d of %d |", p / n, t, n }' "$work/real_$run.csv")
    [ "$run" = defaults ] && cells+=$(paste -d, <(cut -d, -f2-7 "$work/real_off.csv") <(cut -d, -f2-7 "$work/real_defaults.csv") |
      awk -F, 'NR > 1 { for (i = 1; i <= 6; ++i) if ($i != $(i + 6)) { n++; break } } END { printf " %d |", n }')
  done
  echo "| $name |$cells"
}

bench_heading "The thin-line test in clutter (tracking_eval_thin_lines)" "host double and S40.23 builds"
echo "The thin-line test (\`<edgetrack><thin_lines>\`; docs/ME.md, \"Thin lines beside the edges\") calls a match"
echo "on a line when its darker side comes back within a line's width. As a drift check (docs/ME.md,"
echo "\"The thin-line test as a drift check\"): a frame whose matches off the lines solve to a pose more than 3"
echo "standard deviations of its uncertainty away takes that pose (\`--thin-lines check=2\`, the default); \`--thin-lines check=0\` is no check;"
echo "\`--thin-lines enabled=1\` is the test as a filter (every line match dropped). Generated: \`edgetrack synth"
echo "--clutter MM --seed S\` (QVGA, 60 frames, dark lines MM mm beside every model edge), tracked from the true first"
echo "pose with the camera-only XML. \"alone\": the mean error of each frame solved alone from its true pose"
echo "without the check (\`tracking_eval_clutter_dynamics\`), and issue 27's target, 1.5 times it, for the mean"
echo "error; lost, uncertain, mean and largest camera position error (mm), and the largest per-frame distance"
echo "between the S40.23 and the double runs (mm)."
echo
echo "| sequence | clutter mm | seed | alone mm | target mm | no check: mean mm | check: lost | uncertain | mean mm | largest mm | S40.23 - double mm | filter: lost | mean mm | largest mm | S40.23 - double mm |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for model in cube60 wood_toy; do
  for mm in 3 5 8; do
    for seed in 1 2 3; do clutter_row "$model" "$mm" "$seed"; done
  done
done
echo
echo "How well it tells the line from the edge (\`tracking_eval_drift_profiles\`, seed 1, the test's settings):"
echo "the matches of the tracked run within a pixel of the true edge (\"right\") and beyond (\"wrong\"), and the"
echo "share of each the test calls a line."
echo
echo "| sequence | clutter mm | right | right called a line | wrong | wrong called a line |"
echo "|---|---:|---:|---:|---:|---:|"
for file in "$work"/profiles.*.txt; do
  model=$(basename "$file" .txt | cut -d. -f2) mm=$(basename "$file" .txt | cut -d. -f3)
  name="60 mm cube"
  [ "$model" = wood_toy ] && name="wood toy"
  awk -v name="$name" -v mm="$mm" '$1 == "tracked" {
      for (i = 2; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
      printf "| %s | %s | %d | %.1f %% | %d | %.1f %% |\n", name, mm, v["right"], 100 * v["right_lines"], v["wrong"],
        100 * v["wrong_lines"] }' "$file"
done
echo
echo "ViSP's real sequences from their given poses, with their files as shipped: control points in the pose"
echo "step per frame and frames reported tracked with no check, with the defaults' drift check (\`check=2\`; \"changed\": the"
echo "frames whose pose differs from no check's) and with the filter."
echo
echo "| sequence | no check: points | tracked | check: points | tracked | changed | filter: points | tracked |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
real_row "mbt/cube 640x480, cube.xml" "$mbt/cube.cao" "$mbt/cube.xml" "$mbt/cube.0.pos" "$mbt/cube/image%04d.pgm"
real_row "mbt/cube QVGA, cube.xml" "$mbt/cube.cao" "$mbt/cube.xml" "$mbt/cube.0.pos" "$mbt/cube/image%04d.pgm" --downscale 2
real_row "mbt/cube 640x480, cube_and_cylinder.cao" "$mbt/cube_and_cylinder.cao" "$mbt/cube.xml" "$mbt/cube.0.pos" \
  "$mbt/cube/image%04d.pgm"
real_row "mbt/cube QVGA, cube_and_cylinder.cao" "$mbt/cube_and_cylinder.cao" "$mbt/cube.xml" "$mbt/cube.0.pos" \
  "$mbt/cube/image%04d.pgm" --downscale 2
real_row "castel, chateau.xml" "$castel/chateau.cao" "$castel/chateau.xml" "$castel/chateau.0.pos" "$castel/castel/image_%04d.pgm"
real_row "Castle-simu, chateau.xml" "$castle_simu/Models/chateau.cao" "$castle_simu/Config/chateau.xml" \
  "$castle_simu/CameraPose/Camera_001.txt" "$castle_simu/Images"
