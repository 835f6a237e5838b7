# SPDX-License-Identifier: BSD-3-Clause
# What every command-line test script starts with, sourced with the script's own arguments
# (EDGETRACK TMPDIR CASE): $edgetrack, $name (the case), $work (its fresh directory), $visp_images
# (ViSP's example images), $mbt (their mbt folder), $data (the repository's data/), and the helpers below.
edgetrack=$1
work=$2/$3
name=$3
source "$(dirname "${BASH_SOURCE[0]}")/../../visp_images.sh"
mbt=$visp_images/mbt
data=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../../data" && pwd)
rm -rf "$work" && mkdir -p "$work"

fail() { echo "FAIL ($name): $*"; exit 1; }

# run_capturing COMMAND...: runs it with its output in $work/stdout and $work/stderr, shows its
# stderr, and sets $status to its exit status.
run_capturing() {
  "$@" >"$work/stdout" 2>"$work/stderr"
  status=$?
  cat "$work/stderr"
}

# expect_error TEXT COMMAND...: non-zero exit, exactly one line on stderr, containing TEXT.
expect_error() {
  local text=$1 status
  shift
  run_capturing "$@"
  [ "$status" -ne 0 ] || fail "exit status 0"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "expected one line on stderr"
  grep -qF -- "$text" "$work/stderr" || fail "stderr lacks '$text'"
  echo "ok: exit $status, message names the problem"
}

# expect_usage_error LINES COMMAND...: exit status 2, nothing on stdout, and stderr opens with
# LINES (one problem a line, each naming the option) followed by the two-line synopsis only,
# not the option list of --help.
expect_usage_error() {
  local lines=$1 status
  shift
  run_capturing "$@"
  [ "$status" -eq 2 ] || fail "exit status $status, expected 2"
  [ ! -s "$work/stdout" ] || fail "output on stdout"
  local count
  count=$(printf '%s\n' "$lines" | wc -l)
  [ "$(head -n "$count" "$work/stderr")" = "$lines" ] || fail "stderr does not open with: $lines"
  [ "$(wc -l <"$work/stderr")" -eq $((count + 2)) ] || fail "expected the problems and the two-line synopsis only"
  sed -n "$((count + 1))p" "$work/stderr" | grep -q "^usage: edgetrack " || fail "no synopsis after the problems"
  echo "ok: exit 2, each problem named before the synopsis"
}

# less A B: A < B as numbers.
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

# check_poses FILE ROWS MIN_POINTS: the poses file has ROWS rows, none lost, and on average at
# least MIN_POINTS matched points per frame.
check_poses() {
  local rows lost uncertain points
  rows=$(($(wc -l <"$1") - 1))
  lost=$(awk -F, 'NR > 1 && $10 == "lost"' "$1" | wc -l)
  uncertain=$(awk -F, 'NR > 1 && $10 == "uncertain"' "$1" | wc -l)
  points=$(awk -F, 'NR > 1 { s += $8; n++ } END { printf "%.1f", s / n }' "$1")
  echo "$1: $rows frames, $uncertain uncertain, $lost lost, $points points per frame"
  [ "$rows" -eq "$2" ] || fail "expected $2 frames"
  [ "$lost" -eq 0 ] || fail "frames lost"
  less "$(($3 - 1)).999" "$points" || fail "fewer than $3 points per frame"
}

# track_with_and_without_lens SEQ PATTERN: tracks synth's cube sequence SEQ (frames SEQ/PATTERN)
# with its intrinsics.xml given and without, evaluates both, and sets $with and $without (mean
# camera position error, mm) and $lost_with (frames lost with the lens given).
track_with_and_without_lens() {
  local seq=$1 pattern=$2 given
  for given in with without; do
    local lens=()
    [ "$given" = with ] && lens=(--intrinsics "$seq/intrinsics.xml")
    "$edgetrack" track --model "$(dirname "$0")/../../../data/models/cube60.cao" --camera "$seq/camera.xml" \
      "${lens[@]}" --init-pose "$seq/first.pos" --images "$seq/frames/$pattern" \
      --poses "$work/$given.csv" --quiet >/dev/null || fail "track $given the lens failed"
    "$edgetrack" eval --poses "$work/$given.csv" --truth "$seq/truth.csv" >"$work/$given.txt" || fail "eval failed"
  done
  lost_with=$(sed -n 's/^eval: .* lost=\([0-9]*\) .*/\1/p' "$work/with.txt")
  with=$(sed -n 's/^eval: .* distance_mm=\([0-9.]*\) .*/\1/p' "$work/with.txt")
  without=$(sed -n 's/^eval: .* distance_mm=\([0-9.]*\) .*/\1/p' "$work/without.txt")
}
