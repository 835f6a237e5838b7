#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs a static ARM binary under QEMU with our instruction-counting plugin and reports how many
# guest instructions it executed, how many of them inside libgcc's soft-float routines, and the
# same inside the edgetrack_count_begin()/edgetrack_count_end() windows. The binary names its
# target: ARMv5TE soft-float on qemu-arm -cpu pxa270, ARMv7-A hard-float on qemu-arm -cpu
# cortex-a7, AArch64 on qemu-aarch64 -cpu cortex-a53 ($EDGETRACK_QEMU_CPU picks another core);
# with EDGETRACK_COUNT_TRIPLE=arm-none-eabi, a firmware image of the bare-metal tree on
# qemu-system-arm's mps2-an385 (toolchains/mcu/run-firmware.sh).
#
#   count-insns.sh [--out FILE] [--windows FILE] [--profile FILE] [--mode tb|insn] <arm-binary> [args...]
#
# The program's stdout and stderr pass through and its exit status is returned. The summary line
#   edgetrack-count total=N softfloat=N windows=N window_total=N window_softfloat=N unbalanced=N
# goes to FILE with --out, else to stderr; --windows FILE gets one line per window
# ("window <i> insns=N softfloat=N"); --profile FILE gets a flat profile of the windows (of the
# whole run, without markers), most first: "<instructions> <calls> <function>", a block counting
# for the function it starts in. The plugin is a host library, built here on first use with the
# host C compiler ($EDGETRACK_HOST_CC, default cc) into $EDGETRACK_PLUGIN_DIR (default
# $EDGETRACK_BUILD_ROOT/qemu-plugin, else build/qemu-plugin).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/../.." && pwd)

usage() { sed -n '7p' "$0" | sed 's/^# *//' >&2; exit 2; }

out= windows= profile= mode=tb
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --windows) windows=$2; shift 2 ;;
    --profile) profile=$2; shift 2 ;;
    --mode) mode=$2; shift 2 ;;
    --) shift; break ;;
    -*) usage ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || usage
binary=$1; shift
[ -f "$binary" ] || { echo "count-insns: no such binary: $binary" >&2; exit 2; }
# Symbol addresses are only run-time addresses in a non-PIE executable (ELF type EXEC).
header=$(readelf -h "$binary" 2>/dev/null || true)
if ! grep -q 'Type: *EXEC' <<<"$header" || ! grep -qE 'Machine: *(ARM|AArch64)' <<<"$header"; then
  echo "count-insns: $binary is not a non-PIE ARM executable (link it with -static -no-pie)" >&2
  exit 2
fi
if grep -q 'Machine: *AArch64' <<<"$header"; then
  triple=aarch64-linux-gnu qemu=qemu-aarch64 cpu=cortex-a53
elif readelf -A "$binary" | grep -q 'Tag_ABI_VFP_args: VFP registers'; then
  triple=arm-linux-gnueabihf qemu=qemu-arm cpu=cortex-a7
else
  triple=arm-linux-gnueabi qemu=qemu-arm cpu=pxa270
fi
# A bare-metal firmware carries no ABI tag that tells it from a Linux one: the caller names it.
[ "${EDGETRACK_COUNT_TRIPLE:-}" = arm-none-eabi ] && triple=arm-none-eabi
cpu=${EDGETRACK_QEMU_CPU:-$cpu}
sysroot=${EDGETRACK_ARM_SYSROOT:-/usr/$triple}

# Build the plugin when it is missing or older than its sources; rename into place, so parallel
# runs never load a half-written library.
plugin_dir=${EDGETRACK_PLUGIN_DIR:-${EDGETRACK_BUILD_ROOT:-$top/build}/qemu-plugin}
plugin=$plugin_dir/insn_count.so
if [ ! -f "$plugin" ] || [ "$here/insn_count.c" -nt "$plugin" ] || [ "$here/qemu_plugin_api.h" -nt "$plugin" ]; then
  mkdir -p "$plugin_dir"
  "${EDGETRACK_HOST_CC:-cc}" -std=c11 -O2 -Wall -Wextra -shared -fPIC -fvisibility=hidden \
    -o "$plugin.$$" "$here/insn_count.c"
  mv -f "$plugin.$$" "$plugin"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/count-insns.XXXXXX")
trap 'rm -rf "$work"' EXIT

# Soft-float routines: every global function that libgcc's floating-point members define (the
# ARM assembly ones, _arm_*df*/_arm_*sf*, and the C soft-fp ones: fix*, float*, pow*, complex,
# fp16). Their names are then looked up in the binary, which is static, so addresses are final.
libgcc=$($triple-gcc -print-libgcc-file-name)
$triple-nm -A --defined-only "$libgcc" 2>/dev/null |
  awk '{ n = split($1, path, ":"); member = path[n - 1] }
       member ~ /(df|sf|dc3|sc3|fp16)/ && ($(NF-1) == "T" || $(NF-1) == "W") { print $NF }' |
  sort -u >"$work/softfloat-names"

# Function ranges from the binary: [address, address + size), or up to the next code symbol when
# the size is missing. Bit 0 (a Thumb entry) is cleared.
$triple-nm --defined-only -S -n "$binary" >"$work/symbols"
awk 'function hex(s,   v, i) { v = 0; for (i = 1; i <= length(s); ++i) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1; return v }
     NR == FNR { wanted[$1] = 1; next }
     { if (NF == 4) { size = $2; type = $3 } else { size = ""; type = $2 } }
     type !~ /^[TtWw]$/ { next }
     { a = hex($1); a -= a % 2
       if (pending != "" && a > pending) { printf "%x %x %s\n", pending, a, pending_name; pending = "" }
       if (!($NF in wanted)) next
       if (size != "") printf "%x %x %s\n", a, a + hex(size), $NF
       else if (pending == "") { pending = a; pending_name = $NF } }' \
  "$work/softfloat-names" "$work/symbols" >"$work/ranges"

marker_address() { awk -v n="$1" '$NF == n { print "0x" $1; exit }' "$work/symbols"; }
escape() { printf '%s' "${1//,/,,}"; }  # QEMU option syntax doubles commas
args="ranges=$(escape "$work/ranges"),mode=$mode,out=$(escape "${out:-$work/summary}")"
begin=$(marker_address edgetrack_count_begin)
end=$(marker_address edgetrack_count_end)
[ -n "$begin" ] && args+=",begin=$begin"
[ -n "$end" ] && args+=",end=$end"
[ -n "$windows" ] && args+=",windows=$(escape "$windows")"
[ -n "$profile" ] && args+=",profile=$(escape "$work/blocks")"

status=0
if [ "$triple" = arm-none-eabi ]; then
  EDGETRACK_QEMU_PLUGIN="$(escape "$plugin"),$args" "$top/toolchains/mcu/run-firmware.sh" "$binary" "$@" || status=$?
else
  "$qemu" -cpu "$cpu" -L "$sysroot" -plugin "$(escape "$plugin"),$args" "$binary" "$@" || status=$?
fi
if [ -z "$out" ]; then
  if [ -s "$work/summary" ]; then cat "$work/summary" >&2; else echo "count-insns: the plugin wrote no summary" >&2; fi
fi
if [ -n "$profile" ]; then
  # Blocks and code symbols, both by address, walked together: each block counts for the last
  # symbol at or below its start, and a block starting at the symbol is one call of it.
  hex_to_dec='function hex(s,   v, i) { v = 0; s = tolower(s); for (i = 1; i <= length(s); ++i) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1; return v }'
  awk "$hex_to_dec"' NF == 3 || NF == 4 { type = $(NF-1) } type ~ /^[TtWw]$/ { a = hex($1); printf "%d S %s\n", a - a % 2, $NF }' \
    "$work/symbols" >"$work/keyed"
  awk "$hex_to_dec"' { printf "%d B %d %d\n", hex($1), $2 * $3, $3 }' "$work/blocks" >>"$work/keyed"
  sort -k1,1n -k2,2r "$work/keyed" |
    awk '$2 == "S" { name = $3; at = $1; next }
         { total[name] += $3; if ($1 == at) calls[name] += $4 }
         END { for (n in total) printf "%d %d %s\n", total[n], calls[n], n }' |
    sort -k1,1nr | $triple-c++filt >"$profile"
fi
exit $status
