#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The README's first command. Until the tracker exists it installs what is missing, builds the
# ARMv5TE tree and prints the table that motivates the port: guest instructions per arithmetic
# operation for double, float, S47.16 and S40.23 on qemu-arm -cpu pxa270, counted by
# toolchains/qemu/count-insns.sh (tests/bench/real_ops/results.sh). Builds under build/.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/toolchains/install-deps.sh"
"$top/tests/bench/real_ops/results.sh"
