# SPDX-License-Identifier: BSD-3-Clause
# Reads a GNU ld map file of a firmware image (toolchains/mcu/mps2-an385.ld) and prints, per
# library (or object) linked in, the bytes it puts in flash (code, constants, unwinding tables,
# the initial values of .data) and in static RAM (.data, .bss): "<library> <flash> <ram>". With
# -v by=object, per object instead ("libtracker.a(pose_solver.cpp.obj)" as "pose_solver.cpp.obj").
# The code compiled at link time (EDGETRACK_MCU_LTO) is one entry, "link-time-optimised".
function hex(s,   v, i) {
  v = 0; s = tolower(substr(s, 3))
  for (i = 1; i <= length(s); ++i) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
  return v
}
function library(path,   n, parts) {
  # GCC's temporary objects of a link-time optimised link (/tmp/ccX.lto.o, /tmp/ccX.ltrans0.ltrans.o).
  if (path ~ /\.(lto|ltrans[0-9]+\.ltrans)\.o$/) return "link-time-optimised"
  if (by == "object" && path ~ /\(.*\)$/) { sub(/^.*\(/, "", path); sub(/\)$/, "", path) }
  sub(/\(.*$/, "", path)
  n = split(path, parts, "/")
  return parts[n]
}
function add(section, size, path) {
  if (size == 0 || path == "") return
  lib = library(path)
  if (section ~ /^\.(text|rodata|ARM\.ex|init|fini|init_array|fini_array|preinit_array)/) flash[lib] += size
  else if (section ~ /^\.data/) { flash[lib] += size; ram[lib] += size }
  else if (section ~ /^(\.bss|COMMON)/) ram[lib] += size
  else return
  seen[lib] = 1
}
/^Linker script and memory map/ { in_map = 1; next }
!in_map { next }
# An input section on one line: " .text.name  0xADDR  0xSIZE  file", or its name alone on a line
# and the rest on the next.
/^ [.A-Z][^ ]* *$/ { pending = $1; next }
/^ [.A-Z][^ ]* +0x[0-9a-f]+ +0x[0-9a-f]+ / { add($1, hex($3), $4); pending = ""; next }
/^ +0x[0-9a-f]+ +0x[0-9a-f]+ / && pending != "" { add(pending, hex($2), $3); pending = ""; next }
{ pending = "" }
END { for (lib in seen) printf "%s %d %d\n", lib, flash[lib], ram[lib] }
