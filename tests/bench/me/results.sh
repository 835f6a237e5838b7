#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/me.md: the agreement of our moving edges with
# Debian's ViSP 3.5 (double and S40.23), host nanoseconds per vpMeSite::track() for ours and
# upstream in one run, and guest instructions on the emulated PXA270 per site and per frame.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

data=$visp_images
cube0="$data/mbt/cube/image0000.pgm"
mkdir -p "$bench_build_root"
host=$(bench_tree host double me_sites_ports me_sites_upstream)
host_s40=$(bench_tree host s40_23 me_sites_ports me_sites_upstream)
arm_double=$(bench_tree arm double me_insns)
arm_s40=$(bench_tree arm s40_23 me_insns)
work=$(mktemp -d "${TMPDIR:-/tmp}/me.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "## Moving edges: our port against ViSP 3.5 (me)"
echo
echo "\`tests/bench/me/results.sh\` on $(bench_machine); $(g++ --version | head -n 1); instruction counts"
echo "on $(qemu-arm --version | head -n 1 | sed 's/ (.*//'), \`-cpu pxa270\`, by \`toolchains/qemu/count-insns.sh\`."
echo
echo "### Agreement with upstream (tests/host/visp/me_compare.sh)"
echo
echo "Sites every 5–6 px on straight edges of visp-images-data's mbt/cube (frames 0–120, range 4 and 7)"
echo "and line (frames 1–20, range 7), snapped with \`track(I, &me, false)\`, then tracked frame to frame"
echo "while kept; a (site, frame) pair counts while either library still tracks the site."
echo
for tree in "$host" "$host_s40"; do
  name=$(grep -m1 EDGETRACK_REAL: "$tree/CMakeCache.txt" | cut -d= -f2)
  target=98; [ "$name" = double ] || target=95
  echo "Host $name (target ${target}%):"
  echo
  echo '```'
  "$top/tests/host/visp/me_compare.sh" "$tree/tests/host/visp/me_sites_upstream" \
    "$tree/tests/host/visp/me_sites_ports" "$target" || true
  echo '```'
  echo
done

echo "RGB24 to grey against upstream's \`vpImageConvert::RGBToGrey\` (host double):"
echo
echo '```'
"$top/tests/host/visp/me_compare.sh" "$host/tests/host/visp/me_sites_upstream" \
  "$host/tests/host/visp/me_sites_ports" grey || true
echo '```'
echo

echo "### Host nanoseconds per track() (range 7, mask 5, 128 sites on mbt/cube frame 0, contrast test on)"
echo
echo "| library | ns per track() |"
echo "|---|---|"
segments=(228,316,205,385,5 205,385,238,430,5 232,318,250,355,5 250,355,238,430,5 250,355,348,358,5
          238,430,318,445,5 348,358,320,445,5 232,318,330,330,5)
for pass in 1 2 3; do
  for side in upstream ports; do
    "$host/tests/host/visp/me_sites_$side" bench 7 "$cube0" 2000 "${segments[@]}" | awk -v s=$side '{print s, $2}'
  done
done >"$work/ns"
for side in upstream ports; do
  best=$(awk -v s=$side '$1 == s { if (b == "" || $2 < b) b = $2 } END { print b }' "$work/ns")
  label="ViSP 3.5 (Debian libvisp-me)"; [ $side = ports ] && label="ours (ports/visp, double)"
  echo "| $label | $best |"
done
echo
echo "Best of three interleaved passes of 2000 × 128 calls each, on a machine shared with other jobs."
echo

echo "### Guest instructions on the emulated PXA270"
echo
echo "| build | per track() (mean, min–max) | of which soft-float | whole RGB565 QVGA to grey | read boxes only (pixels converted) |"
echo "|---|---|---|---|---|"
for tree in "$arm_double" "$arm_s40"; do
  name=$(grep -m1 EDGETRACK_REAL: "$tree/CMakeCache.txt" | cut -d= -f2)
  "$top/toolchains/qemu/count-insns.sh" --out "$work/s.sum" --windows "$work/s.win" \
    "$tree/tests/bench/me/me_insns" sites "$cube0" >/dev/null
  "$top/toolchains/qemu/count-insns.sh" --out "$work/c.sum" --windows "$work/c.win" \
    "$tree/tests/bench/me/me_insns" convert "$cube0" >"$work/c.out"
  awk -v name="$name" -v conv="$(cat "$work/c.out")" '
    FILENAME ~ /s.win/ { split($3, i, "="); split($4, f, "="); t += i[2]; sf += f[2]; n++
                         if (n == 1 || i[2] < lo) lo = i[2]; if (i[2] > hi) hi = i[2]; next }
    { split($3, i, "="); w[++m] = i[2] }
    END { split(conv, c, " "); printf "| ARM %s | %.0f (%d–%d) | %.0f | %d | %d (%s of %s px) |\n",
          name, t / n, lo, hi, sf / n, w[1], w[2], c[6], c[8] }' "$work/s.win" "$work/c.win"
done
echo
points=$(awk '{ print $4 }' "$work/c.out")
echo "Per track(): 128 sites on mbt/cube frame 0 (640x480). Conversion: the tracker's grey step"
echo "(\`grey_conversion.h\`) on frame 0 halved to 320x240 RGB565, the whole frame, or only the read"
echo "boxes (\`me_search_box.h\`, \`BoxGreyScaler\`) of $points control points on the cube's edges (range 7,"
echo "mask 5); \`search_moving_edges\` finds the same matches in both grey images."
