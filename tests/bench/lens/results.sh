#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/lens.md: tracking through a lens (ViSP's radial
# model, docs/ARCHITECTURE.md "Through a lens"). Accuracy: tests/tracker/test_lens_tracking.cxx's
# sequences in the host double and S40.23 builds (the test prints its errors). Cost: guest
# instructions per frame and per step on the emulated PXA270 (S40.23), bench_tracker on the
# generated cube with the lens against the same without it.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"

frames=10
kud=-0.25
mkdir -p "$bench_build_root"
work=$(mktemp -d "${TMPDIR:-/tmp}/lens.XXXXXX")
trap 'rm -rf "$work"' EXIT
host=$(bench_tree host double tracker_sequence_test_all)
host_s40=$(bench_tree host s40_23 tracker_sequence_test_all)
arm=$(bench_tree arm s40_23 bench_tracker)

echo "## Tracking through a lens (lens)"
echo
echo "\`tests/bench/lens/results.sh\` on $(bench_machine); guest counts on"
echo "$(qemu-arm --version | head -n 1 | sed 's/ (.*//'), \`-cpu pxa270\`, by \`toolchains/qemu/count-insns.sh\`."
echo
echo "### Accuracy (tests/tracker/test_lens_tracking.cxx)"
echo
echo "QVGA generated sequences rendered through ViSP's radial lens model, tracked from the true first"
echo "pose with the default settings: with the lens given to the tracker, with the lens ignored (the"
echo "pinhole), and the same frames rendered without a lens. Mean camera position error against the truth."
echo
echo "| build | sequence | kud | frames | lens given mm | lens ignored mm | no lens mm | lost (given, ignored, no lens) |"
echo "|---|---|---:|---:|---:|---:|---:|---|"
for tree in "$host" "$host_s40"; do
  for test in test_lens_tracking_cube test_lens_tracking_wood_toy test_lens_tracking_wood_toy_barrel; do
    "$tree/tests/tracker/tracker_sequence_test_all" "$test" >"$work/lens.txt"
    # "<real> <name> through kud = <k>, <n> frames: mean camera position error <a> mm with the
    # lens given, <b> mm ignoring it, <c> mm on the same frames without a lens; lost <x>, <y>, <z>"
    sed -n 's/^\([^ ]*\) \(.*\) through kud = \([-+0-9.]*\), \([0-9]*\) frames: mean camera position error \([0-9.]*\) mm with the lens given, \([0-9.]*\) mm ignoring it, \([0-9.]*\) mm on the same frames without a lens; lost \(.*\)$/| \1 | \2 | \3 | \4 | \5 | \6 | \7 | \8 |/p' \
      "$work/lens.txt"
  done
done
echo

echo "### Cost on the emulated PXA270 (S40.23)"
echo
echo "\`bench_tracker $frames cube steps on-demand 1 lmder - $kud\` (the generated QVGA cube rendered"
echo "through kud = $kud, the tracker given the lens) against the same frames and settings without a lens:"
echo "guest instructions per frame, per step (one count window each) and in all."
echo
echo "| camera | visible edges | grey scaling | ME | pose | the four steps | of which soft-float |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for lens in none "$kud"; do
  args=("$frames" cube steps on-demand 1 lmder -)
  [ "$lens" = none ] || args+=("$lens")
  "$top/toolchains/qemu/count-insns.sh" --out "$work/steps.sum" --windows "$work/steps.win" \
    "$arm/tests/bench/tracker/bench_tracker" "${args[@]}" >/dev/null
  label="pinhole"; [ "$lens" = none ] || label="kud = $lens"
  awk -v label="$label" '{ split($3, a, "="); split($4, b, "="); s[(NR - 1) % 4] += a[2]; soft += b[2] }
    END { f = NR / 4; t = s[0] + s[1] + s[2] + s[3]
          printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", label, s[0] / f, s[1] / f, s[2] / f, s[3] / f, t / f, soft / f }' \
    "$work/steps.win"
done
echo
echo "The pose step evaluates the lens at every match of every evaluation, and its derivative where"
echo "MINPACK asks for the Jacobian; the visible edges cut lines and faces into pieces along the"
echo "curved images (docs/ARCHITECTURE.md)."
