#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The firmware's `edgetrack track` against the host's: renders 20 QVGA frames of the cube with the
# host build (synth, PGM), tracks them with both, and requires the same poses CSV (every column
# but ms, the step time, which the board's 10 ms semihosting clock cannot give). With
# --tracker-only, FIRMWARE_IMAGE is the tracker-only firmware (app/mcu), given the same inputs
# as its positional arguments, and it must report no allocation after the tracker was created
# (its heap is locked then: docs/MCU.md) and, with RAM_KB, use at most RAM_KB of RAM in all (its
# static RAM and its heap and stack high-water marks, the board's report). With SETTINGS.xml both
# track with that ViSP XML's <ecm> moving-edge settings and the generated camera.
# usage: track-against-host.sh HOST_EDGETRACK FIRMWARE_IMAGE MODEL WORKDIR [--tracker-only [RAM_KB [SETTINGS.xml]]]
set -euo pipefail
host=${1:?usage: track-against-host.sh HOST_EDGETRACK FIRMWARE_IMAGE MODEL WORKDIR [--tracker-only [RAM_KB [SETTINGS.xml]]]}
firmware=${2:?} model=${3:?} work=${4:?} mode=${5:-} ram_kb=${6:-} settings=${7:-}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$host" synth --out seq --frames 20 --pgm >/dev/null
camera=seq/camera.xml
if [ -n "$settings" ]; then
  [ -f "$settings" ] || { echo "track-against-host: $settings: no such file" >&2; exit 1; }
  camera=settings.xml
  { echo '<?xml version="1.0"?>'; echo '<conf>'; sed -n '/<ecm>/,/<\/ecm>/p' "$settings"
    sed -n '/<camera>/,/<\/camera>/p' seq/camera.xml; echo '</conf>'; } >"$camera"
  grep -q '<ecm>' "$camera" || { echo "track-against-host: $settings: no <ecm> settings" >&2; exit 1; }
fi
run=(track --model "$model" --camera "$camera" --init-pose seq/first.pos --images 'seq/frames/frame%04d.pgm'
     --first 0 --last 19 --quiet)
"$host" "${run[@]}" --poses host.csv >/dev/null
if [ "$mode" = --tracker-only ]; then
  EDGETRACK_BOARD_REPORT=1 "$here/../../toolchains/mcu/run-firmware.sh" "$firmware" "$model" "$camera" seq/first.pos \
    'seq/frames/frame%04d.pgm' 0 19 mcu.csv 2>report.txt || { cat report.txt >&2; exit 1; }
  if ! grep -q '^allocations: [0-9]* until the tracker was created, 0 after it (0 refused)$' report.txt; then
    cat report.txt >&2
    echo "track-against-host: the tracker firmware allocated after the tracker was created" >&2
    exit 1
  fi
  if [ -n "$ram_kb" ]; then
    ram=$(sed -n 's/^board: static \([0-9]*\) bytes.*heap high-water \([0-9]*\) bytes, stack high-water \([0-9]*\) bytes$/\1 \2 \3/p' report.txt |
          awk '{ print $1 + $2 + $3 }')
    [ -n "$ram" ] || { cat report.txt >&2; echo "track-against-host: no board report of the RAM used" >&2; exit 1; }
    if [ "$ram" -gt $((ram_kb * 1024)) ]; then
      grep '^board:\|^tracker memory:' report.txt >&2
      echo "track-against-host: the firmware used $ram bytes of RAM, over its $ram_kb KB" >&2
      exit 1
    fi
    echo "track-against-host: $ram bytes of RAM, within $ram_kb KB"
  fi
else
  EDGETRACK_MCU_FIRMWARE=$firmware "$here/../../toolchains/mcu/edgetrack-mcu.sh" "${run[@]}" --poses mcu.csv >/dev/null
fi
rows=$(($(wc -l <mcu.csv) - 1))
if [ "$rows" -ne 20 ]; then echo "track-against-host: the firmware wrote $rows poses, not 20" >&2; exit 1; fi
if ! diff <(cut -d, -f1-8,10 host.csv) <(cut -d, -f1-8,10 mcu.csv); then
  echo "track-against-host: the firmware's poses differ from the host's (above: <host >firmware)" >&2
  exit 1
fi
echo "track-against-host: 20 poses, the same as the host's"
