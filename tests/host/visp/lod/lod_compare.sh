#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs lod_visibility built against Debian's ViSP and against edgetrack on the same model,
# configuration and poses, and checks that the same faces and lines are kept at every pose. Prints
# how many were compared and how many of them level of detail hid.
#   lod_compare.sh UPSTREAM_EXE OURS_EXE DIR
set -euo pipefail
up=$1 ours=$2 dir=$3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$up" "$dir/lod_config.xml" "$dir/lod_model.cao" "$dir/poses.txt" 640 480 2>/dev/null | grep "^kept " | sort >"$tmp/u"
"$ours" "$dir/lod_config.xml" "$dir/lod_model.cao" "$dir/poses.txt" 640 480 | grep "^kept " | sort >"$tmp/o"
if ! diff "$tmp/u" "$tmp/o" >"$tmp/d"; then
  echo "ViSP (<) and edgetrack (>) keep different primitives:"; cat "$tmp/d"; exit 1
fi
echo "level of detail: $(wc -l <"$tmp/o") primitive-poses agree with ViSP, $(grep -c hidden "$tmp/o") of them hidden"
[ -s "$tmp/o" ]
