#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs a firmware image on QEMU's mps2-an385 board (Cortex-M3) with its arguments passed by
# semihosting, its files read and written through the host (relative to the current directory),
# and its exit status returned: CMake's emulator for the bare-metal tree (toolchains/cortex-m3.cmake).
# QEMU joins the arguments with spaces, so an argument may not contain one.
# EDGETRACK_QEMU_PLUGIN=<plugin.so,args> adds a TCG plugin (the instruction counter, count-insns.sh).
set -euo pipefail
image=${1:?usage: run-firmware.sh <firmware image> [arguments...]}
shift
config="enable=on,target=native"
# EDGETRACK_BOARD_REPORT=1: the startup code prints the run's memory high-water marks at exit.
[ -n "${EDGETRACK_BOARD_REPORT:-}" ] && config+=",arg=--board-report"
config+=",arg=$(basename "$image")"
for arg in "$@"; do
  if [[ $arg == *" "* || -z $arg ]]; then
    echo "run-firmware: the argument '$arg' is empty or has a space; semihosting passes neither" >&2
    exit 2
  fi
  config+=",arg=${arg//,/,,}"  # a comma in a -semihosting-config value is written twice
done
plugin=()
[ -n "${EDGETRACK_QEMU_PLUGIN:-}" ] && plugin=(-plugin "$EDGETRACK_QEMU_PLUGIN")
exec qemu-system-arm -M mps2-an385 -nographic -monitor none -serial none "${plugin[@]}" \
  -semihosting-config "$config" -kernel "$image"
