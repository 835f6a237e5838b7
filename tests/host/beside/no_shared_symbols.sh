#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Lists every symbol that Debian's ViSP library (first argument after nm) and one of our static
# libraries both define, apart from the C++ library's own templates and inline functions, which
# both may carry; fails if there is any.
# Usage: no_shared_symbols.sh NM UPSTREAM_SHARED_LIBRARY OUR_LIBRARY...
set -euo pipefail
nm=$1 upstream=$2
shift 2
for library in "$upstream" "$@"; do
  [ -f "$library" ] || { echo "$0: $library: no such library" >&2; exit 2; }
done
defined() { "$nm" "$@" --defined-only 2>/dev/null | awk 'NF >= 3 && $2 ~ /^[TWVDBRu]$/ { print $3 }' | sort -u; }
shared=$(comm -12 <(defined -D "$upstream") <(defined "$@") | c++filt | grep -v -E '^(std::|__gnu_cxx::|void std::|bool std::|.* std::.*::_M_|typeinfo (name )?for std::|guard variable for std::)' || true)
if [ -n "$shared" ]; then
  echo "symbols defined both by $upstream and by our libraries:"
  echo "$shared"
  exit 1
fi
echo "no symbol of $* is also defined by $upstream"
