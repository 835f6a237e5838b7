#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Host-only options of `edgetrack track`, one case per call: track_host_test.sh EDGETRACK TMPDIR CASE.
# --visibility (GL Edge-ID from the command line, a bad value refused) and --init-click, clicked
# for real in a window on a virtual X display (Xvfb) with xdotool. The lean command: the host
# libraries come in only through the host extras plugin, whose absence is one line.
set -u

# fail, expect_error, less, check_poses
source "$(dirname "$0")/cli_common.sh" "$@"

track_cube() {
  "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --images "$mbt/cube/image%04d.pgm" --quiet "$@"
}

# largest_difference A.csv B.csv: "MM DEG", the largest difference between same rows of two poses
# files in translation (mm) and in thetaU (degrees; the rotation angle for small differences).
largest_difference() {
  paste -d, "$1" "$2" | awk -F, 'NR > 1 {
      b = NF / 2  # the second file's columns follow the first's
      mm = 1000 * sqrt(($2 - $(b + 2))^2 + ($3 - $(b + 3))^2 + ($4 - $(b + 4))^2); if (mm > m) m = mm
      deg = 57.29578 * sqrt(($5 - $(b + 5))^2 + ($6 - $(b + 6))^2 + ($7 - $(b + 7))^2); if (deg > d) d = deg
    } END { printf "%.4f %.4f\n", m, d }'
}

# pose_distance A.pos B.pos: "MM DEG", translation distance and rotation angle between two poses.
pose_distance() {
  paste "$1" "$2" | awk '
    function rot(t1, t2, t3, R,   th, k1, k2, k3, c, s, v) {
      th = sqrt(t1 * t1 + t2 * t2 + t3 * t3)
      if (th < 1e-12) { k1 = 1; k2 = 0; k3 = 0 } else { k1 = t1 / th; k2 = t2 / th; k3 = t3 / th }
      c = cos(th); s = sin(th); v = 1 - c
      R[1,1] = c + k1*k1*v;    R[1,2] = k1*k2*v - k3*s; R[1,3] = k1*k3*v + k2*s
      R[2,1] = k2*k1*v + k3*s; R[2,2] = c + k2*k2*v;    R[2,3] = k2*k3*v - k1*s
      R[3,1] = k3*k1*v - k2*s; R[3,2] = k3*k2*v + k1*s; R[3,3] = c + k3*k3*v
    }
    NR <= 6 { a[NR] = $1; b[NR] = $2 }
    END {
      rot(a[4], a[5], a[6], A); rot(b[4], b[5], b[6], B)
      tr = 0
      for (i = 1; i <= 3; i++) for (j = 1; j <= 3; j++) tr += A[i,j] * B[i,j]
      c = (tr - 1) / 2; if (c > 1) c = 1; if (c < -1) c = -1
      printf "%.3f %.3f\n", 1000 * sqrt((a[1]-b[1])^2 + (a[2]-b[2])^2 + (a[3]-b[3])^2), atan2(sqrt(1 - c * c), c) * 57.29578
    }'
}

# project_init INIT POS CAMERA_XML: the .init points where the pose projects them, rounded to
# whole pixels ("u v" per line), as a user would click them.
project_init() {
  local px py u0 v0
  px=$(sed -n 's:.*<px>\(.*\)</px>.*:\1:p' "$3"); py=$(sed -n 's:.*<py>\(.*\)</py>.*:\1:p' "$3")
  u0=$(sed -n 's:.*<u0>\(.*\)</u0>.*:\1:p' "$3"); v0=$(sed -n 's:.*<v0>\(.*\)</v0>.*:\1:p' "$3")
  awk -v px="$px" -v py="$py" -v u0="$u0" -v v0="$v0" '
    FNR == 1 { file++ }
    { sub(/#.*/, "") } NF == 0 { next }
    file == 1 { p[++np] = $1 }
    file == 2 && !count { count = $1; next }
    file == 2 { X[++n] = $1; Y[n] = $2; Z[n] = $3 }
    END {
      th = sqrt(p[4]^2 + p[5]^2 + p[6]^2); k1 = p[4] / th; k2 = p[5] / th; k3 = p[6] / th
      c = cos(th); s = sin(th); v = 1 - c
      for (i = 1; i <= n; i++) {
        x = (c + k1*k1*v) * X[i] + (k1*k2*v - k3*s) * Y[i] + (k1*k3*v + k2*s) * Z[i] + p[1]
        y = (k2*k1*v + k3*s) * X[i] + (c + k2*k2*v) * Y[i] + (k2*k3*v - k1*s) * Z[i] + p[2]
        z = (k3*k1*v - k2*s) * X[i] + (k3*k2*v + k1*s) * Y[i] + (c + k3*k3*v) * Z[i] + p[3]
        printf "%d %d\n", int(u0 + px * x / z + 0.5), int(v0 + py * y / z + 0.5)
      }
    }' "$2" "$1"
}

# wait_for TEXT FILE SECONDS: until FILE has a line containing TEXT.
wait_for() {
  local i
  for ((i = 0; i < $3 * 10; i++)); do
    grep -qF -- "$1" "$2" 2>/dev/null && return 0
    sleep 0.1
  done
  cat "$2"
  fail "no '$1' within $3 s"
}

case $name in
  error_bad_visibility)
    expect_error "--visibility must be 'soft' (portable Edge-ID) or 'gl' (OSMesa), not 'bogus'" \
      track_cube --init-pose "$mbt/cube.0.pos" --last 3 --visibility bogus ;;
  error_init_click_without_display)
    expect_error "--init-click needs a display (DISPLAY is not set); give the points' image positions with --init I.init --init-points P.txt" \
      env -u DISPLAY "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-click "$mbt/cube.init" \
      --images "$mbt/cube/image%04d.pgm" --last 3 ;;
  visibility_gl_40_frames)
    # The command line's --visibility gl: 40 mbt/cube frames, none lost, the poses within 1 mm
    # and 0.5 degree of the portable run's on every frame (the full comparison is
    # app_test_track_visibility_gl).
    track_cube --init-pose "$mbt/cube.0.pos" --last 39 --visibility soft --poses "$work/soft.csv" || fail "track failed"
    track_cube --init-pose "$mbt/cube.0.pos" --last 39 --visibility gl --poses "$work/gl.csv" || fail "track --visibility gl failed"
    check_poses "$work/gl.csv" 40 40
    read -r mm deg < <(largest_difference "$work/soft.csv" "$work/gl.csv")
    echo "largest difference GL vs portable: $mm mm, thetaU $deg deg"
    less "$mm" 1.0 || fail "GL and portable poses differ by 1 mm or more"
    less "$deg" 0.5 || fail "GL and portable orientations differ by 0.5 degree or more" ;;
  init_click_xvfb)
    # A virtual display; xdotool clicks the cube.init points where cube.0.pos projects them (in
    # screen coordinates: the window's position plus the pixel) and presses Enter on the
    # confirmation view. The pose is within 3 mm and 1 degree of cube.0.pos, 20 frames track
    # from it, and the saved clicks and pose repeat the run without a display.
    command -v Xvfb >/dev/null && command -v xdotool >/dev/null || fail "needs Xvfb and xdotool (toolchains/install-deps.sh)"
    project_init "$mbt/cube.init" "$mbt/cube.0.pos" "$mbt/cube.xml" >"$work/expected.txt"
    echo "clicking at:"; cat "$work/expected.txt"
    exec 3>"$work/display"
    Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
    xvfb=$!
    exec 3>&-
    track_pid=
    trap 'kill $track_pid $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
    for ((i = 0; i < 50; i++)); do [ -s "$work/display" ] && break; sleep 0.1; done
    [ -s "$work/display" ] || fail "Xvfb did not start: $(cat "$work/xvfb.log")"
    export DISPLAY=:$(head -n 1 "$work/display")
    export XDG_RUNTIME_DIR=$work/runtime  # Qt's, for highgui
    mkdir -m 700 "$XDG_RUNTIME_DIR"
    echo "Xvfb on $DISPLAY"
    timeout 25 "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --images "$mbt/cube/image%04d.pgm" \
      --last 19 --quiet --init-click "$mbt/cube.init" --save-clicks "$work/clicks.txt" --save-pose "$work/clicked.pos" \
      --poses "$work/clicked.csv" >"$work/track.out" 2>"$work/track.err" &
    track_pid=$!
    wait_for "click point 1 of 4" "$work/track.err" 10
    # The window, once mapped at the frame's size.
    window= WIDTH=0 HEIGHT=0
    for ((i = 0; i < 50; i++)); do
      window=$(xdotool search --onlyvisible --name "edgetrack: click the initial points" 2>/dev/null | head -n 1)
      [ -n "$window" ] && eval "$(xdotool getwindowgeometry --shell "$window")"
      [ "$WIDTH" -eq 640 ] && [ "$HEIGHT" -eq 480 ] && break
      sleep 0.1
    done
    echo "window ${window:-none} at ${X:-?},${Y:-?}, ${WIDTH}x$HEIGHT"
    [ "$WIDTH" -eq 640 ] && [ "$HEIGHT" -eq 480 ] || fail "no window showing the 640x480 frame"
    point=1
    while read -r u v; do
      xdotool mousemove $((X + u)) $((Y + v)) click 1
      point=$((point + 1))
      if [ $point -le 4 ]; then wait_for "click point $point of 4" "$work/track.err" 5; fi
    done <"$work/expected.txt"
    wait_for "press Enter" "$work/track.err" 5
    xdotool key Return
    wait $track_pid
    status=$?
    track_pid=
    cat "$work/track.err"
    [ "$status" -eq 0 ] || fail "track --init-click exited with $status"
    diff <(grep -v '^#' "$work/clicks.txt") "$work/expected.txt" || fail "the saved clicks are not where xdotool clicked"
    read -r mm deg < <(pose_distance "$work/clicked.pos" "$mbt/cube.0.pos")
    echo "clicked pose against cube.0.pos: $mm mm, $deg deg"
    less "$mm" 3.0 || fail "the clicked pose is 3 mm or more from cube.0.pos"
    less "$deg" 1.0 || fail "the clicked pose is 1 degree or more from cube.0.pos"
    check_poses "$work/clicked.csv" 20 40
    # Repeated without a display, from the saved pose and from the saved clicks.
    env -u DISPLAY "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --images "$mbt/cube/image%04d.pgm" \
      --last 19 --quiet --init-pose "$work/clicked.pos" --poses "$work/from_pos.csv" >/dev/null || fail "rerun from the saved pose failed"
    env -u DISPLAY "$edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --images "$mbt/cube/image%04d.pgm" \
      --last 19 --quiet --init "$mbt/cube.init" --init-points "$work/clicks.txt" --poses "$work/from_clicks.csv" >/dev/null ||
      fail "rerun from the saved clicks failed"
    # Not bit-exact: the .pos holds the pose in decimal, and the pose read back differs from the
    # clicked one by up to half a unit of the real's resolution, which 20 frames of tracking carry
    # on (measured: S40.23 0.003 mm, 0.001 deg; S47.16, 2^-16 m and rad, 0.12 mm, 0.043 deg). The
    # bounds are those of the resolution: 128 times coarser in S47.16 than in S40.23.
    real=$(sed -n 's/.*real = \([a-z0-9_]*\).*/\1/p' "$work/track.out" | head -n 1)
    case $real in
      s47_16) bound_mm=0.3 bound_deg=0.15 ;;  # 2^-16 = 1.5e-5
      *) bound_mm=0.02 bound_deg=0.01 ;;      # double, float, s40_23 (2^-23 = 1.2e-7)
    esac
    for rerun in from_pos from_clicks; do
      read -r mm deg < <(largest_difference "$work/clicked.csv" "$work/$rerun.csv")
      echo "$rerun: largest difference to the clicked run $mm mm, $deg deg (real $real: within $bound_mm mm, $bound_deg deg)"
      less "$mm" "$bound_mm" && less "$deg" "$bound_deg" || fail "the $rerun rerun does not repeat the clicked run"
    done ;;
  lean_command_needs_no_host_library)
    needed=$(readelf -d "$edgetrack" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
    echo "edgetrack needs: $needed"
    [ -n "$needed" ] || fail "readelf lists no library"
    ! printf '%s\n' $needed | grep -E 'opencv|OSMesa|X11|visp|Qt|gdal|LLVM' || fail "edgetrack links a host library"
    plugin=$(dirname "$edgetrack")/../libexec/edgetrack/edgetrack-host.so
    readelf -d "$plugin" | grep -q 'NEEDED.*opencv' || fail "the host extras plugin $plugin does not carry OpenCV"
    echo "ok: OpenCV, OSMesa and X11 only in the plugin" ;;
  missing_host_extras_named)
    mkdir -p "$work/bin" && cp "$edgetrack" "$work/bin/edgetrack"
    lean=$work/bin/edgetrack
    "$lean" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
      --images "$mbt/cube/image%04d.pgm" --last 4 --poses "$work/poses.csv" --quiet || fail "PGM frames need the plugin"
    [ "$(wc -l <"$work/poses.csv")" -eq 6 ] || fail "expected 5 poses"
    missing="$work/libexec/edgetrack/edgetrack-host.so: drawing the overlay (--overlay, --video) needs the host extras plugin, which is missing"
    expect_error "$missing" "$lean" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
      --images "$mbt/cube/image%04d.pgm" --last 2 --video "$work/out.mp4"
    [ ! -e "$work/out.mp4" ] || fail "a video was written"
    expect_error "edgetrack-host.so: synth needs the host extras plugin, which is missing" "$lean" synth --out "$work/seq"
    cut -d, -f1-7 "$work/poses.csv" >"$work/truth.csv"
    expect_error "--plots needs the host extras plugin, which is missing" "$lean" eval --poses "$work/poses.csv" \
      --truth "$work/truth.csv" --plots "$work"
    echo "ok: image files tracked without the plugin, each option that needs it named" ;;
  *)
    fail "unknown case" ;;
esac
