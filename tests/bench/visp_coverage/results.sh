#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/visp_coverage.md: for each ViSP 3.5 class in the
# scope of ports/visp (the ME module's headers, the core headers they include, and the core
# classes the ME and pose code use), whether ports/visp has it at upstream's include path, which
# of upstream's public member names it lacks, and which of our tests exercise it.
# Upstream's headers are read from Debian's libvisp-dev (UPSTREAM_VISP_INCLUDE to override).
set -euo pipefail
top=$(cd "$(dirname "$0")/../../.." && pwd)
upstream=${UPSTREAM_VISP_INCLUDE:-/usr/include/x86_64-linux-gnu}
ours="$top/ports/visp/include"
[ -d "$upstream/visp3/me" ] || { echo "visp_coverage: no ViSP headers under $upstream" >&2; exit 1; }

# The ME module's headers, the core headers they include, and the classes the ME sources and
# the pose code use (upstream's modules/tracker/me/src and the issue's list).
scope() {
  for h in "$upstream"/visp3/me/*.h; do echo "me/$(basename "$h")"; done
  grep -ho '#include <visp3/core/[A-Za-z0-9]*\.h>' "$upstream"/visp3/me/*.h | sed 's/.*<visp3\///; s/>//'
  printf 'core/%s.h\n' vpRGBa vpImageConvert vpRobust vpException vpTrackingException vpTranslationVector \
    vpRotationMatrix vpThetaUVector vpHomogeneousMatrix vpPoseVector
}

# Member names a header declares: on declaration lines (indented two spaces, clang-format's and
# our class-member indent), outside comments, the first identifier followed by "(" that is not a
# keyword or macro; operators and destructors are not counted.
members() {
  sed -e 's://.*$::' "$1" | awk '
    /\/\*/ { skip = 1 }
    { line = $0; if (skip) { if (line ~ /\*\//) { sub(/.*\*\//, "", line); skip = 0 } else next } print line }' |
    grep -E '^  [^ ]' | grep -v '^\s*#' |
    sed -E 's/\b(explicit|virtual|static|inline|const|VISP_EXPORT|vp_deprecated|friend)\b//g' |
    grep -oE '\b[A-Za-z_][A-Za-z0-9_]*\s*\(' | head -n 100000 | sed 's/\s*($//' |
    grep -vxE 'if|for|while|switch|return|sizeof|static_cast|const_cast|reinterpret_cast|throw|defined|decltype|operator|noexcept|catch|try|typedef|enum|struct' |
    sort -u || true
}

# Our tests that include the header, or one of our headers that includes it.
tests_using() {
  local header=$1 found="" names
  names=("visp3/$header")
  for h in "$ours"/visp3/*/*.h; do
    if grep -q "include \"visp3/$header\"" "$h"; then names+=("visp3/${h#"$ours"/visp3/}"); fi
  done
  for f in "$top"/tests/ports/visp/*.cxx "$top"/tests/ports/visp/*.cpp "$top"/tests/host/visp/*.cpp; do
    [ -f "$f" ] || continue
    for n in "${names[@]}"; do
      if grep -q "$n" "$f"; then found="$found${found:+, }$(basename "$f")"; break; fi
    done
  done
  echo "${found:-none}"
}

echo "## ViSP classes in ports/visp (visp_coverage)"
echo
echo "\`tests/bench/visp_coverage/results.sh\` against ViSP's headers in \`$upstream\`"
echo "($(dpkg-query -W -f '${Package} ${Version}' libvisp-core-dev 2>/dev/null || echo 'version unknown'))."
echo "Scope: the ME module's headers, the core headers they include, and the core classes the"
echo "ME and pose code use. \"Missing\" lists the member names upstream's header declares and ours"
echo "does not (operators and destructors not counted; protected and deprecated members included);"
echo "tests are ours that include the header, directly or through another of our headers."
echo
echo "| header | status | upstream names | missing in ours | tests |"
echo "|---|---|---|---|---|"
ported=0 total=0
for header in $(scope | sort -u); do
  total=$((total + 1))
  up="$upstream/visp3/$header"
  mine="$ours/visp3/$header"
  n_up=$(members "$up" | wc -l)
  if [ -f "$mine" ]; then
    ported=$((ported + 1))
    missing=$(comm -23 <(members "$up") <(members "$mine") | tr '\n' ' ' | sed 's/ $//; s/ /, /g')
    n_missing=$(comm -23 <(members "$up") <(members "$mine") | wc -l)
    status="ported, $((n_up - n_missing))/$n_up names"
    echo "| \`visp3/$header\` | $status | $n_up | ${missing:-—} | $(tests_using "$header") |"
  else
    echo "| \`visp3/$header\` | not ported | $n_up | all | — |"
  fi
done
echo
echo "$ported of $total headers in scope are ported."
