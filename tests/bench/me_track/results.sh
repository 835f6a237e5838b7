#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/me_track.md: ViSP's trackMeLine and trackMeEllipse
# set-ups (tests/ports/visp/track_me_*.cpp) on our vpMeLine / vpMeEllipse against Debian's ViSP 3.5,
# frame by frame (tests/host/visp/me_track_compare.sh), in the host double and S40.23 builds, and
# how far the ARM builds under QEMU (S40.23, soft-float double) are from the host build of their type;
# then the transformation classes against upstream on a grid of rotations (tests/host/visp/transforms.cpp).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

examples=(visp_example_track_me_line visp_example_track_me_ellipse)
upstream_targets=(track_me_line_upstream track_me_ellipse_upstream transforms_upstream transforms_ports)
host=$(bench_tree host double "${examples[@]}" "${upstream_targets[@]}")
host_s40=$(bench_tree host s40_23 "${examples[@]}" "${upstream_targets[@]}")
arm_s40=$(bench_tree arm s40_23 "${examples[@]}")
arm_double=$(bench_tree arm double "${examples[@]}")
sysroot=$(grep -m1 '^EDGETRACK_ARM_SYSROOT:' "$arm_s40/CMakeCache.txt" | cut -d= -f2 || true)
work=$(mktemp -d "${TMPDIR:-/tmp}/me_track.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "## Line and ellipse tracking: our port against ViSP 3.5 (me_track)"
echo
echo "\`tests/bench/me_track/results.sh\` on $(bench_machine); $(g++ --version | head -n 1); ARM runs on"
echo "$(qemu-arm --version | head -n 1 | sed 's/ (.*//'), \`-cpu pxa270\`."
echo
echo "ViSP's example set-ups without display or clicks: \`trackMeLine\` on ViSP-images/line (range 15,"
echo "threshold 15000, the line through (96, 191) and (122, 211), frames 1-29 after two passes on frame 1)"
echo "and \`trackMeEllipse\` on ViSP-images/ellipse-1 (range 20, sample step 10 degrees, threshold 15000,"
echo "five points, frames 1-50). Every site of every frame is compared by list position."
echo
for tree in "$host" "$host_s40"; do
  name=$(grep -m1 EDGETRACK_REAL: "$tree/CMakeCache.txt" | cut -d= -f2)
  echo "Host $name:"
  echo
  echo '```'
  "$top/tests/host/visp/me_track_compare.sh" "$tree/tests/host/visp/track_me_line_upstream" \
    "$tree/tests/ports/visp/visp_example_track_me_line" line 0.001 0.00001 0.01 || true
  "$top/tests/host/visp/me_track_compare.sh" "$tree/tests/host/visp/track_me_ellipse_upstream" \
    "$tree/tests/ports/visp/visp_example_track_me_ellipse" ellipse 0.1 0.0002 0.1 || true
  echo '```'
  echo
done

echo "ARM under QEMU against the host build of the same \`real\` (the same program; largest difference"
echo "of any printed number, over every frame and site):"
echo
for pair in "$arm_s40|$host_s40|S40.23" "$arm_double|$host|double (soft-float)"; do
  IFS='|' read -r arm_tree host_tree name <<<"$pair"
  for example in "${examples[@]}"; do
    qemu-arm -cpu pxa270 ${sysroot:+-L "$sysroot"} "$arm_tree/tests/ports/visp/$example" --sites >"$work/arm"
    "$host_tree/tests/ports/visp/$example" --sites >"$work/host"
    if cmp -s "$work/arm" "$work/host"; then
      verdict="identical"
    else
      verdict=$(paste -d' ' "$work/arm" "$work/host" | awk '{ h = NF / 2; for (c = 2; c <= h; c++) { d = $c - $(c + h);
        if (d < 0) d = -d; if (d > m) m = d } } END { printf "largest difference %.3g", m }')
    fi
    echo "- $name \`$example\`: $(wc -l <"$work/host") lines, $verdict"
  done
done
echo
echo "### Transformation classes against ViSP 3.5 (tests/host/visp/transforms_compare.sh)"
echo
echo "R(theta u), theta u back from R, the inverse of [R t], a transformed point and the pose vector,"
echo "for 6 axes and 8 angles from 0 to pi - 1e-6:"
echo
echo '```'
for tree in "$host" "$host_s40"; do
  name=$(grep -m1 EDGETRACK_REAL: "$tree/CMakeCache.txt" | cut -d= -f2)
  # tolerance and the real's resolution, as tests/host/visp/CMakeLists.txt
  tolerance=2e-5 resolution=1.1920928955078125e-07
  [ "$name" = double ] && tolerance=1e-9 resolution=0
  printf '%s: ' "$name"
  "$top/tests/host/visp/transforms_compare.sh" "$tree/tests/host/visp/transforms_upstream" \
    "$tree/tests/host/visp/transforms_ports" "$tolerance" "$resolution" || true
done
echo '```'

