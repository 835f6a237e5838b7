#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `edgetrack calibrate` as a user runs it, one case per call: calibrate_test.sh EDGETRACK TMPDIR
# CASE. ViSP's own calibration images (a 6 x 6 grid of circles 34 mm apart, as ViSP's
# default-circles.cfg describes it) give a plausible camera whose files `track --intrinsics`
# reads; a frame without the target is named; bad command lines and inputs are one line each.
set -u

# fail, expect_error, expect_usage_error, less
source "$(dirname "$0")/cli_common.sh" "$@"

grids=$visp_images/calibration

calibrate_grids() {
  "$edgetrack" calibrate --target circles --count 6x6 --spacing 0.034 --visp "$work/camera.xml" \
    --opencv "$work/camera.yaml" "$@"
}

# value KEY FILE MODEL: the number after "KEY " on the line of MODEL (OpenCV, ...) in calibrate's output.
value() { sed -n "s/^calibrate: $3:.* $1 \([-0-9.]*\) .*/\1/p" "$2"; }

case $name in
  calibrate_visp_circle_grids)
    calibrate_grids --images "$grids/grid36-%02d.pgm" --overlay "$work/overlay" >"$work/out.txt" ||
      fail "calibrate failed"
    cat "$work/out.txt"
    grep -q "^calibrate: frames=4 rejected=0 " "$work/out.txt" || fail "expected the grid in all 4 images"
    rms=$(sed -n 's/.* rms_opencv=\([0-9.]*\) .*/\1/p' "$work/out.txt")
    less "$rms" 0.5 || fail "RMS reprojection error $rms px, expected under 0.5 px"
    # A plausible camera for 640x480: square pixels within 2 %, the principal point within 10 %
    # of the image's centre.
    px=$(value px "$work/out.txt" OpenCV) py=$(value py "$work/out.txt" OpenCV)
    u0=$(value u0 "$work/out.txt" OpenCV) v0=$(value v0 "$work/out.txt" OpenCV)
    awk -v px="$px" -v py="$py" 'BEGIN { r = px / py; exit !(r > 0.98 && r < 1.02 && px > 300 && px < 3000) }' ||
      fail "px $px and py $py are not a plausible camera"
    awk -v u="$u0" -v v="$v0" 'BEGIN { exit !(u > 256 && u < 384 && v > 192 && v < 288) }' ||
      fail "principal point $u0, $v0 far from the centre"
    [ "$(ls "$work/overlay"/overlay*.png | wc -l)" -eq 4 ] || fail "expected 4 overlay images"
    [ ! -e "$work/overlay/INCOMPLETE" ] || fail "the overlay is marked incomplete"
    grep -q "<type>perspectiveProjWithDistortion</type>" "$work/camera.xml" || fail "no distorted model in the ViSP file"
    head -n 1 "$work/camera.yaml" | grep -q "^%YAML:1.0" || fail "the OpenCV file is not cv::FileStorage YAML"
    echo "ok: px $px py $py u0 $u0 v0 $v0, $rms px RMS" ;;
  calibrate_files_read_by_track)
    # Both files on ViSP's mbt/cube frames, also 640x480: track reads each and tracks.
    calibrate_grids --images "$grids/grid36-%02d.pgm" >/dev/null || fail "calibrate failed"
    for file in camera.xml camera.yaml; do
      "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
        --images "$mbt/cube/image%04d.pgm" --last 4 --intrinsics "$work/$file" --poses "$work/$file.csv" --quiet \
        >/dev/null || fail "track --intrinsics $file failed"
      [ "$(wc -l <"$work/$file.csv")" -eq 6 ] || fail "expected 5 poses with $file"
    done
    echo "ok: track --intrinsics reads both files" ;;
  calibrate_names_rejected_frames)
    mkdir -p "$work/frames"
    cp "$grids"/grid36-0[1-4].pgm "$work/frames/"
    cp "$mbt/cube/image0000.pgm" "$work/frames/grid36-05.pgm"
    calibrate_grids --images "$work/frames" >"$work/out.txt" || fail "calibrate failed"
    grep -q "^calibrate: rejected grid36-05.pgm: target not found" "$work/out.txt" ||
      grep -q "^calibrate: rejected .*grid36-05.pgm: target not found" "$work/out.txt" || fail "the frame without the grid is not named"
    grep -q "^calibrate: frames=4 rejected=1 " "$work/out.txt" || fail "expected 4 frames kept, 1 rejected"
    # Every second frame: grid36-01, -03 and the frame without the grid, too few.
    expect_error "the target is in 2 frames, 3 or more are needed (not found in: $work/frames/grid36-05.pgm)" \
      calibrate_grids --images "$work/frames" --step 2
    echo "ok: the frame without the target named" ;;
  error_calibrate_missing_options)
    expect_usage_error "edgetrack calibrate: --count is required
edgetrack calibrate: --spacing is required
edgetrack calibrate: --opencv is required" \
      "$edgetrack" calibrate --images "$grids/grid36-%02d.pgm" --visp "$work/camera.xml" ;;
  error_calibrate_bad_values)
    expect_error "--count '6': expected COLUMNSxROWS" calibrate_grids --images "$grids/grid36-%02d.pgm" --count 6
    expect_error "--target 'dots': expected chessboard, circles or asymmetric-circles" \
      calibrate_grids --images "$grids/grid36-%02d.pgm" --target dots
    expect_error "--spacing must be 0.0001..10 metres" calibrate_grids --images "$grids/grid36-%02d.pgm" --spacing 0
    expect_error "--step must be 1 or more" calibrate_grids --images "$grids/grid36-%02d.pgm" --step 0
    [ ! -e "$work/camera.xml" ] && [ ! -e "$work/camera.yaml" ] || fail "a refused run wrote a file" ;;
  error_calibrate_target_not_found)
    # The chessboard asked for is in none of them: nothing written.
    expect_error "the target is in 0 frames, 3 or more are needed" \
      calibrate_grids --images "$grids/grid36-%02d.pgm" --target chessboard --count 9x6
    [ ! -e "$work/camera.xml" ] && [ ! -e "$work/camera.yaml" ] || fail "a failed run wrote a file"
    ls "$work" | grep -q partial && fail "a .partial file left"
    # The OpenCV file cannot be written (its directory is missing): neither file is left.
    expect_error "$work/missing/camera.yaml: cannot open the file for writing" calibrate_grids --images "$grids/grid36-%02d.pgm" \
      --opencv "$work/missing/camera.yaml"
    [ ! -e "$work/camera.xml" ] || fail "the ViSP file left without the OpenCV file"
    echo "ok" ;;
  *)
    fail "unknown case" ;;
esac
