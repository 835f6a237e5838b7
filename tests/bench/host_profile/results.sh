#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/host_profile.md: where the host tracker's
# instructions go at ViSP's settings, the work `edgetrack compare` times. valgrind's callgrind
# counts the instructions inside Tracker::track (repeatable on a shared machine, unlike times)
# for each step of the paper's table (the inclusive cost of the step's calls from
# Tracker::track) and per function, on mbt/cube (cube.cao and cube_and_cylinder.cao, 640x480 and
# QVGA, cube.xml) and the generated QVGA cube with cube.xml's <ecm>. The working tree and each git
# revision in $HOST_PROFILE_REVISIONS (built from `git archive` in a temporary directory).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
frames=50
top_functions=12
revisions=(${HOST_PROFILE_REVISIONS:-})
mbt=$visp_images/mbt

work=$(mktemp -d "${TMPDIR:-/tmp}/host_profile.XXXXXX")
trap 'rm -rf "$work"' EXIT

# host_edgetrack REVISION: prints the path of a host double edgetrack built from REVISION
# ("working tree": this checkout, in build/bench-host-double).
host_edgetrack() {
  if [ "$1" = "working tree" ]; then
    echo "$(bench_tree host double edgetrack)/app/edgetrack"
    return
  fi
  local src=$work/src dir=$work/build
  rm -rf "$src" "$dir"
  mkdir -p "$src"
  git -C "$top" archive "$1" | tar -x -C "$src"
  cmake -S "$src" -B "$dir" -G Ninja -DEDGETRACK_REAL=double -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; return 1; }
  cmake --build "$dir" --target edgetrack >"$work/build.log" 2>&1 || { tail -n 40 "$work/build.log" >&2; return 1; }
  cp "$dir/app/edgetrack" "$work/edgetrack-$1"
  echo "$work/edgetrack-$1"
}

# The generated cube, with the <ecm> of cube.xml (ViSP's settings) and synth's camera.
current=$(host_edgetrack "working tree")
"$current" synth --out "$work/cube60" --model "$top/data/models/cube60.cao" >/dev/null
awk -v ecm="$(sed -n '/<ecm>/,/<\/ecm>/p' "$mbt/cube.xml")" '{ print } /<conf>/ { print ecm }' \
  "$work/cube60/camera.xml" >"$work/cube60/visp.xml"

"$current" synth --out "$work/wood_toy" --model "$top/data/models/wood_toy.cao" >/dev/null
awk -v ecm="$(sed -n '/<ecm>/,/<\/ecm>/p' "$mbt/cube.xml")" '{ print } /<conf>/ { print ecm }' \
  "$work/wood_toy/camera.xml" >"$work/wood_toy/visp.xml"

runs=("mbt/cube.cao 640x480" "mbt/cube.cao QVGA" "mbt/cube_and_cylinder.cao 640x480" "mbt/cube_and_cylinder.cao QVGA"
      "generated 60 mm cube QVGA" "generated wood toy QVGA")
# run_args RUN: the track arguments of one run.
run_args() {
  case "$1" in
    "generated wood toy"*) echo "--model $top/data/models/wood_toy.cao --camera $work/wood_toy/visp.xml" \
      "--init-pose $work/wood_toy/first.pos --images $work/wood_toy/frames/frame%04d.ppm" ;;
    generated*) echo "--model $top/data/models/cube60.cao --camera $work/cube60/visp.xml --init-pose $work/cube60/first.pos" \
      "--images $work/cube60/frames/frame%04d.ppm" ;;
    *) local model=${1#mbt/} && model=${model%% *}
       local factor=1 && [ "${1##* }" = QVGA ] && factor=2
       echo "--model $mbt/$model --camera $mbt/cube.xml --init-pose $mbt/cube.0.pos --images $mbt/cube/image%04d.pgm" \
         "--downscale $factor" ;;
  esac
}

labels=("${revisions[@]}" "working tree")
declare -A step_row points
for label in "${labels[@]}"; do
  edgetrack=$(host_edgetrack "$label")
  for run in "${runs[@]}"; do
    key="${label// /_}.${run//[ \/]/_}"
    # shellcheck disable=SC2046
    valgrind --tool=callgrind --callgrind-out-file="$work/$key.cg" --toggle-collect='edgetrack::Tracker::track*' \
      "$edgetrack" track $(run_args "$run") --last $((frames - 1)) --poses "$work/$key.csv" --quiet >/dev/null 2>"$work/$key.err"
    step_row[$label.$run]=$(callgrind_steps "$work/$key.cg" "$frames")
    # The control points per frame: the mean of the poses CSV's points column (matches kept).
    points[$label.$run]=$(awk -F, 'NR > 1 { s += $8; n++ } END { printf "%.1f", s / n }' "$work/$key.csv")
  done
done

echo "## Host profile: instructions per frame at ViSP's settings (host_profile)"
echo
echo "\`tests/bench/host_profile/results.sh\` (revisions compared: ${revisions[*]:-none}), host double build, $(bench_machine)."
echo
echo "valgrind callgrind inside Tracker::track, \`edgetrack track\` on the first $frames frames: ViSP's mbt/cube"
echo "with its cube.xml (step 4 px, range 7; QVGA: \`--downscale 2\`, step and range halved), and the generated"
echo "QVGA cube and wood toy (\`edgetrack synth\`, RGB frames, converted on demand inside Tracker::track;"
echo "\`edgetrack compare\` hands both trackers grey frames instead, so its times hold no grey scaling) with"
echo "cube.xml's <ecm>. Per step: the inclusive cost of the"
echo "calls Tracker::track makes for it (visible edges: Edge-ID rendering, sampling, visibility, contrast"
echo "references; grey scaling; ME: the moving-edge search and refinement; pose: the robust LM solve);"
echo "other: the frame's status and prediction, the drift check (on by default: the thin-line test, its gate and"
echo "its second solves; docs/ME.md), and Tracker::track's own code."
echo
echo "| sequence | build | visible edges | grey scaling | ME | pose | other | whole Tracker::track |"
echo "|---|---|---:|---:|---:|---:|---:|---:|"
for run in "${runs[@]}"; do
  for label in "${labels[@]}"; do echo "| $run | $label | ${step_row[$label.$run]} |"; done
done
echo
echo "### Edge-ID's render per frame, working tree: its parts"
echo
echo "Inclusive instructions per frame of the calls EdgeIdBuffer::render makes (edge_id_buffer.h), and the"
echo "render's share of Tracker::track: the surfaces under the lines (find_nearest_surfaces, which"
echo "draw_segments calls for each line), the cylinders' facets projected (collect_cylinder_sides), the faces'"
echo "triangles, the lines, drawing them (draw_segments without find_nearest_surfaces) and clearing the last"
echo "frame's."
echo
echo "| sequence | nearest surfaces | cylinder sides | faces | lines | draw | clear | whole render | share of the frame |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for run in "${runs[@]}"; do
  key="working_tree.${run//[ \/]/_}"
  callgrind_annotate --tree=calling --inclusive=yes "$work/$key.cg" 2>/dev/null | awk -v f="$frames" -v run="$run" '
    /\*  .*edgetrack::Tracker::track\(/ { gsub(",", "", $1); frame = $1 }
    /\*  .*edgetrack::EdgeIdBuffer::render\(/ { gsub(",", "", $1); whole = $1; go = 1; next }
    /\*  .*edgetrack::EdgeIdBuffer::draw_segments\(/ { in_draw = 1; next }
    (go || in_draw) && /^ *$/ { go = 0; in_draw = 0 }
    # find_nearest_surfaces is a function of its own, called by draw_segments: its inclusive count
    # is the nearest surfaces, and comes off the draw.
    in_draw && / >   / && /find_nearest_surfaces/ { c = $1; gsub(",", "", c); part["n"] += c; part["d"] -= c }
    go && / >   / {
      c = $1; gsub(",", "", c)
      if ($0 ~ /collect_cylinder_sides/) part["y"] += c
      else if ($0 ~ /collect_faces/) part["f"] += c
      else if ($0 ~ /collect_segments/) part["l"] += c
      else if ($0 ~ /draw_segments/) part["d"] += c
      else if ($0 ~ /clear_lines/) part["c"] += c
    }
    END {
      printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.1f %% |\n", run, part["n"] / f, part["y"] / f,
        part["f"] / f, part["l"] / f, part["d"] / f, part["c"] / f, whole / f, 100 * whole / frame
    }'
done
echo
echo "### Per control point"
echo
echo "The same counts over the control points matched per frame (the mean of the poses' points column):"
echo "instructions per control point in each step, and in the whole Tracker::track."
echo
echo "| sequence | build | control points per frame | ME | pose | visible edges | whole Tracker::track |"
echo "|---|---|---:|---:|---:|---:|---:|"
for run in "${runs[@]}"; do
  for label in "${labels[@]}"; do
    echo "${step_row[$label.$run]}" | awk -F'|' -v run="$run" -v label="$label" -v n="${points[$label.$run]}" '
      function per_point(field) { split(field, part, " "); return sprintf("%.0f", part[1] * 1e6 / n) }
      { printf "| %s | %s | %s | %s | %s | %s | %s |\n", run, label, n, per_point($3), per_point($4), per_point($1),
          per_point($6) }'
  done
done
for run in "mbt/cube.cao 640x480" "mbt/cube_and_cylinder.cao 640x480" "generated wood toy QVGA"; do
  key="working_tree.${run//[ \/]/_}"
  total=$(callgrind_annotate "$work/$key.cg" 2>/dev/null | sed -n 's/^ *\([0-9,]*\) .*PROGRAM TOTALS.*/\1/p' | tr -d ,)
  echo
  echo "### $run, working tree: the $top_functions largest functions"
  echo
  echo "Instructions per frame in each function's own code (inlined callees included), per control point"
  echo "(${points[working tree.$run]} per frame), and its share of Tracker::track."
  echo
  echo "| function | instructions per frame | per control point | share |"
  echo "|---|---:|---:|---:|"
  callgrind_annotate "$work/$key.cg" 2>/dev/null |
    awk -v n="$top_functions" '/file:function/ { go = 1; next } go && /^ *[0-9,]+ / && shown++ < n { print }' |
    while read -r count _ rest; do
      name=$(echo "$rest" | sed 's/^[^:]*://; s/ \[.*//; s/(anonymous namespace):://g; s/(.*//')
      awk -v c="${count//,/}" -v t="$total" -v f="$frames" -v n="$name" -v p="${points[working tree.$run]}" \
        'BEGIN { printf "| `%s` | %.0f | %.0f | %.1f %% |\n", n, c / f, c / f / p, 100 * c / t }'
    done
done

# work_kind FUNCTION: the kind of work a function's own instructions do (the table below).
work_kind_awk='
  function kind(f) {
    if (f ~ /netlib::/) return "MINPACK (QR, norms, LM steps)"
    if (f ~ /vpMeResponse::|MaskResponse::|padded_windows_/) return "moving-edge mask responses"
    if (f ~ /search_moving_edges|search_sites|refined_edge_point|ridge_on_line|me_search_box|normal_mask/) return "moving-edge search and refinement"
    if (f ~ /PointToLineProblem|solve_pose|solve_once|kth_smallest|median_of|tukey|rotation_exp|so3_|choose_nearest/) return "pose problem (residuals, Jacobian, weights, medians)"
    if (f ~ /EdgeIdBuffer|setup_triangle|draw_line|walk_line|clip_|project_vertex|cylinder_rim_boxes|in_front_of_near_plane|contour|on_guard_band/) return "Edge-ID rendering"
    if (f ~ /check_drift|thin_line|excluded_pull|to_perturbation|hold_marks|give_back_marks|mark_outliers_at|largest_overlay_distance/) return "drift check (thin-line test, gate; its second solves count as pose and MINPACK)"
    if (f ~ /edge_support|support_in_lanes|project_points|pose_uncertainty|pixel_gradient|sum_information|InformationSum|factor_at|judge|conclude|Status/) return "status (edge support, pose uncertainty)"
    if (f ~ /ContrastMemory/) return "contrast memory"
    if (f ~ /sample_|keep_visible|FaceVisibility/) return "control points (sampling, visibility tests)"
    return "other (grey scaling, prediction, the track call itself, allocation)"
  }'
echo
echo "### Where the remaining instructions go, by kind of work"
echo
echo "The own instructions of every function inside Tracker::track (as in the tables above), summed by the"
echo "kind of work they do, per frame and per control point, at ViSP's settings (the mbt runs' share of the"
echo "frame in brackets). The sentence under the table is computed from the same counts."
echo
echo "| kind of work | mbt/cube.cao 640x480 | mbt/cube_and_cylinder.cao 640x480 |"
echo "|---|---:|---:|"
kinds=$work/kinds
: >"$kinds"
for run in "mbt/cube.cao 640x480" "mbt/cube_and_cylinder.cao 640x480"; do
  key="working_tree.${run//[ \/]/_}"
  callgrind_annotate --threshold=100 "$work/$key.cg" 2>/dev/null |
    awk -v run="$run" -v f="$frames" -v p="${points[working tree.$run]}" "$work_kind_awk"'
      /file:function/ { go = 1; next }
      go && /^ *[0-9,]+ / { c = $1; gsub(",", "", c); name = $0; sub(/^[^:]*:/, "", name); part[kind(name)] += c; total += c }
      END { for (k in part) printf "%s\t%s\t%.0f\t%.0f\t%.1f\n", run, k, part[k] / f, part[k] / f / p, 100 * part[k] / total }' >>"$kinds"
done
sort -t$'\t' -k2,2 "$kinds" | awk -F'\t' '
  { row[$2] = row[$2] sprintf(" %s per frame, %s per point (%s %%) |", $3, $4, $5); if (!($2 in order)) order[$2] = ++n; cube[$2] += ($1 ~ /_and_/) ? $3 : 0 }
  END { for (k in row) printf "%d\t| %s |%s\n", -cube[k], k, row[k] }' | sort -n | cut -f2
echo
awk -F'\t' '$1 ~ /_and_/ { print $5 "\t" $2 }' "$kinds" | sort -rn | head -n 3 | awk -F'\t' '
  NR == 1 { largest = $1 }
  { parts = parts (NR > 1 ? (NR == 3 ? " and " : ", ") : "") sprintf("%s (%s %%)", $2, $1) }
  END {
    printf "On mbt/cube_and_cylinder.cao the largest kinds are %s of the frame%s\n", parts,
      largest < 50 ? ": no kind of work holds half of it, the rest is spread over the steps of the paper." : "."
  }'
