#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# How often `detect` finds the generated cube with the default templates at each image size, and
# the size detection ran at: synth's first 10 frames (its path) rendered at each size with the
# same field of view (px = 0.6875 x width), one detect per frame, exit status 0 counted as found.
# The figures behind kMaxDetectionSide (tracker/include/edgetrack/detector/template_set.h).
# large_frames.sh EDGETRACK [WIDTHxHEIGHT...]
set -euo pipefail
edgetrack=$1
shift
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(640x480 960x720 1280x960 1920x1440 2560x1920)
model=$(cd "$(dirname "$0")/../../../data" && pwd)/models/cube60.cao
work=$(mktemp -d "${TMPDIR:-/tmp}/large_frames.XXXXXX")
trap 'rm -rf "$work"' EXIT
for size in "${sizes[@]}"; do
  width=${size%x*}
  height=${size#*x}
  # Supersampling as far as synth's render cap allows (16384 a side, 64 M pixels).
  supersample=4
  while [ $((width * height * supersample * supersample)) -gt $((64 << 20)) ]; do supersample=$((supersample - 1)); done
  dir=$work/$size
  mkdir -p "$dir"
  px=$(awk -v w="$width" 'BEGIN { printf "%.4f", 0.6875 * w }')
  printf '<?xml version="1.0"?>\n<conf><camera><u0>%s</u0><v0>%s</v0><px>%s</px><py>%s</py></camera></conf>\n' \
    $((width / 2)) $((height / 2)) "$px" "$px" >"$dir/camera.xml"
  "$edgetrack" synth --out "$dir/seq" --camera "$dir/camera.xml" --size "$size" --frames 10 \
    --supersample "$supersample" >/dev/null
  found=0
  at="$size"
  for k in $(seq 0 9); do
    if "$edgetrack" detect --model "$model" --camera "$dir/seq/camera.xml" \
      --image "$dir/seq/frames/frame$(printf %04d "$k").ppm" >"$dir/detect.txt"; then
      found=$((found + 1))
    fi
    reduced=$(sed -n 's/.*detecting at \(1\/[0-9]* size ([0-9x]*)\).*/\1/p' "$dir/detect.txt")
    [ -z "$reduced" ] || at=$reduced
  done
  echo "$size: detected at $at, found on $found of 10 frames"
done
