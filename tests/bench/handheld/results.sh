#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/handheld.md: guest instructions per frame on
# today's handheld cores (AArch64 on qemu-aarch64 -cpu cortex-a53, ARMv7-A hard-float on
# qemu-arm -cpu cortex-a7) in double and float, beside the PXA270's S40.23: per step of
# Tracker::track on the generated QVGA cube (bench_tracker), and the whole `edgetrack track`
# frame on the same cube rendered to PGM files (as the app section does for the PXA270), counted
# by toolchains/qemu/count-insns.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
frames=60
short=20 long=60

work=$(mktemp -d "${TMPDIR:-/tmp}/handheld.XXXXXX")
trap 'rm -rf "$work"' EXIT
export EDGETRACK_PLUGIN_DIR=$work/plugin

# kind|real|label: the builds compared (bench_tree kinds, lib.sh). The PXA270's S40.23 figures of the
# same runs are the tracker and app sections' (tests/bench/tracker, tests/bench/app).
builds=(
  "aarch64|double|Cortex-A53 (AArch64), double"
  "armv7hf|double|Cortex-A7 (ARMv7-A hard-float, NEON), double"
  "aarch64|float|Cortex-A53 (AArch64), float"
  "armv7hf|float|Cortex-A7 (ARMv7-A hard-float, NEON), float"
)

cat <<EOF
## Handheld cores: guest instructions per frame on Cortex-A53 and Cortex-A7 (handheld)

\`tests/bench/handheld/results.sh\`: $(bench_machine); $(qemu-aarch64 --version | head -n 1 | sed 's/ (.*//'),
\`qemu-aarch64 -cpu cortex-a53\` (\`toolchains/aarch64-linux.cmake\`: \`-march=armv8-a\`), \`qemu-arm -cpu cortex-a7\`
(\`toolchains/armv7a-hf.cmake\`: \`-march=armv7-a -mfpu=neon -mfloat-abi=hard -mthumb\`);
GCC $(aarch64-linux-gnu-gcc -dumpversion), Release (\`-O3\`), \`-ffp-contract=off\`; counted by
\`toolchains/qemu/count-insns.sh\`, $(date -u +%Y-%m-%d). Guest instructions are not cycles: QEMU
models no pipeline, and on an in-order Cortex-A53 or A7 a double multiply or divide takes several
cycles where an integer add takes one.

### Tracker::track per step, generated QVGA cube

The 60 mm cube sequence of the tracker section ($frames frames, default TrackerParams, on-demand grey):
one count window per step (\`bench_tracker $frames cube steps\`) and one per \`Tracker::track\` call
(\`bench_tracker $frames cube frame\`; the total also holds the status and the prediction). The same runs
on the emulated PXA270 are in the tracker section's \`Emulated PXA270: guest instructions per frame\`
(S40.23, on demand: the row to compare with).

| core, real | visible edges | grey scaling | ME | pose | whole Tracker::track | in soft-float routines |
|---|---:|---:|---:|---:|---:|---:|
EOF
for entry in "${builds[@]}"; do
  IFS='|' read -r kind real label <<<"$entry"
  bench=$(bench_tree "$kind" "$real" bench_tracker edgetrack)
  echo "$bench" >"$work/$kind-$real.dir"
  "$top/toolchains/qemu/count-insns.sh" --out "$work/steps.sum" --windows "$work/steps.win" \
    "$bench/tests/bench/tracker/bench_tracker" "$frames" cube steps on-demand >/dev/null
  "$top/toolchains/qemu/count-insns.sh" --out "$work/frames.sum" --windows "$work/frames.win" \
    "$bench/tests/bench/tracker/bench_tracker" "$frames" cube frame on-demand >/dev/null
  awk -v label="$label" 'NR == FNR { split($3, a, "="); s[(FNR-1)%4] += a[2]; steps = FNR; next }
    { split($3, a, "="); split($4, b, "="); t += a[2]; soft += b[2]; n++ }
    END { f = steps / 4
          printf "| %s | %.3f M | %.3f M | %.3f M | %.3f M | %.3f M | %.0f |\n", label, s[0]/f/1e6, s[1]/f/1e6, s[2]/f/1e6,
            s[3]/f/1e6, t/n/1e6, soft/n }' "$work/steps.win" "$work/frames.win"
done

cat <<EOF

### The whole \`edgetrack track\` frame, generated QVGA cube from PGM files

\`edgetrack track\` (\`--quiet --poses OUT.csv\`, default settings) on the generated 60 mm cube sequence
written as PGM by \`edgetrack synth --pgm\` (read in place as grey8), runs of $short and $long frames under
the counter; per frame = difference of the two counts / $((long - short)), so the start-up work cancels.
"tracker": the count window \`edgetrack track\` opens around \`Tracker::track\`; "whole frame": the whole
process (reading the file, tracking, writing the pose row). The PXA270's S40.23 row of the same runs is
the app section's \`PGM (P5, 8-bit)\` row.

| core, real | tracker per frame | whole frame | ratio | in soft-float routines per frame |
|---|---:|---:|---:|---:|
EOF
"$(bench_tree host double edgetrack)/app/edgetrack" synth --out "$work/pgm" --pgm >/dev/null
for entry in "${builds[@]}"; do
  IFS='|' read -r kind real label <<<"$entry"
  edgetrack=$(cat "$work/$kind-$real.dir")/app/edgetrack
  for count in $short $long; do
    "$top/toolchains/qemu/count-insns.sh" --out "$work/track_$count.sum" "$edgetrack" track \
      --model "$top/data/models/cube60.cao" --camera "$work/pgm/camera.xml" --init-pose "$work/pgm/first.pos" \
      --images "$work/pgm/frames/frame%04d.pgm" --last $((count - 1)) --quiet --poses "$work/poses.csv" >/dev/null
  done
  cat "$work/track_$short.sum" "$work/track_$long.sum" | tr ' ' '\n' | awk -F= -v label="$label" -v n=$((long - short)) '
    $1 == "total" { t[++i] = $2 } $1 == "softfloat" { s[i] = $2 } $1 == "window_total" { w[i] = $2 }
    END { tracker = (w[2] - w[1]) / n; whole = (t[2] - t[1]) / n
          printf "| %s | %.3f M | %.3f M | %.3f | %.0f |\n", label, tracker / 1e6, whole / 1e6, whole / tracker,
            (s[2] - s[1]) / n }'
done
