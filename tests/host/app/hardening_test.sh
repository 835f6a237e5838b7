#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# One class of bad input per call: hardening_test.sh EDGETRACK TMPDIR CASE. Each case must end in
# one line on stderr naming the input and the problem, a non-zero exit, no abort (status 134 or
# a signal) and, for outputs, no partial file under the name of a complete one.
set -u
source "$(dirname "$0")/cli_common.sh" "$@"

track() {
  "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" --quiet "$@"
}
poses_header="frame,tx,ty,tz,tux,tuy,tuz,points,ms,status"
truth_header="frame,tx,ty,tz,tux,tuy,tuz"

case $name in
  images_name_too_long)
    long=$(printf 'a%.0s' $(seq 1 300))
    expect_error "File name too long" track --images "$work/$long/frame%04d.pgm" --last 1
    expect_error "File name too long" track --images "$work/$long" ;;
  images_directory_not_enterable)
    [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null || { echo "skipped: needs root to drop to nobody"; exit 0; }
    mkdir -p "$work/locked/inner" && chmod 700 "$work/locked" && chmod 755 "$work"
    expect_error "$work/locked/inner" setpriv --reuid=nobody --regid=nogroup --clear-groups "$edgetrack" track \
      --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" --images "$work/locked/inner" ;;
  image_is_a_device_or_directory)
    mkdir -p "$work/frames/frame0000.pgm"
    expect_error "$work/frames/frame0000.pgm: is a directory" track --images "$work/frames/frame%04d.pgm" --last 0
    ln -s /dev/zero "$work/zero.pgm"
    expect_error "$work/zero.pgm: is not a regular file" track --images "$work/zero.pgm" ;;
  image_too_large)
    printf 'P5\n100000 100000\n255\n' >"$work/huge.pgm"
    expect_error "$work/huge.pgm:2: image size 100000x100000 is outside" track --images "$work/huge.pgm"
    printf 'P5\n16384 16384\n255\n' >"$work/area.pgm"
    expect_error "$work/area.pgm:2: image size 16384x16384 is outside" track --images "$work/area.pgm" ;;
  size_options_bounded)
    expect_error "option --size asks for 100000x100000" "$edgetrack" edgeid --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --size 100000x100000 --poses "$work/none.csv"
    expect_error "option --raw-size asks for 99999999999x2: sides must be at most 16384" track --images "$work/f.rgb565" \
      --raw-size 99999999999x2 ;;
  frame_range_checked)
    expect_error "option --first needs a frame number (0 or more), not '-1'" track --images "$mbt/cube/image%04d.pgm" --first -1
    expect_error "--first 5 is after --last 2" track --images "$mbt/cube/image%04d.pgm" --first 5 --last 2 ;;
  directory_frames_numbered_by_name)
    mkdir -p "$work/dir"
    for i in 3 4 5 6; do ln -s "$mbt/cube/image000$i.pgm" "$work/dir/image000$i.pgm"; done
    track --images "$work/dir" --first 4 --last 5 --poses "$work/poses.csv" >/dev/null || fail "track failed"
    frames=$(tail -n +2 "$work/poses.csv" | cut -d, -f1 | tr '\n' ' ')
    [ "$frames" = "4 5 " ] || fail "frames '$frames', expected '4 5 ' (numbers from the names)"
    echo "ok: frames $frames" ;;
  failed_run_leaves_no_complete_file)
    mkdir -p "$work/seq"
    for i in 0 1 2; do ln -s "$mbt/cube/image000$i.pgm" "$work/seq/image000$i.pgm"; done
    echo "broken" >"$work/seq/image0003.pgm"
    expect_error "$work/seq/image0003.pgm:1: not a PGM or PPM image" track --images "$work/seq/image%04d.pgm" \
      --poses "$work/poses.csv"
    [ ! -e "$work/poses.csv" ] || fail "a failed run left poses.csv"
    [ -s "$work/poses.csv.partial" ] || fail "the rows written before the failure are not kept in poses.csv.partial"
    echo "ok: only poses.csv.partial"
    expect_error "$work/seq/image0003.pgm:1: not a PGM or PPM image" track --images "$work/seq/image%04d.pgm" \
      --video "$work/overlay.mp4"
    [ ! -e "$work/overlay.mp4" ] || fail "a failed run left overlay.mp4"
    expect_error "$work/seq/image0003.pgm:1: not a PGM or PPM image" track --images "$work/seq/image%04d.pgm" \
      --overlay "$work/frames"
    [ -e "$work/frames/INCOMPLETE" ] || fail "a failed run's overlay directory does not say it is incomplete"
    [ -s "$work/overlay.partial.mp4" ] || fail "no overlay.partial.mp4"
    track --images "$work/seq/image%04d.pgm" --last 2 --video "$work/done.mp4" --overlay "$work/done" ||
      fail "track --video failed"
    [ -s "$work/done.mp4" ] && [ ! -e "$work/done.partial.mp4" ] || fail "a complete run did not name its video"
    [ ! -e "$work/done/INCOMPLETE" ] && [ -e "$work/done/overlay0002.png" ] || fail "a complete overlay directory is marked"
    echo "ok: a video is named only when complete" ;;
  video_refusal_is_one_line)
    expect_error "a video is written as .mp4, .avi, .mkv or .mov, not '.xyz'" track --images "$mbt/cube/image%04d.pgm" \
      --last 2 --video "$work/x.xyz"
    expect_error "cannot open the video for writing" track --images "$mbt/cube/image%04d.pgm" --last 2 \
      --video "$work/no/such/dir/x.mp4" ;;
  eval_refuses_bad_tables)
    printf '%s\n0,0,0,0.15,0,0,0\n1,0,0,0.15,0,0,0\n2,0,0,0.15,0,0,0\n' "$truth_header" >"$work/truth.csv"
    row() { echo "$1,0,0,0.15,$2,0,0,50,1.0,tracked"; }
    { echo "$poses_header"; row 0.5 0; } >"$work/fraction.csv"
    expect_error "$work/fraction.csv:2: frame is not a whole number" "$edgetrack" eval --poses "$work/fraction.csv" --truth "$work/truth.csv"
    { echo "$poses_header"; row 0 0; row 0 0; } >"$work/twice.csv"
    expect_error "$work/twice.csv:3: frame 0 appears twice" "$edgetrack" eval --poses "$work/twice.csv" --truth "$work/truth.csv"
    { echo "$poses_header"; row 1 0; row 0 0; } >"$work/unsorted.csv"
    expect_error "$work/unsorted.csv:3: frame 0 comes after frame 1" "$edgetrack" eval --poses "$work/unsorted.csv" --truth "$work/truth.csv"
    for bad in nan inf 1e999; do
      { echo "$poses_header"; row 0 "$bad"; } >"$work/$bad.csv"
      expect_error "$work/$bad.csv:2: column 5 is not a finite number" "$edgetrack" eval --poses "$work/$bad.csv" --truth "$work/truth.csv"
    done
    { echo "$poses_header"; row 0 0; row 1 0; } >"$work/short.csv"
    expect_error "$work/short.csv: covers 2 of the 3 frames" "$edgetrack" eval --poses "$work/short.csv" --truth "$work/truth.csv"
    "$edgetrack" eval --poses "$work/short.csv" --truth "$work/truth.csv" --coverage >"$work/out.txt" || fail "--coverage refused"
    grep -q "coverage: 2 of 3 truth frames tracked (first missing: 2)" "$work/out.txt" || fail "no coverage line"
    echo "ok: every bad table refused, --coverage reports" ;;
  pose_and_points_values_checked)
    printf '0.01\n0\n0.6\nnan\n0\n0\n' >"$work/nan.pos"
    expect_error "$work/nan.pos:4: tux (rad) is not a finite number" "$edgetrack" track --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --init-pose "$work/nan.pos" --images "$mbt/cube/image%04d.pgm" --last 1
    printf '0\n0\n1e308\n0\n0\n0\n' >"$work/far.pos"
    expect_error "$work/far.pos:3: tz (m) is out of its range (-1000..1000)" "$edgetrack" track --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --init-pose "$work/far.pos" --images "$mbt/cube/image%04d.pgm" --last 1
    printf '4\n0 0 0\n0.1 0 0\n0 inf 0\n0 0 0.1\n' >"$work/inf.init"
    printf '1 1\n2 2\n3 3\n4 4\n' >"$work/ok.txt"
    expect_error "$work/inf.init:4: Y (m) is not a finite number" "$edgetrack" track --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --init "$work/inf.init" --init-points "$work/ok.txt" --images "$mbt/cube/image%04d.pgm"
    printf '4.5\n' >"$work/count.init"
    expect_error "$work/count.init:1: the number of points is not a whole number" "$edgetrack" track \
      --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init "$work/count.init" --init-points "$work/ok.txt" \
      --images "$mbt/cube/image%04d.pgm"
    printf '1 1\n2 nan\n' >"$work/nan.txt"
    printf '4\n0 0 0\n0.1 0 0\n0 0.1 0\n0 0 0.1\n' >"$work/ok.init"
    expect_error "$work/nan.txt:2: a pixel coordinate is not a finite number" "$edgetrack" track --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --init "$work/ok.init" --init-points "$work/nan.txt" --images "$mbt/cube/image%04d.pgm" ;;
  number_options_finite)
    for bad in nan inf -inf; do
      expect_error "option --blur needs a finite number, not '$bad'" "$edgetrack" synth --out "$work/s" --blur "$bad"
    done
    expect_error "--blur must be 0..50 pixels" timeout 10 "$edgetrack" synth --out "$work/s" --blur 1e6
    printf '<camera><px>300</px><py>300</py><u0>160</u0><v0>120</v0></camera>\n' >"$work/c.xml"
    expect_error "option --size asks for 40000x40000" "$edgetrack" synth --out "$work/s" --camera "$work/c.xml" --size 40000x40000
    expect_error "would be 32768x16384" "$edgetrack" synth --out "$work/s" --camera "$work/c.xml" --size 8192x4096 \
      --supersample 4 ;;
  outputs_named_and_written_whole)
    # Names checked before any work: an empty one, two naming one file (through other spellings).
    expect_error "--poses names no file" track --images "$mbt/cube/image%04d.pgm" --poses ""
    expect_error "--poses and --video name the same file" track --images "$mbt/cube/image%04d.pgm" \
      --poses "$work/out.mp4" --video "$work/../$name/out.mp4"
    expect_error "--out names no file" "$edgetrack" templates --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --out ""
    [ -z "$(ls "$work" | grep -v std)" ] || fail "a refused run left files: $(ls "$work")"
    # Writes that fail (a file-size limit, its signal ignored so that write() reports it): each
    # output refused by name, nothing under the final name.
    limited() { (trap '' XFSZ; ulimit -f "$1"; shift; "$@"); }
    expect_error "$work/cut.mp4: the video was not written whole" limited 20 track \
      --images "$mbt/cube/image%04d.pgm" --last 20 --video "$work/cut.mp4"
    [ ! -e "$work/cut.mp4" ] || fail "a video cut short is under its final name"
    expect_error "$work/cut.csv: write failed" limited 8 track --images "$mbt/cube/image%04d.pgm" --poses "$work/cut.csv"
    [ ! -e "$work/cut.csv" ] || fail "a poses table cut short is under its final name"
    expect_error "$work/templates.txt: write failed" limited 20 "$edgetrack" templates --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --size 640x480 --distance 0.3:0.4 --out "$work/templates.txt"
    [ ! -e "$work/templates.txt" ] && [ ! -e "$work/templates.txt.partial" ] || fail "templates cut short were left"
    echo "ok: nothing under a final name" ;;
  detect_bounds_checked_first)
    printf 'P5\n1 1\n255\n\x80' >"$work/one.pgm"
    expect_error "$work/one.pgm: the downscaled image is under 16 x 16" "$edgetrack" detect --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --image "$work/one.pgm"
    expect_error "puts the camera inside the model" timeout 20 "$edgetrack" templates --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --size 640x480 --distance 0.001:100 --out "$work/t.txt"
    expect_error "more than the 74560 a template file holds" timeout 20 "$edgetrack" templates --model "$mbt/cube.cao" \
      --camera "$mbt/cube.xml" --size 640x480 --subdivisions 4 --in-plane 360 --out "$work/t.txt"
    printf '<conf><camera><px>1e308</px></camera></conf>\n' >"$work/px.xml"
    expect_error "$work/px.xml:1: <camera><px>: the camera's px must be in (0, 1e+06]" "$edgetrack" templates --model "$mbt/cube.cao" \
      --camera "$work/px.xml" --size 640x480 --out "$work/t.txt"
    printf '<conf><camera><px>600</px><width>100000</width><height>10</height></camera></conf>\n' >"$work/wide.xml"
    expect_error "$work/wide.xml:1: <camera><width> must be 1..16384" "$edgetrack" templates --model "$mbt/cube.cao" \
      --camera "$work/wide.xml" --out "$work/t.txt"
    [ ! -e "$work/t.txt" ] || fail "a refused templates run wrote its file" ;;
  downscale_refusal_named)
    # A --downscale the frame cannot take is blamed on --downscale, not on the init-pose file,
    # before any output is made.
    { printf 'P5\n7 7\n255\n'; head -c 49 /dev/zero; } >"$work/small.pgm"
    expect_error "track: --downscale 8: leaves no pixel of a 7x7 frame" track --images "$work/small.pgm" --downscale 8 \
      --poses "$work/small.csv"
    ! grep -q "cube.0.pos" "$work/stderr" || fail "the init-pose file is blamed"
    [ ! -e "$work/small.csv" ] && [ ! -e "$work/small.csv.partial" ] || fail "a poses file was written" ;;
  frame_gap_named)
    mkdir -p "$work/seq"
    for i in 0 1 2 4; do ln -s "$mbt/cube/image000$i.pgm" "$work/seq/image000$i.pgm"; done
    track --images "$work/seq/image%04d.pgm" --poses "$work/gap.csv" >"$work/stdout" 2>"$work/stderr" || fail "the run failed"
    grep -qF "note: $work/seq/image0003.pgm is missing but $work/seq/image0004.pgm exists" "$work/stderr" ||
      fail "the gap is not named: $(cat "$work/stderr")"
    [ "$(wc -l <"$work/gap.csv")" -eq 4 ] || fail "the run did not stop at the gap"
    expect_error "$work/seq/image0003.pgm: missing frame" track --images "$work/seq/image%04d.pgm" --last 4 ;;
  overlay_directory_of_one_run)
    mkdir -p "$work/seq"
    for i in 0 1 2; do ln -s "$mbt/cube/image000$i.pgm" "$work/seq/image000$i.pgm"; done
    track --images "$work/seq/image%04d.pgm" --overlay "$work/frames" >/dev/null 2>&1 || fail "the first run failed"
    track --images "$work/seq/image%04d.pgm" --last 1 --overlay "$work/frames" >/dev/null 2>&1 || fail "the second run failed"
    [ "$(ls "$work/frames" | wc -l)" -eq 2 ] || fail "an earlier, longer run's frames stayed: $(ls "$work/frames")"
    echo "ok: the earlier run's frames removed"
    echo "mine" >"$work/frames/notes.txt"
    expect_error "$work/frames: holds notes.txt, which is not an overlay frame" track --images "$work/seq/image%04d.pgm" \
      --overlay "$work/frames"
    [ -e "$work/frames/notes.txt" ] && [ "$(ls "$work/frames" | wc -l)" -eq 3 ] || fail "a refused run touched the directory" ;;
  *) fail "unknown case" ;;
esac
