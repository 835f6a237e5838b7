#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# links-no-iostream.sh MAP: fails when the firmware image of link map MAP links libstdc++'s
# iostreams, locales or std::filesystem, or its throwing operator new and std::__throw_*: each is tens of KB of a
# microcontroller's flash (docs/MCU.md), pulled in by one <iostream>, string stream or path.
set -euo pipefail
map=${1:?usage: links-no-iostream.sh <link map>}
# The "Archive member included" section names each library member linked and the symbol it was
# linked for.
members=$(awk '/^Archive member included/ { p = 1; next } /^(Discarded input sections|Memory Configuration)/ { p = 0 } p' "$map" |
  grep -oE 'libstdc\+\+(_nano)?\.a\([a-z0-9_+-]+\.o\)' | sort -u)  # newlib-nano's build: libstdc++_nano.a
bad=$(grep -E '\((ios_init|locale_init|locale|sstream-inst|istream-inst|ostream-inst|fs_path|fs_ops|functexcept|new_op)\.o\)' <<<"$members" || true)
if [ -n "$bad" ]; then
  echo "links-no-iostream: $map links:" >&2
  echo "$bad" >&2
  exit 1
fi
if [ -z "$members" ]; then
  echo "links-no-iostream: $map names no libstdc++ member: not a link map of the tree's images" >&2
  exit 1
fi
echo "links-no-iostream: $(wc -l <<<"$members") libstdc++ members in $map, none of iostream, locale, filesystem or their throwing new"
