#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `edgetrack compare` against Debian's ViSP on the first frames of mbt/cube (and of a generated colour
# sequence), one case per call:
# compare_test.sh EDGETRACK TMPDIR CASE. Both trackers must run, give finite figures and agree.
set -u

# fail, expect_error, less, check_poses
source "$(dirname "$0")/cli_common.sh" "$@"
models=$data/models

compare_cube() {
  "$edgetrack" compare --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
    --images "$mbt/cube/image%04d.pgm" "$@"
}

# field KEY: the value of KEY=... on the compare: line of $work/compare.txt.
field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" "$work/compare.txt"; }

# check_csv FILE ROWS MAX_PX: ROWS frames, every figure a finite number, times positive, no frame
# lost by either tracker, at least 50 control points each, the corner difference under MAX_PX.
check_csv() {
  awk -F, -v rows="$2" -v max_px="$3" '
    NR == 1 { next }
    {
      n++
      for (i = 1; i <= NF; i++) if ($i !~ /^-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?$/) { print "not a number: " $i; bad = 1 }
      if ($2 <= 0 || $3 <= 0) { print "frame " $1 ": a time is not positive"; bad = 1 }
      if ($4 < 50 || $5 < 50) { print "frame " $1 ": fewer than 50 control points"; bad = 1 }
      if ($6 != 0 || $7 != 0) { print "frame " $1 ": lost"; bad = 1 }
      if ($8 >= max_px) { print "frame " $1 ": corners " $8 " px apart"; bad = 1 }
    }
    END { if (n != rows) { print n " frames, expected " rows; bad = 1 } exit bad }' "$1"
}

case $name in
  compare_mbt_cube_first_frames)
    # 640x480, cube.xml's settings for both: the poses stay within a pixel or two of each other.
    compare_cube --last 9 --csv "$work/frames.csv" | tee "$work/compare.txt" || fail "compare failed"
    check_csv "$work/frames.csv" 10 2.0 || fail "per-frame figures"
    [ "$(field frames)" = 10 ] || fail "expected 10 frames"
    less "$(field corner_px)" 1.5 || fail "mean corner difference of 1.5 px or more"
    less 0 "$(field visp_median_ms)" || fail "no ViSP time" ;;
  compare_mbt_cube_qvga)
    compare_cube --last 9 --downscale 2 --repeat 2 --csv "$work/frames.csv" | tee "$work/compare.txt" ||
      fail "compare --downscale 2 failed"
    check_csv "$work/frames.csv" 10 2.0 || fail "per-frame figures"
    grep -q "10 frames of 320x240, 20 timed per tracker" "$work/compare.txt" || fail "not 10 QVGA frames timed twice" ;;
  compare_ours_as_track)
    # Our side of compare is `edgetrack track` with the XML as --camera and --config: the same poses.
    "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --config "$mbt/cube.xml" \
      --init-pose "$mbt/cube.0.pos" --images "$mbt/cube/image%04d.pgm" --last 9 --quiet --poses "$work/track.csv" ||
      fail "track failed"
    { echo "frame,tx,ty,tz,tux,tuy,tuz"; tail -n +2 "$work/track.csv" | cut -d, -f1-7; } >"$work/truth.csv"
    compare_cube --last 9 --truth "$work/truth.csv" | tee "$work/compare.txt" || fail "compare --truth failed"
    less "$(field ours_max_distance_mm)" 0.001 || fail "our poses in compare differ from track's"
    less "$(field visp_max_distance_mm)" 20 || fail "ViSP's camera position is 20 mm or more from ours" ;;
  compare_colour_as_track)
    # Colour frames: compare gives both trackers one grey conversion of each frame, made outside
    # the timed calls; ours must track it as `track` tracks the colour frame itself.
    "$edgetrack" synth --out "$work/seq" --model "$models/cube60.cao" --frames 6 --supersample 1 >/dev/null || fail "synth failed"
    "$edgetrack" track --model "$models/cube60.cao" --camera "$work/seq/camera.xml" --init-pose "$work/seq/first.pos" \
      --images "$work/seq/frames/frame%04d.ppm" --quiet --poses "$work/track.csv" || fail "track failed"
    { echo "frame,tx,ty,tz,tux,tuy,tuz"; tail -n +2 "$work/track.csv" | cut -d, -f1-7; } >"$work/truth.csv"
    "$edgetrack" compare --model "$models/cube60.cao" --camera "$work/seq/camera.xml" --init-pose "$work/seq/first.pos" \
      --images "$work/seq/frames/frame%04d.ppm" --truth "$work/truth.csv" | tee "$work/compare.txt" ||
      fail "compare on colour frames failed"
    [ "$(field frames)" = 6 ] || fail "expected 6 frames"
    less "$(field ours_max_distance_mm)" 0.001 || fail "our poses on colour frames in compare differ from track's" ;;
  error_compare_missing_model)
    expect_error "missing.cao" "$edgetrack" compare --model "$work/missing.cao" --camera "$mbt/cube.xml" \
      --init-pose "$mbt/cube.0.pos" --images "$mbt/cube/image%04d.pgm" ;;
  error_compare_missing_init_pose)
    expect_usage_error "edgetrack compare: --init-pose is required" \
      "$edgetrack" compare --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --images "$mbt/cube/image%04d.pgm" ;;
  *) fail "unknown case" ;;
esac
