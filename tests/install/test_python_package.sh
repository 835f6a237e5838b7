#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Python package as a user gets it: from `cmake --install` of the python component into a
# scratch prefix (mode prefix, found through PYTHONPATH as docs/PYTHON.md says), or from the
# python3-edgetrack .deb CPack makes, unpacked with dpkg-deb -x (mode deb: its Depends checked).
# Then, in a fresh interpreter started outside the build tree, the module loads from there and
# examples/python/track_sequence.py tracks the first frames of ViSP's mbt/cube and evaluate.py a
# generated sequence.
# usage: test_python_package.sh prefix|deb BUILD SOURCE WORK VERSION PYTHON VISP_IMAGES
set -euo pipefail
mode=$1 build=$2 source=$3 work=$4 version=$5 python=$6 visp=$7
fail() { echo "FAIL: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work"
case $mode in
  prefix)
    cmake --install "$build" --component python --prefix "$work/root" >"$work/install.log" || fail "cmake --install failed"
    site=$work/root/lib/python3/dist-packages ;;
  deb)
    (cd "$build" && cpack -G DEB -B "$work/debs" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; fail "cpack failed"; }
    deb=$(ls "$work"/debs/python3-edgetrack_"$version"_*.deb 2>/dev/null) || fail "no python3-edgetrack .deb in $work/debs"
    depends=$(dpkg-deb -f "$deb" Depends)
    echo "python3-edgetrack: Depends: $depends"
    for package in python3-numpy "python3 (>= " "python3 (<< " libstdc++6 libc6; do
      grep -qF "$package" <<<"$depends" || fail "$deb: Depends lacks $package: $depends"
    done
    [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "$deb: Version is not $version"
    dpkg-deb -x "$deb" "$work/root"
    [ -s "$work/root/usr/share/doc/python3-edgetrack/copyright" ] || fail "$deb has no /usr/share/doc/python3-edgetrack/copyright"
    site=$work/root/usr/lib/python3/dist-packages ;;
  *) fail "unknown mode $mode" ;;
esac
for file in edgetrack/__init__.py edgetrack/__init__.pyi edgetrack/py.typed; do
  [ -e "$site/$file" ] || fail "$site/$file is not installed"
done
ls "$site"/edgetrack/_edgetrack*.so >/dev/null 2>&1 || fail "no compiled module in $site/edgetrack"

cd "$work"  # not the build tree: only PYTHONPATH leads to the module
loaded=$(env -u PYTHONHOME PYTHONPATH="$site" "$python" -c 'import edgetrack; print(edgetrack.__file__)')
[ "$loaded" = "$site/edgetrack/__init__.py" ] || fail "edgetrack loaded from $loaded, not $site"
PYTHONPATH="$site" "$python" "$source/examples/python/track_sequence.py" "$visp/mbt/cube.cao" "$visp/mbt/cube.xml" \
  "$visp/mbt/cube.0.pos" "$visp/mbt/cube/image%04d.pgm" 0 4 --poses "$work/poses.csv" >"$work/track.log" ||
  fail "track_sequence.py failed: $(cat "$work/track.log")"
[ "$(grep -c ',tracked,' "$work/poses.csv")" = 5 ] || fail "the installed module did not track the 5 frames: $(cat "$work/poses.csv")"
# examples/python/evaluate.py on a short sequence of the build's `edgetrack synth`.
"$build/app/edgetrack" synth --out "$work/seq" --model "$source/data/models/cube60.cao" --frames 4 --supersample 1 \
  >"$work/synth.log" 2>&1 || fail "edgetrack synth failed: $(cat "$work/synth.log")"
PYTHONPATH="$site" "$python" "$source/examples/python/evaluate.py" "$source/data/models/cube60.cao" "$work/seq" \
  >"$work/evaluate.log" 2>&1 || fail "evaluate.py failed: $(cat "$work/evaluate.log")"
grep -Eq '^4 frames, [34] tracked: ' "$work/evaluate.log" || fail "evaluate.py did not track 3 of the 4 frames: $(cat "$work/evaluate.log")"
echo "$mode: the module loads from $site and tracks"
