#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# run.sh FUZZ_BUILD SECONDS [TARGET...]: a long fuzzing campaign. Runs each target (all of
# tests/fuzz by default) for SECONDS on its seed corpus, growing a corpus under
# FUZZ_BUILD/campaign/TARGET, one job per target, and prints a Markdown table row per target:
# executions, corpus files, peak memory, slowest input, findings (crash-, leak-, timeout- and
# oom- files). Exits non-zero when any target found something. The fuzz tree is the one
# tests/run-all.sh builds (host-fuzz).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd) seconds=$2
shift 2
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(cao obj pos points camera_xml netpbm raw_rgb565 pose_table templates camera_file api)
found=0
echo "| target | seconds | executions | corpus files | peak RSS (MB) | slowest input (whole s) | findings |"
echo "|---|---:|---:|---:|---:|---:|---|"
for target in "${targets[@]}"; do
  fuzzer=$build/tests/fuzz/fuzz_$target
  work=$build/campaign/$target
  mkdir -p "$work/corpus" "$work/findings"
  cp -n "$here/corpus/$target"/* "$work/corpus/"
  (cd "$work" && ASAN_OPTIONS=detect_leaks=1 "$fuzzer" -max_total_time="$seconds" -timeout=1 -rss_limit_mb=2048 \
     -max_len=65536 -artifact_prefix="$work/findings/" -print_final_stats=1 corpus >"$work/log.txt" 2>&1)
  status=$?
  stat() { sed -n "s/^stat::$1: *//p" "$work/log.txt" | tail -n 1; }
  findings=$(ls "$work/findings" | tr '\n' ' ')
  [ "$status" -eq 0 ] && [ -z "$findings" ] && [ -n "$(stat number_of_executed_units)" ] ||
    { found=1; findings="${findings:-the fuzzer exited with $status: $work/log.txt}"; }
  echo "| $target | $seconds | $(stat number_of_executed_units) | $(ls "$work/corpus" | wc -l) | $(stat peak_rss_mb) | $(stat slowest_unit_time_sec) | ${findings:-none} |"
done
exit $found
