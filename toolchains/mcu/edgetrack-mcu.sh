#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `edgetrack` on the microcontroller: runs the command line built by the bare-metal tree
# (toolchains/cortex-m3.cmake) on QEMU's mps2-an385 board (Cortex-M3, no FPU), its arguments
# passed and its files read and written by semihosting, relative to the current directory:
#   toolchains/mcu/edgetrack-mcu.sh track --model M --camera C.xml --init-pose P.pos \
#       --images 'seq/frame%04d.pgm' --first 0 --last 19 --poses poses.csv
# The firmware image is $EDGETRACK_MCU_FIRMWARE, by default build/mcu-s40_23/app/edgetrack.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firmware=${EDGETRACK_MCU_FIRMWARE:-$here/../../build/mcu-s40_23/app/edgetrack}
if [ ! -f "$firmware" ]; then
  echo "edgetrack-mcu: no firmware image at $firmware (build the tree: docs/MCU.md, or set EDGETRACK_MCU_FIRMWARE)" >&2
  exit 2
fi
exec "$here/run-firmware.sh" "$firmware" "$@"
