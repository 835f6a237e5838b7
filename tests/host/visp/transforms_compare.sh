#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs transforms.cpp built against upstream ViSP and against ports/visp and checks that every
# printed number agrees within TOLERANCE (absolute; the numbers are rotation entries, radians and
# metres of order 1). Prints the largest difference.
#   transforms_compare.sh UPSTREAM_EXE PORTS_EXE TOLERANCE
set -euo pipefail
up=$1 ours=$2 tolerance=$3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$up" >"$tmp/u"
"$ours" >"$tmp/o"
[ "$(wc -l <"$tmp/u")" -eq "$(wc -l <"$tmp/o")" ] || { echo "outputs differ in length"; exit 1; }
paste -d' ' "$tmp/u" "$tmp/o" | awk -v tol="$tolerance" '
  { h = NF / 2; d = $h - $NF; if (d < 0) d = -d; n++
    if (d > worst) { worst = d; where = $1 } }
  END {
    printf "transformations: %d numbers, largest difference %.3g (in %s), tolerance %s\n", n, worst, where, tol
    exit (n > 0 && worst <= tol) ? 0 : 1
  }'
