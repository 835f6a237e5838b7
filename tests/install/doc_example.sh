#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The example of docs/API.md is real code: its ```cpp block, line for line (indentation aside),
# is a run of lines of examples/minimal/minimal.cpp, which the package tests build and run.
#   doc_example.sh <source-dir>
set -euo pipefail
source=$1
strip() { sed 's/^[[:space:]]*//; /^$/d'; }
block=$(awk '/^```cpp$/ { inside = 1; next } /^```$/ { inside = 0 } inside' "$source/docs/API.md" | strip)
[ -n "$block" ] || { echo "docs/API.md has no \`\`\`cpp block" >&2; exit 1; }
program=$(strip <"$source/examples/minimal/minimal.cpp")
lines=$(wc -l <<<"$block")
echo "docs/API.md: a $lines-line example"
if ! awk -v n="$lines" 'FNR == NR { want[FNR] = $0; next }
       { have[FNR] = $0 }
       END { for (s = 1; s + n - 1 <= FNR; s++) { ok = 1; for (i = 1; i <= n; i++) if (have[s + i - 1] != want[i]) { ok = 0; break }
             if (ok) exit 0 } ; exit 1 }' <(echo "$block") <(echo "$program"); then
  echo "docs/API.md's example is not the code of examples/minimal/minimal.cpp: update one from the other" >&2
  exit 1
fi
