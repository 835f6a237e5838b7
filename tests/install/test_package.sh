#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The package as a user gets it, either from `cmake --install` into a scratch prefix (mode
# prefix) or from the .deb files CPack makes, unpacked with dpkg-deb -x (mode deb). Then, in
# fresh build trees: examples/minimal through find_package(edgetrack) and through pkg-config,
# run on the first frames of ViSP's mbt/cube (under the emulator for ARM) and held to the
# installed `edgetrack track` on the same frames. Mode prefix also builds examples/ar_overlay
# (host), programs written for upstream VXL and ViSP (tests/install/upstream_api), and checks
# find_package with a `real` component.
# usage: test_package.sh prefix|deb BUILD SOURCE WORK VERSION REAL VISP_IMAGES CXX_COMMAND DEB_ARCH
#        [TOOLCHAIN EMULATOR]   (env EDGETRACK_CONSUMER_FLAGS: extra flags, e.g. sanitizers)
set -euo pipefail
mode=$1 build=$2 source=$3 work=$4 version=$5 real=$6 visp=$7 cxx=$8 arch=$9
toolchain=${10:-} emulator=${11:-}
flags=${EDGETRACK_CONSUMER_FLAGS:-}
fail() { echo "FAIL: $*" >&2; exit 1; }
run() { $emulator "$@"; }  # word splitting of the emulator command is intended

rm -rf "$work" && mkdir -p "$work"
dev_package=libedgetrack-${real//_/-}-dev  # Debian names allow no underscore
case $mode in
  prefix)
    cmake --install "$build" --prefix "$work/root" >"$work/install.log" || fail "cmake --install failed"
    prefix=$work/root ;;
  deb)
    (cd "$build" && cpack -G DEB -B "$work/debs" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; fail "cpack failed"; }
    for package in edgetrack "$dev_package"; do
      deb=$(ls "$work"/debs/${package}_"$version"_*.deb 2>/dev/null) || fail "no $package .deb in $work/debs"
      dpkg-deb -f "$deb" Package Version Architecture Maintainer Depends Provides Conflicts | sed "s/^/$package: /"
      [ "$(dpkg-deb -f "$deb" Architecture)" = "$arch" ] || fail "$deb: Architecture is not $arch"
      [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "$deb: Version is not $version"
      [ "$(dpkg-deb -f "$deb" Maintainer)" = "edgetrack developers <edgetrack-dev@users.noreply.github.com>" ] ||
        fail "$deb: Maintainer is '$(dpkg-deb -f "$deb" Maintainer)'"
      dpkg-deb -x "$deb" "$work/root"
      [ -s "$work/root/usr/share/doc/$package/copyright" ] || fail "$deb has no /usr/share/doc/$package/copyright"
    done
    # Two reals' development packages cannot sit over each other: each provides and conflicts
    # with the same virtual package.
    dev_deb=$(ls "$work"/debs/${dev_package}_"$version"_*.deb)
    [ "$(dpkg-deb -f "$dev_deb" Provides)" = libedgetrack-dev ] && [ "$(dpkg-deb -f "$dev_deb" Conflicts)" = libedgetrack-dev ] ||
      fail "$dev_deb does not provide and conflict with libedgetrack-dev"
    if [ -z "$toolchain" ]; then
      # The host tools link OpenCV and OSMesa dynamically: dpkg-shlibdeps must have named them.
      depends=$(dpkg-deb -f "$work"/debs/edgetrack_*.deb Depends)
      for library in libc6 libstdc++6 libopencv-core libosmesa6; do
        grep -q "$library" <<<"$depends" || fail "edgetrack.deb Depends lacks $library: $depends"
      done
    fi
    prefix=$work/root/usr ;;
  *) fail "unknown mode $mode" ;;
esac

# What the package holds, and where: drop-in headers only under include/edgetrack/ports/<port>; the
# licence as each package's Debian copyright file; no template (*.in) among the headers.
for file in bin/edgetrack share/edgetrack/models/cube60.cao include/edgetrack/tracker.h \
            include/edgetrack/ports/vnl/vnl/vnl_vector.h include/edgetrack/ports/visp/visp3/me/vpMe.h \
            include/edgetrack/ports/real/real/real_config.h lib/pkgconfig/edgetrack.pc \
            lib/cmake/edgetrack/edgetrack-config.cmake lib/cmake/edgetrack/edgetrack-config-version.cmake \
            share/doc/edgetrack/copyright "share/doc/$dev_package/copyright"; do
  [ -e "$prefix/$file" ] || fail "$prefix/$file is not installed"
done
grep -q "^License: BSD-3-Clause$" "$prefix/share/doc/edgetrack/copyright" || fail "the copyright file names no BSD-3-Clause"
templates=$(find "$prefix/include" -name '*.in')
[ -z "$templates" ] || fail "template files installed: $templates"
# Static or shared (BUILD_SHARED_LIBS=ON): shared ones carry the SONAME of the version's major.minor.
if [ -e "$prefix/lib/libedgetrack_tracker.so" ]; then
  for library in "$prefix"/lib/libedgetrack_*.so; do
    soname=$(readelf -d "$library" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
    [ "$soname" = "$(basename "$library").${version%.*}" ] || fail "$library: SONAME '$soname', expected $(basename "$library").${version%.*}"
    [ -e "$prefix/lib/$soname" ] || fail "$prefix/lib/$soname is not installed"
  done
  "$prefix/bin/edgetrack" --version >/dev/null || fail "the installed edgetrack does not find its libraries"
  export LD_LIBRARY_PATH="$prefix/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"  # the pkg-config build has no rpath
  echo "shared libraries: $(cd "$prefix/lib" && ls libedgetrack_*.so.*.*.* | tr '\n' ' ')"
else
  [ -e "$prefix/lib/libedgetrack_tracker.a" ] || fail "$prefix/lib/libedgetrack_tracker.a is not installed"
fi
for dir in vnl vcl visp3 real netlib testlib; do
  [ ! -e "$prefix/include/$dir" ] || fail "$prefix/include/$dir would collide with an upstream install"
done
reported=$(run "$prefix/bin/edgetrack" --version)
[ "$reported" = "edgetrack $version (real = $real)" ] || fail "edgetrack --version says '$reported'"

configure() {  # configure <source dir> <build dir> [cmake args]
  local src=$1 dir=$2; shift 2
  # Through the environment, so the toolchain file's own flags (CMAKE_*_FLAGS_INIT) still apply.
  CXXFLAGS="$flags" LDFLAGS="$flags" cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release ${toolchain:+-DCMAKE_TOOLCHAIN_FILE="$toolchain"} \
    -DCMAKE_CXX_COMPILER_LAUNCHER="${EDGETRACK_CONSUMER_LAUNCHER:-}" "$@"
}
configure "$source/examples/minimal" "$work/minimal" >"$work/minimal.configure.log" 2>&1 ||
  { cat "$work/minimal.configure.log"; fail "examples/minimal does not configure against $prefix"; }
grep -q "edgetrack $version (real = $real) from $prefix/lib/cmake/edgetrack" "$work/minimal.configure.log" ||
  fail "examples/minimal did not find the package in $prefix"
cmake --build "$work/minimal" >"$work/minimal.build.log" 2>&1 || { cat "$work/minimal.build.log"; fail "examples/minimal does not build"; }
if [ -n "$toolchain" ]; then
  # Built as the toolchain file says: static (no program interpreter), and for the PXA270 ARMv5TE
  # soft-float.
  if [[ $toolchain == */armv5te-pxa270.cmake ]]; then
    "$source/toolchains/check-soft-float.sh" "$work/minimal" || fail "minimal is not an ARMv5TE soft-float program"
  fi
  ! readelf -l "$work/minimal/minimal" | grep -q INTERP || fail "minimal is not static"
fi

# The same program through pkg-config, with the build's own compiler command.
pc_flags=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs edgetrack)
! grep -q -- "-std=" <<<"$pc_flags" || fail "pkg-config's flags choose the language standard: $pc_flags"
[ "$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --variable=real edgetrack)" = "$real" ] || fail "edgetrack.pc: real is not $real"
# shellcheck disable=SC2086
${EDGETRACK_CONSUMER_LAUNCHER:-} $cxx $flags "$source/examples/minimal/minimal.cpp" $pc_flags -o "$work/minimal_pc" || fail "minimal does not build with pkg-config's flags"
# The public headers reach no port but real: otherwise a ViSP or VXL installed on the consumer's
# machine would be taken in their place, silently, or the build would fail where none is.
# shellcheck disable=SC2086
reached=$(echo '#include <edgetrack/edgetrack.h>' | $cxx $flags $pc_flags -x c++ -E -H - -o /dev/null 2>&1 |
          grep -E '^\.+ .*/(visp3|vnl|vcl|netlib|testlib)/' || true)
[ -z "$reached" ] || fail "edgetrack/edgetrack.h reaches headers other than real's: $reached"

# Five frames of the real cube sequence: every pose solved, most points matched, and the pose
# the installed command line finds for each frame with the same (default) settings.
# The camera only (cube.xml's <camera>): the command line would also apply the file's <ecm> and
# <face> settings, which minimal leaves at the library's defaults.
mbt=$visp/mbt
last=4
camera=$work/camera.xml
{ echo '<?xml version="1.0"?>'; echo '<conf>'; sed -n '/<camera>/,/<\/camera>/p' "$mbt/cube.xml"; echo '</conf>'; } >"$camera"
grep -q '<px>' "$camera" || fail "no <camera> in $mbt/cube.xml"
for program in "$work/minimal/minimal" "$work/minimal_pc"; do
  run "$program" "$mbt/cube.cao" "$camera" "$mbt/cube.0.pos" "$mbt/cube/image%04d.pgm" 0 $last >"$program.out" ||
    fail "$program failed"
done
cat "$work/minimal/minimal.out"
# The ms column is a time: every other column is the same in both builds.
same_rows() { cmp -s <(cut -d, -f1-8,10- "$1") <(cut -d, -f1-8,10- "$2"); }
same_rows "$work/minimal/minimal.out" "$work/minimal_pc.out" || fail "the pkg-config build prints other results"
run "$prefix/bin/edgetrack" track --model "$mbt/cube.cao" --camera "$camera" --init-pose "$mbt/cube.0.pos" \
    --images "$mbt/cube/image%04d.pgm" --last $last --quiet --poses "$work/track.csv" >/dev/null || fail "edgetrack track failed"
# minimal prints the poses CSV: track's header, no frame lost, 30 points or more on each, and the
# pose and edge angle edgetrack track finds for it.
awk -v frames=$((last + 1)) '
  FNR == NR { if (FNR == 1) header = $0; else { for (i = 2; i <= 7; i++) pose[$1, i] = $i; angle[$1] = $11 } ; next }
  FNR == 1 { if ($0 != header || $11 != "edge_angle_deg") { print "header: " $0 " (edgetrack track: " header ")"; bad++ } ; next }
  {
    n++
    if ($1 != n - 1) { print "line " FNR ": not frame " n - 1 ": " $0; bad++; next }
    if ($10 != "tracked" && $10 != "uncertain") { print "frame " $1 ": " $10; bad++ }
    if ($8 < 30) { print "frame " $1 ": " $8 " points"; bad++ }
    if (NF != 11 || $11 != angle[$1] || !($11 > 0 && $11 < 90))
      { print "frame " $1 ": edge angle " $11 ", edgetrack track says " angle[$1]; bad++ }
    for (i = 2; i <= 7; i++) {
      d = $i - pose[$1, i]
      if (d > 1e-5 || d < -1e-5) { print "frame " $1 ": column " i " is " $i ", edgetrack track says " pose[$1, i]; bad++ }
    }
  }
  END { if (n != frames) { print n " frames printed, expected " frames; bad++ } ; exit bad > 0 }
' FS=, "$work/track.csv" "$work/minimal/minimal.out" || fail "minimal disagrees with edgetrack track"
# ... and eval reads it as it is (against track's poses as the truth: no error).
{ echo "frame,tx,ty,tz,tux,tuy,tuz"; tail -n +2 "$work/track.csv" | cut -d, -f1-7; } >"$work/track_truth.csv"
run "$prefix/bin/edgetrack" eval --poses "$work/minimal/minimal.out" --truth "$work/track_truth.csv" >"$work/eval.txt" ||
  fail "edgetrack eval does not read minimal's output"
grep -q "^eval: frames=$((last + 1)) lost=0 .* distance_mm=0.0000 " "$work/eval.txt" || { cat "$work/eval.txt"; fail "eval of minimal's output"; }

# Host: the AR example (OpenCV) on the same frames, read by OpenCV from an image pattern, tracks
# as minimal does and writes one overlay image per frame.
if [ "$mode" = prefix ] && [ -z "$toolchain" ]; then
  configure "$source/examples/ar_overlay" "$work/ar_overlay" >"$work/ar_overlay.configure.log" 2>&1 &&
    cmake --build "$work/ar_overlay" >"$work/ar_overlay.build.log" 2>&1 ||
    { cat "$work/ar_overlay.configure.log" "$work/ar_overlay.build.log"; fail "examples/ar_overlay does not build"; }
  mkdir -p "$work/frames" "$work/overlay"
  for ((i = 0; i <= last; i++)); do ln -s "$mbt/cube/$(printf 'image%04d.pgm' $i)" "$work/frames/"; done
  "$work/ar_overlay/ar_overlay" "$mbt/cube.cao" "$camera" "$mbt/cube.0.pos" "$work/frames/image%04d.pgm" \
    "$work/overlay/overlay%04d.png" >"$work/ar_overlay.out" || fail "ar_overlay failed"
  same_rows "$work/minimal/minimal.out" "$work/ar_overlay.out" || { diff "$work/minimal/minimal.out" "$work/ar_overlay.out"; fail "ar_overlay tracks otherwise than minimal"; }
  [ "$(ls "$work"/overlay/overlay*.png | wc -l)" -eq $((last + 1)) ] || fail "ar_overlay did not write $((last + 1)) overlay images"
fi

# Host: a ViSP program (Debian's ViSP: vpImageIo, vpImage, vpHomogeneousMatrix) tracking with
# edgetrack in one translation unit, built with find_package and with pkg-config, gets the
# installed command line's poses.
if [ "$mode" = prefix ] && [ -z "$toolchain" ]; then
  beside_last=24
  # ViSP prints thetaU from the matrix in double; edgetrack track's CSV has the real's own thetaU.
  case $real in double) beside_tol=1e-6 ;; s40_23) beside_tol=2e-5 ;; *) beside_tol=1e-3 ;; esac
  configure "$source/tests/install/visp_beside" "$work/visp_beside" >"$work/visp_beside.log" 2>&1 &&
    cmake --build "$work/visp_beside" >>"$work/visp_beside.log" 2>&1 ||
    { cat "$work/visp_beside.log"; fail "the ViSP program with edgetrack does not build with find_package"; }
  visp_pc=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs edgetrack visp)
  # shellcheck disable=SC2086
  ${EDGETRACK_CONSUMER_LAUNCHER:-} $cxx $flags "$source/tests/install/visp_beside/visp_beside.cpp" $visp_pc \
    -o "$work/visp_beside_pc" || fail "the ViSP program with edgetrack does not build with pkg-config's flags"
  run "$prefix/bin/edgetrack" track --model "$mbt/cube.cao" --camera "$camera" --init-pose "$mbt/cube.0.pos" \
      --images "$mbt/cube/image%04d.pgm" --last $beside_last --quiet --poses "$work/beside.csv" >/dev/null ||
    fail "edgetrack track failed"
  # pkg-config links every ViSP library, visp_me included, after edgetrack's: a port class that
  # kept upstream's symbol names would be linked in place of ViSP's (or ViSP's in place of ours).
  shared=$(comm -12 <(nm --defined-only "$prefix"/lib/libedgetrack_*.a 2>/dev/null | awk 'NF == 3 { print $3 }' | sort -u) \
                    <(for so in $(pkg-config --libs-only-l visp | sed 's/-l//g'); do
                        f=$(ls /usr/lib/*/lib"$so".so 2>/dev/null | head -1); [ -n "$f" ] && nm -D --defined-only "$f"
                      done | awk 'NF == 3 { print $3 }' | sort -u) | wc -l)
  echo "symbols defined both by the installed edgetrack libraries and by ViSP's: $shared"
  for program in "$work/visp_beside/visp_beside" "$work/visp_beside_pc"; do
    "$program" "$mbt/cube.cao" "$camera" "$mbt/cube.0.pos" "$mbt/cube/image%04d.pgm" 0 $beside_last >"$program.out" ||
      fail "$program failed ($shared symbols of the ports have the same names as ViSP's)"
    awk -v frames=$((beside_last + 1)) -v tol=$beside_tol '
      FNR == NR { if (FNR > 1) { for (i = 2; i <= 7; i++) pose[$1, i] = $i } ; next }
      {
        n++
        if ($1 != "frame" || $2 != n - 1) { print "line " n ": not frame " n - 1 ": " $0; bad++; next }
        for (i = 2; i <= 7; i++) {
          d = $(i + 1) - pose[$2, i]
          if (d > tol || d < -tol) { print "frame " $2 ": coordinate " i - 1 " is " $(i + 1) ", edgetrack track says " pose[$2, i]; bad++ }
        }
      }
      END { if (n != frames) { print n " frames printed, expected " frames; bad++ } ; exit bad > 0 }
    ' FS=, "$work/beside.csv" FS=' ' "$program.out" || fail "$program disagrees with edgetrack track"
  done
fi

# compare (host, with ViSP): its ViSP child is installed under libexec/edgetrack and found from
# the running executable, so the installed command owes nothing to the build tree (no path of
# it compiled in) and still works with the whole prefix moved; without the child, one line
# names where it should be.
if [ "$mode" = prefix ] && [ -z "$toolchain" ] && "$prefix/bin/edgetrack" compare --help >/dev/null 2>&1; then
  ! readelf -p .rodata "$prefix/bin/edgetrack" | grep -qF "$(cd "$build" && pwd)" || fail "bin/edgetrack holds a path of the build tree"
  rm -rf "$work/moved" && cp -a "$prefix" "$work/moved"
  "$work/moved/bin/edgetrack" compare --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
    --images "$mbt/cube/image%04d.pgm" --last 2 >"$work/compare.txt" 2>&1 || { cat "$work/compare.txt"; fail "the moved compare failed"; }
  grep -q "^compare: frames=3 " "$work/compare.txt" || { cat "$work/compare.txt"; fail "the moved compare did not track 3 frames"; }
  rm "$work/moved/libexec/edgetrack/edgetrack-visp-mbt"
  if "$work/moved/bin/edgetrack" compare --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
       --images "$mbt/cube/image%04d.pgm" --last 2 >/dev/null 2>"$work/compare.err"; then
    fail "compare ran without its ViSP child"
  fi
  cat "$work/compare.err"
  [ "$(wc -l <"$work/compare.err")" -eq 1 ] &&
    grep -qF "$work/moved/libexec/edgetrack/edgetrack-visp-mbt: ViSP's tracker program is missing" "$work/compare.err" ||
    fail "no one-line message naming the missing child"
  echo "compare: installed, moved with its prefix, runs its ViSP child from libexec/edgetrack"
fi

# The host extras plugin (host): installed under libexec/edgetrack and loaded from the running
# executable's place when an option needs OpenCV or OSMesa, with the prefix moved too; image
# files need no plugin, and without it the option that needed it is named in one line.
if [ "$mode" = prefix ] && [ -z "$toolchain" ] && [ -e "$prefix/libexec/edgetrack/edgetrack-host.so" ]; then
  rm -rf "$work/moved" && cp -a "$prefix" "$work/moved"
  track_moved() {
    "$work/moved/bin/edgetrack" track --model "$mbt/cube.cao" --camera "$mbt/cube.xml" --init-pose "$mbt/cube.0.pos" \
      --images "$mbt/cube/image%04d.pgm" --last 2 --quiet "$@"
  }
  track_moved --overlay "$work/moved_overlay" >/dev/null || fail "the moved edgetrack does not load its host extras plugin"
  [ "$(ls "$work"/moved_overlay/overlay*.png | wc -l)" -eq 3 ] || fail "the moved edgetrack wrote no PNG overlay"
  rm "$work/moved/libexec/edgetrack/edgetrack-host.so"
  track_moved --poses "$work/moved.csv" >/dev/null || fail "PGM frames need the host extras plugin"
  if track_moved --overlay "$work/moved_overlay2" >/dev/null 2>"$work/plugin.err"; then
    fail "--overlay ran without the host extras plugin"
  fi
  cat "$work/plugin.err"
  [ "$(wc -l <"$work/plugin.err")" -eq 1 ] &&
    grep -qF "$work/moved/libexec/edgetrack/edgetrack-host.so: drawing the overlay (--overlay, --video) needs the host extras plugin, which is missing" \
      "$work/plugin.err" || fail "no one-line message naming the missing plugin"
  echo "host extras: installed, loaded from libexec/edgetrack when an option needs them"
fi

# Programs written for upstream VXL and ViSP build unchanged on edgetrack::vnl_algo / visp_me.
if [ "$mode" = prefix ]; then
  configure "$source/tests/install/upstream_api" "$work/upstream_api" >"$work/upstream_api.log" 2>&1 &&
    cmake --build "$work/upstream_api" >>"$work/upstream_api.log" 2>&1 ||
    { cat "$work/upstream_api.log"; fail "the upstream-API programs do not build"; }
  run "$work/upstream_api/visp_me_upstream" || fail "visp_me_upstream failed"
  run "$work/upstream_api/vnl_upstream" || fail "vnl_upstream failed"
fi

# A consumer may require the package's `real`; another one is refused with a clear message.
# (The .deb files hold the same config file.)
if [ "$mode" = deb ]; then
  echo "package (deb) in $prefix: minimal built with find_package and pkg-config, agrees with edgetrack track on $((last + 1)) frames"
  exit 0
fi
configure "$source/tests/install/needs_real" "$work/needs_same" -DNEEDED_REAL="$real" >"$work/needs_same.log" 2>&1 ||
  { cat "$work/needs_same.log"; fail "find_package(edgetrack COMPONENTS $real) failed"; }
other=$([ "$real" = s40_23 ] && echo double || echo s40_23)
if configure "$source/tests/install/needs_real" "$work/needs_other" -DNEEDED_REAL=$other >"$work/needs_other.log" 2>&1; then
  fail "find_package(edgetrack COMPONENTS $other) accepted a $real package"
fi
# CMake wraps the message: compare it with the lines joined.
tr -s ' \n' ' ' <"$work/needs_other.log" | grep -q "needs real = $other, but the edgetrack in .* was built with real = $real" ||
  { cat "$work/needs_other.log"; fail "no clear message for the wrong real"; }
echo "package (prefix) in $prefix: minimal built with find_package and pkg-config, agrees with edgetrack track on $((last + 1)) frames; ar_overlay and a ViSP program tracking with edgetrack (host) and the upstream-API programs build and run; the real component is checked"
