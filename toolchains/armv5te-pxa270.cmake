# SPDX-License-Identifier: BSD-3-Clause
# Cross build for the paper's target: Intel PXA270 (XScale, ARMv5TE, no FPU, soft-float ABI),
# with Debian's armel compilers (g++-arm-linux-gnueabi). Every test runs on qemu-arm -cpu pxa270,
# where a stray VFP instruction traps instead of passing unnoticed.
set(CMAKE_SYSTEM_PROCESSOR armv5te)
set(EDGETRACK_ARM_TRIPLE arm-linux-gnueabi)
# Pinned here rather than trusted from the compiler's defaults.
set(EDGETRACK_ARM_FLAGS "-march=armv5te -mtune=xscale -marm -mfloat-abi=soft")
set(EDGETRACK_QEMU qemu-arm;-cpu;pxa270)
set(EDGETRACK_DEB_ARCHITECTURE armel)
include(${CMAKE_CURRENT_LIST_DIR}/cross-linux.cmake)
