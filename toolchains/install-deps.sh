#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian 12 packages edgetrack builds and tests with; silent when all are there.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config           # host build
  ccache                                     # tests/run-all.sh: a source the trees share is compiled once
  g++-arm-linux-gnueabi qemu-user            # ARMv5TE soft-float build, run on qemu-arm -cpu pxa270
  g++-aarch64-linux-gnu g++-arm-linux-gnueabihf  # AArch64 and ARMv7-A hard-float builds (Cortex-A53, A7)
  gcc-arm-none-eabi libnewlib-arm-none-eabi  # bare-metal Cortex-M3 firmware (toolchains/cortex-m3.cmake)
  libstdc++-arm-none-eabi-newlib qemu-system-arm  # its C++ library; run on qemu-system-arm -M mps2-an385
  libcminpack-dev libeigen3-dev              # upstream MINPACK and Eigen's LM, for comparisons
  libvisp-dev visp-images-data               # upstream ViSP 3.5 and its real image sequences
  libopencv-dev libosmesa6-dev               # host image/video I/O and offscreen GL
  libx11-dev xvfb xauth xdotool              # track --init-click: display check; its test on a virtual display
  dpkg-dev                                   # cpack -G DEB: dpkg-shlibdeps fills the tools' Depends
  valgrind                                   # callgrind: the benchmarks' instruction counts (tests/bench)
  pybind11-dev python3-dev python3-numpy     # the Python module (python/) and its tests
  clang libclang-rt-14-dev                   # libFuzzer, ASan and UBSan for the fuzz tree (tests/fuzz)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
