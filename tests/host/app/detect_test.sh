#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# One command-line test of `detect`, `templates` and `track --init-auto` per call:
# detect_test.sh EDGETRACK TMPDIR CASE.
set -u

# fail, expect_error, less
source "$(dirname "$0")/cli_common.sh" "$@"

# centre_offsets A.csv B.csv CENTRE: per frame, the distance (mm) between the model point CENTRE
# ("x y z", model frame) in the camera frame at the poses of A and B: the same for any symmetric
# pose of a model symmetric about CENTRE. Both files have the same columns (frame, tx .. tuz
# first). Prints the largest and the mean.
centre_offsets() {
  paste -d, "$1" "$2" | awk -F, -v centre="$3" '
    function place(t1, t2, t3, w1, w2, w3,   th, k1, k2, k3, c, s, C, x, y, z) {
      th = sqrt(w1 * w1 + w2 * w2 + w3 * w3); x = P[1]; y = P[2]; z = P[3]
      if (th < 1e-12) { X = x + t1; Y = y + t2; Z = z + t3; return }
      k1 = w1 / th; k2 = w2 / th; k3 = w3 / th; c = cos(th); s = sin(th); C = 1 - c
      X = (c + k1 * k1 * C) * x + (k1 * k2 * C - k3 * s) * y + (k1 * k3 * C + k2 * s) * z + t1
      Y = (k2 * k1 * C + k3 * s) * x + (c + k2 * k2 * C) * y + (k2 * k3 * C - k1 * s) * z + t2
      Z = (k3 * k1 * C - k2 * s) * x + (k3 * k2 * C + k1 * s) * y + (c + k3 * k3 * C) * z + t3
    }
    BEGIN { split(centre, P, " ") }
    NR > 1 {
      place($2, $3, $4, $5, $6, $7); ax = X; ay = Y; az = Z
      b = NF / 2 + 1
      place($(b + 1), $(b + 2), $(b + 3), $(b + 4), $(b + 5), $(b + 6))
      d = 1000 * sqrt((ax - X)^2 + (ay - Y)^2 + (az - Z)^2); s += d; n++
      if (d > worst) worst = d
    }
    END { printf "%.3f %.3f\n", worst, s / n }'
}

# pos_as_row POS: a .pos file as a poses-CSV row for frame 0.
pos_as_row() { echo "frame,tx,ty,tz,tux,tuy,tuz"; echo "0,$(tr -s ' \n' ',' <"$1" | sed 's/,$//')"; }

# large_frame_found WIDTHxHEIGHT SUPERSAMPLE FRAME REDUCED: synth's cube path rendered at that
# size with the field of view of its 640x480 camera (px = 0.6875 width), frame FRAME detected
# with the default templates on a copy reduced as REDUCED says ("1/2 size (640x480)"); the pose,
# the full-size camera's, puts the cube's centre within 2 mm of the truth.
large_frame_found() {
  local size=$1 width=${1%x*} height=${1#*x} frame=$3 dir=$work/$1 px worst mean status
  px=$(awk -v w="$width" 'BEGIN { printf "%.4f", 0.6875 * w }')
  printf '<?xml version="1.0"?>\n<conf><camera><u0>%d</u0><v0>%d</v0><px>%s</px><py>%s</py></camera></conf>\n' \
    $((width / 2)) $((height / 2)) "$px" "$px" >"$dir.xml"
  "$edgetrack" synth --out "$dir" --camera "$dir.xml" --size "$size" --supersample "$2" --frames $((frame + 1)) \
    >/dev/null || fail "synth failed"
  "$edgetrack" detect --model "$data/models/cube60.cao" --camera "$dir/camera.xml" \
    --image "$dir/frames/frame$(printf %04d "$frame").ppm" --out "$dir.pos" >"$dir.txt"
  status=$?
  cat "$dir.txt"
  [ "$status" -eq 0 ] || fail "not found at $size (exit status $status)"
  grep -q "detecting at $4" "$dir.txt" || fail "no line saying the image was reduced to $4"
  pos_as_row "$dir.pos" >"$dir.found.csv"
  awk -F, -v OFS=, -v k="$frame" 'NR == 1 || $1 == k { if (NR > 1) $1 = 0; print $1, $2, $3, $4, $5, $6, $7 }' \
    "$dir/truth.csv" >"$dir.truth.csv"
  read -r worst mean < <(centre_offsets "$dir.found.csv" "$dir.truth.csv" "0 0 0")
  echo "$size: centre $worst mm from the truth"
  less "$worst" 2.0 || fail "the centre is 2 mm or more from the truth at $size"
}

case $name in
  detect_synthetic_cube)
    # The generated cube (synth, OSMesa) found from the model alone with the default templates:
    # its centre (the model's origin) within 2 mm of the truth (any of the 24 symmetric poses).
    "$edgetrack" synth --out "$work/seq" --frames 1 >/dev/null || fail "synth failed"
    "$edgetrack" detect --model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" \
      --image "$work/seq/frames/frame0000.ppm" --out "$work/found.pos" | tee "$work/detect.txt" || fail "not found"
    grep -q "detect: found=1" "$work/detect.txt" || fail "no found=1 line"
    pos_as_row "$work/found.pos" >"$work/found.csv"
    pos_as_row "$work/seq/first.pos" >"$work/truth.csv"
    read -r worst mean < <(centre_offsets "$work/found.csv" "$work/truth.csv" "0 0 0")
    echo "centre $worst mm from the truth"
    less "$worst" 2.0 || fail "the centre is 2 mm or more from the truth" ;;
  detect_budget)
    # The detection's work budget from the command line and from the configuration's
    # <edgetrack><detector> block: one control point runs one frame and finds nothing (exit 3, no
    # pose written); a bad value or name is refused with one line.
    "$edgetrack" synth --out "$work/seq" --frames 1 >/dev/null || fail "synth failed"
    args=(--model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --image "$work/seq/frames/frame0000.ppm"
      --distance 0.4:0.6 --subdivisions 1 --in-plane 12)
    "$edgetrack" detect "${args[@]}" --detector max_points_searched=1 --out "$work/none.pos" >"$work/budget.txt"
    status=$?
    cat "$work/budget.txt"
    [ "$status" -eq 3 ] || fail "a budget of one point: exit status $status, not 3 (not found)"
    grep -q "detect: found=0 .* cut_short=1" "$work/budget.txt" || fail "no found=0 line saying it was cut short"
    [ ! -e "$work/none.pos" ] || fail "a pose was written though nothing was found"
    printf '<conf><edgetrack><detector><max_points_searched>1</max_points_searched></detector></edgetrack></conf>\n' \
      >"$work/budget.xml"
    "$edgetrack" detect "${args[@]}" --config "$work/budget.xml" >"$work/budget_xml.txt"
    status=$?
    [ "$status" -eq 3 ] || fail "<edgetrack><detector> budget of one point: exit status $status, not 3"
    expect_error "--detector max_points_searched=-1: max_points_searched must be a whole number" \
      "$edgetrack" detect "${args[@]}" --detector max_points_searched=-1
    expect_error "--detector points=10: 'points' is not a detector setting" \
      "$edgetrack" detect "${args[@]}" --detector points=10 ;;
  detect_large_image)
    # A frame of 1280x960 (its shorter side above the detector's 480 px) is detected on a copy
    # half its size, and one of 2560x1920 on a copy a quarter its size: synth's sixth frame,
    # which detection at 853x640 (a bound of 640 px) did not find, as it found 2 of the first 10.
    large_frame_found 1280x960 4 0 "1/2 size (640x480)"
    large_frame_found 2560x1920 1 5 "1/4 size (640x480)" ;;
  templates_file_large_frames)
    # A template file for a 1280x960 camera records that camera (the frames' size) and holds
    # templates made at the size detection runs at (640x480): detect --templates on the full-size
    # image detects as the same templates made in the run, reduced alike.
    printf '<?xml version="1.0"?>\n<conf><camera><u0>640</u0><v0>480</v0><px>880</px><py>880</py></camera></conf>\n' \
      >"$work/large.xml"
    "$edgetrack" synth --out "$work/seq" --camera "$work/large.xml" --size 1280x960 --supersample 2 --frames 1 \
      >/dev/null || fail "synth failed"
    range=(--subdivisions 1 --in-plane 12)
    args=(--model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --image "$work/seq/frames/frame0000.ppm")
    "$edgetrack" templates --model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --out "$work/t.txt" \
      "${range[@]}" || fail "templates failed"
    grep -q "^camera 880.000000 880.000000 640.000000 480.000000 1280 960$" "$work/t.txt" ||
      fail "the file does not record the full-size camera"
    "$edgetrack" detect "${args[@]}" "${range[@]}" | grep -v 'ms=' >"$work/made.txt"
    "$edgetrack" detect "${args[@]}" --templates "$work/t.txt" | grep -v 'ms=' >"$work/read.txt"
    cat "$work/read.txt"
    grep -q "detecting at 1/2 size (640x480)" "$work/read.txt" || fail "no line saying the image was reduced"
    cmp -s "$work/made.txt" "$work/read.txt" || fail "templates read from the file detect differently"
    sed '1s/ [0-9]*$/ 1/' "$work/t.txt" >"$work/v1.txt"
    expect_error "v1.txt:1: template format version 1 for frames above 480 px" "$edgetrack" detect "${args[@]}" \
      --templates "$work/v1.txt" ;;
  track_init_auto_large_frames)
    # Three generated frames of 1280x960: track --init-auto detects on them reduced to 640x480
    # (the library reduces them; the run says so) and tracks them at full size, the cube's centre
    # within 2 mm of the truth in every frame, none lost.
    printf '<?xml version="1.0"?>\n<conf><camera><u0>640</u0><v0>480</v0><px>880</px><py>880</py></camera></conf>\n' \
      >"$work/large.xml"
    "$edgetrack" synth --out "$work/seq" --camera "$work/large.xml" --size 1280x960 --supersample 2 --frames 3 \
      >/dev/null || fail "synth failed"
    "$edgetrack" track --model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --init-auto \
      --init-distance 0.12:0.2 --images "$work/seq/frames/frame%04d.ppm" --poses "$work/auto.csv" \
      >"$work/track.txt" 2>"$work/track.err" || { cat "$work/track.err"; fail "track --init-auto failed"; }
    grep -h "detecting at\| detection: " "$work/track.txt" "$work/track.err"
    grep -q "track: .*detecting at 1/2 size (640x480)" "$work/track.txt" || fail "no line saying frames are reduced"
    grep -q "^frame 0 detection: found" "$work/track.err" || fail "the cube is not found on frame 0"
    check_poses "$work/auto.csv" 3 40
    cut -d, -f1-7 "$work/auto.csv" >"$work/found.csv"
    cut -d, -f1-7 "$work/seq/truth.csv" >"$work/truth.csv"
    read -r worst mean < <(centre_offsets "$work/found.csv" "$work/truth.csv" "0 0 0")
    echo "centre: largest $worst mm, mean $mean mm from the truth"
    less "$worst" 2.0 || fail "the centre is 2 mm or more from the truth" ;;
  detect_not_found)
    # A flat grey frame: "not found", exit status 3, no pose file.
    { printf 'P5\n320 240\n255\n'; head -c $((320 * 240)) /dev/zero | tr '\0' '\200'; } >"$work/flat.pgm"
    "$edgetrack" synth --out "$work/seq" --frames 1 >/dev/null || fail "synth failed"
    "$edgetrack" detect --model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --image "$work/flat.pgm" \
      --out "$work/found.pos" --subdivisions 1 >"$work/detect.txt"
    status=$?
    cat "$work/detect.txt"
    [ "$status" -eq 3 ] || fail "exit status $status, expected 3"
    grep -q "detect: found=0" "$work/detect.txt" || fail "no found=0 line"
    [ ! -e "$work/found.pos" ] || fail "a pose file was written" ;;
  templates_file_checked)
    # Templates from a file detect as the same templates made in the run; a file for another
    # model, of another version, or with range options beside it is refused in one line.
    "$edgetrack" synth --out "$work/seq" --frames 1 >/dev/null || fail "synth failed"
    range=(--subdivisions 1 --in-plane 12)
    args=(--model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --image "$work/seq/frames/frame0000.ppm")
    "$edgetrack" templates --model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --out "$work/t.txt" \
      "${range[@]}" || fail "templates failed"
    "$edgetrack" detect "${args[@]}" "${range[@]}" | grep -v 'ms=' >"$work/made.txt"
    "$edgetrack" detect "${args[@]}" --templates "$work/t.txt" | grep -v 'ms=' >"$work/read.txt"
    cat "$work/read.txt"
    cmp -s "$work/made.txt" "$work/read.txt" || fail "templates read from the file detect differently"
    expect_error "t.txt:2: made for another model" "$edgetrack" detect --model "$data/models/wood_toy.cao" \
      --camera "$work/seq/camera.xml" --image "$work/seq/frames/frame0000.ppm" --templates "$work/t.txt"
    sed '1s/ [0-9]*$/ 9/' "$work/t.txt" >"$work/v9.txt"
    expect_error "v9.txt:1: template format version 9" "$edgetrack" detect "${args[@]}" --templates "$work/v9.txt"
    expect_error "--cone cannot be used with --templates" "$edgetrack" detect "${args[@]}" --templates "$work/t.txt" \
      --cone 30 ;;
  track_init_auto_mbt_cube)
    # ViSP's mbt/cube from frame 0 with no pose given: all 218 frames tracked, none lost, and the
    # cube's centre with the run started from cube.0.pos: under 1 mm on average, and under 6 mm
    # (7 px at 0.5 m, the overlay bound of the other mbt/cube comparisons) in every frame.
    "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-auto --init-distance 0.4:0.6 \
      --images "$mbt/cube/image%04d.pgm" --poses "$work/auto.csv" --quiet >/dev/null || fail "track --init-auto failed"
    "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
      --images "$mbt/cube/image%04d.pgm" --poses "$work/pos.csv" --quiet >/dev/null || fail "track failed"
    check_poses "$work/auto.csv" 218 40
    read -r worst mean < <(centre_offsets "$work/auto.csv" "$work/pos.csv" "-0.042 0.042 0.042")
    echo "cube centre against the run from cube.0.pos: largest $worst mm, mean $mean mm"
    less "$mean" 1.0 || fail "the centre is 1 mm or more from the run from cube.0.pos on average"
    less "$worst" 6.0 || fail "the centre strays 6 mm or more from the run from cube.0.pos" ;;
  track_init_auto_as_shipped)
    # ViSP's mbt/cube with cube.cao and cube.xml alone: no --init-distance, the range is every
    # distance at which the cube's bounding sphere spans a tenth to the whole of the image's
    # shorter side (0.164 to 1.64 m here). Frames 0-19 tracked, none lost, the cube's centre within
    # 6 mm of the run from cube.0.pos in every frame.
    "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-auto --last 19 \
      --images "$mbt/cube/image%04d.pgm" --poses "$work/auto.csv" --quiet >/dev/null || fail "track --init-auto failed"
    "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" --last 19 \
      --images "$mbt/cube/image%04d.pgm" --poses "$work/pos.csv" --quiet >/dev/null || fail "track failed"
    check_poses "$work/auto.csv" 20 40
    read -r worst mean < <(centre_offsets "$work/auto.csv" "$work/pos.csv" "-0.042 0.042 0.042")
    echo "cube centre against the run from cube.0.pos: largest $worst mm, mean $mean mm"
    less "$worst" 6.0 || fail "the centre strays 6 mm or more from the run from cube.0.pos" ;;
  track_init_auto_nothing_found)
    # Three flat frames: the detector finds nothing, says so with the distances it searched, and
    # track exits non-zero, no frame of the run having been tracked.
    "$edgetrack" synth --out "$work/seq" --frames 1 >/dev/null || fail "synth failed"
    mkdir -p "$work/flat"
    for i in 0 1 2; do
      { printf 'P5\n320 240\n255\n'; head -c $((320 * 240)) /dev/zero | tr '\0' '\200'; } >"$work/flat/flat$i.pgm"
    done
    "$edgetrack" track --model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --init-auto \
      --init-distance 0.12:0.2 --images "$work/flat/flat%d.pgm" --poses "$work/auto.csv" >"$work/track.txt" 2>"$work/track.err"
    status=$?
    cat "$work/track.err"
    [ "$status" -ne 0 ] || fail "exit status 0 with no frame tracked"
    grep -q "frame 0 detection: not found (camera distances 0.120 to 0.[0-9]* m searched)" "$work/track.err" ||
      fail "no not-found line with the distances searched"
    grep -q "did not find the model in any of 3 frames (camera distances 0.120 to" "$work/track.err" ||
      fail "no closing line saying the model was never found" ;;
  track_init_auto_redetects_after_cover)
    # The generated cube (synth's path, 20 frames) covered by a board on frames 6-9 and 20 mm
    # lower when it comes back on frame 10, beyond the tracker's own recovery from where it went:
    # no covered frame tracked, the cube re-detected on its return and tracked again within 3
    # frames of it (a detection frame is reported uncertain until the next frame confirms it),
    # within 2 mm of the truth from then on.
    "$edgetrack" synth --out "$work/path" --frames 20 >/dev/null || fail "synth failed"
    awk -F, -v OFS=, 'NR > 1 && $1 >= 6 { $3 += 0.02 } { print }' "$work/path/truth.csv" >"$work/moved.csv"
    "$edgetrack" synth --out "$work/seq" --trajectory "$work/moved.csv" --frames 20 --hide 6:9 >/dev/null ||
      fail "synth failed"
    "$edgetrack" track --model "$data/models/cube60.cao" --camera "$work/seq/camera.xml" --init-auto \
      --init-distance 0.12:0.2 --images "$work/seq/frames/frame%04d.ppm" --poses "$work/auto.csv" \
      >"$work/track.txt" 2>"$work/track.err" || fail "track --init-auto failed"
    grep -h " detection: \|^detection:" "$work/track.err" "$work/track.txt"
    statuses=$(awk -F, 'NR > 1 { printf "%s", substr($10, 1, 1) }' "$work/auto.csv")
    echo "statuses (t tracked, u uncertain, l lost): $statuses"
    [ "${#statuses}" -eq 20 ] || fail "expected 20 frames"
    [ -z "$(echo "${statuses:6:4}" | tr -d lu)" ] || fail "a covered frame is reported tracked"
    grep -Eq "^frame 1[0-2] detection: found" "$work/track.err" || fail "not re-detected within 3 frames of the return"
    back=$(awk -v s="${statuses:10}" 'BEGIN { print index(s, "t") - 1 }')
    [ "$back" -ge 0 ] && [ "$back" -le 2 ] || fail "not tracked again within 3 frames of the return"
    awk -F, -v first=$((10 + back)) 'NR == 1 || ($1 >= first && $10 == "tracked")' "$work/auto.csv" | cut -d, -f1-7 >"$work/back.csv"
    awk -F, 'NR == FNR { keep[$1] = 1; next } FNR == 1 || keep[$1]' "$work/back.csv" "$work/seq/truth.csv" >"$work/truth.csv"
    read -r worst mean < <(centre_offsets "$work/back.csv" "$work/truth.csv" "0 0 0")
    echo "tracked again $back frames after the return; centre from then on: largest $worst mm, mean $mean mm"
    less "$worst" 2.0 || fail "the centre is 2 mm or more from the truth after the return" ;;
  track_init_auto_mbt_cube_qvga_prefix)
    # The first 30 frames of mbt/cube halved to QVGA (--downscale 2), from frame 0 with no pose:
    # the cube found on frame 0 (uncertain until frame 1, tracked from it, confirms it), every
    # later frame tracked, and its centre within 1 mm of the run from cube.0.pos on average and
    # 3 mm (2 QVGA px at 0.5 m) in every frame.
    args=(--model "$mbt/cube.cao" --camera "$mbt/cube.xml" --images "$mbt/cube/image%04d.pgm" --last 29 --downscale 2)
    "$edgetrack" track "${args[@]}" --init-auto --init-distance 0.4:0.6 --poses "$work/auto.csv" \
      >"$work/track.txt" 2>"$work/track.err" || fail "track --init-auto failed"
    "$edgetrack" track "${args[@]}" --init-pose "$mbt/cube.0.pos" --poses "$work/pos.csv" --quiet >/dev/null ||
      fail "track failed"
    grep -h " detection: \|^detection:" "$work/track.err" "$work/track.txt"
    grep -q "^frame 0 detection: found" "$work/track.err" || fail "the cube is not found on frame 0"
    statuses=$(awk -F, 'NR > 1 { printf "%s", substr($10, 1, 1) }' "$work/auto.csv")
    echo "statuses (t tracked, u uncertain, l lost): $statuses"
    [ "$statuses" = "u$(printf 't%.0s' $(seq 29))" ] || fail "expected frame 0 uncertain and frames 1-29 tracked"
    read -r worst mean < <(centre_offsets "$work/auto.csv" "$work/pos.csv" "-0.042 0.042 0.042")
    echo "cube centre against the run from cube.0.pos: largest $worst mm, mean $mean mm"
    less "$mean" 1.0 || fail "the centre is 1 mm or more from the run from cube.0.pos on average"
    less "$worst" 3.0 || fail "the centre strays 3 mm or more from the run from cube.0.pos" ;;
  *) fail "unknown case" ;;
esac
echo "PASS ($name)"
