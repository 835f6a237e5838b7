#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# check_float_free.sh <objdump> <object>...: disassembles fixed64's out-of-line operations and
# fails if any calls a soft-float routine (libgcc's __aeabi_d*/__aeabi_f*, the __*df3/__*sf3
# family, int<->float conversions) or uses an x86 SSE/x87 floating-point instruction.
set -euo pipefail
objdump=${1:?usage: check_float_free.sh <objdump> <object>...}
shift
listing=$("$objdump" -d -r -C "$@")
functions=$(grep -c '^[0-9a-f]* <fixed64_probe::' <<<"$listing" || true)
echo "check_float_free: $functions probe functions disassembled"
[ "$functions" -ge 44 ] || { echo "check_float_free: expected at least 44 probe functions" >&2; exit 1; }
soft_float='__aeabi_(d[a-z]|f[a-z]|[iul]+2[df]|[df]2[iul])|__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord)[sdt]f[23]|__(float|fix|extend|trunc)[a-z]*[sdt]f'
x86_float='\b(cvt[a-z0-9]*|(add|sub|mul|div|sqrt|min|max|ucomi|comi|mov)s[sd]|fld[a-z0-9]*|fst[a-z]*|fmul[a-z]*|fadd[a-z]*|fdiv[a-z]*)\b'
bad=$(grep -nE "$soft_float|$x86_float" <<<"$listing" || true)
if [ -n "$bad" ]; then
  echo "check_float_free: floating-point code inside fixed64 operations:" >&2
  echo "$bad" | head -n 40 >&2
  exit 1
fi
echo "check_float_free: no soft-float call and no floating-point instruction"
