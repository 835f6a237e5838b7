#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# synth's camera effects through the command line, one case per call: camera_effects_test.sh
# EDGETRACK TMPDIR CASE. An exposure step changes the frames' levels by its factor from its
# frame on and not before; motion blur and rolling shutter change the frames and not the truth;
# everything at once through a lens is tracked, better with the lens given; bad values are refused.
set -u

# fail, expect_error, less, track_with_and_without_lens
source "$(dirname "$0")/cli_common.sh" "$@"

synth() { "$edgetrack" synth --supersample 1 "$@"; }

# grey_levels FILE: a binary QVGA PGM's pixels, one a line (synth's header is 15 bytes).
grey_levels() { tail -c $((320 * 240)) "$1" | od -An -v -tu1 -w1; }

case $name in
  synth_exposure_step_levels)
    synth --out "$work/plain" --frames 4 --noise 0 --blur 0 --pgm >/dev/null || fail "synth failed"
    synth --out "$work/step" --frames 4 --noise 0 --blur 0 --pgm --exposure 0:1,1:1,2:1.4 >"$work/out.txt" ||
      fail "synth --exposure failed"
    grep -q "brightness factor 1 on the first frame, 1.4 on the last" "$work/out.txt" || fail "no brightness line"
    cmp -s "$work/plain/frames/frame0001.pgm" "$work/step/frames/frame0001.pgm" || fail "frame 1, before the step, changed"
    cmp -s "$work/plain/truth.csv" "$work/step/truth.csv" || fail "the exposure changed the truth"
    # Where the brighter frame does not saturate, each level is 1.4 times the plain frame's.
    read -r ratio saturated <<<"$(paste <(grey_levels "$work/plain/frames/frame0002.pgm") \
      <(grey_levels "$work/step/frames/frame0002.pgm") |
      awk '$2 < 250 { a += $1; b += $2 } $2 >= 250 { s++ } END { printf "%.4f %d", b / a, s }')"
    echo "frame 2 over the plain frame: $ratio where unsaturated, $saturated pixels saturated"
    less 1.39 "$ratio" && less "$ratio" 1.41 || fail "levels $ratio times the plain frame's, expected 1.4" ;;
  synth_timing_changes_frames_not_truth)
    synth --out "$work/plain" --frames 3 --speed 4.2 --pgm >/dev/null || fail "synth failed"
    for effect in "--shutter 1" "--readout 1"; do
      # shellcheck disable=SC2086
      synth --out "$work/effect" --frames 3 --speed 4.2 --pgm $effect >"$work/out.txt" || fail "synth $effect failed"
      apart=$(sed -n 's/.* renders per frame, \([0-9.]*\) px apart.*/\1/p' "$work/out.txt")
      [ -n "$apart" ] && less "$apart" 1.0001 || fail "$effect: renders '$apart' px apart, expected at most 1"
      cmp -s "$work/plain/frames/frame0001.pgm" "$work/effect/frames/frame0001.pgm" && fail "$effect changed nothing"
      cmp -s "$work/plain/truth.csv" "$work/effect/truth.csv" || fail "$effect changed the truth"
    done
    echo "ok: frames changed, truth kept" ;;
  track_all_effects_through_lens)
    # A barrel lens, 12 px per frame, the shutter open and the rows read over the whole frame
    # interval, a 40 % exposure step and JPEG at 50: tracked with the lens given, none lost and
    # the lens still worth giving. The error is the rolling shutter's shear and the saturated
    # ramps of blurred edges after the step (tests/bench/camera_eval/results_causes.sh), not the lens.
    synth --out "$work/seq" --frames 12 --pgm --kud -0.25 --speed 4.2 --shutter 1 --readout 1 \
      --exposure 0:1,5:1,6:1.4 --jpeg 50 >/dev/null || fail "synth failed"
    track_with_and_without_lens "$work/seq" "frame%04d.pgm"
    echo "all effects at once: $lost_with frames lost, mean camera position error $with mm with the lens given, $without mm without"
    [ "$lost_with" = 0 ] || fail "$lost_with frames lost"
    less "$with" 2 || fail "mean error $with mm with the lens given, expected under 2 mm"
    less "$(awk -v a="$with" 'BEGIN { print 2 * a }')" "$without" || fail "the lens given does not halve the error" ;;
  error_synth_bad_camera_effects)
    expect_error "--shutter must be 0..1" "$edgetrack" synth --out "$work/seq" --shutter 1.5
    expect_error "--readout must be 0..1" "$edgetrack" synth --out "$work/seq" --readout -0.1
    expect_error "--jpeg must be a quality 1..100" "$edgetrack" synth --out "$work/seq" --jpeg 101
    expect_error "frames must be 0 or more and increasing" "$edgetrack" synth --out "$work/seq" --exposure 5:1,3:1.4 ;;
  *) fail "unknown case" ;;
esac
