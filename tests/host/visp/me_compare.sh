#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs me_sites built against upstream ViSP and against ports/visp on the same images, sites and
# parameters, and prints the share of (site, frame) pairs whose found position agrees within
# 0.5 px and whose suppression decision agrees. Exits non-zero below TARGET percent.
#   me_compare.sh UPSTREAM_EXE PORTS_EXE TARGET     (sites on visp-images-data's mbt/cube and line)
#   me_compare.sh UPSTREAM_EXE PORTS_EXE masks      (masks and defaults must be identical)
#   me_compare.sh UPSTREAM_EXE PORTS_EXE grey       (RGB24 to grey: within one level everywhere,
#                                                    the same level for at least 99% of colours)
set -euo pipefail
up=$1 ours=$2 target=$3
source "$(dirname "$0")/../../visp_images.sh"
data=$visp_images
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

if [ "$target" = masks ]; then
  status=0
  for size in 3 5 7 9; do
    for n in 180 90 36; do
      "$up" masks $size $n >"$tmp/u"; "$ours" masks $size $n >"$tmp/o"
      cmp -s "$tmp/u" "$tmp/o" || { echo "masks differ: size $size, n_mask $n"; diff "$tmp/u" "$tmp/o" | head; status=1; }
    done
  done
  "$up" defaults >"$tmp/u"; "$ours" defaults >"$tmp/o"
  cmp -s "$tmp/u" "$tmp/o" || { echo "defaults differ"; diff "$tmp/u" "$tmp/o"; status=1; }
  [ $status -eq 0 ] && echo "masks (sizes 3 5 7 9, n_mask 180 90 36) and defaults identical to upstream"
  exit $status
fi

if [ "$target" = grey ]; then
  "$up" grey >"$tmp/u"; "$ours" grey >"$tmp/o"
  paste -d' ' "$tmp/u" "$tmp/o" | awk '
    { n++; d = $8 - $4; count[d]++; if (d < -1 || d > 1) far++ }
    END {
      printf "RGB24 to grey, %d colours, ours - upstream: -1 %.3f%%, 0 %.3f%%, +1 %.3f%%, beyond one level %d\n",
             n, 100 * count[-1] / n, 100 * count[0] / n, 100 * count[1] / n, far
      exit (far == 0 && count[0] >= 0.99 * n) ? 0 : 1
    }'
  exit
fi

# Straight edges of the first frame (i1,j1,i2,j2,spacing): the cube's outline, the paper sheet
# and the pillar in mbt/cube; the edge in line.
cube=(228,316,205,385,5 205,385,238,430,5 232,318,250,355,5 250,355,238,430,5 250,355,348,358,5
      238,430,318,445,5 348,358,320,445,5 232,318,330,330,5 220,150,430,262,6 430,262,330,445,6
      0,172,255,215,6 0,268,255,285,6)
line=(0,112,256,318,4)
run() {  # name range pattern first last segments...
  local name=$1 range=$2 pattern=$3 first=$4 last=$5; shift 5
  "$up" track "$range" "$pattern" "$first" "$last" "$@" >"$tmp/$name.u"
  "$ours" track "$range" "$pattern" "$first" "$last" "$@" >"$tmp/$name.o"
  paste -d' ' "$tmp/$name.u" "$tmp/$name.o" >"$tmp/$name.pairs"
}
run cube4 4 "$data/mbt/cube/image%04d.pgm" 0 120 "${cube[@]}"
run cube7 7 "$data/mbt/cube/image%04d.pgm" 0 120 "${cube[@]}"
run line7 7 "$data/line/image.%04d.pgm" 1 20 "${line[@]}"

# A pair counts while either side still tracks the site (kept at the previous frame, or first frame).
awk -v target="$target" '
  function report(name) {
    printf "%-6s %6d pairs: position within 0.5 px %6.2f%%, decision %6.2f%%, state code %6.2f%%\n",
           name, n[name], 100 * pos[name] / n[name], 100 * dec[name] / n[name], 100 * code[name] / n[name]
  }
  FNR == 1 { file = FILENAME; sub(/.*\//, "", file); sub(/\.pairs$/, "", file); names[file] = 1 }
  {
    key = file " " $2
    alive = ($1 == first[file] || first[file] == "") || live_u[key] || live_o[key]
    if (first[file] == "") first[file] = $1
    if ($1 == first[file]) alive = 1
    if (alive) {
      n[file]++; n["all"]++
      ku = ($3 == 0); ko = ($8 == 0)
      if (ku == ko) { dec[file]++; dec["all"]++ }
      if ($3 == $8) { code[file]++; code["all"]++ }
      di = $4 - $9; dj = $5 - $10
      if (di < 0) di = -di; if (dj < 0) dj = -dj
      if ((ku && ko && di <= 0.5 && dj <= 0.5) || (!ku && !ko)) { pos[file]++; pos["all"]++ }
    }
    live_u[key] = ($3 == 0); live_o[key] = ($8 == 0)
  }
  END {
    for (name in names) report(name)
    report("all")
    ok = 100 * pos["all"] / n["all"] >= target && 100 * dec["all"] / n["all"] >= target
    printf "target %s%%: %s\n", target, ok ? "met" : "NOT met"
    exit ok ? 0 : 1
  }' "$tmp"/cube4.pairs "$tmp"/cube7.pairs "$tmp"/line7.pairs
