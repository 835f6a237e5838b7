#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The README's first command: installs what is missing, builds edgetrack (host, and ARMv5TE
# soft-float with S40.23 fixed point), then runs the paper's experiments and writes everything
# under one folder (default out/, or the first argument):
#   synthetic/         the paper-like sequence (60 mm cube, QVGA, 60 frames, ~150 mm) rendered
#                      by `edgetrack synth`, tracked, evaluated against its ground truth, with
#                      plots like Fig. 4 and Fig. 5, the Table 1 summary and the overlay video
#   synthetic_arm_s40_23/  the same sequence tracked by the ARM build in S40.23 fixed point on
#                      qemu-arm -cpu pxa270, evaluated the same way
#   mbt_cube_640x480/  ViSP's real mbt/cube sequence (218 frames), tracked from cube.0.pos
#   mbt_cube_qvga/     the same, frames and camera halved to 320x240
#   real_ops.md        guest instructions per arithmetic operation for each `real` (the table
#                      that motivates fixed point)
# Builds go under build/ (EDGETRACK_BUILD_ROOT to change).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
out=$(mkdir -p "${1:-$top/out}" && cd "${1:-$top/out}" && pwd)

"$top/toolchains/install-deps.sh"
source "$top/tests/bench/lib.sh"
mbt=$visp_images/mbt
echo "== building edgetrack (host, double) and (ARMv5TE soft-float, s40_23)"
host=$(bench_tree host double edgetrack)
arm=$(bench_tree arm s40_23 edgetrack)
edgetrack="$host/app/edgetrack"
arm_edgetrack=(qemu-arm -cpu pxa270 -L /usr/arm-linux-gnueabi "$arm/app/edgetrack")


# run_track NAME EDGETRACK... TRACK-OPTIONS: tracks into $out/NAME, keeps the summary.
run_track() {
  local dir=$out/$1
  shift
  mkdir -p "$dir"
  "$@" --poses "$dir/poses.csv" | tee "$dir/table1.md"
}

echo "== synthetic sequence: render, track, evaluate"
syn=$out/synthetic
"$edgetrack" synth --out "$syn/sequence"
track_syn=(track --model "$top/data/models/cube60.cao" --camera "$syn/sequence/camera.xml"
  --init-pose "$syn/sequence/first.pos" --images "$syn/sequence/frames/frame%04d.ppm")
run_track synthetic "$edgetrack" "${track_syn[@]}" --overlay "$syn/overlay" --video "$syn/overlay.mp4"
"$edgetrack" eval --poses "$syn/poses.csv" --truth "$syn/sequence/truth.csv" --plots "$syn/plots" | tee "$syn/eval.txt"

echo "== synthetic sequence on the emulated PXA270 (ARMv5TE, soft-float, s40_23)"
run_track synthetic_arm_s40_23 "${arm_edgetrack[@]}" "${track_syn[@]}" --quiet
"$edgetrack" eval --poses "$out/synthetic_arm_s40_23/poses.csv" --truth "$syn/sequence/truth.csv" \
  --plots "$out/synthetic_arm_s40_23/plots" | tee "$out/synthetic_arm_s40_23/eval.txt"

track_cube=(track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos"
  --images "$mbt/cube/image%04d.pgm")
echo "== mbt/cube, 640x480"
run_track mbt_cube_640x480 "$edgetrack" "${track_cube[@]}" --overlay "$out/mbt_cube_640x480/overlay" \
  --video "$out/mbt_cube_640x480/overlay.mp4"
echo "== mbt/cube, QVGA"
run_track mbt_cube_qvga "$edgetrack" "${track_cube[@]}" --downscale 2 --overlay "$out/mbt_cube_qvga/overlay" \
  --video "$out/mbt_cube_qvga/overlay.mp4"

echo "== guest instructions per arithmetic operation"
"$top/tests/bench/real_ops/results.sh" | tee "$out/real_ops.md"

cat <<SUMMARY

Everything is under $out:
  synthetic/eval.txt, plots/fig4_time_per_frame.png, plots/fig5_camera_position.png,
  synthetic/table1.md, poses.csv, overlay/ and overlay.mp4   (host, double)
  synthetic_arm_s40_23/eval.txt, table1.md, poses.csv         (qemu-arm -cpu pxa270, S40.23)
  mbt_cube_640x480/ and mbt_cube_qvga/: table1.md, poses.csv, overlay/, overlay.mp4
  real_ops.md
SUMMARY
