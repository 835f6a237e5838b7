#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/camera_eval_cost.md (issue 26, point 6): what tracking
# through a lens costs, per step and per frame, beside the same scene through a pinhole. The
# generated QVGA cube (kud = -0.25) and wood toy (kud = +0.12), bench_tracker with the default
# TrackerParams (the paper's settings): guest instructions of the ARM S40.23 build on the emulated
# PXA270 (our QEMU plugin, one count window per step and one per frame) and instructions of the
# host double build (valgrind callgrind inside Tracker::track).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
frames=30   # the first 30 frames of the 60 the profile section counts: the emulator is slow

bench_scratch camera_cost
export EDGETRACK_PLUGIN_DIR=$work/plugin
arm=$(bench_tree arm s40_23 bench_tracker)/tests/bench/tracker/bench_tracker
host=$(bench_tree host double bench_tracker)/tests/bench/tracker/bench_tracker

# bench_args SCENE KUD [XML]: bench_tracker's arguments with the default settings (or XML's), the lens
# kud (0: none).
bench_args() { echo "$frames $1 %s on-demand 1 lmder ${3:--} $2"; }

# A rolling shutter read over one frame interval (<edgetrack><camera><readout>), the rest the defaults.
rolling_xml=$work/readout.xml
printf '<?xml version="1.0"?>\n<conf><edgetrack><camera><readout>1</readout></camera></edgetrack></conf>\n' >"$rolling_xml"

# arm_steps SCENE KUD [XML]: "visible grey ME pose whole" guest instructions per frame.
arm_steps() {
  local key=$work/arm.$1.$2.${3:+rolling}
  # shellcheck disable=SC2046
  "$top/toolchains/qemu/count-insns.sh" --out "$key.steps.sum" --windows "$key.steps" \
    "$arm" $(printf "$(bench_args "$1" "$2" "${3:-}")" steps) >/dev/null
  # shellcheck disable=SC2046
  "$top/toolchains/qemu/count-insns.sh" --out "$key.frames.sum" --windows "$key.frames" \
    "$arm" $(printf "$(bench_args "$1" "$2" "${3:-}")" frame) >/dev/null
  awk -v f="$frames" 'NR == FNR { split($3, a, "="); s[(FNR-1)%4] += a[2]; next } { split($3, a, "="); t += a[2] }
    END { printf "%.0f %.0f %.0f %.0f %.0f", s[0]/f, s[1]/f, s[2]/f, s[3]/f, t/f }' "$key.steps" "$key.frames"
}

# host_steps SCENE KUD: "visible grey ME pose whole" host instructions per frame.
host_steps() {
  local key=$work/host.$1.$2
  # shellcheck disable=SC2046
  valgrind --tool=callgrind --callgrind-out-file="$key.cg" --toggle-collect='edgetrack::Tracker::track*' \
    "$host" $(printf "$(bench_args "$1" "$2")" frame) >/dev/null 2>"$key.err"
  callgrind_steps "$key.cg" "$frames" | awk -F'|' '{ for (i = 1; i <= 6; ++i) { split($i, a, " "); n[i] = a[1] * 1e6 } }
    END { printf "%.0f %.0f %.0f %.0f %.0f", n[1], n[2], n[3], n[4], n[6] }'
}

# rows BUILD SCENE KUD PINHOLE LENS: the two table rows of one build, the lens's with its change.
rows() {
  local build=$1 scene=$2 kud=$3
  read -r -a pin <<<"$4"
  read -r -a lens <<<"$5"
  printf '| %s | %s | pinhole | %s | %s | %s | %s | %s |\n' "$build" "$scene" "${pin[@]}"
  local cells="" i
  for i in 0 1 2 3 4; do
    cells+=$(awk -v a="${pin[$i]}" -v b="${lens[$i]}" 'BEGIN { printf " %.0f (%+.1f %%) |", b, 100 * (b - a) / a }')
  done
  printf '| %s | %s | kud = %s |%s\n' "$build" "$scene" "$kud" "$cells"
}

declare -A kud_of=([cube]=-0.25 [toy]=0.12)
declare -A result
for scene in cube toy; do
  for kud in 0 "${kud_of[$scene]}"; do
    result[arm.$scene.$kud]=$(arm_steps "$scene" "$kud")
    result[host.$scene.$kud]=$(host_steps "$scene" "$kud")
  done
  result[arm.$scene.rolling]=$(arm_steps "$scene" 0 "$rolling_xml")
done

bench_heading "Real cameras: what the lens costs per frame (camera_eval_cost)" "ARM S40.23 and host double builds"
echo "$(qemu-arm --version | head -n 1 | sed 's/ (.*//') \`-cpu pxa270\`, $(date -u +%Y-%m-%d)."
echo
echo "\`bench_tracker $frames cube|toy ... kud\`: the generated QVGA cube and wood toy ($frames frames, the portable"
echo "test-scene renderer, RGB565), the default TrackerParams (the paper's settings), tracked through a pinhole"
echo "and, on frames rendered through ViSP's radial lens, with the lens given (kud = -0.25 for the cube, a"
echo "wide barrel; +0.12 for the toy, a pincushion). Instructions per frame in each of the paper's steps and"
echo "in the whole Tracker::track (which also holds the status and the prediction). PXA270: guest"
echo "instructions of the ARM S40.23 build under our QEMU plugin (one count window per step, one per frame);"
echo "host: instructions of the host double build inside Tracker::track (valgrind callgrind, inclusive"
echo "cost of each step's calls). The target of issue 26: at most +15 % per frame on the PXA270."
echo
echo "| build | scene | camera | visible edges | grey scaling | ME | pose | whole Tracker::track |"
echo "|---|---|---|---:|---:|---:|---:|---:|"
for build in arm host; do
  [ "$build" = arm ] && label="PXA270 S40.23" || label="host double"
  for scene in cube toy; do
    rows "$label" "$scene" "${kud_of[$scene]}" "${result[$build.$scene.0]}" "${result[$build.$scene.${kud_of[$scene]}]}"
  done
done
echo
echo "### The rolling-shutter step (\`<edgetrack><camera><readout>\`, \`track --readout\`)"
echo
echo "The same pinhole frames on the PXA270 with a readout of one frame interval: each control point moved to"
echo "its row's read time and the frame solved a second time with its own velocity (docs/ARCHITECTURE.md,"
echo "\"Rolling shutter\"). The frames are global-shutter renders, so this counts the step's work, not how a"
echo "rolling-shutter frame tracks (docs/results/camera_eval.md). The first two frames have no velocity yet and"
echo "are tracked as without it."
echo
echo "| build | scene | readout | visible edges | grey scaling | ME | pose | whole Tracker::track |"
echo "|---|---|---|---:|---:|---:|---:|---:|"
for scene in cube toy; do
  read -r -a pin <<<"${result[arm.$scene.0]}"
  read -r -a rolling <<<"${result[arm.$scene.rolling]}"
  printf '| PXA270 S40.23 | %s | 0 | %s | %s | %s | %s | %s |\n' "$scene" "${pin[@]}"
  cells=""
  for i in 0 1 2 3 4; do
    cells+=$(awk -v a="${pin[$i]}" -v b="${rolling[$i]}" 'BEGIN { printf " %.0f (%+.1f %%) |", b, 100 * (b - a) / a }')
  done
  printf '| PXA270 S40.23 | %s | 1 frame |%s\n' "$scene" "$cells"
done
