#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/profile.md: where the tracker's time goes.
# Emulated PXA270 (ARM S40.23, the generated QVGA cube, default settings): guest instructions per
# frame and per step, then a flat profile per function (toolchains/qemu/count-insns.sh --profile),
# for the working tree and for each git revision in $PROFILE_REVISIONS (built from `git archive`
# in a temporary directory), so that a change's before and after sit side by side. Host (double,
# ViSP's mbt/cube at 640x480 with its cube.xml, the settings `edgetrack compare` uses): valgrind
# callgrind's instructions per function inside Tracker::track (perf's hardware counters are not
# available on this machine).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
frames=60
top_functions=25
host_frames=50
revisions=(${PROFILE_REVISIONS:-})
mbt=$visp_images/mbt

work=$(mktemp -d "${TMPDIR:-/tmp}/profile.XXXXXX")
trap 'rm -rf "$work"' EXIT
export EDGETRACK_PLUGIN_DIR=$work/plugin

# arm_bench REVISION: prints the path of an ARM S40.23 bench_tracker built from REVISION
# ("working tree": this checkout, in build/bench-arm-s40_23). Revisions are built one after the
# other in the same directories, so that a compiler cache finds what they share.
arm_bench() {
  if [ "$1" = "working tree" ]; then
    echo "$(bench_tree arm s40_23 bench_tracker)/tests/bench/tracker/bench_tracker"
    return
  fi
  local src=$work/src dir=$work/build
  rm -rf "$src" "$dir"
  mkdir -p "$src"
  git -C "$top" archive "$1" | tar -x -C "$src"
  cmake -S "$src" -B "$dir" -G Ninja -DEDGETRACK_REAL=s40_23 -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_TOOLCHAIN_FILE="$src/toolchains/armv5te-pxa270.cmake" >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; return 1; }
  cmake --build "$dir" --target bench_tracker >"$work/build.log" 2>&1 || { tail -n 40 "$work/build.log" >&2; return 1; }
  cp "$dir/tests/bench/tracker/bench_tracker" "$work/bench_tracker-$1"
  echo "$work/bench_tracker-$1"
}

labels=("${revisions[@]}" "working tree")
declare -A step_row profile_of
for label in "${labels[@]}"; do
  bench=$(arm_bench "$label")
  key=${label// /_}
  "$top/toolchains/qemu/count-insns.sh" --out "$work/$key.steps.sum" --windows "$work/$key.steps" \
    "$bench" "$frames" cube steps on-demand >/dev/null
  "$top/toolchains/qemu/count-insns.sh" --out "$work/$key.sum" --windows "$work/$key.frames" \
    --profile "$work/$key.profile" "$bench" "$frames" cube frame on-demand >/dev/null
  step_row[$label]=$(awk -v f="$frames" 'NR == FNR { split($3, a, "="); s[(FNR-1)%4] += a[2]; next }
    { split($3, a, "="); t += a[2] }
    END { printf "%.3f M | %.3f M | %.3f M | %.3f M | %.3f M", s[0]/f/1e6, s[1]/f/1e6, s[2]/f/1e6, s[3]/f/1e6, t/f/1e6 }' \
    "$work/$key.steps" "$work/$key.frames")
  profile_of[$label]=$work/$key.profile
done

echo "## Profile: where the tracker's instructions go"
echo
echo "\`tests/bench/profile/results.sh\` (revisions compared: ${PROFILE_REVISIONS:-none}), $(bench_machine),"
echo "$(qemu-arm --version | head -n 1 | sed 's/ (.*//') \`-cpu pxa270\`, $(date -u +%Y-%m-%d)."
echo
echo "### Emulated PXA270, S40.23: guest instructions per frame"
echo
echo "The generated QVGA cube, $frames frames, default TrackerParams (as in the tracker section): one count window"
echo "per step (\`bench_tracker $frames cube steps\`) and one per \`Tracker::track\` call (the total also holds"
echo "the status and prediction after the pose step)."
echo
echo "| build | visible edges | grey scaling | ME | pose | whole Tracker::track |"
echo "|---|---:|---:|---:|---:|---:|"
for label in "${labels[@]}"; do echo "| $label | ${step_row[$label]} |"; done
echo
echo "### Emulated PXA270, S40.23: the functions (flat profile)"
echo
echo "Guest instructions per frame spent in each function's own code (inlined callees included, called"
echo "functions not), and its calls per frame, from \`count-insns.sh --profile\`; the $top_functions largest of the"
echo "working tree, with the same functions in each compared revision."
echo
header="| function |" rule="|---|"
for label in "${labels[@]}"; do header+=" $label: instructions | calls |"; rule+="---:|---:|"; done
echo "$header"
echo "$rule"
# Function names, shortened: no argument lists, no template arguments of the scalar.
shorten() { sed -E 's/fixedpoint::fixed64<23>/real/g; s/\(anonymous namespace\):://g; s/\(.*//; s/^(void|int|long long|bool|real|double) //; s/<real[^>]*>//g'; }
current=${profile_of["working tree"]}
for label in "${labels[@]}"; do
  awk '{ n = $3; for (i = 4; i <= NF; ++i) n = n " " $i; print $1 "\t" $2 "\t" n }' "${profile_of[$label]}" |
    while IFS=$'\t' read -r insns calls name; do printf '%s\t%s\t%s\n' "$insns" "$calls" "$(printf '%s' "$name" | shorten)"; done |
    awk -F'\t' '{ i[$3] += $1; c[$3] += $2 } END { for (n in i) printf "%s\t%d\t%d\n", n, i[n], c[n] }' >"$work/${label// /_}.short"
done
sort -t$'\t' -k2,2nr "$work/working_tree.short" | head -n "$top_functions" | cut -f1 >"$work/top"
while IFS= read -r name; do
  row="| \`$name\` |"
  for label in "${labels[@]}"; do
    row+=$(awk -F'\t' -v n="$name" -v f="$frames" '$1 == n { printf " %.0f | %.1f |", $2 / f, $3 / f; found = 1 }
      END { if (!found) printf " 0 | 0 |" }' "$work/${label// /_}.short")
  done
  echo "$row"
done <"$work/top"
echo

echo "### Emulated PXA270, S40.23: by area, and the gap to the 2.0 M target"
echo
echo "The working tree's flat profile summed by area (the first matching rule names a function's area);"
echo "fixed-point routines kept out of line (the 128-bit multiply and divide) are counted on their own."
echo
echo "| area | instructions per frame | share |"
echo "|---|---:|---:|"
awk -F'\t' -v f="$frames" '
  function area(n) {
    if (n ~ /netlib::|euclidean_norm|dot_product|normal_equations_lm/) return "pose: least-squares solver (MINPACK lmder: QR, enorm, LM steps)"
    if (n ~ /PointToLineProblem|solve_once|solve_pose|tukey_weights|median_of|choose_nearest|to_strongest|rotation|so3_/) return "pose: residuals, Jacobian, weights and rotations"
    if (n ~ /operator\*/) return "3 x 3 matrix and vector products (every step)"
    if (n ~ /EdgeIdBuffer|clip_and_project|to_screen|project$|fill_triangle|draw_line|face_passes|FaceVisibility/) return "visible edges: Edge-ID fill, lines and face tests"
    if (n ~ /sample_segment|control_point|clip_to_view|keep_visible|shows/) return "visible edges: sampling the control points"
    if (n ~ /vpMe|convolve|moving_edges|refined_edge_point|me_search_box|normal_sign|sin_or_cos/) return "moving edges"
    if (n ~ /RGB565ToGrey|convert_to_grey|BoxGreyScaler|grey_scale/) return "grey conversion"
    if (n ~ /ContrastMemory/) return "contrast memory"
    if (n ~ /edge_support|gradient_normal_angle|arctangent_deg/) return "status: support of the outline in the image (edge_support.h)"
    if (n ~ /pose_uncertainty|pixel_gradient|whitened_square/) return "status: pose uncertainty"
    if (n ~ /Tracker::judge|judge_frame|MotionModel|largest_image_shift/) return "status: frame measures, judgement and prediction"
    if (n ~ /multiply_general|divide_general|sqrt|__udivmoddi4|__aeabi|operator\//) return "fixed-point multiply, divide, sqrt out of line"
    if (n ~ /^mem(set|cpy|move)/) return "memset, memcpy"
    return "other (shared geometry, bookkeeping)"
  }
  { a = area($1); t[a] += $2; total += $2 }
  END { for (k in t) printf "%s\t%.0f\t%.1f\n", k, t[k] / f, 100 * t[k] / total }' "$work/working_tree.short" |
  sort -t$'\t' -k2,2nr | awk -F'\t' '{ printf "| %s | %.0f | %.1f %% |\n", $1, $2, $3 }'
echo
awk -v f="$frames" '{ split($3, a, "="); t += a[2]; n++ } END {
  g = t / n - 2000000
  if (g > 0) printf "Whole Tracker::track: %.3f M per frame, %.3f M above the 2.0 M target.\n", t / n / 1e6, g / 1e6
  else printf "Whole Tracker::track: %.3f M per frame, within the 2.0 M target.\n", t / n / 1e6 }' "$work/working_tree.frames"
echo

# Host: callgrind inside Tracker::track on mbt/cube at 640x480.
host_dir=$(bench_tree host double edgetrack)
valgrind --tool=callgrind --callgrind-out-file="$work/host.cg" --toggle-collect='edgetrack::Tracker::track*' \
  "$host_dir/app/edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
  --images "$mbt/cube/image%04d.pgm" --last $((host_frames - 1)) --poses "$work/host.csv" --quiet >/dev/null 2>"$work/host.err"
callgrind_annotate "$work/host.cg" 2>/dev/null >"$work/host.txt"
total=$(sed -n 's/^ *\([0-9,]*\) .*PROGRAM TOTALS.*/\1/p' "$work/host.txt" | tr -d ,)
echo "### Host, double: instructions inside Tracker::track (callgrind)"
echo
echo "ViSP's mbt/cube, the first $host_frames frames at 640x480 with \`cube.xml\` (ViSP's settings), \`edgetrack track\`;"
echo "instructions per frame in each function's own code, as a share of Tracker::track's"
echo "($(awk -v t="$total" -v f="$host_frames" 'BEGIN { printf "%.2f M", t / f / 1e6 }') per frame)."
echo
echo "| function | instructions per frame | share |"
echo "|---|---:|---:|"
awk '/file:function/ { go = 1; next } go && /^ *[0-9,]+ / { print }' "$work/host.txt" | head -n 20 |
  while read -r count _ rest; do
    name=$(printf '%s' "$rest" | sed -E 's/^[^:]*://; s/ \[.*$//' | shorten)
    awk -v c="${count//,/}" -v t="$total" -v f="$host_frames" -v n="$name" \
      'BEGIN { printf "| `%s` | %.0f | %.1f %% |\n", n, c / f, 100 * c / t }'
  done
