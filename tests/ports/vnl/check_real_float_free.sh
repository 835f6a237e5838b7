#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# check_real_float_free.sh <objdump> <library>...: disassembles vnl's fixed-point `real`
# instances and fails if a function computing on real calls a soft-float routine or uses an
# x86 floating-point instruction. Exempt are the functions whose upstream signature carries a
# double (a tolerance or an angle converted once at the call, e.g. vnl_svd::zero_out_absolute)
# and text I/O (operator<<, read_ascii, the minimisers' diagnose_outcome, verbose report_iter and
# check_jacobian), which print and read reals as doubles.
set -euo pipefail
objdump=${1:?usage: check_real_float_free.sh <objdump> <library>...}
shift
listing=$("$objdump" -d -r -C "$@")
soft_float='__aeabi_(d[a-z]|f[a-z]|[iul]+2[df]|[df]2[iul])|__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord)[sdt]f[23]|__(float|fix|extend|trunc)[a-z]*[sdt]f'
x86_float='\b(cvt[a-z0-9]*|(add|sub|mul|div|sqrt|min|max|ucomi|comi|mov)s[sd]|fld[a-z0-9]*|fst[a-z]*|fmul[a-z]*|fadd[a-z]*|fdiv[a-z]*)\b'
exempt='double|float|operator<<|operator>>|read_ascii|::read\(|::print\(|print_element|read_element|::angle\(\)|diagnose_outcome|report_iter|check_jacobian'
report=$(awk -v soft="$soft_float|$x86_float" '
  /^[0-9a-f]+ <.*>:$/ { fn = $0; if (fn ~ /fixed64/) real_functions++ ; next }
  fn ~ /fixed64/ && $0 ~ soft { bad[fn] = 1 }
  END { print "functions " real_functions; for (f in bad) print f }' <<<"$listing")
count=$(head -1 <<<"$report" | cut -d' ' -f2)
echo "check_real_float_free: $count functions on fixed-point real disassembled"
[ "${count:-0}" -ge 100 ] || { echo "check_real_float_free: expected at least 100 such functions" >&2; exit 1; }
offenders=$(tail -n +2 <<<"$report" | grep -vE "$exempt" || true)
exempted=$(tail -n +2 <<<"$report" | grep -cE "$exempt" || true)
echo "check_real_float_free: $exempted exempt functions (double in the upstream signature, or text I/O)"
if [ -n "$offenders" ]; then
  echo "check_real_float_free: floating point inside real arithmetic:" >&2
  echo "$offenders" | head -n 40 >&2
  exit 1
fi
echo "check_real_float_free: no other function on real uses floating point"
