#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# copy_init_probe.sh COMPILER PROBE -I...: the probe's stated conversions compile, and
# copy-initialising fixed64 from a double is refused by the compiler for that reason.
set -u
export LC_ALL=C  # the compiler's quotes in ASCII
compiler=$1 probe=$2
shift 2
"$compiler" -std=c++17 -fsyntax-only "$@" "$probe" || { echo "FAIL: the forms that must compile do not"; exit 1; }
if out=$("$compiler" -std=c++17 -fsyntax-only -DPROBE_DOUBLE "$@" "$probe" 2>&1); then
  echo "FAIL: 'fixed64 x = 0.5;' compiles (it would silently be 0)"; exit 1
fi
echo "$out" | grep -qE "conversion from .double." || { echo "FAIL: refused for another reason:"; echo "$out"; exit 1; }
echo "ok: real(0.5) and real x = 2 compile; real x = 0.5 is refused: $(echo "$out" | grep -m1 "conversion from")"
