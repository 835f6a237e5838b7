#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A firmware image's flash within a budget: what the board keeps in flash (code and constants in
# .text, the unwinding index .ARM.exidx, .data's initial values), as `arm-none-eabi-size -A` lists it.
# usage: flash-within.sh IMAGE KB
set -euo pipefail
image=$1 budget_kb=$2
bytes=$(arm-none-eabi-size -A "$image" | awk '$1 == ".text" || $1 == ".ARM.exidx" || $1 == ".data" { s += $2 } END { print s + 0 }')
[ "$bytes" -gt 0 ] || { echo "$image: no .text in arm-none-eabi-size -A" >&2; exit 1; }
budget=$((budget_kb * 1024))
echo "$image: flash $bytes bytes, budget $budget ($((budget - bytes)) to spare)"
[ "$bytes" -le "$budget" ] || { echo "$image: flash over the ${budget_kb} KB budget by $((bytes - budget)) bytes" >&2; exit 1; }
