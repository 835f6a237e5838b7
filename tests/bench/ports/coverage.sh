#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Writes docs/PORTS.md: each upstream vnl, vnl_algo, vcl and testlib header and test (listed
# offline in upstream_vxl.tsv) with its status in our tree. A header counts as ported when our
# file of the same name exists; a test when our test_<x>.cxx exists and its CMakeLists.txt
# registers it. Reasons for what is left out come from not_ported.tsv, notes on what a ported
# file does differently from notes.tsv.
# Usage: tests/bench/ports/coverage.sh [output]   (default docs/PORTS.md)
set -euo pipefail
top=$(cd "$(dirname "$0")/../../.." && pwd)
here="$top/tests/bench/ports"
out=${1:-$top/docs/PORTS.md}

ours_header() {  # library, upstream path -> our path
  local lib=$1 path=$2 name=${2##*/}
  case $lib in
    vnl) echo "ports/vnl/include/vnl/${name%.in}" ;;
    vnl_algo) echo "ports/vnl/include/vnl/algo/$name" ;;
    vcl)
      local rel=${path#vcl/}
      if [ -e "$top/ports/vcl/include/$rel" ]; then echo "ports/vcl/include/$rel"; else echo "ports/vcl/include/${rel%.in}"; fi ;;
    testlib) echo "ports/testlib/include/testlib/$name" ;;
  esac
}

ours_test_dirs() {  # library -> our test folders
  case $1 in
    vnl) echo "tests/ports/vnl" ;;
    vnl_algo) echo "tests/ports/vnl/algo" ;;
    vcl) echo "tests/ports/vcl" ;;
    testlib) echo "tests/ports/testlib" ;;
  esac
}

note() {  # name -> what a ported file leaves out or does differently, if anything
  awk -F'\t' -v n="$1" '$1 == n { print $2; exit }' "$here/notes.tsv"
}

reason() {  # library, name -> why it is not ported, or a default
  local found
  found=$(awk -F'\t' -v n="$2" '$1 == n { print $2; exit }' "$here/not_ported.tsv")
  if [ -z "$found" ] && [ "$1" = vnl_algo ]; then
    found="outside the scope ported: the paper took LM and what pairs with it (SVD, QR, Cholesky, eigensystem, determinant, inverse)"
  fi
  echo "${found:-not ported yet}"
}

status_of() {  # library, kind, path -> "status<TAB>our file<TAB>note"
  local lib=$1 kind=$2 path=$3 name=${3##*/}
  if [ "$kind" = header ]; then
    local mine
    mine=$(ours_header "$lib" "$path")
    if [ -e "$top/$mine" ]; then
      local n
      n=$(note "$name")
      # A note starting "partial:" marks a header that leaves part of upstream's out.
      if [[ $n == partial:* ]]; then printf 'partial\t%s\t%s\n' "$mine" "${n#partial: }"; else printf 'ported\t%s\t%s\n' "$mine" "$n"; fi
    else
      printf 'missing\t\t%s\n' "$(reason "$lib" "$name")"
    fi
    return
  fi
  local test=${name%.*} dirs
  dirs=$(ours_test_dirs "$lib")
  # Two of upstream's algo tests live in our vnl driver: LM (next to the LM path it was written
  # with) and rank (vnl_rank.h is a core header).
  case $lib/$test in vnl_algo/test_levenberg_marquardt | vnl_algo/test_rank) dirs="tests/ports/vnl" ;; esac
  for dir in $dirs; do
    if [ -e "$top/$dir/$test.cxx" ]; then
      if grep -qw "$test" "$top/$dir/CMakeLists.txt"; then
        printf 'ported\t%s\t%s\n' "$dir/$test.cxx" "$(note "$test")"
      else
        printf 'file only\t%s\tnot registered in %s/CMakeLists.txt\n' "$dir/$test.cxx" "$dir"
      fi
      return
    fi
  done
  printf 'missing\t\t%s\n' "$(reason "$lib" "$test")"
}

declaration_tables() {  # comparison TSV, title of the gap list -> counts per header, then the gaps
  echo "| header | upstream | found | compatible | via alias | other signature | missing |"
  echo "|---|---|---|---|---|---|---|"
  awk -F'\t' '$2 == "total" {
      n = split($3, part, ", "); for (i = 1; i <= n; ++i) { v = part[i]; sub(/.* /, "", v); c[i] = v }
      printf "| `%s` | %d | %s | %s | %s | %s | %s |\n", $1, c[1] + c[2] + c[3] + c[4] + c[5], c[1], c[2], c[3], c[4], c[5]
      for (i = 1; i <= 5; ++i) sum[i] += c[i] }
    END { printf "| all | %d | %d | %d | %d | %d | %d |\n", sum[1] + sum[2] + sum[3] + sum[4] + sum[5], sum[1], sum[2], sum[3], sum[4], sum[5] }' "$1"
  echo
  echo "### $2"
  echo
  awk -F'\t' '!/^#/ && $2 != "total" {
      if ($1 != last) { printf "\n- `%s`:", $1; last = $1; sep = " " }
      printf "%s%s `%s`", sep, ($2 == "missing" ? "missing" : "other"), $3; sep = "; " }
    END { print "" }' "$1" | sed '1{/^$/d}'
}

api_section() {  # upstream_api.tsv -> the section comparing declarations, per header
  local tsv=$here/upstream_api.tsv
  echo
  echo "## vnl and vnl_algo public API against upstream's headers"
  echo
  echo "Each upstream vnl and vnl_algo header's public declarations (functions, methods,"
  echo "constructors, operators with their parameter, return and const types; data members,"
  echo "typedefs) against those a program sees when it includes our header of that name, as"
  echo "\`tests/bench/ports/upstream_api.py VXL_CHECKOUT BUILD_DIR\` measured them into"
  echo "\`tests/bench/ports/upstream_api.tsv\` (run where a VXL checkout exists, not in CI). Both sides"
  echo "are parsed by clang's front end (\`clang++ -fsyntax-only -Xclang -ast-dump=json\`, upstream's"
  echo "configured headers filled with this host's values), not by matching text. *found*: same"
  echo "scope, name and signature; *compatible*: ours takes the same calls (a template of ours,"
  echo "\`const X&\` for upstream's \`X\`, \`size_t\` for \`unsigned int\`); *via alias*: upstream's"
  echo "class is a typedef of ours (\`vnl_double_3\` is \`vnl_vector_fixed<double, 3>\`), its members"
  echo "not compared; *other signature*: ours has the name with other signatures only; *missing*: ours"
  echo "lacks the name. Limits: types are compared as spelled (a typedef spelled differently on the"
  echo "two sides counts as another signature), template parameters by position (P0_1: the second"
  echo "parameter of the outer template); default arguments, noexcept and virtual are not compared;"
  echo "declarations in #if branches the parse does not take (upstream's with this host's"
  echo "configuration, ours with the double build's) are not seen."
  echo
  declaration_tables "$tsv" "Declarations ours lacks or declares otherwise"
}

checks_section() {  # upstream_checks.tsv -> per upstream test, the checks ours covers
  local tsv=$here/upstream_checks.tsv
  echo
  echo "## Upstream's checks covered by our tests"
  echo
  echo "Per upstream vnl and vnl_algo test: its checks (TEST, TEST_NEAR, testlib_test_assert... calls),"
  echo "and those whose exercised functions our test of the same name also calls, as"
  echo "\`tests/bench/ports/upstream_checks.py VXL_CHECKOUT BUILD_DIR\` measured them into"
  echo "\`tests/bench/ports/upstream_checks.tsv\` (run where a VXL checkout exists, not in CI). A check"
  echo "exercises the vnl and vnl_algo API names (functions, methods, constructors, as read from"
  echo "upstream's headers) called in its arguments or in the code since the previous check; it is"
  echo "covered when our test calls each of those names. A name matches as an identifier, so a name"
  echo "several classes share (\`size\`, \`get\`) counts once, and covering a name says our test calls"
  echo "it, not that it checks the same values; operators are not counted."
  echo
  echo "| upstream test | checks | covered | names upstream's checks call and ours does not (checks) |"
  echo "|---|---|---|---|"
  awk -F'\t' '!/^#/ { printf "| `%s` | %d | %d | %s |\n", $1, $2, $3, $4; n += $2; c += $3 }
    END { printf "| all | %d | %d |  |\n", n, c }' "$tsv"
}

visp_section() {  # visp_coverage/signatures.tsv -> the section comparing ports/visp with ViSP 3.5
  local tsv=$top/tests/bench/visp_coverage/signatures.tsv
  echo
  echo "## ports/visp against ViSP 3.5's headers"
  echo
  echo "The same comparison for the ViSP headers ports/visp mirrors (the ME classes and the core"
  echo "classes they use), against Debian's libvisp-dev read without VISP_BUILD_DEPRECATED_FUNCTIONS"
  echo "(deprecated members, some of them public data members there, are not counted), ours in the"
  echo "double build: \`tests/bench/visp_coverage/signatures.py BUILD_DIR\` writes"
  echo "\`tests/bench/visp_coverage/signatures.tsv\`. Gaps left on purpose: \`display\` (ports/ draw"
  echo "nothing: no vpDisplay), the click-driven \`initTracking(I)\` of vpMeLine and"
  echo "\`initTracking(I, trackArc)\` of vpMeEllipse (they wait for clicks in a vpDisplay window),"
  echo "\`vpMe::getMask\` (ours returns int16 tables read as \`mask[k][a][b]\`, not vpMatrix, see"
  echo "docs/ME.md), vpImage's min/max queries (upstream throws on an empty image; the bare-metal tree"
  echo "builds without exceptions), and the core classes' members no ME program needs (vpMatrix's"
  echo "decompositions, vpImageConvert's colour formats, vpRect-based vpImagePoint queries)."
  echo
  declaration_tables "$tsv" "ViSP declarations ours lacks or declares otherwise"
}

rows=$(grep -v '^#' "$here/upstream_vxl.tsv" | while IFS=$'\t' read -r lib kind path; do
  printf '%s\t%s\t%s\t%s\n' "$lib" "$kind" "$path" "$(status_of "$lib" "$kind" "$path")"
done)
commit=$(sed -n 's/.*at commit \([0-9a-f]*\).*/\1/p' "$here/upstream_vxl.tsv" | head -1)

{
  echo "# Ports coverage: vnl, vnl_algo, vcl and testlib against upstream VXL"
  echo
  echo "Generated by \`tests/bench/ports/coverage.sh\` from the tree and from"
  echo "\`tests/bench/ports/upstream_vxl.tsv\` (upstream's file list at vxl/vxl commit \`${commit:0:12}\`)."
  echo "Do not edit by hand. A header is ported when our file of that name exists under \`ports/\`;"
  echo "a test when our \`test_<x>.cxx\` of that name exists and is registered in its driver, so it"
  echo "runs in every CI tree (host double, host s40_23, host asan, arm s40_23 and arm double under"
  echo "\`qemu-arm -cpu pxa270\`). Our code and tests are our own; only names, signatures and the"
  echo "behaviour checked follow upstream. Notes on the algorithms we chose are in \`docs/ARCHITECTURE.md\`."
  echo
  echo "| library | headers ported | of which partial | tests ported |"
  echo "|---|---|---|---|"
  for lib in vnl vnl_algo vcl testlib; do
    h_all=$(awk -F'\t' -v l="$lib" '$1 == l && $2 == "header"' <<<"$rows" | wc -l)
    h_ok=$(awk -F'\t' -v l="$lib" '$1 == l && $2 == "header" && ($4 == "ported" || $4 == "partial")' <<<"$rows" | wc -l)
    h_part=$(awk -F'\t' -v l="$lib" '$1 == l && $2 == "header" && $4 == "partial"' <<<"$rows" | wc -l)
    t_all=$(awk -F'\t' -v l="$lib" '$1 == l && $2 == "test"' <<<"$rows" | wc -l)
    t_ok=$(awk -F'\t' -v l="$lib" '$1 == l && $2 == "test" && $4 == "ported"' <<<"$rows" | wc -l)
    echo "| $lib | $h_ok / $h_all | $h_part | $t_ok / $t_all |"
  done
  measured=("$here"/upstream_tests/*.tsv)
  if [ -e "${measured[0]}" ]; then
    echo
    echo "## VXL's own tests compiled against ports/"
    echo
    echo "Upstream's \`core/vnl/tests\` driver tests and vnl_algo's \`test_levenberg_marquardt.cxx\`, each"
    echo "compiled unchanged against ports/ and our testlib and run, from a VXL checkout at the commit"
    echo "above, outside this repository: neither fetched code nor a script that builds it is committed,"
    echo "so \`tests/bench/ports/upstream_tests/BUILD.tsv\` holds each build's outcome as measured. test_matlab and"
    echo "test_sample need VXL's vpl and vul libraries, which are not ported."
    echo
    echo "What of upstream's tests depends on the platform or the configuration: the long double"
    echo "checks of test_math and test_bignum compile only with INCLUDE_LONG_DOUBLE_TESTS, which"
    echo "neither upstream's build nor this check defines (on ARM EABI long double is double anyway);"
    echo "the out-of-bounds sections of test_diag_matrix and test_diag_matrix_fixed compile only with"
    echo "VNL_CONFIG_CHECK_BOUNDS, which is 0 in our vnl_config.h (our containers do not throw on an"
    echo "index out of range), so they are not run. The ARM double build computes double in software"
    echo "(the PXA270 has no FPU)."
    echo
    echo "| build | compile | pass |"
    echo "|---|---|---|"
    for file in "${measured[@]}"; do
      awk -F'\t' '$1 ~ /^total / { sub(/^total /, "", $1); printf "| %s | %s | %s |\n", $1, $2, $3 }' "$file"
    done
    echo
    printf '| test |'
    for file in "${measured[@]}"; do printf ' %s |' "$(basename "$file" .tsv)"; done
    echo ' why not |'
    printf '|---|'
    for file in "${measured[@]}"; do printf -- '---|'; done
    echo '---|'
    # The first file is upstream_test_notes.tsv (test, why it does not compile or pass).
    awk -F'\t' 'FILENAME ~ /notes/ { why[$1] = $2; next }
      FNR == 1 { ++n } FNR > 1 && $1 !~ /^total / {
        if (!($1 in seen)) { seen[$1] = 1; order[++count] = $1 }
        cell[$1, n] = $2 == "no" ? "does not compile" : ($3 == "yes" ? "passes" : "fails") }
      END { for (i = 1; i <= count; ++i) { t = order[i]; printf "| `%s` |", t
              all = 1
              for (j = 1; j <= n; ++j) { printf " %s |", ((t, j) in cell ? cell[t, j] : "-"); all = all && cell[t, j] == "passes" }
              printf " %s |\n", all ? "" : why[t] } }' \
      "$here/upstream_test_notes.tsv" "${measured[@]}"
  fi
  if [ -e "$here/upstream_api.tsv" ]; then api_section; fi
  if [ -e "$here/upstream_checks.tsv" ]; then checks_section; fi
  if [ -e "$top/tests/bench/visp_coverage/signatures.tsv" ]; then visp_section; fi
  for lib in vnl vnl_algo vcl testlib; do
    for kind in header test; do
      echo
      echo "## $lib ${kind}s"
      echo
      echo "| upstream | status | ours | note |"
      echo "|---|---|---|---|"
      awk -F'\t' -v l="$lib" -v k="$kind" '$1 == l && $2 == k {
        ours = $5 == "" ? "" : "`" $5 "`"
        printf "| `%s` | %s | %s | %s |\n", $3, $4, ours, $6 }' <<<"$rows"
    done
  done
} >"$out"
echo "coverage: wrote ${out#"$top"/}"
