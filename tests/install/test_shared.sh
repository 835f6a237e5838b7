#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The package with shared libraries: configures this source tree again with BUILD_SHARED_LIBS=ON
# and no host extras (the libraries and the command line only, to keep it short), builds the
# command line and the libraries it does not link (testlib), and runs test_package.sh's prefix mode on it (which checks the SONAMEs).
# Unoptimised: what it checks (the SONAMEs, the exported symbols, a program linked against them) does not
# depend on the optimisation, and the tree is built from nothing in every host double test run.
# usage: test_shared.sh SOURCE WORK VERSION REAL VISP_IMAGES CXX_COMMAND
set -euo pipefail
source=$1 work=$2
shift 2
tree=$work/tree
mkdir -p "$work"
cmake -S "$source" -B "$tree" -G Ninja -DBUILD_SHARED_LIBS=ON -DEDGETRACK_HOST_EXTRAS=OFF -DEDGETRACK_PYTHON=OFF -DEDGETRACK_REAL="$2" \
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O0 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O0 -DNDEBUG" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$tree" --target edgetrack testlib -j2 >"$work/build.log" 2>&1 || { tail -n 40 "$work/build.log"; exit 1; }
exec "$(dirname "$0")/test_package.sh" prefix "$tree" "$source" "$work/prefix" "$@" none
