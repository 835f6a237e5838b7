#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs transforms.cpp (or lens_conversions.cpp) built against upstream ViSP and against ours and
# checks that every printed number agrees within TOLERANCE (absolute; the numbers are rotation
# entries, radians and metres of order 1, or pixels). Prints the largest difference. A theta u
# (tu, and pose 3..5) whose theta is within RESOLUTION of pi (the real's ulp; 0 for double) may come back as -theta u, the same
# rotation: below that ulp sin(theta), which gives the axis its sign, is not representable.
#   transforms_compare.sh UPSTREAM_EXE PORTS_EXE TOLERANCE RESOLUTION
set -euo pipefail
up=$1 ours=$2 tolerance=$3 resolution=$4
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$up" >"$tmp/u"
"$ours" >"$tmp/o"
[ "$(wc -l <"$tmp/u")" -eq "$(wc -l <"$tmp/o")" ] || { echo "outputs differ in length"; exit 1; }
paste -d' ' "$tmp/u" "$tmp/o" | awk -v tol="$tolerance" -v ulp="$resolution" '
  function absd(x) { return x < 0 ? -x : x }
  function keep(d, name) { if (d > worst) { worst = d; where = name } }
  { h = NF / 2; n++
    k = $1 == "tu" ? $2 : ($1 == "pose" && $2 >= 3 ? $2 - 3 : -1)
    if (k < 0) { keep(absd($h - $NF), $1); next }
    u[k] = $h; o[k] = $NF
    if (k < 2) next
    same = 0; opposite = 0
    for (j = 0; j < 3; j++) {
      if (absd(u[j] - o[j]) > same) same = absd(u[j] - o[j])
      if (absd(u[j] + o[j]) > opposite) opposite = absd(u[j] + o[j])
    }
    theta = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
    keep(3.14159265358979 - theta <= ulp && opposite < same ? opposite : same, $1)
  }
  END {
    printf "transformations: %d numbers, largest difference %.3g (in %s), tolerance %s\n", n, worst, where, tol
    exit (n > 0 && worst <= tol) ? 0 : 1
  }'
