#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# smoke.sh FUZZER SEEDS WORK SECONDS: runs FUZZER for SECONDS on a copy of the SEEDS corpus in
# WORK (one job; inputs over 1 s or 2 GB are findings), and fails with libFuzzer's report.
set -euo pipefail
fuzzer=$1 seeds=$2 work=$3 seconds=$4
rm -rf "$work" && mkdir -p "$work/corpus" "$work/findings"
cp "$seeds"/* "$work/corpus/"
cd "$work"
if ! "$fuzzer" -max_total_time="$seconds" -timeout=1 -rss_limit_mb=2048 -max_len=65536 \
     -artifact_prefix="$work/findings/" -print_final_stats=1 corpus >"$work/log.txt" 2>&1; then
  tail -n 40 "$work/log.txt"
  echo "FAIL: $(basename "$fuzzer") found an input that crashes, leaks or hangs: $(ls "$work/findings")"
  exit 1
fi
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$work/log.txt" || true
echo "ok: $(basename "$fuzzer") ran ${seconds} s without a finding"
