# SPDX-License-Identifier: BSD-3-Clause
# Cross build for today's 64-bit handhelds and boards (Android's arm64-v8a, Raspberry Pi 3 and
# later): AArch64 with Debian's arm64 compilers (g++-aarch64-linux-gnu); tests run on
# qemu-aarch64 -cpu cortex-a53, the in-order core of most phones' little clusters.
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(EDGETRACK_ARM_TRIPLE aarch64-linux-gnu)
set(EDGETRACK_ARM_FLAGS "-march=armv8-a")
set(EDGETRACK_QEMU qemu-aarch64;-cpu;cortex-a53)
set(EDGETRACK_DEB_ARCHITECTURE arm64)
include(${CMAKE_CURRENT_LIST_DIR}/cross-linux.cmake)
