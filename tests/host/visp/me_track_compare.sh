#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs ViSP's line or ellipse tracking example set-up (tests/ports/visp/track_me_*.cpp) built
# against upstream ViSP and against ports/visp, frame by frame, and checks that they agree:
# the same number of sites in every frame, the same state for every site, site positions and
# the line's rho, theta (or the ellipse's centre, A, B, E) within the given tolerances.
# Prints the measured maxima. Exits non-zero when a tolerance is exceeded.
#   me_track_compare.sh UPSTREAM_EXE PORTS_EXE line    RHO_PX THETA_RAD SITE_PX
#   me_track_compare.sh UPSTREAM_EXE PORTS_EXE ellipse AXES_PX E_RAD    SITE_PX
set -euo pipefail
up=$1 ours=$2 kind=$3 tol_shape=$4 tol_angle=$5 tol_site=$6
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$up" --sites >"$tmp/u" || { echo "upstream run failed"; exit 1; }
"$ours" --sites >"$tmp/o" || { echo "ports run failed"; exit 1; }
[ "$(wc -l <"$tmp/u")" -eq "$(wc -l <"$tmp/o")" ] || { echo "outputs differ in length (site counts differ)"; exit 1; }

paste -d' ' "$tmp/u" "$tmp/o" | awk -v kind="$kind" -v ts="$tol_shape" -v ta="$tol_angle" -v tp="$tol_site" '
  function absd(x) { return x < 0 ? -x : x }
  function keep(name, v) { if (v > worst[name]) worst[name] = v }
  $1 == "site" {
    # site FRAME K STATE I J ALPHA | site FRAME K STATE I J ALPHA
    if ($2 != $9 || $3 != $10) { misaligned++; next }
    sites++
    if ($4 != $11) states++
    keep("site", absd($5 - $12) > absd($6 - $13) ? absd($5 - $12) : absd($6 - $13))
    next
  }
  $1 == "line" {
    # line FRAME RHO THETA A B C SITES
    frames++; off = 8
    if ($8 != $(8 + off)) counts++
    d = absd($3 - $(3 + off)) > absd($4 - $(4 + off)) ? absd($3 - $(3 + off)) : absd($4 - $(4 + off))
    if (d <= 1e-6) exact++
    keep("shape", absd($3 - $(3 + off))); keep("angle", absd($4 - $(4 + off)))
    next
  }
  $1 == "ellipse" {
    # ellipse FRAME UC VC A B E N20 N11 N02 SITES
    frames++; off = 11
    if ($11 != $(11 + off)) counts++
    d = 0
    for (c = 3; c <= 7; c++) if (absd($c - $(c + off)) > d) d = absd($c - $(c + off))
    if (d <= 1e-6) exact++
    for (c = 3; c <= 6; c++) keep("shape", absd($c - $(c + off)))
    keep("angle", absd($7 - $(7 + off)))
    next
  }
  END {
    shape = kind == "line" ? "rho" : "centre, A, B"
    angle = kind == "line" ? "theta" : "E"
    printf "%s: %d frames (%d equal to 1e-6), %d sites; site-count mismatches %d, state mismatches %d\n",
           kind, frames, exact, sites, counts, states
    printf "  max |d %s| %.3g px (tolerance %s), max |d %s| %.3g rad (tolerance %s), max site offset %.3g px (tolerance %s)\n",
           shape, worst["shape"], ts, angle, worst["angle"], ta, worst["site"], tp
    ok = frames > 0 && misaligned == 0 && counts == 0 && states == 0 && worst["shape"] <= ts && worst["angle"] <= ta && worst["site"] <= tp
    print ok ? "agreement: met" : "agreement: NOT met"
    exit ok ? 0 : 1
  }'
