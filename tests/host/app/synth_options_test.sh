#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The evaluation options of `edgetrack synth`, one case per call: synth_options_test.sh EDGETRACK
# TMPDIR CASE. What synth measures and prints (motion, covered share, clutter offset) must be
# what was asked for, --reverse turns back over the same poses; bad values are refused with one line; a fast sequence is tracked;
# a sequence through a lens (--kud) is tracked with its intrinsics.xml (--intrinsics), and a bad calibration refused.
set -u

# fail, expect_error, expect_usage_error, less, check_poses, track_with_and_without_lens
source "$(dirname "$0")/cli_common.sh" "$@"

synth() { "$edgetrack" synth --frames 10 --supersample 1 "$@"; }

case $name in
  synth_speed_scales_motion)
    synth --out "$work/slow" >"$work/slow.txt" || fail "synth failed"
    synth --out "$work/fast" --speed 2.5 >"$work/fast.txt" || fail "synth --speed failed"
    slow=$(sed -n 's/.*largest image motion \([0-9.]*\) px.*/\1/p' "$work/slow.txt")
    fast=$(sed -n 's/.*largest image motion \([0-9.]*\) px.*/\1/p' "$work/fast.txt")
    echo "largest motion: $slow px/frame, with --speed 2.5: $fast px/frame"
    ratio=$(awk -v a="$slow" -v b="$fast" 'BEGIN { printf "%.3f", b / a }')
    less 2.3 "$ratio" && less "$ratio" 2.7 || fail "motion ratio $ratio, expected about 2.5"
    [ "$(head -n 2 "$work/fast/truth.csv" | tail -n 1)" = "$(head -n 2 "$work/slow/truth.csv" | tail -n 1)" ] ||
      fail "the fast path does not start where the slow one does"
    [ "$(wc -l <"$work/fast/truth.csv")" -eq 11 ] || fail "expected 10 truth rows" ;;
  synth_reverse_turns_back)
    # 10 frames: poses 0..5 of the path, then back over 4..1.
    synth --out "$work/ahead" --frames 6 >/dev/null || fail "synth failed"
    synth --out "$work/seq" --reverse >/dev/null || fail "synth --reverse failed"
    [ "$(wc -l <"$work/seq/truth.csv")" -eq 11 ] || fail "expected 10 truth rows"
    pose() { sed -n "$(($2 + 2))p" "$1/truth.csv" | cut -d, -f2-; }
    [ "$(pose "$work/seq" 5)" = "$(pose "$work/ahead" 5)" ] || fail "frame 5 is not the path's pose 5 (the turn)"
    [ "$(pose "$work/seq" 6)" = "$(pose "$work/ahead" 4)" ] || fail "frame 6 is not the path's pose 4"
    [ "$(pose "$work/seq" 9)" = "$(pose "$work/ahead" 1)" ] || fail "frame 9 is not the path's pose 1"
    echo "ok: there and back" ;;
  synth_cover_measured)
    synth --out "$work/seq" --cover 0.3 | tee "$work/out.txt" || fail "synth --cover failed"
    read -r mean low high <<<"$(sed -n 's/.*covers \([0-9.]*\) % .*(\([0-9.]*\) to \([0-9.]*\) %).*/\1 \2 \3/p' "$work/out.txt")"
    less 29.99 "$low" && less "$high" 32 || fail "covered share $low..$high %, expected 30 to 32 %"
    less "$low" "$mean" || [ "$low" = "$mean" ] || fail "mean below the lowest" ;;
  synth_clutter_beside_edges)
    synth --out "$work/plain" >/dev/null || fail "synth failed"
    synth --out "$work/seq" --clutter 3 | tee "$work/out.txt" || fail "synth --clutter failed"
    read -r lines px <<<"$(sed -n 's/.*: \([0-9]*\) clutter lines .* \([0-9.]*\) px off them.*/\1 \2/p' "$work/out.txt")"
    [ "$lines" = 12 ] || fail "expected one line per cube edge (12), got $lines"
    less 1 "$px" && less "$px" 5 || fail "clutter $px px off the edges, expected a few"
    cmp -s "$work/plain/frames/frame0000.ppm" "$work/seq/frames/frame0000.ppm" && fail "the clutter is not drawn"
    cmp -s "$work/plain/truth.csv" "$work/seq/truth.csv" || fail "the clutter changed the truth"
    echo "ok: clutter drawn, truth unchanged" ;;
  track_fast_cube)
    # 12 px per QVGA frame over synth's cluttered backdrop: a good prediction, wide ranges that
    # reach background lines beside weak silhouette edges, and no frame lost for it.
    synth --out "$work/seq" --frames 20 --speed 4.2 >/dev/null || fail "synth --speed failed"
    "$edgetrack" track --model "$(dirname "$0")/../../../data/models/cube60.cao" --camera "$work/seq/camera.xml" \
      --init-pose "$work/seq/first.pos" --images "$work/seq/frames/frame%04d.ppm" --poses "$work/poses.csv" --quiet \
      >/dev/null || fail "track failed"
    "$edgetrack" eval --poses "$work/poses.csv" --truth "$work/seq/truth.csv" | tee "$work/eval.txt" || fail "eval failed"
    lost=$(sed -n 's/.* lost=\([0-9]*\) .*/\1/p' "$work/eval.txt")
    mm=$(sed -n 's/.* distance_mm=\([0-9.]*\) .*/\1/p' "$work/eval.txt")
    [ "$lost" = 0 ] || fail "$lost frames lost"
    less "$mm" 0.5 || fail "mean camera position error $mm mm, expected under 0.5 mm" ;;
  track_through_lens)
    # A barrel lens (kud = -0.25): tracked with synth's intrinsics.xml the error stays that of
    # a pinhole sequence; without it, the pinhole alone is millimetres off.
    synth --out "$work/seq" --kud -0.25 >/dev/null || fail "synth --kud failed"
    grep -q "<kud>-0.25</kud>" "$work/seq/intrinsics.xml" || fail "intrinsics.xml lacks the lens"
    track_with_and_without_lens "$work/seq" "frame%04d.ppm"
    echo "mean camera position error: $with mm with --intrinsics, $without mm without"
    less "$with" 0.3 || fail "$with mm with the lens given, expected under 0.3 mm"
    less 1 "$without" || fail "$without mm without the lens, expected over 1 mm" ;;
  error_intrinsics_rational)
    printf '%%YAML:1.0\nimage_width: 320\nimage_height: 240\ncamera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ 220., 0., 160., 0., 220., 120., 0., 0., 1. ]\ndistortion_coefficients: !!opencv-matrix\n   rows: 8\n   cols: 1\n   dt: d\n   data: [ -0.2, 0.05, 0., 0., 0., 0.3, 0., 0. ]\n' >"$work/rational.yml"
    synth --out "$work/seq" >/dev/null || fail "synth failed"
    expect_error "rational.yml:9: distortion_coefficients' rational" "$edgetrack" track \
      --model "$(dirname "$0")/../../../data/models/cube60.cao" --camera "$work/seq/camera.xml" \
      --intrinsics "$work/rational.yml" --init-pose "$work/seq/first.pos" --images "$work/seq/frames/frame%04d.ppm" ;;
  error_synth_bad_cover)
    expect_error "--cover must be a share" "$edgetrack" synth --out "$work/seq" --cover 1.5 ;;
  error_synth_bad_speed)
    expect_error "--speed must be 1..16" "$edgetrack" synth --out "$work/seq" --speed 0.5 ;;
  error_synth_bad_hide)
    expect_error "--hide '9:3': expected FIRST:LAST" "$edgetrack" synth --out "$work/seq" --hide 9:3 ;;
  error_synth_options_named)
    expect_usage_error "edgetrack synth: --size needs --camera" "$edgetrack" synth --out "$work/seq" --size 640x480
    expect_usage_error "edgetrack synth: --intrinsics-name needs --intrinsics" \
      "$edgetrack" synth --out "$work/seq" --intrinsics-name Camera
    expect_error "--kud and --intrinsics both give the lens: give one" \
      "$edgetrack" synth --out "$work/seq" --kud -0.2 --intrinsics "$work/none.xml"
    [ ! -e "$work/seq" ] || fail "synth wrote frames after a refused command line" ;;
  *) fail "unknown case" ;;
esac
