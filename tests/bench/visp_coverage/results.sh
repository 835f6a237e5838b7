#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints the markdown section for docs/results/visp_coverage.md: for each ViSP 3.5 class in the
# scope of ports/visp (the ME module's headers, the core headers they include, and the core
# classes the ME and pose code use), whether ports/visp has it at upstream's include path, which
# of upstream's public member names it lacks, and which of our tests exercise it; then upstream's
# own tests of those classes (ViSP v3.5.0's modules/core/test and modules/tracker/me/test, listed
# below from upstream's tree) with the test of ours that covers the same class.
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
echo "Names only: \`tests/bench/visp_coverage/signatures.py\` compares whole declarations (parameter,"
echo "return and const types) with clang's front end, and docs/PORTS.md lists the gaps it finds."
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
echo
echo "### Upstream's tests of these classes"
echo
echo "ViSP v3.5.0's tests in \`modules/core/test\` and \`modules/tracker/me/test\` for the classes above"
echo "(upstream has no test of vpMe, vpMeSite, vpMeTracker, vpMeLine or vpMeEllipse; ours are the"
echo "\`test_me_*\` tests and the trackMeLine/trackMeEllipse comparisons in \`tests/host/visp\`)."
echo
echo "| upstream test | what it checks | ours | status |"
echo "|---|---|---|---|"
# upstream test | what it checks | our test | what ours leaves out
while IFS='|' read -r upstream_test checks our_test left_out; do
  if [ -f "$top/tests/ports/visp/$our_test.cxx" ] || [ -f "$top/tests/host/visp/$our_test" ]; then
    status="ported${left_out:+; not: $left_out}"
  else
    status="not ported${left_out:+ ($left_out)}"; our_test="—"
  fi
  echo "| \`$upstream_test\` | $checks | \`$our_test\` | $status |"
done <<'TESTS'
image/testImagePoint.cpp|set_i/j/u/v, == and !=|test_image_point|
math/testMath.cpp|round, equal, isNaN/isInf, saturate, mean/median/stdev|test_math|isNaN, isInf, saturate, getMean/Median/Stdev (not ported)
math/testColVector.cpp|resize, insert, stack, t, median, stdev|test_matrix|insert, stack, t, median, stdev (not ported)
math/testMatrix.cpp|eye, getCol/Row/Diag, insert, stack, juxtapose, hadamard, t, load/save|test_matrix|getRow, getDiag, stack, juxtapose, hadamard, load/save (not ported)
math/testSvd.cpp|SVD of random matrices (A = U W V^T), eigenValues of AtA, det|test_matrix|eigenValues, AtA, det (not ported)
math/testMatrixPseudoInverse.cpp|pseudo-inverse (A A+ A = A) per backend|test_matrix|per-backend variants (ours has one)
math/testRobust.cpp|Tukey's weight formula over residues -10..10, written to a file (vpRobust is not called)|test_robust|
math/testRotation.cpp|R, theta u, Euler angles and quaternions back and forth; isARotationMatrix|test_transformations|Euler angles, quaternions (not ported)
math/testHomogeneousMatrix.cpp|re-orthogonalising a nearly orthonormal rotation on construction|test_transformations|re-orthogonalisation (not ported: ours keeps the entries given)
math/testPoseVector.cpp|constructors, buildFrom (t, R), (t, tu), M; set, size, assignment|test_transformations|
math/testTranslationVector.cpp|cross product, skew matrix, norms|test_transformations|
tracker/me/test/testNurbs.cpp|vpNurbs curve fitting|—|vpMeNurbs and vpNurbs are outside the paper's scope
TESTS

