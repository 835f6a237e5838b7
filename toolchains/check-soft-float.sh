#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Checks that every ARM executable under a build directory is ARMv5TE soft-float: no VFP
# architecture or VFP-argument attributes (the PXA270 has no FPU; qemu -cpu pxa270 would trap).
set -euo pipefail
dir=${1:?usage: check-soft-float.sh <arm build dir>}
readelf=arm-linux-gnueabi-readelf
checked=0 bad=0
while IFS= read -r -d '' binary; do
  head -c 4 "$binary" | grep -q $'\x7fELF' || continue
  attributes=$("$readelf" -A "$binary")
  checked=$((checked + 1))
  if ! grep -q 'Tag_CPU_arch: v5TE' <<<"$attributes" || grep -qE 'Tag_FP_arch|Tag_ABI_VFP_args|Tag_Advanced_SIMD_arch' <<<"$attributes"; then
    echo "check-soft-float: $binary is not ARMv5TE soft-float:" >&2
    grep -E 'Tag_CPU_arch|Tag_FP_arch|Tag_ABI_VFP_args|Tag_Advanced_SIMD' <<<"$attributes" >&2 || true
    bad=$((bad + 1))
  fi
done < <(find "$dir" -type f -perm -u+x -not -path '*/CMakeFiles/*' -print0)
if [ "$checked" -eq 0 ]; then echo "check-soft-float: no ARM executable found under $dir" >&2; exit 1; fi
echo "check-soft-float: $checked ARM executables checked, $bad not soft-float ARMv5TE"
[ "$bad" -eq 0 ]
